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
          slab      = make_slab(grid, 0, grid.n[0]);
          N         = N_global;
          Nc        = N / row * cn[dim - 1];
          stride    = row;
          real_size = N;
          alloc     = Nc;
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
          alloc     = std::max<std::size_t>(l.alloc, 1);
          real_size = 2 * alloc;
        }

      real = fftw_alloc_real(real_size);
      spectrum(0);
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
            forward_plan = fftw_plan_dft_r2c(dim, n, real, spectra[0], flags);
            inverse_plan = fftw_plan_dft_c2r(dim, n, spectra[0], real, flags);
          }
        else
          {
            std::ptrdiff_t n[dim];
            for (unsigned int d = 0; d < dim; ++d)
              n[d] = grid.n[d];
            forward_plan = fftw_mpi_plan_dft_r2c(
              dim, n, real, spectra[0], comm, flags | FFTW_MPI_TRANSPOSED_OUT);
            inverse_plan = fftw_mpi_plan_dft_c2r(
              dim, n, spectra[0], real, comm, flags | FFTW_MPI_TRANSPOSED_IN);
          }
      }
      if (forward_plan == nullptr || inverse_plan == nullptr)
        throw std::runtime_error("FFTW could not make a plan");
      make_kernels();
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
      fftw_free(real);
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
    FftOperator<dim>::Impl::make_kernel(const F     &value,
                                        const bool   odd,
                                        const double scale)
    {
      // sampled on this rank's slab (a kernel is a function of the
      // periodic offset: each rank samples its own planes)
      std::memset(real, 0, real_size * sizeof(double));
      for (const auto &o : offsets)
        {
          std::array<unsigned int, dim> i;
          for (unsigned int d = 0; d < dim; ++d)
            i[d] = static_cast<unsigned int>((o.p[d] + int(grid.n[d])) %
                                             int(grid.n[d]));
          const std::size_t node = grid.node(i);
          if (!slab.contains(node))
            continue;
          const std::size_t k              = node - slab.begin;
          real[k / row * stride + k % row] = value(o);
        }
      fftw_complex *s = spectrum(0);
      forward(s);
      Kernel k;
      k.odd = odd;
      k.s.resize(Nc);
      // conj(k^) = k^ (even: real) or -i Im k^ (odd).
      for (std::size_t j = 0; j < Nc; ++j)
        k.s[j] = scale * (odd ? -s[j][1] : s[j][0]);
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
                  false,
                  scale));
            if (material.model == Model::linear_bond_based)
              break;
            for (unsigned int i = 0; i < dim; ++i)
              a.push_back(make_kernel(
                [&](const Offset<dim> &o) {
                  return alpha * omega(o) * o.xi[i] / (o.length * o.length);
                },
                true,
                scale));
            c = make_kernel(
              [&](const Offset<dim> &o) {
                return alpha * omega(o) / (o.length * o.length);
              },
              false,
              scale);
            break;
          case Model::lps:
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                K.push_back(make_kernel(
                  [&](const Offset<dim> &o) {
                    return omega(o) * o.xi[i] * o.xi[j] / (o.length * o.length);
                  },
                  false,
                  scale));
            for (unsigned int i = 0; i < dim; ++i)
              g.push_back(make_kernel(
                [&](const Offset<dim> &o) { return omega(o) * o.xi[i]; },
                true,
                scale));
            break;
        }
    }

    template <int dim>
    void
    FftOperator<dim>::Impl::correlate_symmetric(
      const std::vector<Kernel>        &kernels,
      const fftw_complex               *b,
      std::vector<std::vector<double>> &out)
    {
      out.resize(kernels.size());
      fftw_complex *t = spectrum(2);
      for (unsigned int s = 0; s < kernels.size(); ++s)
        {
          multiply(t, kernels[s], b, 1., false);
          inverse(t);
          take(out[s]);
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
      o.body = internal::mask_or_one(body_mask, N);
      o.beta = internal::mask_or_one(integrity, N);
      for (std::size_t k = 0; k < N; ++k)
        o.beta[k] *= o.body[k];

      fftw_complex *b = o.spectrum(1), *t = o.spectrum(2);
      o.fill([&](std::size_t k) { return o.beta[k]; });
      o.forward(b);
      if (this->material_.model != Model::lps)
        {
          o.correlate_symmetric(o.C, b, o.P);
          if (this->material_.model == Model::nonlinear_bond_based)
            {
              o.q.resize(dim);
              for (unsigned int i = 0; i < dim; ++i)
                {
                  o.multiply(t, o.a[i], b, 1., false);
                  o.inverse(t);
                  o.take(o.q[i]);
                }
              o.multiply(t, o.c, b, 1., false);
              o.inverse(t);
              o.take(o.p);
            }
          return;
        }

      // LPS: m = beta [omega |xi|^2 beta], gb_i = [g_i beta],
      // P_s = (1/m) [K_s beta] + [K_s (beta/m)].
      {
        const typename Impl::Kernel w = o.make_kernel(
          [&](const Offset<dim> &b_) {
            return this->material_.omega(b_.length) * b_.length * b_.length;
          },
          false,
          o.dV / o.N_global);
        o.multiply(t, w, b, 1., false);
      }
      o.inverse(t);
      o.m.resize(N);
      o.minv.resize(N);
      o.use([&](std::size_t k, double r) {
        o.m[k]    = o.beta[k] * r;
        o.minv[k] = o.m[k] != 0. ? 1. / o.m[k] : 0.;
      });
      o.gb.resize(dim);
      for (unsigned int i = 0; i < dim; ++i)
        {
          o.multiply(t, o.g[i], b, 1., false);
          o.inverse(t);
          o.take(o.gb[i]);
        }
      o.correlate_symmetric(o.K, b, o.P);
      o.fill([&](std::size_t k) { return o.beta[k] * o.minv[k]; });
      o.forward(b);
      for (unsigned int s = 0; s < o.K.size(); ++s)
        {
          o.multiply(t, o.K[s], b, 1., false);
          o.inverse(t);
          auto &P = o.P[s];
          o.use([&](std::size_t k, double r) { P[k] = o.minv[k] * P[k] + r; });
        }
      o.theta.assign(N, 0.);
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
      impl->lps_dilatation(u, false);
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
            o.quadratic_form(u, o.C, o.P, W);
            for (std::size_t k = 0; k < o.N; ++k)
              W[k] *= 0.5 * o.beta[k];
            return;
          case Model::nonlinear_bond_based:
            throw std::logic_error("FFT: no energy density for the nonlinear "
                                   "bond-based model yet");
          case Model::lps:
            {
              o.lps_dilatation(u, false);
              // [K_s beta] (P holds the combined variable-m field)
              std::vector<std::vector<double>> KB;
              fftw_complex                    *b = o.spectrum(dim + 1);
              o.fill([&](std::size_t k) { return o.beta[k]; });
              o.forward(b);
              o.correlate_symmetric(o.K, b, KB);
              o.quadratic_form(u, o.K, KB, W);
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
      Impl &o = *impl;
      if (!o.have_omega0)
        {
          o.omega0      = o.make_kernel([](const Offset<dim> &) { return 1.; },
                                   false,
                                   1. / o.N_global);
          o.have_omega0 = true;
        }
      fftw_complex       *b = o.spectrum(1), *t = o.spectrum(2);
      std::vector<double> count(o.N), D(o.N, double(o.offsets.size()));
      o.fill([&](std::size_t k) { return o.beta[k]; });
      o.forward(b);
      o.multiply(t, o.omega0, b, 1., false);
      o.inverse(t);
      o.take(count);
      if (normalisation == DamageNormalisation::body)
        {
          o.fill([&](std::size_t k) { return o.body[k]; });
          o.forward(b);
          o.multiply(t, o.omega0, b, 1., false);
          o.inverse(t);
          o.take(D);
        }
      d.resize(o.N);
      const double none = 1e-9 * o.offsets.size();
      for (std::size_t k = 0; k < o.N; ++k)
        d[k] = o.body[k] == 0. ? 0. :
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
      return impl->m;
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
      reals += double(o.c.s.size() + o.omega0.s.size());
      const auto fields = [&](const std::vector<std::vector<double>> &fs) {
        for (const auto &f : fs)
          reals += double(f.size());
      };
      fields(o.P);
      fields(o.q);
      fields(o.gb);
      fields({o.beta, o.body, o.p, o.m, o.minv, o.theta});
      reals += double(o.real_size);                     // real buffer
      reals += 2. * double(o.spectra.size()) * o.alloc; // spectra
      reals += double(o.periodic_inverse.size());       // G^-1
      return 8. * reals;
    }

    template <int dim>
    double
    FftOperator<dim>::bytes_per_node() const
    {
      return bytes() / double(std::max<std::size_t>(impl->N, 1));
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
