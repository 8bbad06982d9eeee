// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: internal force, tangent (assembled or matrix-free), external
// force, residual, solve.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/solvers/inertia.h>

#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_values.h>

#include <algorithm>
#include <cmath>

#include "coupled_system_impl.h"
#include <Epetra_CrsMatrix.h>

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    void
    CoupledSystem<dim>::Impl::add_to_matrix(
      TrilinosWrappers::SparseMatrix      &target,
      const std::vector<global_dof_index> &rows,
      const std::vector<global_dof_index> &cols,
      const std::vector<double>           &values,
      const bool                           eliminate) const
    {
      // Prescribed DoFs: their rows are replaced by a diagonal entry (added
      // once, after assembly) and their columns dropped, since du = 0 there.
      static thread_local std::vector<global_dof_index> c;
      static thread_local std::vector<double>           v;
      for (std::size_t i = 0; i < rows.size(); ++i)
        {
          if (eliminate && dof_fixed[rows[i]])
            continue;
          c.clear();
          v.clear();
          for (std::size_t j = 0; j < cols.size(); ++j)
            if (!eliminate || !dof_fixed[cols[j]])
              {
                c.push_back(cols[j]);
                v.push_back(values[i * cols.size() + j]);
              }
          target.add(rows[i], c.size(), c.data(), v.data(), false, false);
        }
    }

    template <int dim>
    double
    CoupledSystem<dim>::Impl::held_diagonal(const global_dof_index i) const
    {
      return settings.material.youngs_modulus *
             std::pow(volume[dof_to_node[i]], (dim - 2.) / dim);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::update_held()
    {
      held_lid.clear();
      held_value.clear();
      for (const auto i : owned)
        if (dof_fixed[i])
          {
            held_lid.push_back(owned.index_within_set(i));
            held_value.push_back(held_diagonal(i));
          }
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        if (decoupled[o])
          for (unsigned int c = 0; c < dim; ++c)
            {
              const auto i = node_dof[families.owners[o]][c];
              if (!dof_fixed[i])
                {
                  held_lid.push_back(owned.index_within_set(i));
                  held_value.push_back(held_diagonal(i));
                }
            }
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::Impl::add_held_diagonal(
      TrilinosWrappers::SparseMatrix &target,
      const std::vector<bool>        *already_added) const
    {
      unsigned int n_added = 0;
      for (unsigned int i = 0; i < held_lid.size(); ++i)
        if (already_added == nullptr || !(*already_added)[held_lid[i]])
          {
            const auto dof = owned.nth_index_in_set(held_lid[i]);
            target.add(dof, dof, held_value[i]);
            ++n_added;
          }
      return n_added;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::assemble_fe_matrix()
    {
      // The FE cells' stiffness, unconstrained (f_int = K_FE u), once.
      fe_matrix = 0.;
      add_cell_stiffness(
        fe_matrix,
        [&](const unsigned int c) { return !cell_pd[c]; },
        [](unsigned int) { return 1.; },
        false);
      fe_matrix.compress(VectorOperation::add);
      if (matrix_free)
        assemble_auxiliary();
    }

    template <int dim>
    std::vector<bool>
    CoupledSystem<dim>::Impl::cells_cut_by_broken_bonds() const
    {
      // A PD cell is cut when broken bonds split its vertices into groups.
      // Only bonds of locally owned families are seen; a cell whose
      // vertices all belong to other ranks' families counts as whole.
      const auto broken = [&](const unsigned int a, const unsigned int b) {
        const std::size_t o = family_of[a];
        if (o == families.owners.size())
          return false;
        for (std::size_t i = families.offsets[o]; i < families.offsets[o + 1];
             ++i)
          if (families.members[i] == b)
            return families.intact[i] == 0;
        return false;
      };
      // Only a family that lost a bond can part a cell's vertices: cells
      // whose vertices own no such family are whole without the pair tests
      // (on the peer's box, no bond broken: 0.03 s per call before).
      std::vector<std::uint8_t> lost_bond(families.owners.size() + 1, 0);
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        lost_bond[o] =
          std::find(families.intact.begin() + families.offsets[o],
                    families.intact.begin() + families.offsets[o + 1],
                    std::uint8_t(0)) !=
          families.intact.begin() + families.offsets[o + 1];
      std::vector<bool> cut(tria.n_active_cells(), false);
      std::array<unsigned int, GeometryInfo<dim>::vertices_per_cell> group;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && cell_pd[cell->active_cell_index()])
          {
            bool may_be_cut = false;
            for (const unsigned int v : cell->vertex_indices())
              may_be_cut =
                may_be_cut ||
                lost_bond[family_of[vertex_to_node[cell->vertex_index(v)]]];
            if (!may_be_cut)
              continue;
            // Group the vertices joined by intact bonds; the cell is cut
            // when they fall apart into two or more groups. A single broken
            // bond (diffuse damage) leaves the vertices joined.
            const unsigned int nv = cell->n_vertices();
            for (unsigned int i = 0; i < nv; ++i)
              group[i] = i;
            for (unsigned int i = 0; i < nv; ++i)
              for (unsigned int j = i + 1; j < nv; ++j)
                {
                  const unsigned int a = vertex_to_node[cell->vertex_index(i)];
                  const unsigned int b = vertex_to_node[cell->vertex_index(j)];
                  if (broken(a, b) || broken(b, a) || group[i] == group[j])
                    continue;
                  const unsigned int from = group[j], to = group[i];
                  for (unsigned int v = 0; v < nv; ++v)
                    if (group[v] == from)
                      group[v] = to;
                }
            for (unsigned int v = 1; v < nv; ++v)
              if (group[v] != group[0])
                cut[cell->active_cell_index()] = true;
          }
      return cut;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::assemble_auxiliary()
    {
      // The preconditioner's matrix for "amg fe": the FE stiffness of every
      // cell, with the cells that a crack (broken bonds) cuts through
      // weakened to cut_cell_stiffness, so that the AMG sees the crack the
      // PD operator sees. On the peer's plateCrack FC1 input: 2 088 GMRES
      // iterations with the uncut stiffness, 1 100 with factor 1e-2, 1 069
      // with 1e-3 or 0 (1e-3 keeps a node whose cells are all cut regular).
      // Bonds only break, so after the first assembly only the newly cut
      // cells change: their stiffness is scaled down in place. A node that
      // lost its last bond is held: its DoFs get the held diagonal added
      // in place (their rows are not eliminated here, unlike prescribed
      // ones). On plateCrack FC2 the full rebuilds took 3.2 % of the samples,
      // the in-place additions 0.9 % (perf). Only a
      // DoF leaving the held set, or a newly prescribed one, rebuilds the
      // whole matrix. 'pd model' preconditions without it: none is made.
      if (settings.linear_solver.model_preconditioner())
        {
          auxiliary_stale = false;
          return;
        }
      const std::vector<bool> cut = cells_cut_by_broken_bonds();
      std::vector<bool>       held(owned.n_elements(), false);
      for (const unsigned int lid : held_lid)
        held[lid] = true;
      bool only_new_held_by_decoupling =
        !auxiliary_cut.empty() && auxiliary_held.size() == held.size();
      for (std::size_t i = 0; i < held.size() && only_new_held_by_decoupling;
           ++i)
        if (auxiliary_held[i] ? !held[i] :
                                held[i] && dof_fixed[owned.nth_index_in_set(i)])
          only_new_held_by_decoupling = false;
      const bool incremental =
        Utilities::MPI::min(static_cast<int>(only_new_held_by_decoupling),
                            comm) == 1;
      if (!incremental)
        {
          auxiliary = 0.;
          auxiliary_cut.assign(cut.size(), false);
          auxiliary_held.assign(held.size(), false);
        }
      unsigned int n_changed = add_cell_stiffness(
        auxiliary,
        [&](const unsigned int c) {
          return !incremental || cut[c] != auxiliary_cut[c];
        },
        [&](const unsigned int c) {
          return !incremental ? (cut[c] ? cut_cell_stiffness : 1.) :
                                cut_cell_stiffness - 1.;
        },
        true);
      n_changed += add_held_diagonal(auxiliary, &auxiliary_held);
      auxiliary_cut  = cut;
      auxiliary_held = std::move(held);
      auxiliary.compress(VectorOperation::add);
      if (Utilities::MPI::sum(n_changed, comm) > 0)
        solver.preconditioner_matrix_changed();
      auxiliary_stale = false;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::assemble_tangent()
    {
      solver.matrix_changed();
      tangent_outdated = false;
      matrix           = 0.;
      // FE cells: the owned rows of the unconstrained FE matrix (assembled
      // once), with prescribed rows and columns dropped.
      std::vector<global_dof_index> cols;
      std::vector<double>           values;
      for_each_free_fe_row(cols, values, [&](const global_dof_index row) {
        matrix.add(row, cols.size(), cols.data(), values.data(), false, false);
      });

      // PD rows: the model's tangent row of each owner, at the state of the
      // last residual (nonlinear models) — its own block first.
      const PDModels::NodalField<dim> field = tangent_field();
      std::vector<global_dof_index>   rows(dim);
      std::vector<double>             K;
      if (layout.family_elements)
        {
          // Each family's blocks on all its nodes, like a cell's.
          const auto add_family = [&](const std::vector<unsigned int> &nodes,
                                      const auto                      &blocks) {
            const std::size_t n = nodes.size(), n_cols = dim * n;
            cols.resize(n_cols);
            for (std::size_t a = 0; a < n; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                cols[dim * a + c] = node_dof[nodes[a]][c];
            K.resize(n_cols * n_cols);
            for (std::size_t a = 0; a < n; ++a)
              for (std::size_t b = 0; b < n; ++b)
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    K[(dim * a + i) * n_cols + dim * b + j] =
                      blocks[a * n + b][i][j];
            add_to_matrix(matrix, cols, cols, K);
          };
          for_each_family_tangent(field, add_family);
          add_held_diagonal(matrix);
          matrix.compress(VectorOperation::add);
          return;
        }
      for_each_tangent_row(field, [&](const std::size_t o, const auto &blocks) {
        const unsigned int k      = families.owners[o];
        const std::size_t  n_cols = dim * blocks.size();
        K.assign(dim * n_cols, 0.);
        cols.resize(n_cols);
        for (unsigned int c = 0; c < dim; ++c)
          rows[c] = cols[c] = node_dof[k][c];
        std::size_t block = 0;
        for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
             ++j)
          if (families.intact[j])
            {
              ++block;
              for (unsigned int c = 0; c < dim; ++c)
                cols[dim * block + c] = node_dof[families.members[j]][c];
            }
        AssertThrow(block + 1 == blocks.size(),
                    ExcMessage("a PD model's tangent row must have one "
                               "block per intact bond and its own"));
        for (std::size_t b = 0; b < blocks.size(); ++b)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              K[i * n_cols + dim * b + j] = blocks[b][i][j];
        add_to_matrix(matrix, rows, cols, K);
      });
      add_held_diagonal(matrix);
      matrix.compress(VectorOperation::add);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::assemble_external(const double t)
    {
      f_ext = 0.;
      std::vector<global_dof_index> local_dofs;
      std::vector<double>           f;
      if (!settings.traction.empty())
        {
          for (auto &fn : traction_fn)
            fn->set_time(t);
          hp::FEFaceValues<dim> face_values(mapping,
                                            fe,
                                            face_quadrature,
                                            update_values |
                                              update_quadrature_points |
                                              update_normal_vectors |
                                              update_JxW_values);
          for (const auto &cell : dofs.active_cell_iterators())
            {
              if (!cell->is_locally_owned() || !cell->at_boundary())
                continue;
              for (const unsigned int face : cell->face_indices())
                {
                  if (!cell->at_boundary(face))
                    continue;
                  const auto id            = cell->face(face)->boundary_id();
                  bool       reinitialised = false;
                  for (std::size_t c = 0; c < settings.traction.size(); ++c)
                    {
                      const auto &bc = settings.traction[c];
                      if (std::find(bc.boundary_ids.begin(),
                                    bc.boundary_ids.end(),
                                    id) == bc.boundary_ids.end())
                        continue;
                      if (c < traction_layers.size() &&
                          traction_layers[c].active &&
                          cell_pd[cell->active_cell_index()])
                        continue; // a body force in the layer (below)
                      if (!reinitialised)
                        {
                          face_values.reinit(cell, face);
                          reinitialised = true;
                        }
                      const FEFaceValues<dim> &fv =
                        face_values.get_present_fe_values();
                      const unsigned int n = fv.dofs_per_cell;
                      local_dofs.resize(n);
                      cell->get_dof_indices(local_dofs);
                      f.assign(n, 0.);
                      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                        {
                          const double value = traction_fn[c]->value(
                            to_3d(fv.quadrature_point(q)));
                          Tensor<1, dim> traction;
                          if (bc.component == dim)
                            traction = value * fv.normal_vector(q);
                          else
                            traction[bc.component] = value;
                          for (unsigned int i = 0; i < n; ++i)
                            {
                              const unsigned int comp =
                                cell->get_fe()
                                  .system_to_component_index(i)
                                  .first;
                              f[i] += fv.shape_value(i, q) * traction[comp] *
                                      fv.JxW(q);
                            }
                        }
                      f_ext.add(local_dofs, f);
                    }
                }
            }
          add_traction_layers(t);
        }
      if (body_fn)
        {
          body_fn->set_time(t);
          hp::FEValues<dim>      fe_values(mapping,
                                      fe,
                                      quadrature,
                                      update_values | update_quadrature_points |
                                        update_JxW_values);
          dealii::Vector<double> b(dim);
          // Particle models take b(x_k) V_k at their PD nodes (below); the
          // cells they cover add nothing then.
          const bool nodal = layout.nodal_body_force;
          for (const auto &cell : dofs.active_cell_iterators())
            {
              if (!cell->is_locally_owned() ||
                  (nodal && cell_pd[cell->active_cell_index()]))
                continue;
              fe_values.reinit(cell);
              const FEValues<dim> &fv = fe_values.get_present_fe_values();
              const unsigned int   n  = fv.dofs_per_cell;
              local_dofs.resize(n);
              cell->get_dof_indices(local_dofs);
              f.assign(n, 0.);
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  body_fn->vector_value(to_3d(fv.quadrature_point(q)), b);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int comp =
                        cell->get_fe().system_to_component_index(i).first;
                      f[i] += fv.shape_value(i, q) * b[comp] * fv.JxW(q);
                    }
                }
              f_ext.add(local_dofs, f);
            }
          if (nodal)
            for (const unsigned int k : owned_nodes)
              if (is_pd[k])
                {
                  body_fn->vector_value(to_3d(x[k]), b);
                  for (unsigned int c = 0; c < dim; ++c)
                    f_ext[node_dof[k][c]] += b[c] * model->nodal_volume(k);
                }
        }
      f_ext.compress(VectorOperation::add);
    }

    // ------------------------------------------------------------ public
    template <int dim>
    void
    CoupledSystem<dim>::apply_dirichlet(Vector &u, const double t) const
    {
      Impl &s = *impl;
      for (auto &fn : s.dirichlet_fn)
        fn->set_time(t);
      for (const auto i : s.owned)
        if (s.dof_dirichlet[i] >= 0)
          u[i] = s.dirichlet_fn[s.dof_dirichlet[i]]->value(
            to_3d(s.x[s.dof_to_node[i]]));
      u.compress(VectorOperation::insert);
    }

    template <int dim>
    double
    CoupledSystem<dim>::residual(const Vector &u,
                                 const double  t,
                                 Vector       &r,
                                 const bool    assemble_tangent)
    {
      Impl &s = *impl;
      s.compute_internal_force(u);
      s.assemble_external(t);
      // Assembled on demand: the last residual of a step only checks.
      s.tangent_stale = assemble_tangent && !s.matrix_free &&
                        (!s.model->linear() || s.tangent_outdated);
      if (!s.model->linear())
        {
          s.u_tangent = s.u_ghosted; // the state check_stability() tests
          if (assemble_tangent && s.matrix_free)
            s.block_inverse.clear(); // matrix-free: rebuilt at u_tangent
        }

      // Reactions: the force the supports exert, f_int - f_ext, summed over
      // each set's nodes (every component), for the 2D thickness.
      const double thickness = dim == 2 ? s.settings.material.thickness : 1.;
      for (std::size_t set = 0; set < s.set_names.size(); ++set)
        {
          Tensor<1, dim> R;
          for (const unsigned int k : s.set_nodes[set])
            if (s.owned.is_element(s.node_dof[k][0]))
              for (unsigned int c = 0; c < dim; ++c)
                R[c] += s.f_int[s.node_dof[k][c]] - s.f_ext[s.node_dof[k][c]];
          s.last_reactions[set] = thickness * Utilities::MPI::sum(R, s.comm);
        }

      r.reinit(s.owned, s.comm);
      r = s.f_ext;
      r -= s.f_int;
      Vector free_f_ext(s.owned, s.comm);
      free_f_ext = s.f_ext;
      double *rv = r.trilinos_vector()[0];
      double *fv = free_f_ext.trilinos_vector()[0];
      for (const unsigned int lid : s.held_lid)
        rv[lid] = fv[lid] = 0.;
      s.force_scale = std::max(free_f_ext.l2_norm(), s.f_int.l2_norm());
      return r.l2_norm();
    }

    template <int dim>
    double
    CoupledSystem<dim>::force_scale() const
    {
      return impl->force_scale;
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::solve_linear(Vector &du, const Vector &r)
    {
      return solve_linear_within(du, r, 0.);
    }

    template <int dim>
    void
    CoupledSystem<dim>::stiffness_row_bounds(Vector &bounds)
    {
      Impl &s = *impl;
      if (s.matrix_free)
        {
          s.matrix_free_row_bounds(bounds);
          return;
        }
      if (s.tangent_stale)
        {
          s.assemble_tangent();
          s.tangent_stale = false;
        }
      bounds.reinit(s.owned, s.comm);
      // Epetra's row views: deal.II's matrix iterator copies every row
      // into a fresh buffer, which was 30 % of a dynamic relaxation run
      // (perf, tests/scenes/reference/adaptive_square_hole_relaxation.prm,
      // one thread: 60 calls for 6 866 iterations).
      const Epetra_CrsMatrix &A      = s.matrix.trilinos_matrix();
      const Epetra_BlockMap  &target = bounds.trilinos_vector().Map();
      double                 *b      = bounds.trilinos_vector()[0];
      for (int row = 0; row < A.NumMyRows(); ++row)
        {
          int     n      = 0;
          double *values = nullptr;
          int    *cols   = nullptr;
          A.ExtractMyRowView(row, n, values, cols);
          double sum = 0.;
          for (int k = 0; k < n; ++k)
            sum += std::abs(values[k]);
          const int local = target.LID(A.GRID64(row));
          if (local >= 0)
            b[local] = sum;
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::matrix_free_row_bounds(Vector &bounds) const
    {
      // sum_j |K_ij| as the assembled tangent's rows would give it (FE rows
      // and PD tangent rows with prescribed rows and columns dropped, the
      // held diagonal), the FE and PD parts of a row summed apart: on
      // interface nodes an upper bound of the assembled row's sum.
      AssertThrow(!layout.family_elements,
                  ExcMessage("matrix-free row bounds need tangent rows"));
      bounds.reinit(owned, comm);
      double                       *b = bounds.trilinos_vector()[0];
      std::vector<global_dof_index> cols;
      std::vector<double>           values;
      for_each_free_fe_row(cols, values, [&](const global_dof_index row) {
        double &sum = b[owned.index_within_set(row)];
        for (const double v : values)
          sum += std::abs(v);
      });
      const PDModels::NodalField<dim> field = tangent_field();
      for_each_tangent_row(field, [&](const std::size_t o, const auto &blocks) {
        const unsigned int k     = families.owners[o];
        std::size_t        block = 0;
        const auto         add   = [&](const unsigned int node, const auto &B) {
          for (unsigned int i = 0; i < dim; ++i)
            if (!dof_fixed[node_dof[k][i]])
              for (unsigned int j = 0; j < dim; ++j)
                if (!dof_fixed[node_dof[node][j]])
                  b[owned_lid[k][i]] += std::abs(B[i][j]);
        };
        add(k, blocks[0]);
        for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
             ++j)
          if (families.intact[j])
            add(families.members[j], blocks[++block]);
      });
      for (unsigned int i = 0; i < held_lid.size(); ++i)
        b[held_lid[i]] += held_value[i];
    }

    template <int dim>
    Drivers::StabilityReport
    CoupledSystem<dim>::Impl::matrix_free_stability()
    {
      // Without a matrix there is no inertia: the Ritz values of the last
      // CG solve of the step (at its last Newton iterate, within the
      // residual tolerance of the state tested) lie inside the spectrum of
      // P^-1 K, which has K's inertia. A negative one proves K indefinite;
      // none is necessary for stability, not a proof of it. Where the step
      // solved nothing (its first state was in equilibrium), a CG solve
      // with a vector of ones at the state gives them; one that diverges
      // there finds the tangent singular or indefinite.
      AssertThrow(settings.linear_solver.conjugate_gradients(),
                  ExcMessage("the matrix-free stability check needs CG"));
      bool                              diverged = false;
      Solvers::LinearSolver::RitzValues ritz;
      if (cg_solved_since_check)
        ritz = solver.last_ritz_values();
      if (!ritz.known)
        {
          Vector b(owned, comm), x(owned, comm);
          b = 1.;
          try
            {
              solve_on_path(x, b, 0.);
            }
          catch (const RunFailure &e)
            {
              if (e.exit_state != "linear solver diverged")
                throw;
              diverged = true;
            }
          ritz = solver.last_ritz_values();
        }
      cg_solved_since_check = false;
      Drivers::StabilityReport report;
      report.n_negative = ritz.known ? ritz.n_negative : 0;
      report.singular   = diverged && report.n_negative == 0;
      report.smallest_relative_pivot =
        ritz.known && ritz.largest > 0. ? ritz.smallest / ritz.largest : 0.;
      return report;
    }

    template <int dim>
    Drivers::StabilityReport
    CoupledSystem<dim>::check_stability()
    {
      Impl &s = *impl;
      AssertThrow(s.model->symmetric(),
                  ExcMessage("the stability check needs a symmetric tangent"));
      if (s.matrix_free)
        {
          // Type = auto: where CG finds the tangent indefinite or singular,
          // the direct path takes over for good and its inertia decides.
          const Drivers::StabilityReport report = s.matrix_free_stability();
          if (!s.choice || (report.n_negative == 0 && !report.singular) ||
              !s.choice->leave_matrix_free(
                "CG found the tangent " +
                std::string(report.singular ? "singular" : "indefinite") +
                " at a stability check: the inertia of its factorisation "
                "decides"))
            return report;
          s.switch_path(Solvers::SolvePath::direct);
        }
      // The tangent at the last residual's state (that residual may have
      // only checked convergence and not assembled it).
      if (s.tangent_stale || !s.model->linear() ||
          s.matrix.n_nonzero_elements() == 0)
        {
          s.assemble_tangent();
          s.tangent_stale = false;
        }
      const Solvers::Inertia   inertia = Solvers::compute_inertia(s.matrix);
      Drivers::StabilityReport report;
      report.singular                = inertia.singular;
      report.n_negative              = inertia.n_negative;
      report.smallest_relative_pivot = inertia.smallest_relative_pivot;
      return report;
    }

#define INSTANTIATE(dim)                                                       \
  template void   CoupledSystem<dim>::Impl::assemble_fe_matrix();              \
  template void   CoupledSystem<dim>::Impl::assemble_auxiliary();              \
  template void   CoupledSystem<dim>::Impl::update_held();                     \
  template double CoupledSystem<dim>::Impl::held_diagonal(global_dof_index)    \
    const;                                                                     \
  template void CoupledSystem<dim>::Impl::assemble_external(double);           \
  template void CoupledSystem<dim>::Impl::assemble_tangent();                  \
  template void CoupledSystem<dim>::Impl::add_to_matrix(                       \
    TrilinosWrappers::SparseMatrix &,                                          \
    const std::vector<global_dof_index> &,                                     \
    const std::vector<global_dof_index> &,                                     \
    const std::vector<double> &,                                               \
    bool) const;                                                               \
  template void   CoupledSystem<dim>::apply_dirichlet(Vector &, double) const; \
  template double CoupledSystem<dim>::residual(const Vector &,                 \
                                               double,                         \
                                               Vector &,                       \
                                               bool);                          \
  template double CoupledSystem<dim>::force_scale() const;                     \
  template Drivers::StabilityReport CoupledSystem<dim>::check_stability();     \
  template Drivers::StabilityReport                                            \
                CoupledSystem<dim>::Impl::matrix_free_stability();             \
  template void CoupledSystem<dim>::Impl::matrix_free_row_bounds(Vector &)     \
    const;                                                                     \
  template unsigned int CoupledSystem<dim>::solve_linear(Vector &,             \
                                                         const Vector &);      \
  template void         CoupledSystem<dim>::stiffness_row_bounds(Vector &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
