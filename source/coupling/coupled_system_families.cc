// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: the PD boundary, the families (the PD model's set-up) and
// the crack faces (cut bonds, crack-face area, decoupled nodes).
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
      add_face_area_vectors(
        [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
            const unsigned int                                    f) {
          const bool on_pd_boundary =
            cell->at_boundary(f) ||
            !cell_pd[cell->neighbor(f)->active_cell_index()];
          n_pd_boundary_faces += on_pd_boundary; // counted as they are taken
          return on_pd_boundary;
        },
        boundary_area);
    }

    template <int dim>
    double
    CoupledSystem<dim>::Impl::add_face_area_vectors(
      const std::function<
        bool(const typename DoFHandler<dim>::active_cell_iterator &,
             unsigned int)>       &selected,
      std::vector<Tensor<1, dim>> &area) const
    {
      hp::FEFaceValues<dim> face_values(mapping,
                                        fe_scalar,
                                        face_quadrature,
                                        update_values | update_normal_vectors |
                                          update_JxW_values);
      double                total = 0.;
      for (const auto &cell : node_dofs_handler.active_cell_iterators())
        {
          if (!cell_pd[cell->active_cell_index()])
            continue;
          for (const unsigned int f : cell->face_indices())
            {
              if (!selected(cell, f))
                continue;
              face_values.reinit(cell, f);
              const FEFaceValues<dim> &fv = face_values.get_present_fe_values();
              for (const unsigned int v : cell->vertex_indices())
                {
                  Tensor<1, dim> s;
                  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                    s += fv.shape_value(v, q) * fv.normal_vector(q) * fv.JxW(q);
                  area[vertex_to_node[cell->vertex_index(v)]] += s;
                }
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                total += fv.JxW(q);
            }
        }
      return total;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_families()
    {
      std::vector<unsigned int> owners;
      for (const unsigned int k : owned_nodes)
        if (is_pd[k])
          owners.push_back(k);
      if (!layout.bonds)
        {
          // A model without bonds: one family per owner, no members.
          families         = PD::Families();
          families.owners  = owners;
          families.offsets = std::vector<std::size_t>(owners.size() + 1, 0);
        }
      else
        {
          std::vector<std::uint8_t> may_be_member(n_nodes, 1);
          if (!settings.fe_nodes_in_families)
            may_be_member = is_pd;
          families = PD::find_families(x, horizon, owners, may_be_member);
        }
      if (layout.bonds && layout.pairwise && settings.fe_nodes_in_families)
        {
          // The reverse of the PD-FE bonds: each owned FE node within a
          // horizon of PD nodes owns the family of those PD nodes.
          std::vector<unsigned int> fe_owners;
          for (const unsigned int k : owned_nodes)
            if (!is_pd[k])
              fe_owners.push_back(k);
          const PD::Families reverse =
            PD::find_families(x, horizon, fe_owners, is_pd);
          for (std::size_t o = 0; o < reverse.owners.size(); ++o)
            if (reverse.offsets[o + 1] > reverse.offsets[o])
              {
                families.owners.push_back(reverse.owners[o]);
                families.members.insert(families.members.end(),
                                        reverse.members.begin() +
                                          reverse.offsets[o],
                                        reverse.members.begin() +
                                          reverse.offsets[o + 1]);
                families.intact.resize(families.members.size(), 1);
                families.offsets.push_back(families.members.size());
              }
        }
      family_of.assign(n_nodes, families.owners.size());
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        family_of[families.owners[o]] = o;

      // Bonds crossing a pre-existing crack are cut for good; a crack that
      // cuts none lies outside every PD region and would not be there.
      families_cut_at_start.clear();
      bonds_cut_at_start.clear();
      const auto                &cracks = settings.cracks;
      std::vector<unsigned long> cut_by(cracks.size(), 0);
      for (std::size_t o = 0; o < families.owners.size() && !cracks.empty();
           ++o)
        {
          bool cut = false;
          for (std::size_t b = families.offsets[o]; b < families.offsets[o + 1];
               ++b)
            for (std::size_t c = 0; c < cracks.size(); ++c)
              if (cracks[c].cuts(x[families.owners[o]], x[families.members[b]]))
                {
                  if (families.intact[b] != 0)
                    bonds_cut_at_start.push_back(b);
                  families.intact[b] = 0;
                  cut                = true;
                  ++cut_by[c];
                }
          if (cut)
            families_cut_at_start.push_back(o);
        }
      Utilities::MPI::sum(cut_by, comm, cut_by);
      // Without PD cells a crack is a slit of the FE mesh, given for the
      // crack-tip integrals: it has no bonds to cut.
      for (std::size_t c = 0; c < cracks.size() && has_pd_cells(); ++c)
        if (cut_by[c] == 0)
          {
            std::ostringstream crack;
            for (unsigned int p = 0; p < dim; ++p)
              for (unsigned int d = 0; d < dim; ++d)
                crack << (d == 0 ? (p ? " -- (" : "(") : ", ")
                      << cracks[c].points[p][d] << (d + 1 == dim ? ")" : "");
            throw InputError(settings.source_file,
                             "Peridynamics/Pre-existing cracks",
                             "crack " + std::to_string(c + 1) + " " +
                               crack.str() +
                               " cuts no bond: it lies outside every PD "
                               "region",
                             "cracks through PD cells (Mesh/PD regions), or "
                             "Fracture/Adaptive margin > 0");
          }
      update_decoupled();

      // Ghosts: every DoF of a family member or of a vertex of an owned
      // cell (marked, not collected: families list millions of members).
      // A model without bonds gathers its neighbours itself.
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
    void
    CoupledSystem<dim>::Impl::initialize_model()
    {
      // The model's per-bond data over the whole initial families.
      region.comm                 = comm;
      region.position             = &x;
      region.volume               = &volume;
      region.pd_volume            = &pd_volume;
      region.horizon              = &horizon;
      region.spacing              = spacing;
      region.fe_nodes_in_families = settings.fe_nodes_in_families;
      region.has_fe_cells         = &is_fe;
      region.boundary_area        = &boundary_area;
      region.families             = &families;
      region.lambda               = settings.material.lambda();
      region.mu                   = settings.material.mu();
      region.youngs_modulus       = settings.material.youngs_modulus;
      region.poissons_ratio       = settings.material.poissons_ratio;
      region.plane_strain         = dim == 2 && !settings.material.plane_stress;
      region.source_file          = settings.source_file;
      // The model sees its whole initial families, no bond cut yet.
      for (const std::size_t b : bonds_cut_at_start)
        families.intact[b] = 1;
      model->initialize(region);
      for (const std::size_t b : bonds_cut_at_start)
        families.intact[b] = 0;

      // The crack faces' area first: a model may read s_k when its bonds
      // change (pdlsm energy's integration constraint).
      if (settings.free_crack_faces && !settings.cracks.empty())
        add_crack_face_area(settings.cracks);
      model->reference_bonds_cut(families_cut_at_start,
                                 settings.free_crack_faces);
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
      fragment.resize(families.owners.size(), 0);
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        decoupled[o] =
          fragment[o] ||
          (layout.bonds && !is_fe[families.owners[o]] &&
           std::none_of(families.intact.begin() + families.offsets[o],
                        families.intact.begin() + families.offsets[o + 1],
                        [](const std::uint8_t i) { return i != 0; }));
    }

#define INSTANTIATE(dim)                                                     \
  template void   CoupledSystem<dim>::Impl::make_pd_boundary();              \
  template double CoupledSystem<dim>::Impl::add_face_area_vectors(           \
    const std::function<bool(                                                \
      const typename DoFHandler<dim>::active_cell_iterator &, unsigned int)> \
      &,                                                                     \
    std::vector<Tensor<1, dim>> &) const;                                    \
  template void CoupledSystem<dim>::Impl::make_families();                   \
  template void CoupledSystem<dim>::Impl::initialize_model();                \
  template void CoupledSystem<dim>::Impl::add_crack_face_area(               \
    const std::vector<Mesh::Crack<dim>> &);                                  \
  template void CoupledSystem<dim>::Impl::update_decoupled();
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
