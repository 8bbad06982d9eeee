// SPDX-License-Identifier: LGPL-2.1-or-later
// The three models' forms for FftOperator (specs/002 §1.2-1.4 with the
// corrections of §7): linear bond based, nonlinear bond based, LPS, and the
// quadratic form of the energy density.
#include <pdfem/fft/fft_operator.h>

#include <algorithm>

#include "fft_operator_impl.h"

namespace pdfem
{
  namespace FFT
  {
    using internal::symmetric_index;
    using internal::symmetric_pair;

    template <int dim>
    void
    FftOperator<dim>::Impl::subtract_P_term(const std::vector<double> &u,
                                            const double               factor,
                                            std::vector<double>       &L)
    {
      for_P([&](unsigned int s, std::size_t k, double v) {
        unsigned int i, j;
        symmetric_pair<dim>(s, i, j);
        L[i * N + k] -= factor * u[j * N + k] * v;
        if (i != j)
          L[j * N + k] -= factor * u[i * N + k] * v;
      });
    }

    // ----------------------------------------------- linear bond based
    template <int dim>
    void
    FftOperator<dim>::Impl::apply_linear(const std::vector<double> &u,
                                         std::vector<double>       &L)
    {
      // L_i = beta ([C_ij (beta u_j)] - u_j P_ij), P = [C beta]; the sum
      // over j of the first term in Fourier space (specs/002 eq. 58).
      // Recomputed P: its term first, while the spectra are free.
      const bool stored = stored_mask_fields;
      if (!stored)
        {
          std::fill(L.begin(), L.end(), 0.);
          subtract_P_term(u, 1., L);
        }
      fftw_complex *h[dim];
      forward_components(
        u, [this](std::size_t k) { return beta[k]; }, h);
      fused_product(h, &C, 1., nullptr, nullptr, 0., nullptr);
      for (unsigned int i = 0; i < dim; ++i)
        {
          inverse(h[i]);
          double *Li = L.data() + i * N;
          if (!stored)
            {
              use(h[i], [&](std::size_t k, double r) {
                Li[k] = beta[k] * (Li[k] + r);
              });
              continue;
            }
          use(h[i], [&](std::size_t k, double r) {
            const std::size_t l = layer_index(k);
            double            s = r;
            for (unsigned int j = 0; j < dim; ++j)
              {
                const unsigned int ij = symmetric_index<dim>(i, j);
                s -= u[j * N + k] * kept(P[ij], P_in[ij], l);
              }
            Li[k] = beta[k] * s;
          });
        }
    }

    template <int dim>
    void
    FftOperator<dim>::Impl::quadratic_form(const std::vector<double> &u,
                                           const std::vector<Kernel> &kernels,
                                           std::vector<double>       &Q)
    {
      // Q = sum_ij [K_ij (beta u_i u_j)] - 2 u_j S_j + u_i u_j [K_ij beta],
      // S_j = sum_i [K_ij (beta u_i)] (specs/002 eq. 47, K symmetric); at
      // most dim work spectra at a time.
      fftw_complex *q = spectrum(0), *h = spectrum(1);
      zero(q);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          {
            const double *ui = u.data() + i * N, *uj = u.data() + j * N;
            fill(h, [&](std::size_t k) { return beta[k] * ui[k] * uj[k]; });
            forward(h);
            multiply(q,
                     kernels[symmetric_index<dim>(i, j)],
                     h,
                     i == j ? 1. : 2.,
                     true);
          }
      inverse(q);
      take(q, Q);
      fftw_complex *S[dim];
      forward_components(
        u, [this](std::size_t k) { return beta[k]; }, S);
      fused_product(S, &kernels, 1., nullptr, nullptr, 0., nullptr);
      for (unsigned int j = 0; j < dim; ++j)
        {
          inverse(S[j]);
          use(S[j],
              [&](std::size_t k, double r) { Q[k] -= 2. * u[j * N + k] * r; });
        }
      // + u_i u_j [K_ij beta]: P of the linear bond-based model, recomputed
      // for LPS (whose P is the combined variable-m field)
      const auto add = [&](unsigned int s, std::size_t k, double v) {
        unsigned int i, j;
        symmetric_pair<dim>(s, i, j);
        Q[k] += (i == j ? 1. : 2.) * u[i * N + k] * u[j * N + k] * v;
      };
      if (material.model == Model::lps)
        for_correlations(
          kernels, [this](std::size_t k) { return beta[k]; }, 0, add);
      else
        for_P(add);
    }

    // -------------------------------------------- nonlinear bond based
    template <int dim>
    void
    FftOperator<dim>::Impl::apply_nonlinear(const std::vector<double> &u,
                                            std::vector<double>       &L)
    {
      // The corrected form of specs/002 §1.3 (§7 E1), as correlations
      // [k b] = sum' k(xi) b' Delta V, a = c xi, c = alpha omega / |xi|^2:
      //   L_i / beta = [C_ij (beta u_j)] - u_j P_ij
      //     + [a_j (beta u_j u_i)] - u_i [a_j (beta u_j)]
      //     - u_j [a_j (beta u_i)] + u_i u_j q_j
      //     + 1/2 [a_i (beta |u|^2)] - u_j [a_i (beta u_j)] + 1/2 |u|^2 q_i
      //     + 1/2 [c (beta |u|^2 u_i)] - 1/2 u_i [c (beta |u|^2)]
      //     - u_k [c (beta u_k u_i)] + u_k u_i [c (beta u_k)]
      //     + 1/2 |u|^2 [c (beta u_i)] - 1/2 |u|^2 u_i p.
      // Terms without a factor outside the correlation are summed in
      // Fourier space (acc_i); the others are inverted one by one and added
      // into L. dim + 2 work spectra (dim + 1 recomputing the fields, below).
      // The mask-field terms (P, q, p): kept
      // fields in the last pass over the nodes; recomputed ones first,
      // field by field (they use spectra 0 and 1 before the sums need them).
      // Both forms are kept: the field-by-field one in the last pass made
      // the 3D evaluation 5-8 % slower (one unfused pass of 10 fields).
      const auto U = [&](unsigned int i, std::size_t k) {
        return u[i * N + k];
      };
      const auto U2 = [&](std::size_t k) {
        double s = 0.;
        for (unsigned int i = 0; i < dim; ++i)
          s += U(i, k) * U(i, k);
        return s;
      };
      std::fill(L.begin(), L.end(), 0.);
      const unsigned int n_sym  = C.size();
      const bool         stored = stored_mask_fields;
      if (!stored)
        compute_bond_fields([&](unsigned int s, std::size_t k, double v) {
          if (s < n_sym) // - u_j P_ij
            {
              unsigned int i, j;
              symmetric_pair<dim>(s, i, j);
              L[i * N + k] -= U(j, k) * v;
              if (i != j)
                L[j * N + k] -= U(i, k) * v;
            }
          else if (s < n_sym + dim) // + u_i u_j q_j + 1/2 |u|^2 q_i
            {
              const unsigned int j = s - n_sym;
              for (unsigned int i = 0; i < dim; ++i)
                L[i * N + k] += U(i, k) * U(j, k) * v;
              L[j * N + k] += 0.5 * U2(k) * v;
            }
          else // - 1/2 |u|^2 u_i p
            for (unsigned int i = 0; i < dim; ++i)
              L[i * N + k] -= 0.5 * U2(k) * U(i, k) * v;
        });

      // h = F(beta w) for a product w of u's; the correlations with a and
      // c taken from it are formed in t, or, recomputing the fields (no
      // spare spectrum: dim + 1 in all), in h itself, which is then remade
      // for the next one (dim more forward transforms per j). The last
      // product taken from an h is formed in h in either setting.
      fftw_complex *h = spectrum(dim), *t = stored ? spectrum(dim + 1) : h;
      for (unsigned int i = 0; i < dim; ++i)
        zero(spectrum(i));
      for (unsigned int j = 0; j < dim; ++j)
        {
          const auto w = [&](std::size_t k) { return beta[k] * U(j, k); };
          fill(h, w);
          forward(h);
          for (unsigned int i = 0; i < dim; ++i)
            multiply(spectrum(i), C[symmetric_index<dim>(i, j)], h, 1., true);
          for (unsigned int l = 0; l <= dim; ++l)
            {
              fftw_complex *r = l < dim ? t : h;
              if (t == h && l > 0)
                {
                  fill(h, w);
                  forward(h);
                }
              multiply(r, l < dim ? a[l] : c, h, 1., false);
              inverse(r);
              if (l == dim)
                {
                  // + u_k u_i [c (beta u_k)] + 1/2 |u|^2 [c (beta u_i)]
                  use(r, [&](std::size_t k, double R) {
                    for (unsigned int i = 0; i < dim; ++i)
                      L[i * N + k] += U(j, k) * U(i, k) * R;
                    L[j * N + k] += 0.5 * U2(k) * R;
                  });
                  continue;
                }
              // G = [a_l (beta u_j)]: -u_j G in L_l, -u_l G in L_j, and
              // for l = j -u_i G in every L_i (- u_i [a_j (beta u_j)])
              use(r, [&](std::size_t k, double G) {
                L[l * N + k] -= U(j, k) * G;
                L[j * N + k] -= U(l, k) * G;
                if (l == j)
                  for (unsigned int i = 0; i < dim; ++i)
                    L[i * N + k] -= U(i, k) * G;
              });
            }
        }

      fill(h, [&](std::size_t k) { return beta[k] * U2(k); });
      forward(h);
      for (unsigned int i = 0; i < dim; ++i)
        multiply(spectrum(i), a[i], h, 0.5, true);
      multiply(h, c, h, 1., false);
      inverse(h);
      use(h, [&](std::size_t k, double r) {
        for (unsigned int i = 0; i < dim; ++i)
          L[i * N + k] -= 0.5 * U(i, k) * r;
      });

      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int l = 0; l <= i; ++l)
          {
            fill(h, [&](std::size_t k) { return beta[k] * U(l, k) * U(i, k); });
            forward(h);
            multiply(spectrum(i), a[l], h, 1., true);
            if (l != i)
              multiply(spectrum(l), a[i], h, 1., true);
            multiply(h, c, h, 1., false);
            inverse(h);
            use(h, [&](std::size_t k, double R) {
              L[i * N + k] -= U(l, k) * R;
              if (l != i)
                L[l * N + k] -= U(i, k) * R;
            });
          }

      for (unsigned int i = 0; i < dim; ++i)
        {
          fill(h, [&](std::size_t k) { return beta[k] * U2(k) * U(i, k); });
          forward(h);
          multiply(spectrum(i), c, h, 0.5, true);
        }
      for (unsigned int i = 0; i < dim; ++i)
        {
          fftw_complex *acc = spectrum(i);
          inverse(acc);
          double *Li = L.data() + i * N;
          use(acc, [&](std::size_t k, double r) {
            double s = Li[k] + r;
            if (stored)
              {
                // q_i = [a_i beta] is 0 off the layer (a_i is odd)
                const std::size_t l  = layer_index(k);
                const double      u2 = U2(k);
                s +=
                  0.5 * u2 * (kept(q[i], 0., l) - U(i, k) * kept(p, p_in, l));
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    const unsigned int ij = symmetric_index<dim>(i, j);
                    s += U(j, k) * (U(i, k) * kept(q[j], 0., l) -
                                    kept(P[ij], P_in[ij], l));
                  }
              }
            Li[k] = beta[k] * s;
          });
        }
    }

    // ------------------------------------------------------------- LPS
    template <int dim>
    void
    FftOperator<dim>::Impl::lps_dilatation(const std::vector<double> &u,
                                           const bool                 keep_sums,
                                           const std::vector<double> *gb_fields)
    {
      // theta = dim beta / m ([g_i (beta u_i)] - u_i [g_i beta]),
      // g = omega xi (specs/002 §1.4 with §7 E3, E4).
      theta.resize(N);
      const bool recompute = gb_fields == nullptr && !stored_mask_fields;
      if (recompute)
        {
          std::fill(theta.begin(), theta.end(), 0.);
          for_gb([&](unsigned int i, std::size_t k, double r) {
            theta[k] -= u[i * N + k] * r;
          });
        }
      fftw_complex *acc = spectrum(dim), *h[dim];
      forward_components(
        u, [this](std::size_t k) { return beta[k]; }, h);
      // acc = sum_j g_j (beta u_j)^; with keep_sums h[i] <- sum_j K_ij h[j]
      fused_product(h, keep_sums ? &K : nullptr, 1., &g, nullptr, 0., acc);
      inverse(acc);
      use(acc, [&](std::size_t k, double r) {
        double s = r;
        if (recompute)
          s += theta[k];
        else if (gb_fields != nullptr)
          for (unsigned int i = 0; i < dim; ++i)
            s -= u[i * N + k] * (*gb_fields)[i * N + k];
        else if (const std::size_t l = layer_index(k); l != interior)
          for (unsigned int i = 0; i < dim; ++i) // 0 in the interior
            s -= u[i * N + k] * gb[i * n_layer + l];
        theta[k] = dim * beta[k] * minv[k] * s;
      });
    }

    template <int dim>
    void
    FftOperator<dim>::Impl::apply_lps(const std::vector<double> &u,
                                      std::vector<double>       &L)
    {
      // L_i = beta { A [(theta/m) [g_i beta] + [g_i (beta theta/m)]]
      //   + B [(1/m) [K_ij (beta u_j)] + [K_ij (beta u_j/m)] - u_j P_ij] }
      // (the variable-m form of specs/002 §1.4). Recomputed mask fields:
      // L holds [g_i beta] until theta is known, and the P term comes
      // last, when the spectra are free.
      const bool stored = stored_mask_fields;
      if (!stored)
        for_gb(
          [&](unsigned int i, std::size_t k, double r) { L[i * N + k] = r; });
      lps_dilatation(u, true, stored ? nullptr : &L);
      for (unsigned int i = 0; i < dim; ++i)
        {
          fftw_complex *si = spectrum(i);
          inverse(si);
          double *Li = L.data() + i * N;
          if (!stored)
            {
              use(si, [&](std::size_t k, double r) {
                Li[k] = minv[k] * (A * theta[k] * Li[k] + B * r);
              });
              continue;
            }
          const double *gi = gb.data() + i * n_layer;
          use(si, [&](std::size_t k, double r) {
            const std::size_t l  = layer_index(k);
            const double      gk = l == interior ? 0. : gi[l];
            Li[k]                = minv[k] * (A * theta[k] * gk + B * r);
          });
        }
      fftw_complex *h[dim], *ht = spectrum(dim);
      forward_components(
        u, [this](std::size_t k) { return beta[k] * minv[k]; }, h);
      fill(ht, [&](std::size_t k) { return beta[k] * minv[k] * theta[k]; });
      forward(ht);
      fused_product(h, &K, B, &g, ht, A, nullptr);
      for (unsigned int i = 0; i < dim; ++i)
        {
          inverse(h[i]);
          double *Li = L.data() + i * N;
          if (!stored)
            {
              use(h[i], [&](std::size_t k, double r) { Li[k] += r; });
              continue;
            }
          use(h[i], [&](std::size_t k, double r) {
            const std::size_t l = layer_index(k);
            double            s = Li[k] + r;
            for (unsigned int j = 0; j < dim; ++j)
              {
                const unsigned int ij = symmetric_index<dim>(i, j);
                s -= B * u[j * N + k] * kept(P[ij], P_in[ij], l);
              }
            Li[k] = beta[k] * s;
          });
        }
      if (stored)
        return;
      subtract_P_term(u, B, L);
      for (unsigned int i = 0; i < dim; ++i)
        {
          double *Li = L.data() + i * N;
          for_nodes([&](std::size_t k, std::size_t) { Li[k] *= beta[k]; });
        }
    }

#define PDFEM_FFT_INSTANTIATE(dim)                                             \
  template void FftOperator<dim>::Impl::apply_linear(                          \
    const std::vector<double> &, std::vector<double> &);                       \
  template void FftOperator<dim>::Impl::apply_nonlinear(                       \
    const std::vector<double> &, std::vector<double> &);                       \
  template void FftOperator<dim>::Impl::apply_lps(const std::vector<double> &, \
                                                  std::vector<double> &);      \
  template void FftOperator<dim>::Impl::lps_dilatation(                        \
    const std::vector<double> &, bool, const std::vector<double> *);           \
  template void FftOperator<dim>::Impl::quadratic_form(                        \
    const std::vector<double> &,                                               \
    const std::vector<Kernel> &,                                               \
    std::vector<double> &);
    PDFEM_FFT_INSTANTIATE(2)
    PDFEM_FFT_INSTANTIATE(3)
#undef PDFEM_FFT_INSTANTIATE
  } // namespace FFT
} // namespace pdfem
