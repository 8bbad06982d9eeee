// SPDX-License-Identifier: LGPL-2.1-or-later
// What the tests of the fft module share: pseudo-random fields, a material
// of every model, and an ellipsoidal body with dead nodes.
#ifndef PDFEM_TESTS_UNIT_FFT_TEST_TOOLS_H
#define PDFEM_TESTS_UNIT_FFT_TEST_TOOLS_H

#include <pdfem/fft/grid.h>

#include <array>
#include <random>
#include <vector>

namespace pdfem
{
  namespace FFT
  {
    namespace test_tools
    {
      /// @p n values uniform in [-amplitude, amplitude] from @p seed.
      inline std::vector<double>
      random_field(const std::size_t  n,
                   const double       amplitude,
                   const unsigned int seed)
      {
        std::mt19937                           generator(seed);
        std::uniform_real_distribution<double> value(-amplitude, amplitude);
        std::vector<double>                    f(n);
        for (auto &v : f)
          v = value(generator);
        return f;
      }

      /// @p model with the horizon @p horizon, micromodulus 2, bulk modulus
      /// 3 and shear modulus 1.25.
      inline Material
      material(const Model model, const double horizon)
      {
        Material m;
        m.model         = model;
        m.horizon       = horizon;
        m.micromodulus  = 2.;
        m.bulk_modulus  = 3.;
        m.shear_modulus = 1.25;
        return m;
      }

      /// chi_B: the ellipsoid centred in the box whose semi-axes end
      /// @p inset[d] inside the outermost grid points (with @p hole, less a
      /// ball of radius^2 1.1 off its centre); integrity 0 at a random 15 %
      /// of the nodes (one draw per node from @p seed).
      template <int dim>
      void
      ellipsoid_masks(const Grid<dim>               &g,
                      const std::array<double, dim> &inset,
                      const bool                     hole,
                      const unsigned int             seed,
                      std::vector<double>           &body,
                      std::vector<double>           &integrity)
      {
        const std::size_t N = g.n_nodes();
        body.assign(N, 0.);
        integrity.assign(N, 1.);
        std::mt19937                           generator(seed);
        std::uniform_real_distribution<double> value(0., 1.);
        for (std::size_t k = 0; k < N; ++k)
          {
            const auto x = g.position(k);
            double     r = 0., off_centre = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double L = g.n[d] * g.spacing[d];
                const double c = (L - g.spacing[d]) / 2, a = c - inset[d];
                r += (x[d] - c) * (x[d] - c) / (a * a);
                off_centre += (x[d] - c - 0.2 * a) * (x[d] - c - 0.2 * a);
              }
            body[k] = r <= 1. && (!hole || off_centre > 1.1) ? 1. : 0.;
            if (value(generator) < 0.15)
              integrity[k] = 0.;
          }
      }
    } // namespace test_tools
  }   // namespace FFT
} // namespace pdfem

#endif
