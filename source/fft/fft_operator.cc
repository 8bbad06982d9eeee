// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD operators by FFT (FCBM, specs/002): the transform engine (FFTW
// plans, kernel spectra, Fourier-space products), the masks, and what the
// models share (energy density, damage). The models' forms are in
// fft_models.cc. One rank: serial r2c/c2r plans on the whole box; several:
// fftw3-mpi plans on slabs of whole planes, the spectra left transposed.
#include <pdfem/base/exceptions.h>
#include <pdfem/fft/fft_operator.h>

#include <mutex>
#include <stdexcept>

#include "fft_operator_impl.h"

namespace pdfem
{
  namespace FFT
  {

    namespace
    {
      // FFTW's planner is not thread-safe: plans are made and destroyed
      // under this lock (executing them is thread-safe).
      std::mutex     planner_mutex;
      std::once_flag threads_initialised, mpi_initialised;

      /// fftw_init_threads() once, then (@p mpi) fftw_mpi_init() once.
      void
      initialise_fftw(const bool mpi)
      {
        std::call_once(threads_initialised, []() { fftw_init_threads(); });
        if (mpi)
          std::call_once(mpi_initialised, []() { fftw_mpi_init(); });
      }

      /// Whether @p comm has several ranks (MPI_COMM_SELF: no MPI call).
      bool
      several_ranks(MPI_Comm comm)
      {
        if (comm == MPI_COMM_SELF)
          return false;
        if (comm == MPI_COMM_NULL)
          throw std::invalid_argument("FFT::FftOptions: the communicator is "
                                      "MPI_COMM_NULL");
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised)
          throw std::logic_error("FFT::FftOptions: a communicator other than "
                                 "MPI_COMM_SELF needs MPI initialised");
        int size = 1;
        MPI_Comm_size(comm, &size);
        return size > 1;
      }

      /// FFTW's transposed r2c layout of the complex box on this rank.
      struct MpiLayout
      {
        std::ptrdiff_t alloc = 0, n0 = 0, first0 = 0, n1 = 0, first1 = 0;
      };

      template <int dim>
      MpiLayout
      mpi_layout(const Grid<dim> &grid, MPI_Comm comm)
      {
        std::ptrdiff_t cn[dim];
        for (unsigned int d = 0; d < dim; ++d)
          cn[d] = grid.n[d];
        cn[dim - 1] = grid.n[dim - 1] / 2 + 1;
        MpiLayout l;
        l.alloc = fftw_mpi_local_size_transposed(
          dim, cn, comm, &l.n0, &l.first0, &l.n1, &l.first1);
        return l;
      }

      template <int dim>
      Slab
      make_slab(const Grid<dim>  &grid,
                const std::size_t first_plane,
                const std::size_t n_planes)
      {
        const std::size_t plane = grid.n_nodes() / grid.n[0];
        Slab              s;
        s.first_plane = static_cast<unsigned int>(first_plane);
        s.n_planes    = static_cast<unsigned int>(n_planes);
        s.begin       = first_plane * plane;
        s.end         = s.begin + n_planes * plane;
        return s;
      }
    } // namespace

    template <int dim>
    Slab
    local_slab(const Grid<dim> &grid, MPI_Comm communicator)
    {
      if (!several_ranks(communicator))
        return make_slab(grid, 0, grid.n[0]);
      initialise_fftw(true);
      const MpiLayout l = mpi_layout(grid, communicator);
      return make_slab(grid, l.first0, l.n0);
    }

    template <int dim>
    FftOperator<dim>::Impl::Impl(const Grid<dim>  &grid_,
                                 const Material   &material_,
                                 const FftOptions &options)
      : grid(grid_)
      , material(material_)
      , threads(std::max(1u, options.threads))
      , distributed(several_ranks(options.communicator))
      , comm(options.communicator)
      , offsets(horizon_offsets(grid_, material_.horizon))
      , keep_mask_fields(options.keep_mask_fields)
    {
      N_global = grid.n_nodes();
      row      = grid.n[dim - 1];
      for (unsigned int d = 0; d < dim; ++d)
        cn[d] = grid.n[d];
      cn[dim - 1] = row / 2 + 1;
      dV          = grid.node_volume();
      internal::lps_constants<dim>(material, A, B);
      initialise_fftw(distributed);
      if (!distributed)
        {
          slab   = make_slab(grid, 0, grid.n[0]);
          N      = N_global;
          Nc     = N / row * cn[dim - 1];
          stride = 2 * cn[dim - 1];
          alloc  = Nc;
        }
      else
        {
          // FFTW's slabs: whole planes of i_0 in real space (rows padded to
          // 2 (n/2 + 1) doubles), whole planes of k_1 in Fourier space
          const MpiLayout l = mpi_layout(grid, comm);
          slab              = make_slab(grid, l.first0, l.n0);
          N                 = slab.n_nodes();
          stride            = 2 * cn[dim - 1];
          k1_first          = l.first1;
          k1_count          = l.n1;
          Nc                = k1_count * cn[0];
          for (unsigned int d = 2; d < dim; ++d)
            Nc *= cn[d];
          alloc = std::max<std::size_t>(l.alloc, 1);
        }

      fftw_complex *s = spectrum(0);
      {
        std::lock_guard<std::mutex> lock(planner_mutex);
        fftw_plan_with_nthreads(static_cast<int>(threads));
        const unsigned int flags =
          options.planning == Planning::measure ? FFTW_MEASURE : FFTW_ESTIMATE;
        if (!distributed)
          {
            int n[dim];
            for (unsigned int d = 0; d < dim; ++d)
              n[d] = static_cast<int>(grid.n[d]);
            forward_plan = fftw_plan_dft_r2c(dim, n, reals(s), s, flags);
            inverse_plan = fftw_plan_dft_c2r(dim, n, s, reals(s), flags);
          }
        else
          {
            std::ptrdiff_t n[dim];
            for (unsigned int d = 0; d < dim; ++d)
              n[d] = grid.n[d];
            forward_plan = fftw_mpi_plan_dft_r2c(
              dim, n, reals(s), s, comm, flags | FFTW_MPI_TRANSPOSED_OUT);
            inverse_plan = fftw_mpi_plan_dft_c2r(
              dim, n, s, reals(s), comm, flags | FFTW_MPI_TRANSPOSED_IN);
          }
      }
      if (forward_plan == nullptr || inverse_plan == nullptr)
        throw std::runtime_error("FFTW could not make a plan");
      make_fold();
      make_kernels();
    }

    template <int dim>
    void
    FftOperator<dim>::Impl::make_fold()
    {
      // the local modes: one rank k_0, k_1, ... (k_{dim-1} < n/2 + 1);
      // several: FFTW's transposed layout, k_1 (distributed) before k_0
      std::array<std::size_t, dim> first{};
      for (unsigned int p = 0; p < dim; ++p)
        fold.order[p] = p;
      if (distributed)
        {
          fold.order[0] = 1;
          fold.order[1] = 0;
          first[1]      = k1_first;
        }
      for (unsigned int p = 0; p < dim; ++p)
        {
          const unsigned int d = fold.order[p];
          fold.extent[p]       = (distributed && d == 1) ? k1_count : cn[d];
        }
      std::array<std::size_t, dim> folded_extent{};
      for (unsigned int p = 0; p < dim; ++p)
        {
          const unsigned int d = fold.order[p];
          const std::size_t  n = grid.n[d];
          // k_d -> min(k_d, n_d - k_d); the last direction is a half
          // spectrum already
          std::vector<std::size_t> folded(fold.extent[p]);
          fold.reflected[d].resize(fold.extent[p]);
          for (std::size_t i = 0; i < fold.extent[p]; ++i)
            {
              const std::size_t k    = first[d] + i;
              const bool        refl = d + 1 < dim && 2 * k > n;
              folded[i]              = refl ? n - k : k;
              fold.reflected[d][i]   = refl;
            }
          // this rank's folded wave numbers, numbered in increasing order
          std::vector<std::size_t> distinct = folded;
          std::sort(distinct.begin(), distinct.end());
          distinct.erase(std::unique(distinct.begin(), distinct.end()),
                         distinct.end());
          fold.index[d].resize(fold.extent[p]);
          for (std::size_t i = 0; i < fold.extent[p]; ++i)
            fold.index[d][i] =
              std::lower_bound(distinct.begin(), distinct.end(), folded[i]) -
              distinct.begin();
          folded_extent[d] = distinct.size();
        }
      // (0 on a rank without modes: its k_1 extent is 0)
      fold.size = 1;
      for (int d = dim - 1; d >= 0; --d)
        {
          fold.stride[d] = fold.size;
          fold.size *= folded_extent[d];
        }
    }

    template <int dim>
    FftOperator<dim>::Impl::~Impl()
    {
      {
        std::lock_guard<std::mutex> lock(planner_mutex);
        if (forward_plan)
          fftw_destroy_plan(forward_plan);
        if (inverse_plan)
          fftw_destroy_plan(inverse_plan);
      }
      for (auto s : spectra)
        fftw_free(s);
    }

    template <int dim>
    fftw_complex *
    FftOperator<dim>::Impl::spectrum(const unsigned int i)
    {
      while (spectra.size() <= i)
        spectra.push_back(fftw_alloc_complex(alloc));
      return spectra[i];
    }

    template <int dim>
    template <typename F>
    typename FftOperator<dim>::Impl::Kernel
    FftOperator<dim>::Impl::make_kernel(const F           &value,
                                        const unsigned int parity,
                                        const double       scale)
    {
      return make_kernel(offsets, value, parity, scale);
    }

    template <int dim>
    template <typename F>
    typename FftOperator<dim>::Impl::Kernel
    FftOperator<dim>::Impl::make_kernel(const std::vector<Offset<dim>> &support,
                                        const F                        &value,
                                        const unsigned int              parity,
                                        const double                    scale)
    {
      // sampled on this rank's slab (a kernel is a function of the
      // periodic offset: each rank samples its own planes)
      fftw_complex *s = spectrum(0);
      double       *r = reals(s);
      std::memset(s, 0, alloc * sizeof(fftw_complex));
      double total = 0.; // every rank sums every bond: the same on all
      for (const auto &o : support)
        {
          total += value(o);
          std::array<unsigned int, dim> i;
          for (unsigned int d = 0; d < dim; ++d)
            i[d] = static_cast<unsigned int>((o.p[d] + int(grid.n[d])) %
                                             int(grid.n[d]));
          const std::size_t node = grid.node(i);
          if (!slab.contains(node))
            continue;
          const std::size_t k           = node - slab.begin;
          r[k / row * stride + k % row] = value(o);
        }
      forward(s);
      Kernel k;
      k.parity = parity;
      k.total  = k.odd() ? 0. : total * scale * double(N_global);
      k.s.assign(fold.size, 0.);
      // conj(k^) = k^ (even: real) or -i Im k^ (odd), on the folded modes
      // (a folded mode met several times gets the same value to round-off;
      // one thread, so the last one written is always the same)
      walk_modes(0, Nc, [&](std::size_t j, std::size_t o, unsigned int flips) {
        k.s[o] = sign(parity, flips) * scale * (k.odd() ? -s[j][1] : s[j][0]);
      });
      return k;
    }

    template <int dim>
    void
    FftOperator<dim>::Impl::make_kernels()
    {
      const double scale = dV / N_global;
      const double alpha = material.micromodulus;
      const auto   omega = [this](const Offset<dim> &o) {
        return material.omega(o.length);
      };
      switch (material.model)
        {
          case Model::linear_bond_based:
          case Model::nonlinear_bond_based:
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                C.push_back(make_kernel(
                  [&](const Offset<dim> &o) {
                    return alpha * omega(o) * o.xi[i] * o.xi[j] /
                           (o.length * o.length);
                  },
                  (1u << i) ^ (1u << j),
                  scale));
            if (material.model == Model::linear_bond_based)
              break;
            for (unsigned int i = 0; i < dim; ++i)
              a.push_back(make_kernel(
                [&](const Offset<dim> &o) {
                  return alpha * omega(o) * o.xi[i] / (o.length * o.length);
                },
                1u << i,
                scale));
            c = make_kernel(
              [&](const Offset<dim> &o) {
                return alpha * omega(o) / (o.length * o.length);
              },
              0u,
              scale);
            break;
          case Model::lps:
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                K.push_back(make_kernel(
                  [&](const Offset<dim> &o) {
                    return omega(o) * o.xi[i] * o.xi[j] / (o.length * o.length);
                  },
                  (1u << i) ^ (1u << j),
                  scale));
            for (unsigned int i = 0; i < dim; ++i)
              g.push_back(make_kernel(
                [&](const Offset<dim> &o) { return omega(o) * o.xi[i]; },
                1u << i,
                scale));
            break;
        }
    }

    // -------------------------------------------------------- the masks
    template <int dim>
    FftOperator<dim>::FftOperator(const Grid<dim>  &grid,
                                  const Material   &material,
                                  const FftOptions &options)
      : Operator<dim>(grid, material)
      , impl(std::make_unique<Impl>(grid, material, options))
    {
      set_masks({}, {});
    }

    template <int dim>
    FftOperator<dim>::~FftOperator() = default;

    template <int dim>
    void
    FftOperator<dim>::set_masks(const std::vector<double> &body_mask,
                                const std::vector<double> &integrity)
    {
      Impl             &o = *impl;
      const std::size_t N = o.N;
      if ((!body_mask.empty() && body_mask.size() != N) ||
          (!integrity.empty() && integrity.size() != N))
        throw std::invalid_argument("FFT::FftOperator::set_masks: a mask has "
                                    "the wrong size");
      const bool binary =
        std::all_of(body_mask.begin(), body_mask.end(), [](double v) {
          return v == 0. || v == 1.;
        });
      o.body_values.clear();
      o.body_bits.clear();
      if (binary)
        {
          o.body_bits.assign(N, 1);
          for (std::size_t k = 0; k < body_mask.size(); ++k)
            o.body_bits[k] = body_mask[k] != 0.;
        }
      else
        o.body_values = body_mask;
      o.beta = internal::mask_or_one(integrity, N);
      for (std::size_t k = 0; k < N; ++k)
        o.beta[k] *= o.body(k);
      o.m.clear();
      o.m.shrink_to_fit();
      o.stored_mask_fields = false;

      const auto beta = [&o](std::size_t k) { return o.beta[k]; };
      const auto made = [](const unsigned int n, const std::size_t size) {
        return std::vector<std::vector<double>>(n,
                                                std::vector<double>(size, 0.));
      };
      o.P.clear();
      o.q.clear();
      o.p.clear();
      o.gb.clear();
      o.layer_bits.clear();
      o.layer_rank.clear();
      o.n_layer = 0;
      double m0 = 0.; // LPS: m where beta is 1 within twice the horizon
      if (this->material_.model == Model::lps)
        {
          // 1/m, m = beta [omega |xi|^2 beta]
          const std::vector<typename Impl::Kernel> w{o.make_kernel(
            [&](const Offset<dim> &b_) {
              return this->material_.omega(b_.length) * b_.length * b_.length;
            },
            0u,
            o.dV / o.N_global)};
          m0 = w[0].total;
          o.minv.resize(N);
          o.for_correlations(w,
                             beta,
                             1,
                             [&](unsigned int, std::size_t k, double r) {
                               const double m = o.beta[k] * r;
                               o.minv[k]      = m != 0. ? 1. / m : 0.;
                             });
          o.theta.assign(N, 0.);
        }
      if (!o.keep_mask_fields)
        return;
      // the kept fields, made as recomputed ones are (stored_mask_fields is
      // false until they are complete), on the layer nodes only
      o.make_layer();
      const std::size_t                n = o.n_layer;
      std::vector<std::vector<double>> P = made(o.C.size() + o.K.size(), n);
      if (this->material_.model == Model::lps)
        {
          o.for_P([&](unsigned int s, std::size_t k, double r) {
            const std::size_t l = o.layer_index(k);
            if (l != Impl::interior)
              P[s][l] += r;
          });
          o.gb.assign(dim * n, 0.);
          o.for_gb([&](unsigned int i, std::size_t k, double r) {
            const std::size_t l = o.layer_index(k);
            if (l != Impl::interior)
              o.gb[i * n + l] = r;
          });
          // (1/m) [K beta] + [K (beta/m)] where m = m_0 = [omega |xi|^2]
          o.P_in.clear();
          for (const auto &K : o.K)
            o.P_in.push_back(2. * K.total / m0);
        }
      else
        {
          // P_s = [C_s beta]; nonlinear: q_i = [a_i beta], p = [c beta]
          const unsigned int               n_sym = o.C.size();
          std::vector<std::vector<double>> qp;
          if (this->material_.model == Model::nonlinear_bond_based)
            qp = made(dim + 1, n);
          o.compute_bond_fields([&](unsigned int s, std::size_t k, double r) {
            const std::size_t l = o.layer_index(k);
            if (l != Impl::interior)
              (s < n_sym ? P[s] : qp[s - n_sym])[l] = r;
          });
          if (!qp.empty())
            {
              o.p = std::move(qp.back());
              qp.pop_back();
              o.q = std::move(qp);
            }
          o.P_in.clear();
          for (const auto &C : o.C)
            o.P_in.push_back(C.total);
          o.p_in = o.c.total;
        }
      o.P                  = std::move(P);
      o.stored_mask_fields = true;
    }

    template <int dim>
    const typename FftOperator<dim>::Impl::Kernel &
    FftOperator<dim>::Impl::indicator()
    {
      if (!have_omega0)
        {
          omega0      = make_kernel([](const Offset<dim> &) { return 1.; },
                               0u,
                               1. / N_global);
          have_omega0 = true;
        }
      return omega0;
    }

    template <int dim>
    void
    FftOperator<dim>::Impl::make_layer()
    {
      // The kept fields at x depend on beta at x + z for z in the reach Z:
      // the bonds H (bond based); for LPS also z = 0 and the sums of two
      // bonds (P holds 1/m at x and at x + xi). near(x): the nodes of
      // beta != 1 in x + Z, counted by one correlation with the indicator
      // of Z (made once; integers to round-off, compared with 1/2). Where
      // beta is 0 or 1 everywhere, 1{beta != 1} = 1 - beta, and LPS's
      // spectrum of beta is still in spectrum 1 (set_masks(), 1/m): one
      // inverse transform then.
      const bool lps = material.model == Model::lps;
      if (lps && !have_reach)
        {
          const std::vector<Offset<dim>> Z =
            internal::offsets_within_two_bonds(grid, offsets);
          reach = make_kernel(
            Z, [](const Offset<dim> &) { return 1.; }, 0u, 1. / N_global);
          have_reach = true;
        }
      const Kernel &Z = lps ? reach : indicator();
      int binary      = std::all_of(beta.begin(), beta.end(), [](double b) {
        return b == 0. || b == 1.;
      });
      if (distributed)
        MPI_Allreduce(MPI_IN_PLACE, &binary, 1, MPI_INT, MPI_LAND, comm);
      // (spectra the set-up uses anyway: 0 and 1, LPS 1 and 2)
      fftw_complex *t    = nullptr;
      double        ones = 0.; // sum of the kernel's values
      if (lps && binary)
        {
          // beta^ in spectrum 1: near = |Z| - [1_Z beta] > 1/2
          t = spectrum(2);
          multiply(t, Z, spectrum(1), 1., false);
          ones = Z.total;
        }
      else
        {
          fftw_complex *n = spectrum(0);
          t               = spectrum(1);
          fill(n, [this](std::size_t k) { return beta[k] != 1. ? 1. : 0.; });
          forward(n);
          multiply(t, Z, n, 1., false);
        }
      inverse(t);
      const double     *count = reals(t);
      const std::size_t words = (N + 63) / 64;
      layer_bits.assign(words, 0);
      layer_rank.assign(words, 0);
      n_layer              = 0;
      const std::size_t nl = row, st = stride;
      for (std::size_t w = 0; w < words; ++w)
        {
          std::uint64_t bits = 0;
          for (std::size_t k = 64 * w; k < std::min(N, 64 * w + 64); ++k)
            {
              const double c = count[k / nl * st + k % nl];
              if (beta[k] != 0. && (binary && lps ? ones - c : c) > 0.5)
                bits |= std::uint64_t(1) << (k - 64 * w);
            }
          layer_bits[w] = bits;
          layer_rank[w] = n_layer;
          n_layer += std::size_t(__builtin_popcountll(bits));
        }
    }

    // ------------------------------------------------------ public face
    template <int dim>
    void
    FftOperator<dim>::apply(const std::vector<double> &u,
                            std::vector<double>       &force)
    {
      Impl &o = *impl;
      if (u.size() != dim * o.N)
        throw std::invalid_argument("FFT::FftOperator::apply: u has the "
                                    "wrong size");
      force.resize(dim * o.N);
      switch (this->material_.model)
        {
          case Model::linear_bond_based:
            o.apply_linear(u, force);
            break;
          case Model::nonlinear_bond_based:
            o.apply_nonlinear(u, force);
            break;
          case Model::lps:
            o.apply_lps(u, force);
            break;
        }
    }

    template <int dim>
    void
    FftOperator<dim>::dilatation(const std::vector<double> &u,
                                 std::vector<double>       &theta)
    {
      if (this->material_.model != Model::lps)
        throw std::logic_error("FFT: the dilatation is defined for LPS only");
      if (u.size() != dim * impl->N)
        throw std::invalid_argument("FFT::FftOperator::dilatation: u has the "
                                    "wrong size");
      impl->lps_dilatation(u, false, nullptr);
      theta = impl->theta;
    }

    template <int dim>
    void
    FftOperator<dim>::energy_density(const std::vector<double> &u,
                                     std::vector<double>       &W)
    {
      Impl &o = *impl;
      if (u.size() != dim * o.N)
        throw std::invalid_argument("FFT::FftOperator::energy_density: u has "
                                    "the wrong size");
      switch (this->material_.model)
        {
          case Model::linear_bond_based:
            o.quadratic_form(u, o.C, W);
            for (std::size_t k = 0; k < o.N; ++k)
              W[k] *= 0.5 * o.beta[k];
            return;
          case Model::nonlinear_bond_based:
            throw std::logic_error("FFT: no energy density for the nonlinear "
                                   "bond-based model yet");
          case Model::lps:
            {
              o.lps_dilatation(u, false, nullptr);
              o.quadratic_form(u, o.K, W);
              for (std::size_t k = 0; k < o.N; ++k)
                W[k] = o.beta[k] * (o.A / dim * o.theta[k] * o.theta[k] +
                                    o.B * o.minv[k] * W[k]);
              return;
            }
        }
    }

    template <int dim>
    void
    FftOperator<dim>::damage(std::vector<double>      &d,
                             const DamageNormalisation normalisation)
    {
      Impl                        &o         = *impl;
      const typename Impl::Kernel &indicator = o.indicator();
      fftw_complex                *b = o.spectrum(1), *t = o.spectrum(2);
      std::vector<double>          count(o.N), D(o.N, double(o.offsets.size()));
      o.fill(b, [&](std::size_t k) { return o.beta[k]; });
      o.forward(b);
      o.multiply(t, indicator, b, 1., false);
      o.inverse(t);
      o.take(t, count);
      if (normalisation == DamageNormalisation::body)
        {
          o.fill(b, [&](std::size_t k) { return o.body(k); });
          o.forward(b);
          o.multiply(t, indicator, b, 1., false);
          o.inverse(t);
          o.take(t, D);
        }
      d.resize(o.N);
      const double none = 1e-9 * o.offsets.size();
      for (std::size_t k = 0; k < o.N; ++k)
        d[k] = o.body(k) == 0. ? 0. :
               D[k] > none     ? 1. - o.beta[k] * count[k] / D[k] :
                                 1. - o.beta[k];
    }

    template <int dim>
    const std::vector<double> &
    FftOperator<dim>::weighted_volume() const
    {
      if (this->material_.model != Model::lps)
        throw std::logic_error("FFT: the weighted volume is defined for LPS "
                               "only");
      // m = 1 / (1/m), made here only (the evaluations use 1/m)
      Impl &o = *impl;
      if (o.m.size() != o.N)
        {
          o.m.resize(o.N);
          for (std::size_t k = 0; k < o.N; ++k)
            o.m[k] = o.minv[k] != 0. ? 1. / o.minv[k] : 0.;
        }
      return o.m;
    }

    template <int dim>
    double
    FftOperator<dim>::bytes() const
    {
      const Impl &o       = *impl;
      double      reals   = 0.; // doubles held
      const auto  kernels = [&](const std::vector<typename Impl::Kernel> &ks) {
        for (const auto &k : ks)
          reals += double(k.s.size());
      };
      kernels(o.C);
      kernels(o.a);
      kernels(o.K);
      kernels(o.g);
      reals += double(o.c.s.size() + o.omega0.s.size() + o.reach.s.size());
      const auto fields = [&](const std::vector<std::vector<double>> &fs) {
        for (const auto &f : fs)
          reals += double(f.size());
      };
      fields(o.P);
      fields(o.q);
      fields({o.gb, o.beta, o.body_values, o.p, o.m, o.minv, o.theta});
      reals += double(o.body_bits.size()) / 8.; // chi_B as bytes
      reals += double(o.layer_bits.size() + o.layer_rank.size()); // layer
      reals += 2. * double(o.spectra.size()) * o.alloc;           // spectra
      reals += double(o.periodic_inverse.size());                 // G^-1
      return 8. * reals;
    }

    template <int dim>
    double
    FftOperator<dim>::bytes_per_node() const
    {
      return bytes() / double(std::max<std::size_t>(impl->N, 1));
    }

    template <int dim>
    std::size_t
    FftOperator<dim>::n_layer_nodes() const
    {
      return impl->n_layer;
    }

    template <int dim>
    const Slab &
    FftOperator<dim>::slab() const
    {
      return impl->slab;
    }

    template <int dim>
    std::size_t
    FftOperator<dim>::n_transforms() const
    {
      return impl->transforms;
    }

    template class FftOperator<2>;
    template class FftOperator<3>;
    template Slab
    local_slab(const Grid<2> &, MPI_Comm);
    template Slab
    local_slab(const Grid<3> &, MPI_Comm);
  } // namespace FFT
} // namespace pdfem
