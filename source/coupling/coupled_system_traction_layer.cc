// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: tractions on PD boundaries as a body force in a layer of
// nodes (PDModels::Layout::traction_layer; the embedded constraints of
// specs/002 §2.5).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/pd/families.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_traction_layers()
    {
      // For each traction condition: its faces on PD cells (area A, and
      // each face vertex's share of the area vector int N_b n dS), the PD
      // nodes within the layer of those vertices, their volume V, and the
      // layer's thickness V / A, so that the body force t / (V / A) on the
      // layer carries the traction's resultant t A (a flat boundary and a
      // uniform t exactly).
      traction_layers.clear();
      const double layer =
        layout.traction_layer * settings.horizon_factor * spacing;
      if (!(layer > 0.) || !has_pd_cells())
        return;
      traction_layers.resize(settings.traction.size());
      for (std::size_t c = 0; c < settings.traction.size(); ++c)
        {
          const auto                 &bc = settings.traction[c];
          TractionLayer              &l  = traction_layers[c];
          std::vector<unsigned int>   boundary; // the faces' vertices
          std::vector<Tensor<1, dim>> area(n_nodes);
          const double                A = add_face_area_vectors(
            [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
                const unsigned int                                    f) {
              const bool selected = cell->at_boundary(f) &&
                                    std::find(bc.boundary_ids.begin(),
                                              bc.boundary_ids.end(),
                                              cell->face(f)->boundary_id()) !=
                                      bc.boundary_ids.end();
              if (selected)
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  boundary.push_back(
                    vertex_to_node[cell->face(f)->vertex_index(v)]);
              return selected;
            },
            area);
          if (boundary.empty())
            continue; // the condition's faces are all on FE cells
          l.active = true;
          std::sort(boundary.begin(), boundary.end());
          boundary.erase(std::unique(boundary.begin(), boundary.end()),
                         boundary.end());
          const std::vector<unsigned int> nodes =
            with_boundary_layer(boundary, {}, layer);

          // Each owned layer node takes the outward normal of its nearest
          // boundary node (its area vector's direction), found among the
          // boundary nodes within the layer (the families' search).
          std::vector<unsigned int> owned_layer;
          double                    V = 0.;
          for (const unsigned int k : nodes)
            {
              V += model->nodal_volume(k);
              if (owned.is_element(node_dof[k][0]))
                owned_layer.push_back(k);
            }
          std::vector<std::uint8_t> is_boundary(n_nodes, 0);
          for (const unsigned int b : boundary)
            is_boundary[b] = 1;
          const PD::Families near =
            PD::find_families(x,
                              std::vector<double>(n_nodes, layer * (1. + 1e-8)),
                              owned_layer,
                              is_boundary);
          l.thickness = V / A;
          for (std::size_t o = 0; o < near.owners.size(); ++o)
            {
              const unsigned int k    = near.owners[o];
              unsigned int       best = k;
              double best_distance    = is_boundary[k] ? 0. : layer * 2.;
              for (std::size_t j = near.offsets[o]; j < near.offsets[o + 1];
                   ++j)
                {
                  const double d = x[k].distance(x[near.members[j]]);
                  if (d < best_distance)
                    {
                      best_distance = d;
                      best          = near.members[j];
                    }
                }
              AssertThrow(area[best].norm() > 0.,
                          ExcMessage("a traction layer node without a "
                                     "boundary node within the layer"));
              l.nodes.push_back(k);
              l.normal.push_back(area[best] / area[best].norm());
            }
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::add_traction_layers(const double t)
    {
      // f_k = t(x_k) V_k / thickness at the owned layer nodes.
      for (std::size_t c = 0; c < traction_layers.size(); ++c)
        {
          const auto          &bc = settings.traction[c];
          const TractionLayer &l  = traction_layers[c];
          traction_fn[c]->set_time(t);
          for (std::size_t i = 0; i < l.nodes.size(); ++i)
            {
              const unsigned int k     = l.nodes[i];
              const double       value = traction_fn[c]->value(to_3d(x[k]));
              Tensor<1, dim>     traction;
              if (bc.component == dim)
                traction = value * l.normal[i];
              else
                traction[bc.component] = value;
              const double scale = model->nodal_volume(k) / l.thickness;
              for (unsigned int d = 0; d < dim; ++d)
                f_ext[node_dof[k][d]] += traction[d] * scale;
            }
        }
    }

#define INSTANTIATE(dim)                                          \
  template void CoupledSystem<dim>::Impl::make_traction_layers(); \
  template void CoupledSystem<dim>::Impl::add_traction_layers(double);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
