// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: nodal results (displacement, stress, damage), replicated.
#include <pdfem/base/config.h>

#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_tools.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <array>

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

      // One contribution to node k: grad u and sigma = C : sym(grad u).
      const double lambda     = s.settings.material.lambda();
      const double mu         = s.settings.material.mu();
      auto         add_stress = [&](const unsigned int    k,
                            const Tensor<2, dim> &grad_u) {
        const SymmetricTensor<2, dim> eps = symmetrize(grad_u);
        const SymmetricTensor<2, dim> sigma =
          lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2. * mu * eps;
        for (unsigned int c = 0; c < n_stress; ++c)
          stress[k * n_stress + c] += sigma.access_raw_entry(c);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            gradient[(k * dim + i) * dim + j] += grad_u[i][j];
        count[k] += 1.;
      };

      // PD nodes: the model's nonlocal gradient, the stress C : sym(grad u)
      // and its damage (by default the fraction of broken bonds). Each
      // owner's gradient is kept apart and added below, so that the threads
      // never write the same node.
      const std::size_t               n_owners = s.families.owners.size();
      std::vector<Tensor<2, dim>>     owner_gradient(n_owners);
      const PDModels::NodalField<dim> field = s.nodal_field(s.u_ghosted);
      s.model->prepare_results(field);
      const auto pd_owners = [&](const std::size_t first,
                                 const std::size_t last) {
        for (std::size_t o = first; o < last; ++o)
          {
            if (!s.is_pd[s.families.owners[o]])
              continue; // an FE node's reverse family (pairwise models)
            damage[s.families.owners[o]] = s.model->damage(o, field);
            owner_gradient[o] = s.model->displacement_gradient(o, field);
          }
      };

      // FE cells: the Gauss-point gradients extrapolated to the vertices
      // (make_vertex_gradients()), one contribution per adjacent FE cell.
      // The stress is linear in the gradient, so C : sym(grad u) of the
      // extrapolated gradient is the extrapolated Gauss-point stress.
      if (!s.vertex_gradients.built)
        s.make_vertex_gradients();
      const auto fe_cells = [&]() {
        const auto &g = s.vertex_gradients;
        std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> u_cell;
        for (std::size_t j = 0; j < g.n.size(); ++j)
          {
            const unsigned int  n     = g.n[j];
            const unsigned int *nodes = &g.nodes[g.start[j]];
            const double       *w     = &g.weights[g.weight_start[j]];
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                u_cell[a][c] = u_at(nodes[a], c);
            for (unsigned int v = 0; v < n; ++v)
              {
                Tensor<2, dim> grad_u;
                for (unsigned int a = 0; a < n; ++a, w += dim)
                  for (unsigned int c = 0; c < dim; ++c)
                    for (unsigned int d = 0; d < dim; ++d)
                      grad_u[c][d] += u_cell[a][c] * w[d];
                add_stress(nodes[n + v], grad_u);
              }
          }
      };

      // The FE cells on the calling thread, the PD owners in the chunks of
      // the matrix-free product (equal bond counts) on every thread.
      s.for_each_pd_chunk(fe_cells, pd_owners);
      for (std::size_t o = 0; o < n_owners; ++o)
        if (!s.decoupled[o] && s.is_pd[s.families.owners[o]])
          add_stress(s.families.owners[o], owner_gradient[o]);

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

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_vertex_gradients()
    {
      // X: the Q1/P1 interpolant of the quadrature values at the vertices.
      std::vector<FullMatrix<double>> extrapolation(fe_scalar.size());
      for (unsigned int i = 0; i < fe_scalar.size(); ++i)
        {
          extrapolation[i].reinit(fe_scalar[i].n_dofs_per_cell(),
                                  quadrature[i].size());
          FETools::compute_projection_from_quadrature_points_matrix(
            fe_scalar[i], quadrature[i], quadrature[i], extrapolation[i]);
        }
      hp::FEValues<dim> fe_values(mapping, fe, quadrature, update_gradients);
      std::vector<types::global_dof_index> local_dofs;
      VertexGradients                     &g = vertex_gradients;
      g                                      = VertexGradients();
      g.start.push_back(0);
      g.weight_start.push_back(0);
      for (const auto &cell : dofs.active_cell_iterators())
        {
          if (!cell->is_locally_owned() || cell_pd[cell->active_cell_index()])
            continue;
          fe_values.reinit(cell);
          const FEValues<dim>      &fv      = fe_values.get_present_fe_values();
          const FiniteElement<dim> &cell_fe = fv.get_fe();
          const FullMatrix<double> &X = extrapolation[cell->active_fe_index()];
          const unsigned int        n = cell->n_vertices();
          AssertDimension(X.m(), n);
          local_dofs.resize(fv.dofs_per_cell);
          cell->get_dof_indices(local_dofs);
          // The DoF of component 0 of each scalar shape function a.
          std::vector<unsigned int> dof_of_shape(n);
          g.nodes.resize(g.start.back() + 2 * n);
          unsigned int *nodes = &g.nodes[g.start.back()];
          for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
            {
              const auto [c, a] = cell_fe.system_to_component_index(i);
              if (c == 0)
                {
                  dof_of_shape[a] = i;
                  nodes[a]        = dof_to_node[local_dofs[i]];
                }
            }
          for (unsigned int v = 0; v < n; ++v)
            nodes[n + v] = vertex_to_node[cell->vertex_index(v)];
          for (unsigned int v = 0; v < n; ++v)
            for (unsigned int a = 0; a < n; ++a)
              {
                Tensor<1, dim> w;
                for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                  w += X(v, q) * fv.shape_grad_component(dof_of_shape[a], q, 0);
                for (unsigned int d = 0; d < dim; ++d)
                  g.weights.push_back(w[d]);
              }
          g.n.push_back(n);
          g.start.push_back(g.nodes.size());
          g.weight_start.push_back(g.weights.size());
        }
      g.built = true;
    }

#define INSTANTIATE(dim)                                                       \
  template NodalResults<dim> CoupledSystem<dim>::nodal_results(const Vector &) \
    const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
