// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: construction, nodes, sparsity, boundary conditions, accessors
// (the families and their weights: coupled_system_families.cc).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/group_by_key.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    namespace
    {
      /// The expression variables are always x, y, z, t (z = 0 in 2D).
      std::unique_ptr<FunctionParser<3>>
      make_function(const std::vector<std::string> &expressions)
      {
        auto f = std::make_unique<FunctionParser<3>>(expressions.size());
        f->initialize("x,y,z,t",
                      expressions,
                      std::map<std::string, double>(),
                      true);
        return f;
      }
    } // namespace

    template <int dim>
    CoupledSystem<dim>::Impl::Impl(
      const parallel::shared::Triangulation<dim, dim> &tria,
      const std::vector<bool>                         &cell_is_pd,
      const Settings<dim>                             &settings)
      : comm(tria.get_communicator())
      , tria(tria)
      , cell_pd(cell_is_pd)
      , settings(settings)
      , model(settings.pd_model ?
                settings.pd_model :
                std::shared_ptr<PDModels::Interface<dim>>(
                  PDModels::make_pdlsm<dim>(settings.weight_factor)))
      , layout(model->layout())
      , dofs(tria)
      , node_dofs_handler(tria)
      , solver(settings.linear_solver)
    {}

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_fe_and_dofs()
    {
      // One element per kind of cell the mesh has: Q1 on quadrilaterals and
      // hexahedra, P1 on triangles and tetrahedra. A mesh of one kind gets
      // collections of one element, so that the DoFHandlers number without
      // hp's work: on the 3D box (32 000 hexahedra) distribute_dofs took
      // 0.16 s in hp mode, on every rank alike (parallel::shared numbers
      // the whole mesh).
      const bool hypercubes = !tria.all_reference_cells_are_simplex();
      const bool simplices  = !tria.all_reference_cells_are_hyper_cube();
      if (hypercubes)
        {
          fe.push_back(FESystem<dim>(FE_Q<dim>(1), dim));
          fe_scalar.push_back(FE_Q<dim>(1));
          mapping.push_back(MappingFE<dim>(FE_Q<dim>(1)));
          quadrature.push_back(QGauss<dim>(2));
          face_quadrature.push_back(QGauss<dim - 1>(2));
        }
      if (simplices)
        {
          fe.push_back(FESystem<dim>(FE_SimplexP<dim>(1), dim));
          fe_scalar.push_back(FE_SimplexP<dim>(1));
          mapping.push_back(MappingFE<dim>(FE_SimplexP<dim>(1)));
          quadrature.push_back(QGaussSimplex<dim>(2));
          if constexpr (dim == 2)
            face_quadrature.push_back(QGauss<1>(2));
          else
            face_quadrature.push_back(QGaussSimplex<dim - 1>(2));
        }
      if (hypercubes && simplices)
        for (DoFHandler<dim> *handler : {&dofs, &node_dofs_handler})
          for (const auto &cell : handler->active_cell_iterators())
            if (cell->is_locally_owned())
              cell->set_active_fe_index(
                cell->reference_cell().is_hyper_cube() ? 0 : 1);
      dofs.distribute_dofs(fe);
      node_dofs_handler.distribute_dofs(fe_scalar);
      owned = dofs.locally_owned_dofs();
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_nodes()
    {
      constexpr auto invalid = numbers::invalid_unsigned_int;
      vertex_to_node.assign(tria.n_vertices(), invalid);
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (vertex_to_node[cell->vertex_index(v)] == invalid)
            vertex_to_node[cell->vertex_index(v)] = n_nodes++;

      x.resize(n_nodes);
      volume.assign(n_nodes, 0.);
      pd_volume.assign(n_nodes, 0.);
      is_pd.assign(n_nodes, 0);
      is_fe.assign(n_nodes, 0);
      no_fail.assign(n_nodes, 0);
      for (const unsigned int v : settings.no_fail_vertices)
        if (v < vertex_to_node.size() && vertex_to_node[v] != invalid)
          no_fail[vertex_to_node[v]] = 1;
      n_fe_cells.assign(n_nodes, 0);
      node_dof.resize(n_nodes);
      node_of_scalar.assign(node_dofs_handler.n_dofs(), invalid);
      dof_to_node.assign(dofs.n_dofs(), invalid);

      hp::FEValues<dim> volume_values(mapping,
                                      fe_scalar,
                                      quadrature,
                                      update_JxW_values);
      auto              scalar_cell = node_dofs_handler.begin_active();
      std::vector<types::global_dof_index> scalar_dofs;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          volume_values.reinit(scalar_cell);
          double cell_volume = 0.;
          for (const double w :
               volume_values.get_present_fe_values().get_JxW_values())
            cell_volume += w;
          const bool   pd    = cell_pd[cell->active_cell_index()];
          const double share = cell_volume / cell->n_vertices();
          const auto   index = cell->active_fe_index();
          scalar_dofs.resize(scalar_cell->get_fe().n_dofs_per_cell());
          scalar_cell->get_dof_indices(scalar_dofs);
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int k = vertex_to_node[cell->vertex_index(v)];
              x[k]                 = cell->vertex(v);
              volume[k] += share;
              if (pd)
                {
                  spacing = std::max(spacing, std::pow(cell_volume, 1. / dim));
                  pd_volume[k] += share;
                  is_pd[k] = 1;
                }
              else
                {
                  is_fe[k] = 1;
                  ++n_fe_cells[k];
                }
              for (unsigned int c = 0; c < dim; ++c)
                {
                  node_dof[k][c] = cell->vertex_dof_index(v, c, index);
                  dof_to_node[node_dof[k][c]] = k;
                }
              // Scalar Q1/P1: shape function v lives on vertex v.
              node_of_scalar[scalar_dofs[v]] = k;
            }
          ++scalar_cell;
        }

      // delta_k = m V_k^(1/dim), or one horizon m h (Layout).
      horizon.resize(n_nodes);
      for (unsigned int k = 0; k < n_nodes; ++k)
        horizon[k] =
          settings.horizon_factor *
          (layout.uniform_horizon ? spacing : std::pow(volume[k], 1. / dim));

      for (unsigned int k = 0; k < n_nodes; ++k)
        if (owned.is_element(node_dof[k][0]))
          owned_nodes.push_back(k);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_sparsity()
    {
      matrix_free = choice ? choice->path() == Solvers::SolvePath::matrix_free :
                             settings.linear_solver.matrix_free();
      // CG needs a symmetric operator: FE cells are, a PD model says.
      if (settings.linear_solver.conjugate_gradients() && has_pd_cells() &&
          !model->symmetric())
        throw InputError(settings.source_file,
                         "Linear solver/Type",
                         "cg needs a symmetric operator, and the stiffness "
                         "of this Peridynamics/Model is not (the collocated "
                         "pdlsm's)",
                         "direct or gmres (or Peridynamics/Model = pdlsm "
                         "energy, which is symmetric)");
      if (matrix_free && !model->linear() && !layout.tangent_products)
        throw InputError(settings.source_file,
                         "Linear solver/Preconditioner",
                         "'amg fe' solves without the assembled tangent, "
                         "which this nonlinear PD model needs (it gives no "
                         "products with its tangent)",
                         "amg, ilu, or Linear solver/Type = direct");
      if (matrix_free && !model->linear() &&
          !settings.linear_solver.conjugate_gradients())
        throw InputError(settings.source_file,
                         "Linear solver/Type",
                         "a nonlinear PD model's matrix-free path ('amg fe') "
                         "is CG: its tangent is symmetric, and CG's Ritz "
                         "values are its stability check",
                         "cg, or direct");

      {
        TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
        add_cell_entries(sp, false);
        sp.compress();
        fe_matrix.reinit(sp);
      }
      auxiliary.clear();
      n_matrix_entries = 0;
      if (matrix_free && settings.linear_solver.model_preconditioner())
        {
          if (!layout.preconditioner ||
              std::find(cell_pd.begin(), cell_pd.end(), false) != cell_pd.end())
            throw InputError(settings.source_file,
                             "Linear solver/Preconditioner",
                             "'pd model' needs an all-PD region whose model "
                             "has a preconditioner of its own",
                             "amg fe, or Peridynamics/Model = lps fft");
        }
      else if (matrix_free)
        make_auxiliary_pattern();
      else
        make_assembled_pattern();

      f_int.reinit(owned, relevant, comm, true);
      f_ext.reinit(owned, relevant, comm, true);
      u_ghosted.reinit(owned, relevant, comm);
      u_tangent.reinit(owned, relevant, comm);
      x_ghosted.reinit(owned, relevant, comm);
      if (layout.family_elements)
        {
          scatter_ghosted.reinit(owned, relevant, comm);
          scatter_owned.reinit(owned, comm);
        }
      x_masked.reinit(owned, comm);

      // AMG's near null space over the owned DoFs: the translations
      // (constant modes) and, in 3D, the rotations e_a x r about the centre
      // of the nodes' box, r in units of its diagonal so that they are of
      // the translations' size (LinearSolver::set_rotation_modes()).
      std::vector<std::vector<bool>>   modes(dim,
                                           std::vector<bool>(owned.n_elements(),
                                                             false));
      std::vector<std::vector<double>> rotations(
        dim == 3 ? dim : 0, std::vector<double>(owned.n_elements(), 0.));
      const BoundingBox<dim> box(x);
      const Point<dim>       centre = box.center();
      const double extent = std::max(box.get_boundary_points().first.distance(
                                       box.get_boundary_points().second),
                                     1e-300);
      for (unsigned int i = 0; i < owned.n_elements(); ++i)
        {
          const auto         dof = owned.nth_index_in_set(i);
          const auto         k   = dof_to_node[dof];
          const unsigned int c   = static_cast<unsigned int>(
            std::find(node_dof[k].begin(), node_dof[k].end(), dof) -
            node_dof[k].begin());
          modes[c][i]            = true;
          const Tensor<1, dim> r = (x[k] - centre) / extent;
          // About axis a: the components a+1 and a+2 of e_a x r are
          // -r_(a+2) and r_(a+1).
          for (unsigned int a = 0; a < rotations.size(); ++a)
            if (c == (a + 1) % 3)
              rotations[a][i] = -r[(a + 2) % 3];
            else if (c == (a + 2) % 3)
              rotations[a][i] = r[(a + 1) % 3];
        }
      solver.set_constant_modes(modes);
      solver.set_rotation_modes(rotations);
      set_up_choice();
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::add_cell_entries(
      TrilinosWrappers::SparsityPattern &sp,
      const bool                         all_cells) const
    {
      // Cell patterns: FE cells only (f_int, tangent), or every cell ("amg
      // fe"); every owned row has its diagonal (held DoFs). Node by node:
      // the rows of a node hold the DoFs of every node it shares a cell
      // with, inserted once, complete and sorted, instead of cell by cell
      // (each row then merged 8 times in 3D): the two patterns of the
      // peer's box (boxVpd4_static.in, 32 000 hexahedra) took 0.43 s, now
      // 0.25 s. The mesh is on every rank, so a row gets all its cells; the
      // rows of the owned cells' nodes that other ranks own go to them, as
      // before (a node's DoFs have one owner).
      std::vector<unsigned int> cell_offsets{0}, cell_nodes;
      std::vector<std::uint8_t> touched(n_nodes, 0);
      for (const auto &cell : dofs.active_cell_iterators())
        if (all_cells || !cell_pd[cell->active_cell_index()])
          {
            for (const unsigned int v : cell->vertex_indices())
              {
                const unsigned int k = vertex_to_node[cell->vertex_index(v)];
                cell_nodes.push_back(k);
                touched[k] |= cell->is_locally_owned();
              }
            cell_offsets.push_back(cell_nodes.size());
          }
      // The cells of each node.
      const auto [node_offsets, node_cells] =
        group_by_key<unsigned int>(n_nodes, [&](const auto &emit) {
          for (unsigned int c = 0; c + 1 < cell_offsets.size(); ++c)
            for (unsigned int i = cell_offsets[c]; i < cell_offsets[c + 1]; ++i)
              emit(cell_nodes[i], c);
        });

      std::vector<unsigned int>            neighbours;
      std::vector<types::global_dof_index> columns;
      for (unsigned int k = 0; k < n_nodes; ++k)
        {
          if (!(touched[k] || owned.is_element(node_dof[k][0])) ||
              node_offsets[k] == node_offsets[k + 1])
            continue;
          neighbours.clear();
          for (std::size_t i = node_offsets[k]; i < node_offsets[k + 1]; ++i)
            {
              const unsigned int c = node_cells[i];
              neighbours.insert(neighbours.end(),
                                cell_nodes.begin() + cell_offsets[c],
                                cell_nodes.begin() + cell_offsets[c + 1]);
            }
          std::sort(neighbours.begin(), neighbours.end());
          neighbours.erase(std::unique(neighbours.begin(), neighbours.end()),
                           neighbours.end());
          columns.clear();
          for (const unsigned int m : neighbours)
            columns.insert(columns.end(),
                           node_dof[m].begin(),
                           node_dof[m].end());
          std::sort(columns.begin(), columns.end());
          for (const auto row : node_dof[k])
            sp.add_entries(row, columns.begin(), columns.end(), true);
        }
      for (const auto i : owned)
        sp.add(i, i);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_auxiliary_pattern()
    {
      TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
      add_cell_entries(sp, true);
      sp.compress();
      auxiliary.reinit(sp);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_assembled_pattern()
    {
      // The coupled tangent: FE cells plus each PD row with its family
      // (family-element models: every node of a family with all of them,
      // like a cell).
      TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
      add_cell_entries(sp, false);
      std::vector<types::global_dof_index> cols;
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        {
          const unsigned int k = families.owners[o];
          cols.clear();
          for (unsigned int c = 0; c < dim; ++c)
            cols.push_back(node_dof[k][c]);
          for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
               ++j)
            for (unsigned int c = 0; c < dim; ++c)
              cols.push_back(node_dof[families.members[j]][c]);
          std::sort(cols.begin(), cols.end());
          if (layout.family_elements)
            for (const auto row : cols)
              sp.add_entries(row, cols.begin(), cols.end(), true);
          else
            for (unsigned int c = 0; c < dim; ++c)
              sp.add_entries(node_dof[k][c], cols.begin(), cols.end(), true);
        }
      sp.compress();
      solver.matrix_rebuilt();
      matrix.reinit(sp);
      n_matrix_entries = matrix.n_nonzero_elements();
      tangent_outdated = true;
    }

    template <int dim>
    std::vector<unsigned int>
    CoupledSystem<dim>::Impl::with_boundary_layer(
      std::vector<unsigned int>      nodes,
      const std::vector<Point<dim>> &points,
      const double                   layer) const
    {
      if (layer > 0.)
        {
          // The PD nodes within `layer` of the centres (the nodes, and the
          // points appended to the positions) are the members of their
          // families with that horizon: the families' cell-list search.
          std::vector<Point<dim>> position = x;
          position.insert(position.end(), points.begin(), points.end());
          std::vector<std::uint8_t> member(position.size(), 0);
          std::copy(is_pd.begin(), is_pd.end(), member.begin());
          std::vector<unsigned int> centres = nodes;
          for (unsigned int p = 0; p < points.size(); ++p)
            centres.push_back(n_nodes + p);
          const PD::Families within =
            PD::find_families(position,
                              std::vector<double>(position.size(), layer),
                              centres,
                              member);
          nodes.insert(nodes.end(),
                       within.members.begin(),
                       within.members.end());
          // A family leaves out its owner's own position: a PD node on a
          // point is in the layer too.
          for (const auto &p : points)
            for (unsigned int k = 0; k < n_nodes; ++k)
              if (is_pd[k] && x[k].distance_square(p) == 0.)
                nodes.push_back(k);
        }
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      return nodes;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_boundary_conditions()
    {
      // Prescribed values act on a layer of PD nodes for nonlocal models.
      const double layer =
        layout.dirichlet_layer * settings.horizon_factor * spacing;
      // Nodes of each named set (boundary or point), in input order.
      auto set_of = [&](const BoundaryCondition<dim> &bc) -> unsigned int {
        const auto it = std::find(set_names.begin(), set_names.end(), bc.name);
        if (it != set_names.end())
          return it - set_names.begin();
        std::vector<unsigned int> nodes;
        if (!bc.vertices.empty())
          {
            for (const unsigned int v : bc.vertices)
              {
                if (v >= vertex_to_node.size() ||
                    vertex_to_node[v] == numbers::invalid_unsigned_int)
                  throw InputError(settings.source_file,
                                   bc.name,
                                   "node " + std::to_string(v + 1) +
                                     " belongs to no element",
                                   "nodes of the mesh's elements");
                nodes.push_back(vertex_to_node[v]);
              }
          }
        else if (bc.at_point && layer > 0.)
          {
            // The nonlocal layer around the point (Layout::dirichlet_layer).
            nodes = with_boundary_layer({}, {bc.point}, layer);
            if (nodes.empty())
              throw InputError(settings.source_file,
                               "Boundary conditions/Dirichlet",
                               "no PD node within the Dirichlet layer (" +
                                 number(layer) + ") of the point " + bc.name,
                               "a point inside the PD region");
          }
        else if (bc.at_point)
          {
            double       best = std::numeric_limits<double>::max();
            unsigned int node = 0;
            Point<dim>   lo = x[0], hi = x[0];
            for (unsigned int k = 0; k < n_nodes; ++k)
              {
                if (x[k].distance(bc.point) < best)
                  {
                    best = x[k].distance(bc.point);
                    node = k;
                  }
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    lo[d] = std::min(lo[d], x[k][d]);
                    hi[d] = std::max(hi[d], x[k][d]);
                  }
              }
            if (best > 1e-6 * lo.distance(hi))
              throw InputError(settings.source_file,
                               "Boundary conditions/Dirichlet",
                               "no mesh node at the point " + bc.name +
                                 " (the nearest is " + number(best) + " away)",
                               "a boundary name, or a point that is a mesh "
                               "node");
            nodes.push_back(node);
          }
        else
          {
            for (const auto &cell : tria.active_cell_iterators())
              for (const unsigned int f : cell->face_indices())
                if (cell->at_boundary(f) &&
                    std::find(bc.boundary_ids.begin(),
                              bc.boundary_ids.end(),
                              cell->face(f)->boundary_id()) !=
                      bc.boundary_ids.end())
                  for (const unsigned int v : cell->face(f)->vertex_indices())
                    nodes.push_back(
                      vertex_to_node[cell->face(f)->vertex_index(v)]);
            nodes = with_boundary_layer(std::move(nodes), {}, layer);
          }
        set_names.push_back(bc.name);
        set_nodes.push_back(nodes);
        return set_names.size() - 1;
      };

      dof_fixed.assign(dofs.n_dofs(), 0);
      dof_dirichlet.assign(dofs.n_dofs(), -1);
      for (unsigned int c = 0; c < settings.dirichlet.size(); ++c)
        {
          const auto &bc = settings.dirichlet[c];
          dirichlet_fn.push_back(make_function({bc.expression}));
          for (const unsigned int k : set_nodes[set_of(bc)])
            {
              const auto dof = node_dof[k][bc.component];
              if (!dof_fixed[dof]) // the first condition on a DoF counts
                {
                  dof_fixed[dof]     = 1;
                  dof_dirichlet[dof] = c;
                }
            }
        }
      for (const auto &bc : settings.traction)
        traction_fn.push_back(make_function({bc.expression}));
      if (!settings.body_force.empty())
        body_fn = make_function(settings.body_force);
      last_reactions.assign(set_names.size(), Tensor<1, dim>());
    }

    // ------------------------------------------------------------ public
    template <int dim>
    CoupledSystem<dim>::CoupledSystem(
      const parallel::shared::Triangulation<dim, dim> &tria,
      const std::vector<bool>                         &cell_is_pd,
      const Settings<dim>                             &settings)
      : impl(std::make_unique<Impl>(tria, cell_is_pd, settings))
    {
      Impl &s     = *impl;
      auto  start = std::chrono::steady_clock::now();
      // Each phase's wall seconds, for summary.json (setup_phases()).
      const auto phase = [&](const char *name, const auto &steps) {
        steps();
        const auto now = std::chrono::steady_clock::now();
        s.setup_phases.emplace_back(
          name, std::chrono::duration<double>(now - start).count());
        start = now;
      };
      phase("dofs", [&] { s.make_fe_and_dofs(); });
      phase("nodes", [&] {
        s.make_nodes();
        s.make_boundary_conditions();
        s.make_pd_boundary();
      });
      phase("families", [&] { s.make_families(); });
      phase("fe_matrix", [&] {
        s.make_sparsity();
        s.update_held();
        s.assemble_fe_matrix();
      });
      phase("preconditioner", [&] { s.prepare_solver(); });
      phase("pd_model", [&] { s.initialize_model(); });
      phase("operator", [&] {
        s.make_traction_layers();
        s.make_pd_chunks();
      });
    }

    template <int dim>
    const std::vector<std::pair<std::string, double>> &
    CoupledSystem<dim>::setup_phases() const
    {
      return impl->setup_phases;
    }

    template <int dim>
    CoupledSystem<dim>::~CoupledSystem() = default;

    template <int dim>
    void
    CoupledSystem<dim>::initialize_vector(Vector &v) const
    {
      v.reinit(impl->owned, impl->comm);
    }

    template <int dim>
    ProblemSize
    CoupledSystem<dim>::size() const
    {
      const Impl &s = *impl;
      ProblemSize p;
      p.n_nodes = s.n_nodes;
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        {
          p.n_pd_nodes += s.is_pd[k];
          p.n_interface_nodes += s.is_pd[k] && s.is_fe[k];
        }
      p.n_cells = s.tria.n_active_cells();
      for (const bool pd : s.cell_pd)
        p.n_pd_cells += pd;
      p.n_dofs              = s.dofs.n_dofs();
      p.n_pd_boundary_faces = s.n_pd_boundary_faces;
      p.n_bonds =
        Utilities::MPI::sum<unsigned long>(s.families.n_bonds(), s.comm);
      p.n_broken_bonds =
        Utilities::MPI::sum<unsigned long>(s.families.n_broken(), s.comm);
      unsigned long n_decoupled = 0;
      for (const std::uint8_t d : s.decoupled)
        n_decoupled += d;
      p.n_decoupled_nodes   = Utilities::MPI::sum(n_decoupled, s.comm);
      p.n_matrix_entries    = s.n_matrix_entries;
      p.n_fe_matrix_entries = s.fe_matrix.n_nonzero_elements();
      return p;
    }

    template <int dim>
    double
    CoupledSystem<dim>::max_damage() const
    {
      // The model's damage (by default the fraction of broken bonds) of
      // the PD nodes at the state of the last residual.
      const Impl                     &s      = *impl;
      const PDModels::NodalField<dim> field  = s.nodal_field(s.u_ghosted);
      double                          result = 0.;
      for (std::size_t o = 0; o < s.families.owners.size(); ++o)
        if (s.is_pd[s.families.owners[o]])
          result = std::max(result, s.model->damage(o, field));
      return Utilities::MPI::max(result, impl->comm);
    }

    template <int dim>
    std::vector<std::string>
    CoupledSystem<dim>::reaction_names() const
    {
      return impl->set_names;
    }

    template <int dim>
    std::vector<Tensor<1, dim>>
    CoupledSystem<dim>::reactions() const
    {
      return impl->last_reactions;
    }

    template <int dim>
    const DoFHandler<dim, dim> &
    CoupledSystem<dim>::dof_handler() const
    {
      return impl->dofs;
    }

    template <int dim>
    const DoFHandler<dim, dim> &
    CoupledSystem<dim>::node_dof_handler() const
    {
      return impl->node_dofs_handler;
    }

    template <int dim>
    const std::vector<unsigned int> &
    CoupledSystem<dim>::node_of_scalar_dof() const
    {
      return impl->node_of_scalar;
    }

    template <int dim>
    const hp::MappingCollection<dim, dim> &
    CoupledSystem<dim>::mapping() const
    {
      return impl->mapping;
    }

    template <int dim>
    const std::vector<bool> &
    CoupledSystem<dim>::cell_is_pd() const
    {
      return impl->cell_pd;
    }

    template <int dim>
    std::vector<bool>
    CoupledSystem<dim>::cracked_cells() const
    {
      return impl->cells_cut_by_broken_bonds();
    }

#define INSTANTIATE(dim) template class CoupledSystem<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
