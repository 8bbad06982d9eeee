// SPDX-License-Identifier: LGPL-2.1-or-later
// FftOperator::apply_periodic_inverse(): the inverse of the operator of an
// unbounded (periodic, unmasked) body by its Fourier symbol, a
// preconditioner for the statics of bounded ones.
#include <pdfem/fft/fft_operator.h>

#include <array>
#include <complex>
#include <stdexcept>
#include <vector>

#include "fft_operator_impl.h"

namespace pdfem
{
  namespace FFT
  {
    namespace
    {
      using Complex = std::complex<double>;

      /// In place: a (n x n, row major, n = 2 or 3) becomes its inverse;
      /// false if it is singular against its own size.
      template <int n>
      bool
      invert(Complex *a)
      {
        Complex inv[n * n];
        if constexpr (n == 2)
          {
            inv[0] = a[3];
            inv[1] = -a[1];
            inv[2] = -a[2];
            inv[3] = a[0];
          }
        else
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              {
                // adjugate: the cofactor of (j, i)
                const int r0 = (j + 1) % 3, r1 = (j + 2) % 3;
                const int c0 = (i + 1) % 3, c1 = (i + 2) % 3;
                inv[i * 3 + j] = a[r0 * 3 + c0] * a[r1 * 3 + c1] -
                                 a[r0 * 3 + c1] * a[r1 * 3 + c0];
              }
        Complex det = 0.;
        for (int j = 0; j < n; ++j)
          det += a[j] * inv[j * n];
        double scale = 0.;
        for (int i = 0; i < n; ++i)
          scale += std::abs(a[i * n + i]);
        if (!(std::abs(det) > 1e-12 * std::pow(scale / n, n)))
          return false;
        for (int k = 0; k < n * n; ++k)
          a[k] = inv[k] / det;
        return true;
      }
    } // namespace

    template <int dim>
    void
    FftOperator<dim>::apply_periodic_inverse(const std::vector<double> &r,
                                             std::vector<double>       &z)
    {
      Impl &o = *impl;
      if (r.size() != dim * o.N)
        throw std::invalid_argument("FFT::FftOperator::apply_periodic_inverse: "
                                    "r has the wrong size");
      if (this->material_.model == Model::nonlinear_bond_based)
        throw std::logic_error("FFT: the periodic inverse is defined for the "
                               "linear models only");
      constexpr unsigned int nn = dim * dim;
      if (!o.have_periodic_inverse)
        {
          // G^ column by column: -L of a unit impulse at node 0 in
          // direction j, transformed, is column j of the symbol (the
          // operator is translation invariant once every mask is 1). Node
          // 0 is on the first rank's slab; each rank keeps its modes.
          const std::vector<double> beta = o.beta, body = o.body;
          set_masks(std::vector<double>(o.N, 1.), std::vector<double>(o.N, 1.));
          o.periodic_inverse.assign(nn * o.Nc, 0.);
          std::vector<double> impulse(dim * o.N, 0.), L;
          const bool          origin = o.slab.contains(0);
          for (unsigned int j = 0; j < dim; ++j)
            {
              if (origin)
                impulse[j * o.N] = 1.;
              apply(impulse, L);
              if (origin)
                impulse[j * o.N] = 0.;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  o.fill([&](std::size_t k) { return -L[i * o.N + k]; });
                  fftw_complex *s = o.spectrum(i);
                  o.forward(s);
                  for (std::size_t m = 0; m < o.Nc; ++m)
                    o.periodic_inverse[m * nn + i * dim + j] =
                      Complex(s[m][0], s[m][1]);
                }
            }
          set_masks(body, beta); // beta = chi_B lambda: the same masks
          // kappa = 0 holds the rigid translations (G^ = 0): s I there, s
          // the mean eigenvalue of the mode (0, ..., 0, 1) (index 1 of the
          // last direction), the softest the box can resolve; its rank
          // sends s to all (the others add 0).
          std::array<std::size_t, dim> k{};
          k[dim - 1]              = 1;
          const std::ptrdiff_t m1 = o.local_mode(k);
          double               s  = 0.;
          if (m1 >= 0)
            for (unsigned int i = 0; i < dim; ++i)
              s += o.periodic_inverse[m1 * nn + i * dim + i].real() / dim;
          s                       = o.sum_over_ranks(s);
          k[dim - 1]              = 0;
          const std::ptrdiff_t m0 = o.local_mode(k);
          if (m0 >= 0)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                o.periodic_inverse[m0 * nn + i * dim + j] = i == j ? s : 0.;
          internal::parallel_for(
            o.threads, o.Nc, [&](std::size_t b, std::size_t e) {
              for (std::size_t m = b; m < e; ++m)
                {
                  Complex *a = &o.periodic_inverse[m * nn];
                  if (!invert<dim>(a))
                    for (unsigned int k = 0; k < nn; ++k) // not expected
                      a[k] = k % (dim + 1) == 0 ? 1. / s : 0.;
                }
            });
          o.have_periodic_inverse = true;
        }

      std::vector<fftw_complex *> h(dim);
      for (unsigned int j = 0; j < dim; ++j)
        {
          o.fill([&](std::size_t k) { return r[j * o.N + k]; });
          h[j] = o.spectrum(j);
          o.forward(h[j]);
        }
      const double scale = 1. / o.N_global; // FFTW's transforms: unnormalised
      internal::parallel_for(o.threads,
                             o.Nc,
                             [&](std::size_t b, std::size_t e) {
                               for (std::size_t m = b; m < e; ++m)
                                 {
                                   const Complex *a =
                                     &o.periodic_inverse[m * nn];
                                   Complex x[dim];
                                   for (unsigned int j = 0; j < dim; ++j)
                                     x[j] = Complex(h[j][m][0], h[j][m][1]);
                                   for (unsigned int i = 0; i < dim; ++i)
                                     {
                                       Complex y = 0.;
                                       for (unsigned int j = 0; j < dim; ++j)
                                         y += a[i * dim + j] * x[j];
                                       h[i][m][0] = scale * y.real();
                                       h[i][m][1] = scale * y.imag();
                                     }
                                 }
                             });
      z.resize(dim * o.N);
      for (unsigned int i = 0; i < dim; ++i)
        {
          o.inverse(h[i]);
          o.use([&](std::size_t k, double v) { z[i * o.N + k] = v; });
        }
    }

    template void
    FftOperator<2>::apply_periodic_inverse(const std::vector<double> &,
                                           std::vector<double> &);
    template void
    FftOperator<3>::apply_periodic_inverse(const std::vector<double> &,
                                           std::vector<double> &);
  } // namespace FFT
} // namespace pdfem
