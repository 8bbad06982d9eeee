// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/mesh/cracks.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>

namespace pdfem
{
  namespace Mesh
  {
    using dealii::Point;
    using dealii::Tensor;

    namespace
    {
      double
      cross2(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /// Segments [a, b] and [c, d] in the plane; touching counts. A
      /// relative tolerance keeps nodes lying on the crack line cut.
      bool
      segments_meet(const Point<2> &a,
                    const Point<2> &b,
                    const Point<2> &c,
                    const Point<2> &d)
      {
        const Tensor<1, 2> r     = b - a;
        const Tensor<1, 2> s     = d - c;
        const double       scale = r.norm() * s.norm();
        const double       eps   = 1e-12 * scale;
        const double       denom = cross2(r, s);
        const Tensor<1, 2> ca    = c - a;
        if (std::abs(denom) <= eps)
          {
            // Parallel: they meet only if collinear and overlapping.
            if (std::abs(cross2(ca, r)) > 1e-12 * r.norm() * ca.norm() + 1e-300)
              return false;
            const double rr = r * r;
            const double t0 = (ca * r) / rr;
            const double t1 = t0 + (s * r) / rr;
            return std::max(std::min(t0, t1), 0.) <=
                   std::min(std::max(t0, t1), 1.) + 1e-12;
          }
        const double t   = cross2(ca, s) / denom;
        const double u   = cross2(ca, r) / denom;
        const double tol = 1e-12;
        return t >= -tol && t <= 1. + tol && u >= -tol && u <= 1. + tol;
      }

      /// Segment [a, b] and triangle [p0, p1, p2] in space; touching counts.
      bool
      segment_meets_triangle(const Point<3> &a,
                             const Point<3> &b,
                             const Point<3> &p0,
                             const Point<3> &p1,
                             const Point<3> &p2)
      {
        const Tensor<1, 3> e1  = p1 - p0;
        const Tensor<1, 3> e2  = p2 - p0;
        const Tensor<1, 3> n   = dealii::cross_product_3d(e1, e2);
        const Tensor<1, 3> dir = b - a;
        const double       da  = (a - p0) * n;
        const double       db  = (b - p0) * n;
        const double       tol = 1e-12 * n.norm() * dir.norm();
        if ((da > tol && db > tol) || (da < -tol && db < -tol))
          return false;
        if (std::abs(da - db) <= tol)
          return false; // in the plane of the crack: treated as not cut
        const double   t = da / (da - db);
        const Point<3> x = a + t * dir;
        // Barycentric coordinates of x in the triangle.
        const Tensor<1, 3> w     = x - p0;
        const double       d11   = e1 * e1;
        const double       d12   = e1 * e2;
        const double       d22   = e2 * e2;
        const double       dw1   = w * e1;
        const double       dw2   = w * e2;
        const double       det   = d11 * d22 - d12 * d12;
        const double       beta  = (d22 * dw1 - d12 * dw2) / det;
        const double       gamma = (d11 * dw2 - d12 * dw1) / det;
        const double       btol  = 1e-12;
        return beta >= -btol && gamma >= -btol && beta + gamma <= 1. + btol;
      }
    } // namespace

    template <>
    bool
    Crack<2>::cuts(const Point<2> &a, const Point<2> &b) const
    {
      return segments_meet(a, b, points[0], points[1]);
    }

    template <>
    bool
    Crack<3>::cuts(const Point<3> &a, const Point<3> &b) const
    {
      // Bounding boxes first: most of a growth step's tests (every bond
      // near a cluster of 12-triangle discs against each triangle) end
      // here, without the normal's square roots.
      return boxes_meet(segment_box(a, b), bounding_box()) &&
             segment_meets_triangle(a, b, points[0], points[1], points[2]);
    }

    template <int dim>
    std::vector<Crack<dim>>
    make_cracks(const std::vector<std::vector<std::array<double, 3>>> &points)
    {
      std::vector<Crack<dim>> cracks;
      for (const auto &crack_points : points)
        {
          Crack<dim> crack;
          for (unsigned int v = 0; v < dim; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              crack.points[v][d] = crack_points[v][d];
          cracks.push_back(crack);
        }
      return cracks;
    }

    template <int dim>
    bool
    cut_by_any(const std::vector<Crack<dim>> &cracks,
               const Point<dim>              &a,
               const Point<dim>              &b)
    {
      for (const auto &crack : cracks)
        if (crack.cuts(a, b))
          return true;
      return false;
    }

#define INSTANTIATE(dim)                                                         \
  template struct Crack<dim>;                                                    \
  template Box<dim> segment_box<dim>(const Point<dim> &, const Point<dim> &);    \
  template bool     boxes_meet<dim>(const Box<dim> &, const Box<dim> &, double); \
  template std::vector<Crack<dim>> make_cracks<dim>(                             \
    const std::vector<std::vector<std::array<double, 3>>> &);                    \
  template bool cut_by_any<dim>(const std::vector<Crack<dim>> &,                 \
                                const Point<dim> &,                              \
                                const Point<dim> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Mesh
} // namespace pdfem
