// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: products with the unconstrained tangent: the load
// derivative d r / d t of loads linear in t (arc length, snap-back
// continuation under hard loading) and the patch test of the coupling.
#include <pdfem/base/config.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    Drivers::NewtonDriver::LoadDerivative
    CoupledSystem<dim>::load_derivative(const bool hard_loading_only)
    {
      Impl &s = *impl;
      // f_ext and u_p at t = 0, 1/2, 1: linear in t iff the midpoint values
      // are the mean of the ends and t = 0 carries no force.
      std::array<Vector, 3> f, up;
      for (unsigned int i = 0; i < 3; ++i)
        {
          s.assemble_external(0.5 * i);
          f[i].reinit(s.owned, s.comm);
          f[i] = s.f_ext;
          initialize_vector(up[i]);
          apply_dirichlet(up[i], 0.5 * i);
        }
      double f_max = 0., f_dev = 0., w_max = 0., u_dev = 0.;
      auto   q = std::make_shared<Vector>(f[2]);
      auto   w = std::make_shared<Vector>(up[2]);
      *w -= up[0];
      for (const auto i : s.owned)
        {
          f_max = std::max(f_max, std::abs(f[2][i]));
          f_dev = std::max(
            {f_dev, std::abs(f[0][i]), std::abs(f[1][i] - 0.5 * f[2][i])});
          if (s.dof_fixed[i])
            {
              w_max = std::max(w_max, std::abs((*w)[i]));
              u_dev =
                std::max(u_dev,
                         std::abs(up[1][i] - 0.5 * (up[0][i] + up[2][i])));
            }
          else
            (*w)[i] = 0.;
        }
      w->compress(VectorOperation::insert);
      f_max = Utilities::MPI::max(f_max, s.comm);
      f_dev = Utilities::MPI::max(f_dev, s.comm);
      w_max = Utilities::MPI::max(w_max, s.comm);
      u_dev = Utilities::MPI::max(u_dev, s.comm);
      const bool linear_in_t =
        !(f_dev > 1e-12 * f_max || u_dev > 1e-12 * w_max ||
          (f_max == 0. && w_max == 0.));
      if (!linear_in_t || (hard_loading_only && w_max == 0.))
        return {};

      // The ghosted copies of u and w the tangent rows read.
      auto u_ghosted = std::make_shared<Vector>(s.owned, s.relevant, s.comm);
      auto w_ghosted = std::make_shared<Vector>(s.owned, s.relevant, s.comm);
      s.import_ghosts(*w, *w_ghosted);
      const bool hard = w_max > 0.;
      return [this, q, u_ghosted, w_ghosted, hard](const Vector &u,
                                                   double,
                                                   Vector &out) {
        Impl &s = *impl;
        out.reinit(s.owned, s.comm);
        if (hard)
          {
            s.import_ghosts(u, *u_ghosted);
            s.tangent_product(*u_ghosted, *w_ghosted, out);
            out *= -1.;
          }
        out += *q;
        double *v = out.trilinos_vector()[0];
        for (const unsigned int lid : s.held_lid)
          v[lid] = 0.;
      };
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::tangent_product(const Vector &u,
                                              const Vector &w,
                                              Vector       &out) const
    {
      // The FE cells, then the PD rows of the owned families.
      Vector w_owned(owned, comm);
      w_owned = w;
      fe_matrix.vmult(out, w_owned);
      const PDModels::NodalField<dim> field = nodal_field(u);
      const PDModels::NodalField<dim> wf    = nodal_field(w);
      if (layout.family_elements)
        {
          // Each family's product on all its nodes, summed at the owners.
          scatter_ghosted.trilinos_vector().PutScalar(0.);
          double *g = scatter_ghosted.trilinos_vector()[0];
          for_each_family_tangent(field,
                                  [&](const auto &nodes, const auto &blocks) {
                                    const std::size_t n = nodes.size();
                                    for (std::size_t a = 0; a < n; ++a)
                                      {
                                        Tensor<1, dim> Kw;
                                        for (std::size_t b = 0; b < n; ++b)
                                          Kw +=
                                            blocks[a * n + b] * wf[nodes[b]];
                                        for (unsigned int c = 0; c < dim; ++c)
                                          g[relevant_lid[nodes[a]][c]] += Kw[c];
                                      }
                                  });
          scatter_add(scatter_ghosted, out);
          return;
        }
      for_each_tangent_row(field, [&](const std::size_t o, const auto &blocks) {
        const unsigned int k  = families.owners[o];
        Tensor<1, dim>     Kw = blocks[0] * wf[k];
        std::size_t        b  = 0;
        for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
             ++j)
          if (families.intact[j])
            Kw += blocks[++b] * wf[families.members[j]];
        for (unsigned int c = 0; c < dim; ++c)
          out[node_dof[k][c]] += Kw[c];
      });
      out.compress(VectorOperation::add);
    }

    template <int dim>
    PatchTest
    CoupledSystem<dim>::patch_test()
    {
      Impl      &s = *impl;
      PatchTest  patch;
      const bool has_fe = std::find(s.is_fe.begin(), s.is_fe.end(), 1) !=
                          s.is_fe.end(),
                 has_pd = std::find(s.is_pd.begin(), s.is_pd.end(), 1) !=
                          s.is_pd.end();
      if (!has_fe || !has_pd || s.matrix_free)
        return patch;

      // Held: the boundary's nodes and the PD nodes within a horizon.
      std::vector<unsigned int> boundary;
      for (const auto &cell : s.tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            for (const unsigned int v : cell->face(f)->vertex_indices())
              boundary.push_back(
                s.vertex_to_node[cell->face(f)->vertex_index(v)]);
      double horizon = 0.;
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        if (s.is_pd[k])
          horizon = std::max(horizon, s.horizon[k]);
      const std::vector<unsigned int> held =
        s.with_boundary_layer(boundary, {}, horizon);
      patch.held_nodes = held.size();
      std::vector<std::uint8_t> patch_fixed(s.dofs.n_dofs(), 0);
      for (const unsigned int k : held)
        for (unsigned int c = 0; c < dim; ++c)
          patch_fixed[s.node_dof[k][c]] = 1;

      const Point<dim> centre = BoundingBox<dim>(s.x).center();

      // The tangent at u = 0 with the patch's constraints.
      std::swap(s.dof_fixed, patch_fixed);
      s.update_held();
      const Vector saved_state = s.u_tangent;
      s.u_tangent              = 0.;
      s.assemble_tangent();
      Vector zero(s.owned, s.relevant, s.comm);

      const double lambda = s.settings.material.lambda();
      const double mu     = s.settings.material.mu();
      const double h_area = std::pow(s.spacing, dim - 1);
      Vector       affine(s.owned, s.comm), held_part(s.owned, s.comm),
        ghosted(s.owned, s.relevant, s.comm), K_affine(s.owned, s.comm),
        rhs(s.owned, s.comm), du(s.owned, s.comm);
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          {
            Tensor<2, dim> eps;
            eps[a][b] = eps[b][a] = 1.;
            const Tensor<2, dim> sigma =
              2. * mu * eps +
              lambda * trace(eps) * unit_symmetric_tensor<dim>();
            double u_max = 0.;
            for (unsigned int k = 0; k < s.n_nodes; ++k)
              u_max = std::max(u_max, (eps * (s.x[k] - centre)).norm());
            for (const unsigned int k : s.owned_nodes)
              {
                const Tensor<1, dim> v = eps * (s.x[k] - centre);
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    const auto i = s.node_dof[k][c];
                    affine[i]    = v[c];
                    held_part[i] = s.dof_fixed[i] ? v[c] : 0.;
                  }
              }
            affine.compress(VectorOperation::insert);
            held_part.compress(VectorOperation::insert);

            // Ghost forces: K u_affine on the free nodes.
            s.import_ghosts(affine, ghosted);
            s.tangent_product(zero, ghosted, K_affine);
            double ghost = 0.;
            for (const unsigned int k : s.owned_nodes)
              if (!s.dof_fixed[s.node_dof[k][0]])
                {
                  Tensor<1, dim> g;
                  for (unsigned int c = 0; c < dim; ++c)
                    g[c] = K_affine[s.node_dof[k][c]];
                  ghost = std::max(ghost, g.norm() / (sigma.norm() * h_area));
                }

            // K_ff du = -K_fp u_p: the free part of the solution.
            s.import_ghosts(held_part, ghosted);
            s.tangent_product(zero, ghosted, rhs);
            rhs *= -1.;
            double *rv = rhs.trilinos_vector()[0];
            for (const unsigned int lid : s.held_lid)
              rv[lid] = 0.;
            s.solver.solve(s.matrix, du, rhs, 0.);
            du += held_part;
            double error = 0.;
            for (const unsigned int k : s.owned_nodes)
              {
                Tensor<1, dim> e;
                for (unsigned int c = 0; c < dim; ++c)
                  e[c] = du[s.node_dof[k][c]] - affine[s.node_dof[k][c]];
                error = std::max(error, e.norm() / u_max);
              }
            patch.max_relative_error =
              std::max(patch.max_relative_error,
                       Utilities::MPI::max(error, s.comm));
            patch.max_relative_ghost_force =
              std::max(patch.max_relative_ghost_force,
                       Utilities::MPI::max(ghost, s.comm));
            ++patch.strain_modes;
          }

      // The run's own constraints and state again.
      std::swap(s.dof_fixed, patch_fixed);
      s.update_held();
      s.u_tangent        = saved_state;
      s.tangent_stale    = true;
      s.tangent_outdated = true;
      s.solver.preconditioner_matrix_changed();
      return patch;
    }

#define INSTANTIATE(dim)                                                       \
  template Drivers::NewtonDriver::LoadDerivative                               \
                     CoupledSystem<dim>::load_derivative(bool);                \
  template PatchTest CoupledSystem<dim>::patch_test();                         \
  template void      CoupledSystem<dim>::Impl::tangent_product(const Vector &, \
                                                          const Vector &, \
                                                          Vector &) const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
