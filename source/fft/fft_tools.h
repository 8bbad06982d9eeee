// SPDX-License-Identifier: LGPL-2.1-or-later
// Helpers shared by the FFT and the direct operators (not installed).
#ifndef PDFEM_SOURCE_FFT_FFT_TOOLS_H
#define PDFEM_SOURCE_FFT_FFT_TOOLS_H

#include <pdfem/fft/grid.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <thread>
#include <vector>

namespace pdfem
{
  namespace FFT
  {
    namespace internal
    {
      /**
       * The offsets z = 0, z = xi and z = xi + xi' for bonds xi, xi' of
       * @p bonds, one per periodic position in @p grid (an offset that
       * reaches round the box meets another one there): the reach of the
       * LPS mask fields (FftOperator's layer, theory.md §14.3).
       */
      template <int dim>
      std::vector<Offset<dim>>
      offsets_within_two_bonds(const Grid<dim>                &grid,
                               const std::vector<Offset<dim>> &bonds)
      {
        // flags on the offsets of half-width 2 max|p| or, in a direction
        // where that reaches round the box, on its n_d planes
        std::array<int, dim> half{}, extent{};
        for (const auto &o : bonds)
          for (unsigned int d = 0; d < dim; ++d)
            half[d] = std::max(half[d], 2 * std::abs(o.p[d]));
        std::array<std::size_t, dim> stride{};
        std::size_t                  size = 1;
        for (int d = dim - 1; d >= 0; --d)
          {
            extent[d] = std::min(2 * half[d] + 1, int(grid.n[d]));
            stride[d] = size;
            size *= std::size_t(extent[d]);
          }
        std::vector<unsigned char> in(size, 0);
        std::vector<Offset<dim>>   Z;
        const auto                 add = [&](const std::array<int, dim> &p) {
          std::size_t at = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const int n = int(grid.n[d]);
              at += std::size_t(extent[d] < n ? p[d] + half[d] :
                                                (p[d] % n + n) % n) *
                    stride[d];
            }
          if (in[at] == 0)
            {
              in[at] = 1;
              Z.emplace_back();
              Z.back().p = p;
            }
        };
        add(std::array<int, dim>{});
        for (const auto &a : bonds)
          {
            add(a.p);
            for (const auto &b : bonds)
              {
                std::array<int, dim> p;
                for (unsigned int d = 0; d < dim; ++d)
                  p[d] = a.p[d] + b.p[d];
                add(p);
              }
          }
        return Z;
      }

      /**
       * f(begin, end) on @p threads contiguous pieces of [0, n) (threads
       * started per call; a single piece below 2^15 items, where starting a
       * thread costs more than it saves). Each item is computed by one
       * thread in a fixed order, so results do not depend on the count.
       */
      template <typename F>
      void
      parallel_for(const unsigned int threads, const std::size_t n, const F &f)
      {
        const std::size_t pieces =
          n < (std::size_t(1) << 15) ? 1 : std::max(1u, threads);
        if (pieces == 1)
          {
            f(std::size_t(0), n);
            return;
          }
        std::vector<std::thread> helpers;
        for (std::size_t p = 1; p < pieces; ++p)
          helpers.emplace_back(
            [&f, p, n, pieces]() { f(p * n / pieces, (p + 1) * n / pieces); });
        f(std::size_t(0), n / pieces);
        for (auto &t : helpers)
          t.join();
      }

      /// The LPS constants A, B of Operator (3D: 3 kappa - 5 mu, 15 mu;
      /// 2D: 2 kappa' - 4 mu, 8 mu).
      template <int dim>
      void
      lps_constants(const Material &material, double &A, double &B)
      {
        const double kappa = material.bulk_modulus, mu = material.shear_modulus;
        if (dim == 3)
          {
            A = 3. * kappa - 5. * mu;
            B = 15. * mu;
          }
        else
          {
            A = 2. * kappa - 4. * mu;
            B = 8. * mu;
          }
      }

      /// The mask field of set_masks(): @p values, or 1 where empty.
      inline std::vector<double>
      mask_or_one(const std::vector<double> &values, const std::size_t n)
      {
        return values.empty() ? std::vector<double>(n, 1.) : values;
      }

      /// Index pairs (i, j), i <= j, of a symmetric dim x dim tensor.
      template <int dim>
      constexpr unsigned int n_symmetric = dim *(dim + 1) / 2;

      template <int dim>
      inline unsigned int
      symmetric_index(const unsigned int i, const unsigned int j)
      {
        const unsigned int a = std::min(i, j), b = std::max(i, j);
        // 2D: (0,0) 0, (0,1) 1, (1,1) 2; 3D: 00 0, 01 1, 02 2, 11 3, 12 4,
        // 22 5.
        return a * dim - a * (a - 1) / 2 + (b - a);
      }

      /// The pair (i, j), i <= j, of the symmetric index @p s.
      template <int dim>
      inline void
      symmetric_pair(const unsigned int s, unsigned int &i, unsigned int &j)
      {
        for (i = 0; i < dim; ++i)
          for (j = i; j < dim; ++j)
            if (symmetric_index<dim>(i, j) == s)
              return;
      }
    } // namespace internal
  }   // namespace FFT
} // namespace pdfem

#endif
