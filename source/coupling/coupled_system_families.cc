// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: the PD boundary, the families, their PDLSM weights and the
// crack faces (refits, crack-face area, decoupled nodes).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_values.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_pd_boundary()
    {
      // s_k = int_{S_pd} N_k n dS over the faces of PD cells that lie on the
      // domain boundary or on the PD/FE interface (outward from the PD cell).
      boundary_area.assign(n_nodes, Tensor<1, dim>());
      hp::FEFaceValues<dim> face_values(mapping,
                                        fe_scalar,
                                        face_quadrature,
                                        update_values | update_normal_vectors |
                                          update_JxW_values);
      for (const auto &cell : node_dofs_handler.active_cell_iterators())
        {
          if (!cell_pd[cell->active_cell_index()])
            continue;
          for (const unsigned int f : cell->face_indices())
            {
              const bool on_pd_boundary =
                cell->at_boundary(f) ||
                !cell_pd[cell->neighbor(f)->active_cell_index()];
              if (!on_pd_boundary)
                continue;
              ++n_pd_boundary_faces;
              face_values.reinit(cell, f);
              const FEFaceValues<dim> &fv = face_values.get_present_fe_values();
              for (const unsigned int v : cell->vertex_indices())
                {
                  Tensor<1, dim> s;
                  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                    s += fv.shape_value(v, q) * fv.normal_vector(q) * fv.JxW(q);
                  boundary_area[vertex_to_node[cell->vertex_index(v)]] += s;
                }
            }
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_families()
    {
      std::vector<unsigned int> owners;
      for (const unsigned int k : owned_nodes)
        if (is_pd[k])
          owners.push_back(k);
      std::vector<std::uint8_t> may_be_member(n_nodes, 1);
      if (!settings.fe_nodes_in_families)
        may_be_member = is_pd;
      families = PD::find_families(x, horizon, owners, may_be_member);
      family_of.assign(n_nodes, families.owners.size());
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        family_of[families.owners[o]] = o;

      // Every family must carry the second-order fit: if one cannot, the
      // horizon is too small for the mesh (or the weight too narrow).
      const unsigned int n_bad       = compute_weights();
      const unsigned int n_bad_total = Utilities::MPI::sum(n_bad, comm);
      if (n_bad_total > 0)
        {
          std::ostringstream where;
          for (std::size_t o = 0; o < families.owners.size() && n_bad > 0; ++o)
            if (families.offsets[o + 1] > families.offsets[o] &&
                bond_block[families.offsets[o]].norm() == 0.)
              {
                where << " (e.g. the node at (" << x[families.owners[o]]
                      << ") with "
                      << families.offsets[o + 1] - families.offsets[o]
                      << " members)";
                break;
              }
          throw InputError(
            settings.source_file,
            "Peridynamics/Horizon factor",
            std::to_string(n_bad_total) +
              " PD node(s) have too few effective family members for the "
              "second-order PDLSM fit with m = " +
              number(settings.horizon_factor) +
              ", a = " + number(settings.weight_factor) + where.str(),
            "a larger Horizon factor or Weight factor (m >= 3 with a >= "
            "0.25 is safe on quads and hexes)");
        }

      // Bonds crossing a pre-existing crack are cut for good.
      if (!settings.cracks.empty())
        for (std::size_t o = 0; o < families.owners.size(); ++o)
          for (std::size_t b = families.offsets[o]; b < families.offsets[o + 1];
               ++b)
            if (Mesh::cut_by_any(settings.cracks,
                                 x[families.owners[o]],
                                 x[families.members[b]]))
              families.intact[b] = 0;
      if (settings.free_crack_faces && !settings.cracks.empty())
        {
          std::vector<std::size_t> cut_families;
          for (std::size_t o = 0; o < families.owners.size(); ++o)
            if (std::any_of(families.intact.begin() + families.offsets[o],
                            families.intact.begin() + families.offsets[o + 1],
                            [](const std::uint8_t i) { return i == 0; }))
              cut_families.push_back(o);
          refit_families(cut_families);
          add_crack_face_area(settings.cracks);
        }
      zero_broken_bond_blocks();
      update_decoupled();

      // Ghosts: every DoF of a family member or of a vertex of an owned
      // cell (marked, not collected: families list millions of members).
      std::vector<std::uint8_t> needed(dofs.n_dofs(), 0);
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < dim; ++c)
              needed[node_dof[vertex_to_node[cell->vertex_index(v)]][c]] = 1;
      for (const unsigned int m : families.members)
        for (unsigned int c = 0; c < dim; ++c)
          needed[node_dof[m][c]] = 1;
      relevant = owned;
      std::vector<types::global_dof_index> extra;
      for (types::global_dof_index i = 0; i < needed.size(); ++i)
        if (needed[i])
          extra.push_back(i);
      relevant.add_indices(extra.begin(), extra.end());
      relevant.compress();

      // Local positions in the vectors' Epetra maps (which list the index
      // sets in increasing order), so that the PD kernel reads raw arrays.
      constexpr auto invalid = numbers::invalid_unsigned_int;
      relevant_lid.assign(n_nodes, {});
      owned_lid.assign(n_nodes, {});
      for (unsigned int k = 0; k < n_nodes; ++k)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const auto dof     = node_dof[k][c];
            relevant_lid[k][c] = relevant.is_element(dof) ?
                                   relevant.index_within_set(dof) :
                                   invalid;
            owned_lid[k][c] =
              owned.is_element(dof) ? owned.index_within_set(dof) : invalid;
          }
    }

    template <int dim>
    SymmetricTensor<2, dim>
    CoupledSystem<dim>::Impl::make_bond_block(
      const unsigned int             k,
      const SymmetricTensor<2, dim> &b) const
    {
      return -pd_volume[k] * symmetrize(pdlsm.divergence_block(b));
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::zero_broken_bond_blocks()
    {
      for (std::size_t j = 0; j < families.n_bonds(); ++j)
        if (!families.intact[j])
          bond_block[j] = SymmetricTensor<2, dim>();
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::Impl::compute_weights()
    {
      weight_a.assign(families.n_bonds(), Tensor<1, dim>());
      bond_block.assign(families.n_bonds(), SymmetricTensor<2, dim>());
      std::vector<Tensor<1, dim>>          xi, a;
      std::vector<double>                  vol;
      std::vector<SymmetricTensor<2, dim>> b;
      unsigned int                         n_failed = 0;
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        {
          const unsigned int k     = families.owners[o];
          const std::size_t  first = families.offsets[o];
          const std::size_t  last  = families.offsets[o + 1];
          xi.clear();
          vol.clear();
          for (std::size_t j = first; j < last; ++j)
            {
              xi.push_back(x[families.members[j]] - x[k]);
              vol.push_back(volume[families.members[j]]);
            }
          if (!pdlsm.compute_weights(xi, vol, horizon[k], a, b))
            {
              ++n_failed; // its weights stay zero
              continue;
            }
          std::copy(a.begin(), a.end(), weight_a.begin() + first);
          for (std::size_t i = 0; i < b.size(); ++i)
            bond_block[first + i] = make_bond_block(k, b[i]);
        }
      return n_failed;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::refit_families(
      const std::vector<std::size_t> &family_indices)
    {
      // The fit over the intact bonds alone: at a crack face the family is
      // one-sided, as at an outer boundary. A family too small for the
      // second-order fit keeps the weights of its whole family.
      std::vector<Tensor<1, dim>>          xi, a;
      std::vector<double>                  vol;
      std::vector<SymmetricTensor<2, dim>> b;
      std::vector<std::size_t>             bond;
      for (const std::size_t o : family_indices)
        {
          const unsigned int k = families.owners[o];
          xi.clear();
          vol.clear();
          bond.clear();
          for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
               ++j)
            if (families.intact[j])
              {
                xi.push_back(x[families.members[j]] - x[k]);
                vol.push_back(volume[families.members[j]]);
                bond.push_back(j);
              }
          if (!pdlsm.compute_weights(xi, vol, horizon[k], a, b))
            continue;
          for (std::size_t i = 0; i < bond.size(); ++i)
            {
              weight_a[bond[i]]   = a[i];
              bond_block[bond[i]] = make_bond_block(k, b[i]);
            }
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::add_crack_face_area(
      const std::vector<Mesh::Crack<dim>> &cracks)
    {
      // s_k += int_crack N_k / (sum of N_j over the vertices on k's side) n_k
      // dS, n_k pointing from k's side into the crack, over the crack's
      // pieces inside PD cells: each face of the crack is a boundary of the
      // cells' vertices on its side, and their shares add up to the face.
      // Midpoint rule with 8 points per cell size along the crack.
      if constexpr (dim == 2)
        for (const auto &crack : cracks)
          {
            const Point<dim>     p0 = crack.points[0], p1 = crack.points[1];
            const Tensor<1, dim> t = p1 - p0;
            const double         L = t.norm();
            if (!(L > 0.))
              continue;
            const Tensor<1, dim> n({-t[1] / L, t[0] / L});
            const auto           first =
              GridTools::find_active_cell_around_point(mapping,
                                                       node_dofs_handler,
                                                       0.5 * (p0 + p1));
            const double       h = first.first.state() == IteratorState::valid ?
                                     first.first->diameter() / std::sqrt(2.) :
                                     L;
            const unsigned int n_points =
              std::max(1u, static_cast<unsigned int>(std::ceil(8. * L / h)));
            for (unsigned int q = 0; q < n_points; ++q)
              {
                const Point<dim> p  = p0 + ((q + 0.5) / n_points) * t;
                const double     ds = L / n_points;
                std::pair<typename DoFHandler<dim>::active_cell_iterator,
                          Point<dim>>
                  found;
                try
                  {
                    found = GridTools::find_active_cell_around_point(
                      mapping, node_dofs_handler, p);
                  }
                catch (...)
                  {
                    continue; // outside the body
                  }
                const auto &cell = found.first;
                if (cell.state() != IteratorState::valid ||
                    !cell_pd[cell->active_cell_index()])
                  continue;
                const auto         &fe = cell->get_fe();
                std::vector<double> N(cell->n_vertices());
                double              side_sum[2] = {0., 0.};
                std::vector<int>    side(cell->n_vertices());
                // Only vertices that the crack separates from a vertex of
                // the other side face it: near the tip, those ahead of it
                // do not.
                std::vector<bool> faces(cell->n_vertices(), false);
                for (const unsigned int v : cell->vertex_indices())
                  side[v] = n * (cell->vertex(v) - p) > 0. ? 0 : 1;
                for (const unsigned int v : cell->vertex_indices())
                  for (const unsigned int u : cell->vertex_indices())
                    if (side[u] != side[v] &&
                        crack.cuts(cell->vertex(v), cell->vertex(u)))
                      faces[v] = true;
                for (const unsigned int v : cell->vertex_indices())
                  if (faces[v])
                    {
                      N[v] = fe.shape_value(v, found.second);
                      side_sum[side[v]] += N[v];
                    }
                for (const unsigned int v : cell->vertex_indices())
                  if (faces[v] && side_sum[side[v]] > 1e-12)
                    boundary_area[vertex_to_node[cell->vertex_index(v)]] +=
                      (side[v] == 0 ? -1. : 1.) * N[v] / side_sum[side[v]] *
                      ds * n;
              }
          }
      else
        (void)cracks;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::update_decoupled()
    {
      decoupled.assign(families.owners.size(), 0);
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        decoupled[o] =
          !is_fe[families.owners[o]] &&
          std::none_of(families.intact.begin() + families.offsets[o],
                       families.intact.begin() + families.offsets[o + 1],
                       [](const std::uint8_t i) { return i != 0; });
    }

#define INSTANTIATE(dim)                                                         \
  template void                    CoupledSystem<dim>::Impl::make_pd_boundary(); \
  template void                    CoupledSystem<dim>::Impl::make_families();    \
  template SymmetricTensor<2, dim> CoupledSystem<dim>::Impl::make_bond_block(    \
    unsigned int, const SymmetricTensor<2, dim> &) const;                        \
  template void         CoupledSystem<dim>::Impl::zero_broken_bond_blocks();     \
  template unsigned int CoupledSystem<dim>::Impl::compute_weights();             \
  template void         CoupledSystem<dim>::Impl::refit_families(                \
    const std::vector<std::size_t> &);                                   \
  template void CoupledSystem<dim>::Impl::add_crack_face_area(                   \
    const std::vector<Mesh::Crack<dim>> &);                                      \
  template void CoupledSystem<dim>::Impl::update_decoupled();
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
