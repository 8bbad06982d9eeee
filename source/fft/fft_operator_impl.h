// SPDX-License-Identifier: LGPL-2.1-or-later
// The state of FftOperator (not installed): the FFTW plans, the kernel
// spectra, the mask fields and the work spectra, with the Fourier-space
// helpers the models' forms are written with. The transforms are in place:
// a spectrum's memory holds the real field before a forward transform and
// after an inverse one (rows padded to FFTW's 2 (n/2 + 1) doubles), so no
// real buffer is kept beside the spectra. With several MPI ranks every
// array is the rank's part: the nodes of its slab and its modes in FFTW's
// transposed layout.
#ifndef PDFEM_SOURCE_FFT_FFT_OPERATOR_IMPL_H
#define PDFEM_SOURCE_FFT_FFT_OPERATOR_IMPL_H

#include <pdfem/fft/fft_operator.h>

#include <algorithm>
#include <array>
#include <complex>
#include <cstdint>
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
       * odd one; @p s holds that real number on the folded modes (Fold).
       * Bit d of @p parity is set where the kernel is odd under the
       * reflection xi_d -> -xi_d; the kernel is odd if an odd number of
       * bits is set.
       */
      struct Kernel
      {
        std::vector<double> s;
        unsigned int        parity = 0;
        /// The correlation of the kernel with 1: the sum of its bond
        /// values times Delta V (0 for an odd kernel), the value of [k beta]
        /// wherever beta is 1 on the whole horizon.
        double total = 0.;

        bool
        odd() const
        {
          return __builtin_parity(parity);
        }
      };

      /**
       * The folded storage of the kernel spectra (and of the periodic
       * inverse's symbol). Every kernel is even or odd under the reflection
       * of each coordinate (xi_d -> -xi_d maps the discrete horizon onto
       * itself, and omega depends on |xi| only), so its spectrum at the
       * wave number k_d reflected to n_d - k_d is +-(its value at k_d):
       * only the modes with k_d <= n_d / 2 in every direction are kept,
       * about 1/4 of the half spectrum in 3D and 1/2 in 2D. Per direction
       * d and local wave number (in the order of the rank's modes), the
       * index of its folded wave number among this rank's folded ones and
       * whether it is reflected; the folded modes are row major over the
       * directions.
       */
      struct Fold
      {
        std::array<std::vector<std::size_t>, dim>   index;
        std::array<std::vector<unsigned char>, dim> reflected;
        std::array<std::size_t, dim>                stride{};
        std::size_t                                 size = 0;
        // the local modes: directions from the slowest to the fastest,
        // and their local extents in that order
        std::array<unsigned int, dim> order{};
        std::array<std::size_t, dim>  extent{};
      };

      /// The sign of a kernel of parity @p parity at a mode whose
      /// reflected directions are the bits of @p flips.
      static double
      sign(const unsigned int parity, const unsigned int flips)
      {
        return __builtin_parity(parity & flips) ? -1. : 1.;
      }

      /// f(m, o, flips) for the local modes m in [b, e): o the folded index
      /// of m, flips its reflected directions (bit d for direction d).
      template <typename F>
      void
      walk_modes(const std::size_t b, const std::size_t e, const F &f) const
      {
        const unsigned int   fast   = fold.order[dim - 1];
        const std::size_t    length = fold.extent[dim - 1];
        const std::size_t   *index  = fold.index[fast].data();
        const unsigned char *refl   = fold.reflected[fast].data();
        const std::size_t    st     = fold.stride[fast];
        std::size_t          m      = b;
        while (m < e)
          {
            // one row of the fastest direction at a time
            std::size_t  r = m / length, kf = m % length, base = 0;
            unsigned int flips = 0;
            for (int p = dim - 2; p >= 0; --p)
              {
                const std::size_t  kp = r % fold.extent[p];
                const unsigned int d  = fold.order[p];
                r /= fold.extent[p];
                base += fold.index[d][kp] * fold.stride[d];
                flips |= unsigned(fold.reflected[d][kp]) << d;
              }
            const std::size_t end = std::min(e, (m / length + 1) * length);
            for (; m < end; ++m, ++kf)
              f(m, base + index[kf] * st, flips | (unsigned(refl[kf]) << fast));
          }
      }

      /// walk_modes() over all local modes, split over the threads.
      template <typename F>
      void
      for_modes(const F &f) const
      {
        internal::parallel_for(threads, Nc, [&](std::size_t b, std::size_t e) {
          walk_modes(b, e, f);
        });
      }

      /// The folding of this rank's modes (in the constructor).
      void
      make_fold();

      Impl(const Grid<dim>  &grid,
           const Material   &material,
           const FftOptions &o);
      ~Impl();

      /// A work spectrum (allocated at the first use).
      fftw_complex *
      spectrum(unsigned int i);

      /// f(k, i) for every local node k, i its place in a spectrum's real
      /// view: the rows (the last, fastest index) padded to @p stride
      /// doubles, the layout of FFTW's in-place real transforms.
      template <typename F>
      void
      for_nodes(const F &f)
      {
        const std::size_t nl = row, st = stride;
        internal::parallel_for(threads, N, [&](std::size_t b, std::size_t e) {
          std::size_t k = b;
          while (k < e)
            {
              const std::size_t r = k / nl, end = std::min(e, (r + 1) * nl);
              for (std::size_t i = r * st + k % nl; k < end; ++k, ++i)
                f(k, i);
            }
        });
      }

      /// The real view of a spectrum (in-place transforms).
      static double *
      reals(fftw_complex *s)
      {
        return reinterpret_cast<double *>(s);
      }

      /// The real view of @p s = f(k) for every node.
      template <typename F>
      void
      fill(fftw_complex *s, const F &f)
      {
        double *r = reals(s);
        for_nodes([&](std::size_t k, std::size_t i) { r[i] = f(k); });
      }

      /// g(k, value) for every node of the real view of @p s, after
      /// inverse(s).
      template <typename G>
      void
      use(fftw_complex *s, const G &g)
      {
        const double *r = reals(s);
        for_nodes([&](std::size_t k, std::size_t i) { g(k, r[i]); });
      }

      /// out = the real view of @p s (N values), after inverse(s).
      void
      take(fftw_complex *s, std::vector<double> &out)
      {
        out.resize(N);
        double *o = out.data();
        use(s, [o](std::size_t k, double r) { o[k] = r; });
      }

      /// s = F(the real view of s), in place.
      void
      forward(fftw_complex *s)
      {
        if (distributed)
          fftw_mpi_execute_dft_r2c(forward_plan, reals(s), s);
        else
          fftw_execute_dft_r2c(forward_plan, reals(s), s);
        ++transforms;
      }

      /// The real view of s = F^-1(s) (unnormalised), in place.
      void
      inverse(fftw_complex *s)
      {
        if (distributed)
          fftw_mpi_execute_dft_c2r(inverse_plan, s, reals(s));
        else
          fftw_execute_dft_c2r(inverse_plan, s, reals(s));
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

      /// h[j] = spectrum(j) = F(w u_j) for j < dim, w(k) = @p weight(k)
      /// (u component-major, N values per component).
      template <typename W>
      void
      forward_components(const std::vector<double> &u,
                         const W                   &weight,
                         fftw_complex *(&h)[dim])
      {
        for (unsigned int j = 0; j < dim; ++j)
          {
            h[j]             = spectrum(j);
            const double *uj = u.data() + j * N;
            fill(h[j], [&](std::size_t k) { return weight(k) * uj[k]; });
            forward(h[j]);
          }
      }

      /// out (+)= factor k in, with k a kernel multiplier.
      void
      multiply(fftw_complex       *out,
               const Kernel       &k,
               const fftw_complex *in,
               const double        factor,
               const bool          add)
      {
        const double *s   = k.s.data();
        const bool    odd = k.odd();
        for_modes([&](std::size_t j, std::size_t o, unsigned int flips) {
          const double f = factor * sign(k.parity, flips) * s[o];
          // odd: i f (a + i b) = -f b + i f a
          const double re = odd ? -f * in[j][1] : f * in[j][0];
          const double im = odd ? f * in[j][0] : f * in[j][1];
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
        for_modes([&](std::size_t m, std::size_t o, unsigned int flips) {
          // the sign of a reflected direction d: K_ij flips with d = i or
          // d = j (not both), g_i with d = i
          double sigma[dim];
          for (unsigned int d = 0; d < dim; ++d)
            sigma[d] = (flips >> d) & 1u ? -1. : 1.;
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
                  const double t = sigma[j] * (*g)[j].s[o];
                  re -= t * x[j][1];
                  im += t * x[j][0];
                }
              gsum[m][0] = re;
              gsum[m][1] = im;
            }
          if (K == nullptr)
            return;
          for (unsigned int i = 0; i < dim; ++i)
            {
              double re = 0., im = 0.;
              for (unsigned int j = 0; j < dim; ++j)
                {
                  const double k =
                    sigma[i] * sigma[j] *
                    (*K)[internal::symmetric_index<dim>(i, j)].s[o];
                  re += k * x[j][0];
                  im += k * x[j][1];
                }
              re *= kf;
              im *= kf;
              if (hg != nullptr)
                {
                  const double t = gf * sigma[i] * (*g)[i].s[o];
                  re -= t * hg[m][1];
                  im += t * hg[m][0];
                }
              h[i][m][0] = re;
              h[i][m][1] = im;
            }
        });
      }

      /// The spectrum of a kernel sampled on the horizon's bonds, times
      /// @p scale, on the folded modes (@p parity as in Kernel).
      template <typename F>
      Kernel
      make_kernel(const F &value, unsigned int parity, double scale);

      /// make_kernel() on the offsets @p support (an offset met twice in
      /// the periodic box takes one value).
      template <typename F>
      Kernel
      make_kernel(const std::vector<Offset<dim>> &support,
                  const F                        &value,
                  unsigned int                    parity,
                  double                          scale);

      /// The kernels of the model (and the influence counts for damage).
      void
      make_kernels();

      static const Kernel &
      kernel_of(const Kernel &k)
      {
        return k;
      }

      static const Kernel &
      kernel_of(const Kernel *k)
      {
        return *k;
      }

      /**
       * f(s, k, c_s(k)) for every kernel s of @p kernels (Kernels or
       * pointers to them) and local node k, c_s = [k_s w] the correlation
       * of the kernel with the field w(k) = @p weight(k): one forward and
       * kernels.size() inverse transforms, spectra @p work and @p work + 1
       * overwritten. For one s the calls come from several threads
       * (disjoint k).
       */
      template <typename Kernels, typename W, typename F>
      void
      for_correlations(const Kernels     &kernels,
                       const W           &weight,
                       const unsigned int work,
                       const F           &f)
      {
        fftw_complex *w = spectrum(work), *t = spectrum(work + 1);
        fill(w, weight);
        forward(w);
        for (unsigned int s = 0; s < kernels.size(); ++s)
          {
            multiply(t, kernel_of(kernels[s]), w, 1., false);
            inverse(t);
            use(t, [&](std::size_t k, double r) { f(s, k, r); });
          }
      }

      /**
       * f(s, k, v) with v summing to P_s(k) over the calls (s the
       * symmetric index of (i, j)): P_s = [C_s beta] (bond based) or
       * (1/m) [K_s beta] + [K_s (beta/m)] (LPS). Stored fields (set_masks)
       * or, with FftOptions::keep_mask_fields false, recomputed: bond
       * based one forward and n_sym inverse transforms, LPS twice that;
       * spectra 0 and 1 are overwritten.
       */
      template <typename F>
      void
      for_P(const F &f)
      {
        if (stored_mask_fields)
          {
            for_nodes([&](std::size_t k, std::size_t) {
              const std::size_t l = layer_index(k);
              for (unsigned int s = 0; s < P.size(); ++s)
                f(s, k, kept(P[s], P_in[s], l));
            });
            return;
          }
        const auto b = [this](std::size_t k) { return beta[k]; };
        if (material.model != Model::lps)
          {
            for_correlations(C, b, 0, f);
            return;
          }
        for_correlations(K, b, 0, [&](unsigned int s, std::size_t k, double r) {
          f(s, k, minv[k] * r);
        });
        for_correlations(
          K, [this](std::size_t k) { return beta[k] * minv[k]; }, 0, f);
      }

      /**
       * f(s, k, v) for the mask fields of the bond-based models computed
       * from beta, v the value at node k of P_s = [C_s beta] (s < n_sym),
       * q_i = [a_i beta] (s = n_sym + i) and p = [c beta] (s = n_sym +
       * dim); the last two of the nonlinear model only. One forward and
       * one inverse transform per field, spectra 0 and 1 overwritten.
       */
      template <typename F>
      void
      compute_bond_fields(const F &f)
      {
        std::vector<const Kernel *> kernels;
        for (const Kernel &k : C)
          kernels.push_back(&k);
        if (material.model == Model::nonlinear_bond_based)
          {
            for (const Kernel &k : a)
              kernels.push_back(&k);
            kernels.push_back(&c);
          }
        for_correlations(
          kernels, [this](std::size_t k) { return beta[k]; }, 0, f);
      }

      /// L_i -= factor sum_j u_j P_ij for every node (P from for_P();
      /// spectra 0 and 1 overwritten where recomputed).
      void
      subtract_P_term(const std::vector<double> &u,
                      double                     factor,
                      std::vector<double>       &L);

      /// f(i, k, [g_i beta](k)) of LPS, computed (one forward, dim inverse
      /// transforms, spectra 0 and 1 overwritten).
      template <typename F>
      void
      for_gb(const F &f)
      {
        for_correlations(
          g, [this](std::size_t k) { return beta[k]; }, 0, f);
      }

      /// The value at a node of layer index @p l (layer_index()) of a kept
      /// mask field with layer values @p field and interior value @p inside.
      static double
      kept(const std::vector<double> &field,
           const double               inside,
           const std::size_t          l)
      {
        return l == interior ? inside : field[l];
      }

      /// The place of local node @p k among the layer nodes, or interior
      /// where its kept mask fields are their interior values (or not
      /// needed: beta = 0).
      std::size_t
      layer_index(const std::size_t k) const
      {
        const std::uint64_t word = layer_bits[k >> 6];
        const std::uint64_t bit  = std::uint64_t(1) << (k & 63u);
        return (word & bit) != 0u ?
                 layer_rank[k >> 6] +
                   std::size_t(__builtin_popcountll(word & (bit - 1u))) :
                 interior;
      }

      /// The layer of the kept mask fields (set_masks(), beta made; LPS:
      /// with the spectrum of beta in spectrum 1). Spectra 0 and 1 (LPS
      /// with beta 0 or 1: 2) overwritten.
      void
      make_layer();

      /// The influence indicator omega_0 (1 on every bond), made at the
      /// first use.
      const Kernel &
      indicator();

      /// Q(x) = sum' beta' K_ij eta_i eta_j Delta V (no outer beta); K = C
      /// (bond based) or K (LPS).
      void
      quadratic_form(const std::vector<double> &u,
                     const std::vector<Kernel> &K,
                     std::vector<double>       &Q);

      void
      apply_linear(const std::vector<double> &u, std::vector<double> &L);

      void
      apply_nonlinear(const std::vector<double> &u, std::vector<double> &L);

      void
      apply_lps(const std::vector<double> &u, std::vector<double> &L);

      /**
       * theta of LPS, with gb_i = [g_i beta] from @p gb_fields (dim N
       * values, component-major) or, where null, the kept fields or
       * for_gb(); leaves Sum_j K_ij^ (beta u_j)^ in spectra 0..dim-1 when
       * @p keep_sums.
       */
      void
      lps_dilatation(const std::vector<double> &u,
                     bool                       keep_sums,
                     const std::vector<double> *gb_fields);

      /// chi_B(k).
      double
      body(const std::size_t k) const
      {
        return body_values.empty() ? double(body_bits[k]) : body_values[k];
      }

      Grid<dim> const    grid;
      Material const     material;
      unsigned int const threads;
      // several ranks (fftw3-mpi plans) or one (serial plans), and the
      // ranks' communicator
      bool     distributed = false;
      MPI_Comm comm        = MPI_COMM_SELF;
      // local nodes N (the slab's), local modes Nc, box nodes N_global;
      // a row (the last, fastest index) has row nodes and takes stride
      // doubles in a spectrum's real view, a spectrum alloc complex numbers
      std::size_t N = 0, Nc = 0, N_global = 0, row = 0, stride = 0;
      std::size_t alloc = 0;
      Slab        slab;
      // the complex box n_0 x ... x (n_{dim-1}/2 + 1); several ranks: the
      // rank's modes are k_1 = k1_first, ..., k1_first + k1_count - 1
      std::array<std::size_t, dim>   cn{};
      std::size_t                    k1_first = 0, k1_count = 0;
      double                         dV = 0.;
      std::vector<Offset<dim>> const offsets;
      fftw_plan                      forward_plan = nullptr;
      fftw_plan                      inverse_plan = nullptr;
      std::vector<fftw_complex *>    spectra;
      std::size_t                    transforms = 0;

      // kernels: C (bond based, symmetric), a and c (nonlinear), K and g
      // (LPS), the influence indicator omega_0 (damage, made when asked)
      std::vector<Kernel> C, a, K, g;
      Kernel              c, omega0;
      bool                have_omega0 = false;
      // LPS: the indicator of the kept fields' reach (make_layer())
      Kernel reach;
      bool   have_reach = false;

      // mask fields: beta = chi_B lambda; chi_B as bytes where every value
      // is 0 or 1, else as doubles; P_s = [C_s beta] (bond based) or
      // (1/m) [K_s beta] + [K_s (beta/m)] (LPS), q_i = [a_i beta],
      // p = [c beta] (nonlinear); LPS: 1/m (0 where m = 0),
      // gb_i = [g_i beta], theta. P, q, p and gb are empty where
      // recomputed (keep_mask_fields false);
      // m is made by weighted_volume() only.
      // (stored_mask_fields: kept and made; a flag, not the sizes, so that
      // ranks without nodes take the same transforms)
      bool                             keep_mask_fields   = true;
      bool                             stored_mask_fields = false;
      std::vector<double>              beta, body_values;
      std::vector<unsigned char>       body_bits;
      std::vector<std::vector<double>> P, q;
      std::vector<double>              gb, p, minv, theta;
      // The kept fields hold the layer nodes only (theory.md §14.3): the
      // nodes of the body (beta != 0) with a node of beta != 1 within their
      // reach, the horizon (LPS: the node itself and twice the horizon, as
      // P depends on m at the neighbours). Elsewhere a field equals its
      // interior value (P_in, p_in; [g_i beta] and q_i are 0, odd
      // kernels) or is not needed (beta = 0 multiplies it). P, q, p have
      // n_layer values, gb dim n_layer (component-major); layer_bits one
      // bit per local node, layer_rank the layer nodes before each word.
      static constexpr std::size_t interior = ~std::size_t(0);
      std::vector<std::uint64_t>   layer_bits;
      std::vector<std::size_t>     layer_rank;
      std::size_t                  n_layer = 0;
      std::vector<double>          P_in;
      double                       p_in = 0.;
      mutable std::vector<double>  m;
      double                       A = 0., B = 0.;
      Fold                         fold;

      // apply_periodic_inverse(): G^(kappa)^-1, real and symmetric, its
      // dim (dim + 1) / 2 entries per folded mode (the diagonal, then the
      // upper triangle; entry (i, j) has the parity of K_ij), made at the first
      // use (a rank may hold no mode: the flag, not the size, says whether it
      // is made, so that all ranks agree).
      std::vector<double> periodic_inverse;
      bool                have_periodic_inverse = false;
    };
  } // namespace FFT
} // namespace pdfem

#endif
