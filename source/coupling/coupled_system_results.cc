// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: nodal results (displacement, stress, damage), replicated.
#include <pdfem/base/config.h>

#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_tools.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    NodalResults<dim>
    CoupledSystem<dim>::nodal_results(const Vector &u) const
    {
      Impl &s = *impl;
      s.import_ghosts(u, s.u_ghosted);
      // u_k^c from the ghosted vector's raw array (operator() looks up
      // every global index: 35 % of this function on plateCrack FC1).
      const double *ug   = s.u_ghosted.trilinos_vector()[0];
      const auto    u_at = [&](const unsigned int k, const unsigned int c) {
        return ug[s.relevant_lid[k][c]];
      };
      constexpr unsigned int n_stress =
        SymmetricTensor<2, dim>::n_independent_components;
      const unsigned int n = s.n_nodes;

      // Each quantity is summed over the ranks that own its contributions.
      std::vector<double> disp(n * dim, 0.), stress(n * n_stress, 0.),
        gradient(n * dim * dim, 0.), count(n, 0.), damage(n, 0.);
      for (const unsigned int k : s.owned_nodes)
        for (unsigned int c = 0; c < dim; ++c)
          disp[k * dim + c] = u_at(k, c);

      auto add_stress = [&](const unsigned int             k,
                            const SymmetricTensor<2, dim> &sigma,
                            const Tensor<2, dim>          &grad_u) {
        for (unsigned int c = 0; c < n_stress; ++c)
          stress[k * n_stress + c] += sigma.access_raw_entry(c);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            gradient[(k * dim + i) * dim + j] += grad_u[i][j];
        count[k] += 1.;
      };

      // PD nodes: the nonlocal stress C : sym(sum_m mu_km (u_m - u_k) (x)
      // a_m); damage = the fraction of broken bonds.
      for (std::size_t o = 0; o < s.families.owners.size(); ++o)
        {
          const unsigned int k        = s.families.owners[o];
          const std::size_t  first    = s.families.offsets[o];
          const std::size_t  last     = s.families.offsets[o + 1];
          std::size_t        n_intact = 0;
          Tensor<2, dim>     grad_u;
          for (std::size_t j = first; j < last; ++j)
            {
              if (!s.families.intact[j])
                continue;
              ++n_intact;
              const unsigned int m = s.families.members[j];
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const double du = u_at(m, c) - u_at(k, c);
                  for (unsigned int d = 0; d < dim; ++d)
                    grad_u[c][d] += du * s.weight_a[j][d];
                }
            }
          damage[k] =
            last > first ? 1. - double(n_intact) / (last - first) : 0.;
          if (!s.decoupled[o])
            add_stress(k, s.pdlsm.stress(grad_u), grad_u);
        }

      // FE cells: Gauss-point stresses extrapolated to the vertices (the
      // Q1/P1 interpolant of the quadrature values), one contribution per
      // adjacent FE cell.
      std::vector<FullMatrix<double>> extrapolation(s.fe_scalar.size());
      for (unsigned int i = 0; i < s.fe_scalar.size(); ++i)
        {
          extrapolation[i].reinit(s.fe_scalar[i].n_dofs_per_cell(),
                                  s.quadrature[i].size());
          FETools::compute_projection_from_quadrature_points_matrix(
            s.fe_scalar[i], s.quadrature[i], s.quadrature[i], extrapolation[i]);
        }
      hp::FEValues<dim>                    fe_values(s.mapping,
                                  s.fe,
                                  s.quadrature,
                                  update_gradients);
      const FEValuesExtractors::Vector     displacement(0);
      std::vector<types::global_dof_index> local_dofs;
      std::vector<double>                  u_local;
      std::vector<Tensor<2, dim>>          grads;
      const double lambda = s.settings.material.lambda();
      const double mu     = s.settings.material.mu();
      for (const auto &cell : s.dofs.active_cell_iterators())
        {
          if (!cell->is_locally_owned() || s.cell_pd[cell->active_cell_index()])
            continue;
          fe_values.reinit(cell);
          const FEValues<dim> &fv = fe_values.get_present_fe_values();
          local_dofs.resize(fv.dofs_per_cell);
          cell->get_dof_indices(local_dofs);
          u_local.resize(fv.dofs_per_cell);
          for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
            u_local[i] = u_at(s.dof_to_node[local_dofs[i]],
                              fv.get_fe().system_to_component_index(i).first);
          grads.resize(fv.n_quadrature_points);
          fv[displacement].get_function_gradients_from_local_dof_values(u_local,
                                                                        grads);
          std::vector<SymmetricTensor<2, dim>> sigma_q(fv.n_quadrature_points);
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            {
              const SymmetricTensor<2, dim> eps = symmetrize(grads[q]);
              sigma_q[q] = lambda * trace(eps) * unit_symmetric_tensor<dim>() +
                           2. * mu * eps;
            }
          const FullMatrix<double> &X = extrapolation[cell->active_fe_index()];
          for (const unsigned int v : cell->vertex_indices())
            {
              SymmetricTensor<2, dim> sigma;
              Tensor<2, dim>          grad_u;
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  sigma += X(v, q) * sigma_q[q];
                  grad_u += X(v, q) * grads[q];
                }
              add_stress(s.vertex_to_node[cell->vertex_index(v)],
                         sigma,
                         grad_u);
            }
        }

      Utilities::MPI::sum(disp, s.comm, disp);
      Utilities::MPI::sum(stress, s.comm, stress);
      Utilities::MPI::sum(gradient, s.comm, gradient);
      Utilities::MPI::sum(count, s.comm, count);
      Utilities::MPI::sum(damage, s.comm, damage);

      NodalResults<dim> results;
      results.position = s.x;
      results.displacement.resize(n);
      results.stress.resize(n);
      results.displacement_gradient.resize(n);
      results.damage = damage;
      results.kind.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          for (unsigned int c = 0; c < dim; ++c)
            results.displacement[k][c] = disp[k * dim + c];
          if (count[k] > 0.)
            {
              for (unsigned int c = 0; c < n_stress; ++c)
                results.stress[k].access_raw_entry(c) =
                  stress[k * n_stress + c] / count[k];
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  results.displacement_gradient[k][i][j] =
                    gradient[(k * dim + i) * dim + j] / count[k];
            }
          results.kind[k] = (s.is_pd[k] ? 1 : 0) + (s.is_fe[k] ? 2 : 0);
        }
      return results;
    }

#define INSTANTIATE(dim)                                                       \
  template NodalResults<dim> CoupledSystem<dim>::nodal_results(const Vector &) \
    const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
