// SPDX-License-Identifier: LGPL-2.1-or-later
// The state of FftOperator (not installed): the FFTW plans, the kernel
// spectra, the mask fields and the work spectra, with the Fourier-space
// helpers the models' forms are written with. With several MPI ranks every
// array is the rank's part: the nodes of its slab (the real buffer padded
// to FFTW's 2 (n/2 + 1) per row) and its modes in FFTW's transposed layout.
#ifndef PDFEM_SOURCE_FFT_FFT_OPERATOR_IMPL_H
#define PDFEM_SOURCE_FFT_FFT_OPERATOR_IMPL_H

#include <pdfem/fft/fft_operator.h>

#include <array>
#include <complex>
#include <cstring>
#include <vector>

#include "fft_tools.h"
#include <fftw3-mpi.h>

namespace pdfem
{
  namespace FFT
  {
    template <int dim>
    struct FftOperator<dim>::Impl
    {
      /**
       * A kernel's spectrum conj(k^)(kappa) times Delta V / N (the scale of
       * a correlation sum_x' k(x' - x) b(x') Delta V by an unnormalised
       * inverse FFT): real for an even kernel, i times a real number for an
       * odd one; @p s holds that real number.
       */
      struct Kernel
      {
        std::vector<double> s;
        bool                odd = false;
      };

      Impl(const Grid<dim>  &grid,
           const Material   &material,
           const FftOptions &o);
      ~Impl();

      /// A work spectrum (allocated at the first use).
      fftw_complex *
      spectrum(unsigned int i);

      /// f(k, i) for every local node k, i its place in the real buffer
      /// (k on one rank; rows padded to @p stride with several).
      template <typename F>
      void
      for_nodes(const F &f)
      {
        const std::size_t nl = row, st = stride;
        internal::parallel_for(threads, N, [&](std::size_t b, std::size_t e) {
          if (st == nl)
            {
              for (std::size_t k = b; k < e; ++k)
                f(k, k);
              return;
            }
          std::size_t col = b % nl, i = b / nl * st + col;
          for (std::size_t k = b; k < e; ++k)
            {
              f(k, i);
              ++i;
              if (++col == nl)
                {
                  col = 0;
                  i += st - nl;
                }
            }
        });
      }

      /// real = f(k) for every node.
      template <typename F>
      void
      fill(const F &f)
      {
        double *r = real;
        for_nodes([&](std::size_t k, std::size_t i) { r[i] = f(k); });
      }

      /// g(k, real[k]) for every node, after an inverse transform.
      template <typename G>
      void
      use(const G &g)
      {
        const double *r = real;
        for_nodes([&](std::size_t k, std::size_t i) { g(k, r[i]); });
      }

      /// out = real (N values), after an inverse transform.
      void
      take(std::vector<double> &out)
      {
        out.resize(N);
        double *o = out.data();
        use([o](std::size_t k, double r) { o[k] = r; });
      }

      void
      forward(fftw_complex *out)
      {
        if (distributed)
          fftw_mpi_execute_dft_r2c(forward_plan, real, out);
        else
          fftw_execute_dft_r2c(forward_plan, real, out);
        ++transforms;
      }

      /// real = F^-1(in) (unnormalised); destroys @p in.
      void
      inverse(fftw_complex *in)
      {
        if (distributed)
          fftw_mpi_execute_dft_c2r(inverse_plan, in, real);
        else
          fftw_execute_dft_c2r(inverse_plan, in, real);
        ++transforms;
      }

      /**
       * The local index of the mode with wave numbers @p k (0 <= k[d] <
       * n[d], the last < n/2 + 1), -1 if another rank holds it. One rank:
       * row major over n_0 x ... x (n_{dim-1}/2 + 1); several: FFTW's
       * transposed layout, the first two indices swapped and the new first
       * one distributed.
       */
      std::ptrdiff_t
      local_mode(const std::array<std::size_t, dim> &k) const
      {
        if (!distributed)
          {
            std::size_t m = 0;
            for (unsigned int d = 0; d < dim; ++d)
              m = m * cn[d] + k[d];
            return static_cast<std::ptrdiff_t>(m);
          }
        if (k[1] < k1_first || k[1] >= k1_first + k1_count)
          return -1;
        std::size_t m = (k[1] - k1_first) * cn[0] + k[0];
        for (unsigned int d = 2; d < dim; ++d)
          m = m * cn[d] + k[d];
        return static_cast<std::ptrdiff_t>(m);
      }

      /// The sum of @p x over the ranks (x on one rank).
      double
      sum_over_ranks(double x) const
      {
        if (distributed)
          MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_SUM, comm);
        return x;
      }

      void
      zero(fftw_complex *out)
      {
        internal::parallel_for(threads, Nc, [&](std::size_t b, std::size_t e) {
          if (e > b)
            std::memset(out + b, 0, (e - b) * sizeof(fftw_complex));
        });
      }

      /// out (+)= factor k in, with k a kernel multiplier.
      void
      multiply(fftw_complex       *out,
               const Kernel       &k,
               const fftw_complex *in,
               const double        factor,
               const bool          add)
      {
        const double *s = k.s.data();
        internal::parallel_for(threads, Nc, [&](std::size_t b, std::size_t e) {
          for (std::size_t j = b; j < e; ++j)
            {
              const double f = factor * s[j];
              // odd: i f (a + i b) = -f b + i f a
              const double re = k.odd ? -f * in[j][1] : f * in[j][0];
              const double im = k.odd ? f * in[j][0] : f * in[j][1];
              if (add)
                {
                  out[j][0] += re;
                  out[j][1] += im;
                }
              else
                {
                  out[j][0] = re;
                  out[j][1] = im;
                }
            }
        });
      }

      /**
       * One pass over the modes for a sum over a kernel index, in place:
       * with x_j = h[j] (j < dim) on entry,
       *
       *   gsum  = sum_j g_j x_j                       (if gsum),
       *   h[i] <- kf sum_j K_ij x_j + gf g_i hg       (if K; hg optional),
       *
       * K symmetric and even, g odd. One pass instead of dim^2 (the pointwise
       * work of an evaluation is memory bound).
       */
      void
      fused_product(fftw_complex *const       *h,
                    const std::vector<Kernel> *K,
                    const double               kf,
                    const std::vector<Kernel> *g,
                    const fftw_complex        *hg,
                    const double               gf,
                    fftw_complex              *gsum)
      {
        internal::parallel_for(threads, Nc, [&](std::size_t b, std::size_t e) {
          for (std::size_t m = b; m < e; ++m)
            {
              double x[dim][2];
              for (unsigned int j = 0; j < dim; ++j)
                {
                  x[j][0] = h[j][m][0];
                  x[j][1] = h[j][m][1];
                }
              if (gsum != nullptr)
                {
                  // i t (a + i b) = -t b + i t a
                  double re = 0., im = 0.;
                  for (unsigned int j = 0; j < dim; ++j)
                    {
                      const double t = (*g)[j].s[m];
                      re -= t * x[j][1];
                      im += t * x[j][0];
                    }
                  gsum[m][0] = re;
                  gsum[m][1] = im;
                }
              if (K == nullptr)
                continue;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  double re = 0., im = 0.;
                  for (unsigned int j = 0; j < dim; ++j)
                    {
                      const double k =
                        (*K)[internal::symmetric_index<dim>(i, j)].s[m];
                      re += k * x[j][0];
                      im += k * x[j][1];
                    }
                  re *= kf;
                  im *= kf;
                  if (hg != nullptr)
                    {
                      const double t = gf * (*g)[i].s[m];
                      re -= t * hg[m][1];
                      im += t * hg[m][0];
                    }
                  h[i][m][0] = re;
                  h[i][m][1] = im;
                }
            }
        });
      }

      /// The spectrum of a kernel sampled on the horizon's bonds, times
      /// @p scale.
      template <typename F>
      Kernel
      make_kernel(const F &value, const bool odd, const double scale);

      /// The kernels of the model (and the influence counts for damage).
      void
      make_kernels();

      /// [k_s beta_field] for the symmetric kernels @p K into @p out, with
      /// the spectrum @p b of the field.
      void
      correlate_symmetric(const std::vector<Kernel>        &K,
                          const fftw_complex               *b,
                          std::vector<std::vector<double>> &out);

      /// Q(x) = sum' beta' K_ij eta_i eta_j Delta V (no outer beta), with
      /// KB_s = [K_s beta].
      void
      quadratic_form(const std::vector<double>              &u,
                     const std::vector<Kernel>              &K,
                     const std::vector<std::vector<double>> &KB,
                     std::vector<double>                    &Q);

      void
      apply_linear(const std::vector<double> &u, std::vector<double> &L);

      void
      apply_nonlinear(const std::vector<double> &u, std::vector<double> &L);

      void
      apply_lps(const std::vector<double> &u, std::vector<double> &L);

      /// theta of LPS; leaves Sum_j K_ij^ (beta u_j)^ in spectra 0..dim-1
      /// when @p keep_sums.
      void
      lps_dilatation(const std::vector<double> &u, bool keep_sums);

      Grid<dim> const    grid;
      Material const     material;
      unsigned int const threads;
      // several ranks (fftw3-mpi plans) or one (serial plans), and the
      // ranks' communicator
      bool     distributed = false;
      MPI_Comm comm        = MPI_COMM_SELF;
      // local nodes N (the slab's), local modes Nc, box nodes N_global;
      // a row (the last, fastest index) has row nodes and takes stride
      // doubles in the real buffer (real_size doubles), a spectrum alloc
      // complex numbers
      std::size_t N = 0, Nc = 0, N_global = 0, row = 0, stride = 0;
      std::size_t real_size = 0, alloc = 0;
      Slab        slab;
      // the complex box n_0 x ... x (n_{dim-1}/2 + 1); several ranks: the
      // rank's modes are k_1 = k1_first, ..., k1_first + k1_count - 1
      std::array<std::size_t, dim>   cn{};
      std::size_t                    k1_first = 0, k1_count = 0;
      double                         dV = 0.;
      std::vector<Offset<dim>> const offsets;
      fftw_plan                      forward_plan = nullptr;
      fftw_plan                      inverse_plan = nullptr;
      double                        *real         = nullptr;
      std::vector<fftw_complex *>    spectra;
      std::size_t                    transforms = 0;

      // kernels: C (bond based, symmetric), a and c (nonlinear), K and g
      // (LPS), the influence indicator omega_0 (damage, made when asked)
      std::vector<Kernel> C, a, K, g;
      Kernel              c, omega0;
      bool                have_omega0 = false;

      // mask fields: beta = chi_B lambda, chi_B; P_s = [C_s beta] (bond
      // based) or (1/m) [K_s beta] + [K_s (beta/m)] (LPS); q_i = [a_i beta],
      // p = [c beta]; LPS: m, 1/m (0 outside), gb_i = [g_i beta], theta.
      std::vector<double>              beta, body;
      std::vector<std::vector<double>> P, q, gb;
      std::vector<double>              p, m, minv, theta;
      double                           A = 0., B = 0.;

      // apply_periodic_inverse(): G^(kappa)^-1, real and symmetric, its
      // dim (dim + 1) / 2 entries per mode (the diagonal, then the upper
      // triangle), made at the first use (a rank may hold no mode: the
      // flag, not the size, says whether it is made, so that all ranks
      // agree).
      std::vector<double> periodic_inverse;
      bool                have_periodic_inverse = false;
    };
  } // namespace FFT
} // namespace pdfem

#endif
