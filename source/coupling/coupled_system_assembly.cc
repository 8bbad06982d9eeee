// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: internal force, tangent, external force, residual, solve.
#include <pdfem/base/config.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_values.h>

#include "coupled_system_impl.h"

#include <cmath>

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      Point<3>
      to_3d(const Point<dim> &p)
      {
        Point<3> q;
        for (unsigned int d = 0; d < dim; ++d)
          q[d] = p[d];
        return q;
      }
    } // namespace

    template <int dim>
    void
    CoupledSystem<dim>::Impl::add_to_matrix(
      const std::vector<global_dof_index> &rows,
      const std::vector<global_dof_index> &cols,
      const std::vector<double>           &values)
    {
      // Prescribed DoFs: their rows are replaced by a diagonal entry (added
      // once, after assembly) and their columns dropped, since du = 0 there.
      static thread_local std::vector<global_dof_index> c;
      static thread_local std::vector<double>           v;
      for (std::size_t i = 0; i < rows.size(); ++i)
        {
          if (dof_fixed[rows[i]])
            continue;
          c.clear();
          v.clear();
          for (std::size_t j = 0; j < cols.size(); ++j)
            if (!dof_fixed[cols[j]])
              {
                c.push_back(cols[j]);
                v.push_back(values[i * cols.size() + j]);
              }
          matrix.add(rows[i], c.size(), c.data(), v.data(), false, false);
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::assemble_internal(
      const TrilinosWrappers::MPI::Vector &u,
      const bool                           assemble_tangent)
    {
      f_int = 0.;
      if (assemble_tangent)
        matrix = 0.;
      const double lambda = settings.material.lambda();
      const double mu     = settings.material.mu();

      // ---- FE cells: K_e = int B^T D B dV, f_e = K_e u_e.
      hp::FEValues<dim>                    fe_values(mapping,
                                  fe,
                                  quadrature,
                                  update_gradients | update_JxW_values);
      const FEValuesExtractors::Vector     displacement(0);
      std::vector<global_dof_index>        local_dofs;
      std::vector<double>                  K, f, u_local;
      std::vector<SymmetricTensor<2, dim>> eps;
      std::vector<double>                  div;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          if (!cell->is_locally_owned() || cell_pd[cell->active_cell_index()])
            continue;
          fe_values.reinit(cell);
          const FEValues<dim> &fv = fe_values.get_present_fe_values();
          const unsigned int   n  = fv.dofs_per_cell;
          local_dofs.resize(n);
          cell->get_dof_indices(local_dofs);
          K.assign(n * n, 0.);
          eps.resize(n);
          div.resize(n);
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            {
              for (unsigned int i = 0; i < n; ++i)
                {
                  eps[i] = fv[displacement].symmetric_gradient(i, q);
                  div[i] = fv[displacement].divergence(i, q);
                }
              const double JxW = fv.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  K[i * n + j] +=
                    (lambda * div[i] * div[j] + 2. * mu * (eps[i] * eps[j])) *
                    JxW;
            }
          u_local.resize(n);
          for (unsigned int j = 0; j < n; ++j)
            u_local[j] = u[local_dofs[j]];
          f.assign(n, 0.);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              f[i] += K[i * n + j] * u_local[j];
          f_int.add(local_dofs, f);
          if (assemble_tangent)
            add_to_matrix(local_dofs, local_dofs, K);
        }

      // ---- PD families: row k gets V_k (-L_k) + sigma_k s_k, summed over
      // the intact bonds with the weights of the whole family.
      std::vector<Tensor<1, dim>>          a;
      std::vector<SymmetricTensor<2, dim>> b;
      std::vector<std::size_t>             bond;
      std::vector<global_dof_index>        rows(dim), cols;
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        {
          if (decoupled[o])
            continue;
          const unsigned int k = families.owners[o];
          family_weights(o, a, b); // checked at set-up
          bond.clear();
          for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
               ++j)
            if (families.intact[j])
              bond.push_back(j);

          const std::size_t n_cols = dim * (bond.size() + 1);
          K.assign(dim * n_cols, 0.);
          auto add_block = [&](const std::size_t     block,
                               const Tensor<2, dim> &B,
                               const double          factor) {
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                K[i * n_cols + dim * block + j] += factor * B[i][j];
          };
          const double         Vk       = pd_volume[k];
          const Tensor<1, dim> s        = boundary_area[k];
          const bool           boundary = s.norm_square() > 0.;
          for (std::size_t n = 0; n < bond.size(); ++n)
            {
              const std::size_t    m = bond[n] - families.offsets[o];
              const Tensor<2, dim> G = pdlsm.divergence_block(b[m]);
              add_block(n + 1, G, -Vk);
              add_block(0, G, Vk);
              if (boundary)
                {
                  const Tensor<2, dim> T = pdlsm.traction_block(s, a[m]);
                  add_block(n + 1, T, 1.);
                  add_block(0, T, -1.);
                }
            }
          cols.resize(n_cols);
          for (unsigned int c = 0; c < dim; ++c)
            {
              rows[c] = node_dof[k][c];
              cols[c] = node_dof[k][c];
              for (std::size_t n = 0; n < bond.size(); ++n)
                cols[dim * (n + 1) + c] = node_dof[families.members[bond[n]]][c];
            }
          u_local.resize(n_cols);
          for (std::size_t j = 0; j < n_cols; ++j)
            u_local[j] = u[cols[j]];
          f.assign(dim, 0.);
          for (unsigned int i = 0; i < dim; ++i)
            for (std::size_t j = 0; j < n_cols; ++j)
              f[i] += K[i * n_cols + j] * u_local[j];
          f_int.add(rows, f);
          if (assemble_tangent)
            add_to_matrix(rows, cols, K);
        }
      f_int.compress(VectorOperation::add);

      if (assemble_tangent)
        {
          // Prescribed and decoupled DoFs: a diagonal of the size of the
          // node's stiffness, E * Delta^(dim-2).
          const double E = settings.material.youngs_modulus;
          for (const auto i : owned)
            if (dof_fixed[i])
              matrix.add(i,
                         i,
                         E * std::pow(volume[dof_to_node[i]],
                                      (dim - 2.) / dim));
          for (std::size_t o = 0; o < families.owners.size(); ++o)
            if (decoupled[o])
              for (unsigned int c = 0; c < dim; ++c)
                if (!dof_fixed[node_dof[families.owners[o]][c]])
                  matrix.add(node_dof[families.owners[o]][c],
                             node_dof[families.owners[o]][c],
                             E * std::pow(volume[families.owners[o]],
                                          (dim - 2.) / dim));
          matrix.compress(VectorOperation::add);
        }
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
                  const auto id = cell->face(face)->boundary_id();
                  bool       reinitialised = false;
                  for (std::size_t c = 0; c < settings.traction.size(); ++c)
                    {
                      const auto &bc = settings.traction[c];
                      if (std::find(bc.boundary_ids.begin(),
                                    bc.boundary_ids.end(),
                                    id) == bc.boundary_ids.end())
                        continue;
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
                                cell->get_fe().system_to_component_index(i).first;
                              f[i] += fv.shape_value(i, q) * traction[comp] *
                                      fv.JxW(q);
                            }
                        }
                      f_ext.add(local_dofs, f);
                    }
                }
            }
        }
      if (body_fn)
        {
          body_fn->set_time(t);
          hp::FEValues<dim> fe_values(mapping,
                                      fe,
                                      quadrature,
                                      update_values | update_quadrature_points |
                                        update_JxW_values);
          for (const auto &cell : dofs.active_cell_iterators())
            {
              if (!cell->is_locally_owned())
                continue;
              fe_values.reinit(cell);
              const FEValues<dim> &fv = fe_values.get_present_fe_values();
              const unsigned int   n  = fv.dofs_per_cell;
              local_dofs.resize(n);
              cell->get_dof_indices(local_dofs);
              f.assign(n, 0.);
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  dealii::Vector<double> b(dim);
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
      Impl &s     = *impl;
      s.u_ghosted = u;
      s.assemble_internal(s.u_ghosted, assemble_tangent);
      s.assemble_external(t);

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
      for (const auto i : s.owned)
        if (s.dof_fixed[i])
          {
            r[i]          = 0.;
            free_f_ext[i] = 0.;
          }
      for (std::size_t o = 0; o < s.families.owners.size(); ++o)
        if (s.decoupled[o])
          for (unsigned int c = 0; c < dim; ++c)
            r[s.node_dof[s.families.owners[o]][c]] = 0.;
      r.compress(VectorOperation::insert);
      free_f_ext.compress(VectorOperation::insert);
      s.f_ext_norm = free_f_ext.l2_norm();
      return r.l2_norm();
    }

    template <int dim>
    double
    CoupledSystem<dim>::external_force_norm() const
    {
      return impl->f_ext_norm;
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::solve_linear(Vector &du, const Vector &r)
    {
      du.reinit(impl->owned, impl->comm);
      return impl->solver.solve(impl->matrix, du, r);
    }

#define INSTANTIATE(dim)                                                     \
  template void CoupledSystem<dim>::Impl::add_to_matrix(                     \
    const std::vector<global_dof_index> &,                                   \
    const std::vector<global_dof_index> &,                                   \
    const std::vector<double> &);                                            \
  template void CoupledSystem<dim>::Impl::assemble_internal(                 \
    const TrilinosWrappers::MPI::Vector &, bool);                            \
  template void   CoupledSystem<dim>::Impl::assemble_external(double);       \
  template void   CoupledSystem<dim>::apply_dirichlet(Vector &, double) const; \
  template double CoupledSystem<dim>::residual(const Vector &,               \
                                               double,                       \
                                               Vector &,                     \
                                               bool);                        \
  template double CoupledSystem<dim>::external_force_norm() const;           \
  template unsigned int CoupledSystem<dim>::solve_linear(Vector &,           \
                                                         const Vector &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
