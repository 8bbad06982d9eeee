// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD operators by the direct neighbour sum on the uniform periodic grid:
// the reference for the FFT forms and their competitor in the benchmark.
#include <pdfem/fft/direct_operator.h>

#include <stdexcept>
#include <type_traits>

#include "fft_tools.h"

namespace pdfem
{
  namespace FFT
  {
    template <int dim>
    DirectOperator<dim>::DirectOperator(const Grid<dim>   &grid,
                                        const Material    &material,
                                        const unsigned int threads_)
      : Operator<dim>(grid, material)
      , threads(std::max(1u, threads_))
      , offsets(horizon_offsets(grid, material.horizon))
    {
      std::array<long long, dim> stride;
      stride[dim - 1] = 1;
      for (int d = dim - 2; d >= 0; --d)
        stride[d] = stride[d + 1] * grid.n[d + 1];
      reach.fill(0);
      for (const auto &o : offsets)
        {
          long long s = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              s += o.p[d] * stride[d];
              reach[d] = std::max<unsigned int>(reach[d], std::abs(o.p[d]));
            }
          step.push_back(s);
          xis.push_back(o.xi);
          // bond based: c = alpha omega / |xi|^2; LPS: omega
          const double w = material.omega(o.length);
          factor.push_back(material.model == Model::lps ?
                             w :
                             material.micromodulus * w / (o.length * o.length));
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          strides[d] = static_cast<std::size_t>(stride[d]);
          wrap[d].resize(grid.n[d] + 2 * reach[d]);
          for (unsigned int t = 0; t < wrap[d].size(); ++t)
            wrap[d][t] = (t + 2 * grid.n[d] - reach[d]) % grid.n[d];
        }
      set_masks({}, {});
    }

    template <int dim>
    template <typename Row>
    void
    DirectOperator<dim>::for_each_node(const Row &row) const
    {
      const Grid<dim> &grid = this->grid_;
      internal::parallel_for(threads,
                             grid.n_nodes(),
                             [&](std::size_t begin, std::size_t end) {
                               for (std::size_t k = begin; k < end; ++k)
                                 {
                                   const auto i       = grid.indices(k);
                                   bool       wrapped = false;
                                   for (unsigned int d = 0; d < dim; ++d)
                                     wrapped = wrapped || i[d] < reach[d] ||
                                               i[d] + reach[d] >= grid.n[d];
                                   row(k, i, wrapped);
                                 }
                             });
    }

    template <int dim>
    std::size_t
    DirectOperator<dim>::neighbour(const std::size_t                    node,
                                   const std::array<unsigned int, dim> &i,
                                   const bool                           wrapped,
                                   const unsigned int                   b) const
    {
      if (!wrapped)
        return node + step[b];
      // (i_d + p_d) mod n_d from a table: no division in the bond loop
      std::size_t j = 0;
      for (unsigned int d = 0; d < dim; ++d)
        j += strides[d] * wrap[d][i[d] + offsets[b].p[d] + reach[d]];
      return j;
    }

    template <int dim>
    std::size_t
    DirectOperator<dim>::padded_node(
      const std::array<unsigned int, dim> &i) const
    {
      std::size_t k = 0;
      for (unsigned int d = 0; d < dim; ++d)
        k = k * (this->grid_.n[d] + 2 * reach[d]) + i[d] + reach[d];
      return k;
    }

    template <int dim>
    template <typename F>
    void
    DirectOperator<dim>::pack(const unsigned int S, const F &value)
    {
      std::array<unsigned int, dim> np;
      std::size_t                   n_padded = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          np[d] = this->grid_.n[d] + 2 * reach[d];
          n_padded *= np[d];
        }
      packed.resize(S * n_padded);
      // padded index t_d holds node (t_d - reach_d) mod n_d
      for (std::size_t t = 0; t < n_padded; ++t)
        {
          std::size_t                   rest = t, node = 0;
          std::array<unsigned int, dim> td;
          for (int d = dim - 1; d >= 0; --d)
            {
              td[d] = rest % np[d];
              rest /= np[d];
            }
          for (unsigned int d = 0; d < dim; ++d)
            node += strides[d] * wrap[d][td[d]];
          value(node, &packed[S * t]);
        }
      bond_step.resize(offsets.size());
      for (unsigned int b = 0; b < offsets.size(); ++b)
        {
          long long step_b = 0, stride_d = 1;
          for (int d = dim - 1; d >= 0; --d)
            {
              step_b += offsets[b].p[d] * stride_d;
              stride_d *= np[d];
            }
          bond_step[b] = step_b * static_cast<long long>(S);
        }
    }

    template <int dim>
    void
    DirectOperator<dim>::set_masks(const std::vector<double> &body_mask,
                                   const std::vector<double> &integrity)
    {
      const std::size_t N = this->grid_.n_nodes();
      if ((!body_mask.empty() && body_mask.size() != N) ||
          (!integrity.empty() && integrity.size() != N))
        throw std::invalid_argument("FFT::DirectOperator::set_masks: a mask "
                                    "has the wrong size");
      body = internal::mask_or_one(body_mask, N);
      beta = internal::mask_or_one(integrity, N);
      for (std::size_t k = 0; k < N; ++k)
        beta[k] *= body[k];
      if (this->material_.model != Model::lps)
        return;
      // m(x) = beta sum' beta' omega |xi|^2 Delta V
      m.assign(N, 0.);
      const double dV = this->grid_.node_volume();
      for_each_node([&](std::size_t k, const auto &i, bool wrapped) {
        if (beta[k] == 0.)
          return;
        double s = 0.;
        for (unsigned int b = 0; b < offsets.size(); ++b)
          s += beta[neighbour(k, i, wrapped, b)] * factor[b] *
               offsets[b].length * offsets[b].length;
        m[k] = beta[k] * s * dV;
      });
    }

    template <int dim>
    void
    DirectOperator<dim>::apply(const std::vector<double> &u,
                               std::vector<double>       &force)
    {
      const std::size_t N = this->grid_.n_nodes();
      if (u.size() != dim * N)
        throw std::invalid_argument("FFT::DirectOperator::apply: u has the "
                                    "wrong size");
      force.assign(dim * N, 0.);
      const double dV    = this->grid_.node_volume();
      const Model  model = this->material_.model;
      double       A = 0., B = 0.;
      internal::lps_constants<dim>(this->material_, A, B);
      if (model == Model::lps)
        dilatation(u, theta_work);
      // u, beta (and for LPS theta / m and 1 / m) interleaved on the grid
      // padded by the horizon's reach: one cache line per neighbour, and
      // the same flat step for every node, periodic wrap included
      const unsigned int S = model == Model::lps ? dim + 3 : dim + 1;
      pack(S, [&](const std::size_t n, double *out) {
        for (unsigned int d = 0; d < dim; ++d)
          out[d] = u[d * N + n];
        out[dim] = beta[n];
        if (model == Model::lps)
          {
            const double mi = m[n] != 0. ? 1. / m[n] : 0.;
            out[dim + 1]    = theta_work[n] * mi;
            out[dim + 2]    = mi;
          }
      });
      // the model a compile-time constant of the bond loop
      std::vector<double> factor_2(offsets.size());
      for (unsigned int b = 0; b < offsets.size(); ++b)
        factor_2[b] = 1. / (offsets[b].length * offsets[b].length);
      const auto rows = [&](auto model_tag) {
        constexpr Model mt = decltype(model_tag)::value;
        for_each_node([&](std::size_t k, const auto &i, bool) {
          if (beta[k] == 0.)
            return;
          const double *wk = packed.data() + padded_node(i) * S;
          // two partial sums (even and odd bonds) halve the chains of
          // dependent additions
          double f2[2][dim] = {};
          for (unsigned int b = 0; b < offsets.size(); ++b)
            {
              double       *f  = f2[b & 1];
              const double *wj = wk + bond_step[b];
              const double  bj = wj[dim];
              if (bj == 0.)
                continue;
              const auto &xi = xis[b];
              double      eta[dim], xe = 0., ee = 0.;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  eta[d] = wj[d] - wk[d];
                  xe += xi[d] * eta[d];
                  ee += eta[d] * eta[d];
                }
              if constexpr (mt == Model::linear_bond_based)
                {
                  // C eta = c (xi.eta) xi
                  const double s = bj * factor[b] * xe;
                  for (unsigned int d = 0; d < dim; ++d)
                    f[d] += s * xi[d];
                }
              else if constexpr (mt == Model::nonlinear_bond_based)
                {
                  // c / 2 (2 xi.eta + eta.eta) (xi + eta)
                  const double s = bj * 0.5 * factor[b] * (2. * xe + ee);
                  for (unsigned int d = 0; d < dim; ++d)
                    f[d] += s * (xi[d] + eta[d]);
                }
              else
                {
                  // A omega xi (theta/m + theta'/m')
                  // + B omega (xi.eta) xi / |xi|^2 (1/m + 1/m')
                  const double s =
                    bj * factor[b] *
                    (A * (wk[dim + 1] + wj[dim + 1]) +
                     B * xe * factor_2[b] * (wk[dim + 2] + wj[dim + 2]));
                  for (unsigned int d = 0; d < dim; ++d)
                    f[d] += s * xi[d];
                }
            }
          for (unsigned int d = 0; d < dim; ++d)
            force[d * N + k] = beta[k] * (f2[0][d] + f2[1][d]) * dV;
        });
      };
      if (model == Model::linear_bond_based)
        rows(std::integral_constant<Model, Model::linear_bond_based>());
      else if (model == Model::nonlinear_bond_based)
        rows(std::integral_constant<Model, Model::nonlinear_bond_based>());
      else
        rows(std::integral_constant<Model, Model::lps>());
    }

    template <int dim>
    void
    DirectOperator<dim>::dilatation(const std::vector<double> &u,
                                    std::vector<double>       &theta)
    {
      if (this->material_.model != Model::lps)
        throw std::logic_error("FFT: the dilatation is defined for LPS only");
      const std::size_t N = this->grid_.n_nodes();
      if (u.size() != dim * N)
        throw std::invalid_argument("FFT::DirectOperator::dilatation: u has "
                                    "the wrong size");
      theta.assign(N, 0.);
      const double dV = this->grid_.node_volume();
      // theta = dim beta / m sum' beta' omega xi.eta Delta V
      constexpr unsigned int S = dim + 1;
      pack(S, [&](const std::size_t n, double *out) {
        for (unsigned int d = 0; d < dim; ++d)
          out[d] = u[d * N + n];
        out[dim] = beta[n];
      });
      for_each_node([&](std::size_t k, const auto &i, bool) {
        if (beta[k] == 0. || m[k] == 0.)
          return;
        const double *wk = packed.data() + padded_node(i) * S;
        double        s  = 0.;
        for (unsigned int b = 0; b < offsets.size(); ++b)
          {
            const double *wj = wk + bond_step[b];
            double        xe = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              xe += xis[b][d] * (wj[d] - wk[d]);
            s += wj[dim] * factor[b] * xe;
          }
        theta[k] = dim * beta[k] / m[k] * s * dV;
      });
    }

    template <int dim>
    void
    DirectOperator<dim>::energy_density(const std::vector<double> &u,
                                        std::vector<double>       &W)
    {
      const Model model = this->material_.model;
      if (model == Model::nonlinear_bond_based)
        throw std::logic_error("FFT: no energy density for the nonlinear "
                               "bond-based model yet");
      const std::size_t N = this->grid_.n_nodes();
      if (u.size() != dim * N)
        throw std::invalid_argument("FFT::DirectOperator::energy_density: u "
                                    "has the wrong size");
      double A = 0., B = 0.;
      internal::lps_constants<dim>(this->material_, A, B);
      if (model == Model::lps)
        dilatation(u, theta_work);
      W.assign(N, 0.);
      const double dV = this->grid_.node_volume();
      for_each_node([&](std::size_t k, const auto &i, bool wrapped) {
        if (beta[k] == 0.)
          return;
        // sum' beta' k(xi) (xi.eta)^2, k = c (bond based: eta.C eta) or
        // omega / |xi|^2 (LPS)
        double s = 0.;
        for (unsigned int b = 0; b < offsets.size(); ++b)
          {
            const std::size_t j  = neighbour(k, i, wrapped, b);
            double            xe = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              xe += offsets[b].xi[d] * (u[d * N + j] - u[d * N + k]);
            const double kb =
              model == Model::lps ?
                factor[b] / (offsets[b].length * offsets[b].length) :
                factor[b];
            s += beta[j] * kb * xe * xe;
          }
        if (model == Model::lps)
          {
            const double mi = m[k] != 0. ? 1. / m[k] : 0.;
            W[k]            = beta[k] *
                   (A / dim * theta_work[k] * theta_work[k] + B * mi * s * dV);
          }
        else
          W[k] = 0.5 * beta[k] * s * dV;
      });
    }

    template <int dim>
    void
    DirectOperator<dim>::damage(std::vector<double>      &d,
                                const DamageNormalisation normalisation)
    {
      const std::size_t N = this->grid_.n_nodes();
      d.assign(N, 0.);
      const double M    = double(offsets.size());
      const double none = 1e-9 * M;
      for_each_node([&](std::size_t k, const auto &i, bool wrapped) {
        if (body[k] == 0.)
          return;
        double count = 0., D = 0.;
        for (unsigned int b = 0; b < offsets.size(); ++b)
          {
            const std::size_t j = neighbour(k, i, wrapped, b);
            count += beta[j];
            D += body[j];
          }
        if (normalisation == DamageNormalisation::full_horizon)
          D = M;
        d[k] = D > none ? 1. - beta[k] * count / D : 1. - beta[k];
      });
    }

    template <int dim>
    const std::vector<double> &
    DirectOperator<dim>::weighted_volume() const
    {
      if (this->material_.model != Model::lps)
        throw std::logic_error("FFT: the weighted volume is defined for LPS "
                               "only");
      return m;
    }

    template <int dim>
    double
    DirectOperator<dim>::bytes_per_node() const
    {
      const double N      = double(this->grid_.n_nodes());
      const double fields = double(beta.size() + body.size() + m.size() +
                                   theta_work.size() + packed.size());
      const double bonds =
        double(offsets.size()) *
        (sizeof(Offset<dim>) + sizeof(long long) + sizeof(double));
      return (8. * fields + bonds) / N;
    }

    template <int dim>
    std::size_t
    DirectOperator<dim>::n_bonds_per_node() const
    {
      return offsets.size();
    }

    template class DirectOperator<2>;
    template class DirectOperator<3>;
  } // namespace FFT
} // namespace pdfem
