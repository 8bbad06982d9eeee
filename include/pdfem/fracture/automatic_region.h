// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FRACTURE_AUTOMATIC_REGION_H
#define PDFEM_FRACTURE_AUTOMATIC_REGION_H

#include <pdfem/coupling/coupled_system.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace pdfem
{
  namespace Fracture
  {
    /** What one check of the automatic PD region found. */
    struct RegionGrowth
    {
      /// FE cells that became PD (the same on every rank).
      unsigned int new_pd_cells = 0;
      /// With none: the factor by which a load proportional to t may grow
      /// before an FE node reaches the threshold (linear response); infinite
      /// when no FE node is in tension.
      double load_ratio = std::numeric_limits<double>::infinity();
    };

    /// The largest distance of a vertex of @p cell from its centre: how far
    /// the region-growing rules reach from a cell's centre to its edge.
    template <typename Cell>
    double
    circumradius(const Cell &cell)
    {
      const auto center = cell->center();
      double     radius = 0.;
      for (const unsigned int v : cell->vertex_indices())
        radius = std::max(radius, cell->vertex(v).distance(center));
      return radius;
    }

    /// How far from the centre of @p cell a seed (a crack, a stressed
    /// cell) makes the cell PD: its circumradius plus @p margin of its sizes
    /// (measure^(1/dim)), the adaptive margin of both region-growing rules.
    template <typename Cell>
    double
    margin_reach(const Cell &cell, const double margin)
    {
      constexpr int dim = std::decay_t<decltype(*cell)>::dimension;
      return circumradius(cell) + margin * std::pow(cell->measure(), 1. / dim);
    }

    /**
     * The load factor ratio a quasi-static driver may jump by: the
     * criterion's @p criterion_ratio, but no further than to where an FE
     * node reaches the automatic region's threshold (@p region_ratio, from
     * RegionGrowth::load_ratio). A ratio that is not finite or not above 1
     * allows no jump.
     */
    inline double
    capped_load_ratio(const double criterion_ratio, const double region_ratio)
    {
      const auto jumps = [](const double r) {
        return std::isfinite(r) && r > 1.;
      };
      if (!jumps(region_ratio))
        return criterion_ratio;
      return jumps(criterion_ratio) ? std::min(criterion_ratio, region_ratio) :
                                      region_ratio;
    }

    /**
     * The automatic PD region (`Fracture/Automatic region` = f): an FE cell
     * with a node whose largest principal stress sigma_1 (the averaged
     * nodal stress of NodalResults) reaches @p threshold = f sigma_t seeds
     * the region; it and every FE cell whose centre lies within its own
     * circumradius plus @p margin of its sizes (measure^(1/dim)) plus the
     * seed's circumradius of a seed's centre become PD in @p cell_is_pd.
     * Collective: the seeds of all ranks are gathered, so that @p
     * cell_is_pd stays the same on every rank.
     */
    template <int dim>
    RegionGrowth
    extend_pd_region_by_stress(const Coupling::CoupledSystem<dim> &system,
                               const Coupling::NodalResults<dim>  &results,
                               double                              threshold,
                               double                              margin,
                               std::vector<bool>                  &cell_is_pd);
  } // namespace Fracture
} // namespace pdfem

#endif
