// SPDX-License-Identifier: LGPL-2.1-or-later
// FftOperator::apply_periodic_inverse(): the inverse of the operator of an
// unbounded (periodic, unmasked) body by its Fourier symbol, a
// preconditioner for the statics of bounded ones.
#include <pdfem/fft/fft_operator.h>

#include <array>
#include <cmath>
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

      /// The entries of a symmetric dim x dim matrix kept per mode: the
      /// diagonal, then (0,1) (2D); the diagonal, then (0,1), (0,2), (1,2)
      /// (3D).
      template <int dim>
      constexpr unsigned int n_packed = dim *(dim + 1) / 2;

      /// The packed index of (i, j).
      template <int dim>
      constexpr unsigned int
      packed(const unsigned int i, const unsigned int j)
      {
        if (i == j)
          return i;
        const unsigned int lo = i < j ? i : j, hi = i < j ? j : i;
        return dim == 2 ? 2 : 3 + lo + hi - 1; // (0,1) 3, (0,2) 4, (1,2) 5
      }

      /// In place: the packed symmetric matrix a becomes its inverse; false
      /// if it is singular against its own size.
      template <int dim>
      bool
      invert_symmetric(double *a)
      {
        double m[dim][dim], inv[dim][dim];
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            m[i][j] = a[packed<dim>(i, j)];
        if constexpr (dim == 2)
          {
            inv[0][0] = m[1][1];
            inv[0][1] = inv[1][0] = -m[0][1];
            inv[1][1]             = m[0][0];
          }
        else
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              {
                // adjugate: the cofactor of (j, i)
                const int r0 = (j + 1) % 3, r1 = (j + 2) % 3;
                const int c0 = (i + 1) % 3, c1 = (i + 2) % 3;
                inv[i][j] = m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
              }
        double det = 0., scale = 0.;
        for (unsigned int j = 0; j < dim; ++j)
          {
            det += m[0][j] * inv[j][0];
            scale += std::abs(m[j][j]);
          }
        if (!(std::abs(det) > 1e-12 * std::pow(scale / dim, dim)))
          return false;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            a[packed<dim>(i, j)] = inv[i][j] / det;
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
      constexpr unsigned int np = n_packed<dim>;
      if (!o.have_periodic_inverse)
        {
          // G^ column by column: -L of a unit impulse at node 0 in
          // direction j, transformed, is column j of the symbol (the
          // operator is translation invariant once every mask is 1). Node
          // 0 is on the first rank's slab; each rank keeps its modes. The
          // stencil is even (xi and -xi carry the same coefficients), so
          // G^ is real and symmetric: its upper triangle's real parts are
          // kept (the imaginary parts and the asymmetry are round-off).
          const std::vector<double> beta = o.beta;
          std::vector<double>       body(o.N);
          for (std::size_t k = 0; k < o.N; ++k)
            body[k] = o.body(k);
          set_masks(std::vector<double>(o.N, 1.), std::vector<double>(o.N, 1.));
          o.periodic_inverse.assign(np * o.fold.size, 0.);
          std::vector<double> impulse(dim * o.N, 0.), L;
          const bool          origin = o.slab.contains(0);
          for (unsigned int j = 0; j < dim; ++j)
            {
              if (origin)
                impulse[j * o.N] = 1.;
              apply(impulse, L);
              if (origin)
                impulse[j * o.N] = 0.;
              for (unsigned int i = 0; i <= j; ++i)
                {
                  fftw_complex *s = o.spectrum(i);
                  o.fill(s, [&](std::size_t k) { return -L[i * o.N + k]; });
                  o.forward(s);
                  // on the folded modes: entry (i, j) has the parity of
                  // K_ij (one thread: the same value is always kept)
                  const unsigned int parity = (1u << i) ^ (1u << j);
                  o.walk_modes(
                    0,
                    o.Nc,
                    [&](std::size_t m, std::size_t f, unsigned int flips) {
                      o.periodic_inverse[f * np + packed<dim>(i, j)] =
                        Impl::sign(parity, flips) * s[m][0];
                    });
                }
            }
          set_masks(body, beta); // beta = chi_B lambda: the same masks
          // kappa = 0 holds the rigid translations (G^ = 0): s I there, s
          // the mean eigenvalue of the mode (0, ..., 0, 1) (index 1 of the
          // last direction), the softest the box can resolve; its rank
          // sends s to all (the others add 0).
          // (both modes are their own folded modes, k_d <= n_d / 2)
          const auto folded = [&o](const std::array<std::size_t, dim> &k) {
            const std::ptrdiff_t m = o.local_mode(k);
            std::ptrdiff_t       f = -1;
            if (m >= 0)
              o.walk_modes(m, m + 1, [&](std::size_t, std::size_t i, unsigned) {
                f = static_cast<std::ptrdiff_t>(i);
              });
            return f;
          };
          std::array<std::size_t, dim> k{};
          k[dim - 1]              = 1;
          const std::ptrdiff_t m1 = folded(k);
          double               s  = 0.;
          if (m1 >= 0)
            for (unsigned int i = 0; i < dim; ++i)
              s += o.periodic_inverse[m1 * np + i] / dim;
          s                       = o.sum_over_ranks(s);
          k[dim - 1]              = 0;
          const std::ptrdiff_t m0 = folded(k);
          if (m0 >= 0)
            for (unsigned int i = 0; i < np; ++i)
              o.periodic_inverse[m0 * np + i] = i < dim ? s : 0.;
          internal::parallel_for(
            o.threads, o.fold.size, [&](std::size_t b, std::size_t e) {
              for (std::size_t m = b; m < e; ++m)
                {
                  double *a = &o.periodic_inverse[m * np];
                  if (!invert_symmetric<dim>(a))
                    for (unsigned int i = 0; i < np; ++i) // not expected
                      a[i] = i < dim ? 1. / s : 0.;
                }
            });
          o.have_periodic_inverse = true;
        }

      fftw_complex *h[dim];
      o.forward_components(
        r, [](std::size_t) { return 1.; }, h);
      const double scale = 1. / o.N_global; // FFTW's transforms: unnormalised
      o.for_modes([&](std::size_t m, std::size_t f, unsigned int flips) {
        const double *a = &o.periodic_inverse[f * np];
        // at a reflected mode the inverse is S G^-1 S, S = diag(sigma)
        double sigma[dim];
        for (unsigned int d = 0; d < dim; ++d)
          sigma[d] = (flips >> d) & 1u ? -1. : 1.;
        Complex x[dim];
        for (unsigned int j = 0; j < dim; ++j)
          x[j] = sigma[j] * Complex(h[j][m][0], h[j][m][1]);
        for (unsigned int i = 0; i < dim; ++i)
          {
            Complex y = 0.;
            for (unsigned int j = 0; j < dim; ++j)
              y += a[packed<dim>(i, j)] * x[j];
            h[i][m][0] = scale * sigma[i] * y.real();
            h[i][m][1] = scale * sigma[i] * y.imag();
          }
      });
      z.resize(dim * o.N);
      for (unsigned int i = 0; i < dim; ++i)
        {
          o.inverse(h[i]);
          o.use(h[i], [&](std::size_t k, double v) { z[i * o.N + k] = v; });
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
