// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/fracture/automatic_region.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <algorithm>
#include <cmath>

namespace pdfem
{
  namespace Fracture
  {
    using namespace dealii;

    template <int dim>
    RegionGrowth
    extend_pd_region_by_stress(const Coupling::CoupledSystem<dim> &system,
                               const Coupling::NodalResults<dim>  &results,
                               const double                        threshold,
                               const double                        margin,
                               std::vector<bool>                  &cell_is_pd)
    {
      const DoFHandler<dim> &node_dofs = system.node_dof_handler();
      const auto            &node_of   = system.node_of_scalar_dof();
      const MPI_Comm         comm      = node_dofs.get_communicator();

      // Seeds: the owned FE cells with a node at the threshold (centre and
      // circumradius, flattened for the gather); the largest sigma_1 of
      // the FE nodes for the load ratio.
      std::vector<double>                  seeds;
      double                               largest = 0.;
      std::vector<types::global_dof_index> local;
      for (const auto &cell : node_dofs.active_cell_iterators())
        if (cell->is_locally_owned() && !cell_is_pd[cell->active_cell_index()])
          {
            local.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(local);
            bool seed = false;
            for (const auto dof : local)
              {
                const double s1 = eigenvalues(results.stress[node_of[dof]])[0];
                largest         = std::max(largest, s1);
                seed            = seed || s1 >= threshold;
              }
            if (seed)
              {
                const Point<dim> c = cell->center();
                for (unsigned int d = 0; d < dim; ++d)
                  seeds.push_back(c[d]);
                seeds.push_back(circumradius(cell));
              }
          }
      largest = Utilities::MPI::max(largest, comm);

      std::vector<double> all_seeds;
      for (const auto &part : Utilities::MPI::all_gather(comm, seeds))
        all_seeds.insert(all_seeds.end(), part.begin(), part.end());
      RegionGrowth growth;
      if (all_seeds.empty())
        {
          if (largest > 0.)
            growth.load_ratio = threshold / largest;
          return growth;
        }

      // Every FE cell (the mesh is known on every rank) near a seed.
      for (const auto &cell :
           node_dofs.get_triangulation().active_cell_iterators())
        {
          const unsigned int i = cell->active_cell_index();
          if (cell_is_pd[i])
            continue;
          const Point<dim> center = cell->center();
          const double     reach  = margin_reach(cell, margin);
          for (std::size_t s = 0; s < all_seeds.size(); s += dim + 1)
            {
              Point<dim> seed;
              for (unsigned int d = 0; d < dim; ++d)
                seed[d] = all_seeds[s + d];
              if (center.distance(seed) <= reach + all_seeds[s + dim])
                {
                  cell_is_pd[i] = true;
                  ++growth.new_pd_cells;
                  break;
                }
            }
        }
      return growth;
    }

#define INSTANTIATE(dim)                                 \
  template RegionGrowth extend_pd_region_by_stress<dim>( \
    const Coupling::CoupledSystem<dim> &,                \
    const Coupling::NodalResults<dim> &,                 \
    double,                                              \
    double,                                              \
    std::vector<bool> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Fracture
} // namespace pdfem
