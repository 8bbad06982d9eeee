// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_MESH_CRACKS_H
#define PDFEM_MESH_CRACKS_H

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace pdfem
{
  namespace Mesh
  {
    /**
     * A straight crack: a segment [p0, p1] in 2D (p1 is the tip when the
     * crack grows from p0), a triangle [p0, p1, p2] in 3D. A bond is cut when
     * the segment between its two nodes meets the crack, touching included
     * (as in PDLSM-FEM).
     */
    template <int dim>
    struct Crack
    {
      std::array<dealii::Point<dim>, dim> points;

      /// Does the segment [a, b] meet the crack (touching counts)?
      bool
      cuts(const dealii::Point<dim> &a, const dealii::Point<dim> &b) const;
    };

    /// Build cracks from the parsed parameter (dim points of 3 coordinates).
    template <int dim>
    std::vector<Crack<dim>>
    make_cracks(const std::vector<std::vector<std::array<double, 3>>> &points);

    /// Does the segment [a, b] meet any of @p cracks?
    template <int dim>
    bool
    cut_by_any(const std::vector<Crack<dim>> &cracks,
               const dealii::Point<dim>      &a,
               const dealii::Point<dim>      &b);
  } // namespace Mesh
} // namespace pdfem

#endif
