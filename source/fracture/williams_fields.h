// SPDX-License-Identifier: LGPL-2.1-or-later
// The interaction integral's auxiliary fields: the near-tip displacements
// of modes I, II (Williams) and III and their gradients by forward-mode
// dual numbers (internal to source/fracture).
#ifndef PDFEM_FRACTURE_WILLIAMS_FIELDS_H
#define PDFEM_FRACTURE_WILLIAMS_FIELDS_H

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace pdfem
{
  namespace Fracture
  {
    namespace internal
    {
      /// A forward-mode dual number: a value and its gradient in the plane
      /// (d/dx1, d/dx2), so that one evaluation gives both derivatives.
      struct Dual
      {
        double v = 0., d[2] = {0., 0.};
      };
      inline Dual
      operator+(Dual a, Dual b)
      {
        return {a.v + b.v, {a.d[0] + b.d[0], a.d[1] + b.d[1]}};
      }
      inline Dual
      operator*(Dual a, Dual b)
      {
        return {a.v * b.v,
                {a.d[0] * b.v + a.v * b.d[0], a.d[1] * b.v + a.v * b.d[1]}};
      }
      inline Dual
      operator*(double s, Dual a)
      {
        return {s * a.v, {s * a.d[0], s * a.d[1]}};
      }
      inline Dual
      operator+(double s, Dual a)
      {
        return {s + a.v, {a.d[0], a.d[1]}};
      }
      /// f(a) with f(a.v) = @p value and f'(a.v) = @p slope.
      inline Dual
      chain(const Dual a, const double value, const double slope)
      {
        return {value, {slope * a.d[0], slope * a.d[1]}};
      }
      inline Dual
      sqrt(Dual a)
      {
        const double r = std::sqrt(a.v);
        return chain(a, r, 1. / (2. * r));
      }
      inline Dual
      sin(Dual a)
      {
        return chain(a, std::sin(a.v), std::cos(a.v));
      }
      inline Dual
      cos(Dual a)
      {
        return chain(a, std::cos(a.v), -std::sin(a.v));
      }
      inline Dual
      atan2(Dual y, Dual x)
      {
        const double r2 = x.v * x.v + y.v * y.v;
        return {std::atan2(y.v, x.v),
                {(x.v * y.d[0] - y.v * x.d[0]) / r2,
                 (x.v * y.d[1] - y.v * x.d[1]) / r2}};
      }

      /// The plane coordinates (x1, x2) of a point as duals: the seeds of
      /// their gradients.
      inline std::array<Dual, 2>
      plane_coordinates(const double x1, const double x2)
      {
        return {{Dual{x1, {1., 0.}}, Dual{x2, {0., 1.}}}};
      }

      /**
       * Williams near-tip displacement of unit K_I (mode 0) or K_II (mode 1)
       * at (x1, x2) in tip axes (Anderson, Fracture Mechanics, Table 2.2).
       */
      inline std::array<Dual, 2>
      williams_displacement(const Dual         x1,
                            const Dual         x2,
                            const unsigned int mode,
                            const double       kappa,
                            const double       mu)
      {
        const Dual r     = sqrt(x1 * x1 + x2 * x2);
        const Dual theta = atan2(x2, x1);
        const Dual f     = (1. / (2. * mu * std::sqrt(2. * M_PI))) * sqrt(r);
        const Dual s = sin(0.5 * theta), c = cos(0.5 * theta);
        if (mode == 0)
          return {{f * c * ((kappa - 1.) + 2. * s * s),
                   f * s * ((kappa + 1.) + (-2.) * c * c)}};
        return {{f * s * ((kappa + 1.) + 2. * c * c),
                 (-1.) * f * c * ((kappa - 1.) + (-2.) * s * s)}};
      }

      /// grad u^aux (component i, direction j) in tip axes.
      inline dealii::Tensor<2, 2>
      williams_gradient(const dealii::Point<2> &x,
                        const unsigned int      mode,
                        const double            kappa,
                        const double            mu)
      {
        const auto [x1, x2]    = plane_coordinates(x[0], x[1]);
        const auto           u = williams_displacement(x1, x2, mode, kappa, mu);
        dealii::Tensor<2, 2> g;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            g[i][j] = u[i].d[j];
        return g;
      }

      /// grad u_3 (d/dx1, d/dx2) of the mode III field of unit K_III,
      /// u_3 = 2/mu sqrt(r/2pi) sin(theta/2), at (x1, x2) in tip axes.
      inline dealii::Tensor<1, 2>
      mode_iii_gradient(const dealii::Point<2> &x, const double mu)
      {
        const auto [x1, x2] = plane_coordinates(x[0], x[1]);
        const Dual r        = sqrt(x1 * x1 + x2 * x2);
        const Dual theta    = atan2(x2, x1);
        const Dual u3 =
          (2. / (mu * std::sqrt(2. * M_PI))) * sqrt(r) * sin(0.5 * theta);
        return dealii::Tensor<1, 2>({u3.d[0], u3.d[1]});
      }
    } // namespace internal
  }   // namespace Fracture
} // namespace pdfem

#endif
