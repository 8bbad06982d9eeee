// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_MESH_CRACKS_H
#define PDFEM_MESH_CRACKS_H

#include <deal.II/base/point.h>

#include <algorithm>
#include <array>
#include <utility>
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
    /// An axis-aligned box: its lowest and highest corner.
    template <int dim>
    using Box = std::pair<dealii::Point<dim>, dealii::Point<dim>>;

    /// The box of the segment [a, b].
    template <int dim>
    inline Box<dim>
    segment_box(const dealii::Point<dim> &a, const dealii::Point<dim> &b)
    {
      Box<dim> box;
      for (unsigned int d = 0; d < dim; ++d)
        {
          box.first[d]  = std::min(a[d], b[d]);
          box.second[d] = std::max(a[d], b[d]);
        }
      return box;
    }

    /**
     * Do the boxes @p x and @p c meet when widened by @p reach and by 1e-9
     * of their largest extent? The margin is far above the tolerances of
     * Crack::cuts(), so a pair of boxes that does not meet holds no
     * segment and crack that meet: a test to take first.
     */
    template <int dim>
    inline bool
    boxes_meet(const Box<dim> &x, const Box<dim> &c, double reach = 0.)
    {
      double extent = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        extent = std::max(
          {extent, x.second[d] - x.first[d], c.second[d] - c.first[d]});
      reach += 1e-9 * extent;
      for (unsigned int d = 0; d < dim; ++d)
        if (x.first[d] > c.second[d] + reach ||
            x.second[d] < c.first[d] - reach)
          return false;
      return true;
    }

    template <int dim>
    struct Crack
    {
      std::array<dealii::Point<dim>, dim> points;

      /// Does the segment [a, b] meet the crack (touching counts)?
      bool
      cuts(const dealii::Point<dim> &a, const dealii::Point<dim> &b) const;

      /// The crack's bounding box.
      Box<dim>
      bounding_box() const
      {
        Box<dim> box(points[0], points[0]);
        for (const auto &p : points)
          for (unsigned int d = 0; d < dim; ++d)
            {
              box.first[d]  = std::min(box.first[d], p[d]);
              box.second[d] = std::max(box.second[d], p[d]);
            }
        return box;
      }
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
