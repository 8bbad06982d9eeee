// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/pdlsm.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <sstream>

namespace pdfem
{
  namespace PDModels
  {
    using dealii::SymmetricTensor;
    using dealii::Tensor;

    namespace
    {
      /// Taylor basis p(s) in the order documented in PDLSM.
      template <int dim, std::size_t n>
      void
      basis(const Tensor<1, dim> &s, std::array<double, n> &p)
      {
        for (unsigned int i = 0; i < dim; ++i)
          {
            p[i]       = s[i];
            p[dim + i] = 0.5 * s[i] * s[i];
          }
        if constexpr (dim == 2)
          p[4] = s[0] * s[1];
        else
          {
            p[6] = s[0] * s[1];
            p[7] = s[1] * s[2];
            p[8] = s[2] * s[0];
          }
      }

      /**
       * Thin Householder QR of the column-major m x n matrix @p A (m >= n):
       * on return A holds the thin Q (m x n, column-major) and @p R the upper
       * triangle. Returns false if a diagonal entry of R is below
       * @p relative_tolerance times the largest column norm of A, i.e. the
       * columns are (numerically) dependent.
       */
      template <std::size_t n>
      bool
      thin_qr(std::vector<double>                  &A,
              const std::size_t                     m,
              std::array<std::array<double, n>, n> &R,
              const double                          relative_tolerance)
      {
        auto a = [&](std::size_t i, std::size_t j) -> double & {
          return A[j * m + i];
        };
        double max_column = 0.;
        for (std::size_t j = 0; j < n; ++j)
          {
            double c = 0.;
            for (std::size_t i = 0; i < m; ++i)
              c += a(i, j) * a(i, j);
            max_column = std::max(max_column, std::sqrt(c));
          }
        if (!(max_column > 0.))
          return false;
        std::vector<double>   v(m * n, 0.); // Householder vectors
        std::array<double, n> beta{};
        // H_k on rows and columns k.. of A: columns -= beta_k v_k (v_k^T
        // column), the sums of all columns in one pass over the rows, each
        // still summed in row order, so the result is the same bit for bit
        // as column by column. With the skipped zero columns of Q below:
        // compute_weights() 0.76 -> 0.57 CPU s on the peer's 3D box (14 637
        // families of 228 bonds, perf samples).
        const auto reflect = [&](const std::size_t k) {
          const double         *w = &v[k * m];
          std::array<double, n> dot{};
          for (std::size_t i = k; i < m; ++i)
            for (std::size_t j = k; j < n; ++j)
              dot[j] += w[i] * a(i, j);
          for (std::size_t j = k; j < n; ++j)
            dot[j] *= beta[k];
          for (std::size_t i = k; i < m; ++i)
            for (std::size_t j = k; j < n; ++j)
              a(i, j) -= dot[j] * w[i];
        };
        for (std::size_t k = 0; k < n; ++k)
          {
            double norm = 0.;
            for (std::size_t i = k; i < m; ++i)
              norm += a(i, k) * a(i, k);
            norm = std::sqrt(norm);
            if (!(norm > relative_tolerance * max_column))
              return false;
            const double alpha  = a(k, k) > 0. ? -norm : norm;
            double       vnorm2 = 0.;
            for (std::size_t i = k; i < m; ++i)
              {
                v[k * m + i] = a(i, k) - (i == k ? alpha : 0.);
                vnorm2 += v[k * m + i] * v[k * m + i];
              }
            beta[k] = vnorm2 > 0. ? 2. / vnorm2 : 0.;
            reflect(k);
          }
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < n; ++j)
            R[i][j] = j >= i ? a(i, j) : 0.;
        // Thin Q = H_0 ... H_{n-1} [I; 0].
        std::fill(A.begin(), A.end(), 0.);
        for (std::size_t j = 0; j < n; ++j)
          a(j, j) = 1.;
        // Columns j < k are still e_j there, zero in H_k's rows.
        for (std::size_t k = n; k-- > 0;)
          reflect(k);
        return true;
      }
    } // namespace

    void
    declare_weight_factor(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Weight factor",
                        "0.33",
                        dealii::Patterns::Double(),
                        "pdlsm, pdlsm energy: a in the weight omega = "
                        "exp(-(|xi|/(a delta))^2); a > 0 (typical: 1/3 for "
                        "quads, 1/4 for triangles).");
    }

    double
    parse_weight_factor(dealii::ParameterHandler &prm, const std::string &file)
    {
      const double a = prm.get_double("Weight factor");
      if (!(a > 0.))
        throw InputError(file,
                         "Peridynamics/Weight factor",
                         "a = " + number(a) + " is not positive",
                         "a > 0");
      return a;
    }

    template <int dim>
    void
    FitWorkspace<dim>::gather(const Region<dim> &region,
                              const std::size_t  o,
                              const bool         intact_only)
    {
      const PD::Families &f = *region.families;
      const auto         &x = *region.position;
      const unsigned int  k = f.owners[o];
      xi.clear();
      volume.clear();
      bond.clear();
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (!intact_only || f.intact[j])
          {
            xi.push_back(x[f.members[j]] - x[k]);
            volume.push_back((*region.volume)[f.members[j]]);
            bond.push_back(j);
          }
    }

    template <int dim>
    void
    fit_every_family(
      const Region<dim>                                           &region,
      const std::function<bool(std::size_t, FitWorkspace<dim> &)> &fit,
      const std::string                                           &fit_name,
      const double                                                 a,
      const std::string                                           &advice)
    {
      // Chunks of families on the threads, taken in increasing order by
      // each member: its first bad family is its lowest, and the lowest of
      // the members' is the one a loop over the families would name.
      // 3D box, 418 275 DoFs: the fits were 20 % of the set-up on one
      // thread (perf).
      const PD::Families            &f        = *region.families;
      const std::size_t              n_owners = f.owners.size();
      constexpr std::size_t          chunk    = 32;
      ThreadTeam                    &team     = ThreadTeam::shared();
      std::vector<FitWorkspace<dim>> workspace(team.size());
      std::vector<unsigned int>      member_bad(team.size(), 0);
      std::vector<std::size_t>       member_first(team.size(), n_owners);
      std::atomic<std::size_t>       next{0};
      team.run([&](const unsigned int member) {
        for (std::size_t first; (first = chunk * next++) < n_owners;)
          for (std::size_t o = first; o < std::min(first + chunk, n_owners);
               ++o)
            if (!fit(o, workspace[member]) && member_bad[member]++ == 0)
              member_first[member] = o;
      });
      unsigned int n_bad = 0;
      std::size_t  first = n_owners;
      for (unsigned int m = 0; m < team.size(); ++m)
        {
          n_bad += member_bad[m];
          first = std::min(first, member_first[m]);
        }
      std::ostringstream where;
      if (n_bad > 0)
        where << " (e.g. the node at (" << (*region.position)[f.owners[first]]
              << ") with " << f.offsets[first + 1] - f.offsets[first]
              << " members)";
      const unsigned int n_bad_total =
        dealii::Utilities::MPI::sum(n_bad, region.comm);
      if (n_bad_total > 0)
        throw InputError(region.source_file,
                         "Peridynamics/Horizon factor",
                         std::to_string(n_bad_total) +
                           " PD node(s) have too few effective family "
                           "members for the " +
                           fit_name + " with a = " + number(a) + where.str(),
                         advice);
    }

    template <int dim>
    PDLSM<dim>::PDLSM(const double lambda,
                      const double mu,
                      const double weight_factor)
      : lambda(lambda)
      , mu(mu)
      , weight_factor(weight_factor)
    {}

    template <int dim>
    bool
    PDLSM<dim>::compute_weights(const std::vector<Tensor<1, dim>>    &xi,
                                const std::vector<double>            &volume,
                                const double                          delta,
                                std::vector<Tensor<1, dim>>          &a,
                                std::vector<SymmetricTensor<2, dim>> &b) const
    {
      constexpr std::size_t n       = n_coefficients;
      const std::size_t     n_bonds = xi.size();
      a.resize(n_bonds);
      b.resize(n_bonds);
      if (n_bonds < n)
        return false;

      // Weighted least squares in s = xi / delta (entries O(1)):
      // minimise sum_m w_m (p(s_m) . D - df_m)^2, w_m = omega_m V_m.
      // With W^1/2 P = Q R (thin Householder QR) the fit is
      // D = R^-1 Q^T W^1/2 df, so the weight of bond m is
      // c_m = sqrt(w_m) R^-1 q_m (q_m: row m of Q). QR instead of the normal
      // equations keeps the error at cond(R) eps rather than cond(R)^2 eps,
      // which matters for one-sided families at corners, where the Gaussian
      // weights span many orders of magnitude.
      const double          inv_delta = 1. / delta;
      const double          inv_a2    = 1. / (weight_factor * weight_factor);
      std::vector<double>   A(n_bonds * n), sqrt_w(n_bonds);
      std::array<double, n> p;
      for (std::size_t m = 0; m < n_bonds; ++m)
        {
          const Tensor<1, dim> s = xi[m] * inv_delta;
          basis<dim, n>(s, p);
          sqrt_w[m] = std::sqrt(std::exp(-(s * s) * inv_a2) * volume[m]);
          for (std::size_t j = 0; j < n; ++j)
            A[j * n_bonds + m] = sqrt_w[m] * p[j];
        }
      std::array<std::array<double, n>, n> R;
      if (!thin_qr<n>(A, n_bonds, R, 1e-12))
        return false;

      // R^-1 q_m by back substitution, every bond at once (the bonds in
      // the inner loop: each bond's operations in the same order as one by
      // one, without waiting for each division in turn): 0.57 -> 0.49 CPU s
      // on the 3D box.
      for (std::size_t i = n; i-- > 0;)
        {
          double *c_i = &A[i * n_bonds];
          for (std::size_t k = i + 1; k < n; ++k)
            {
              const double  r_ik = R[i][k];
              const double *c_k  = &A[k * n_bonds];
              for (std::size_t m = 0; m < n_bonds; ++m)
                c_i[m] -= r_ik * c_k[m];
            }
          const double r_ii = R[i][i];
          for (std::size_t m = 0; m < n_bonds; ++m)
            c_i[m] /= r_ii;
        }
      const double inv_delta2 = inv_delta * inv_delta;
      for (std::size_t m = 0; m < n_bonds; ++m)
        {
          std::array<double, n> c;
          for (std::size_t j = 0; j < n; ++j)
            c[j] = A[j * n_bonds + m] * sqrt_w[m];
          for (unsigned int i = 0; i < dim; ++i)
            {
              a[m][i]    = c[i] * inv_delta;
              b[m][i][i] = c[dim + i] * inv_delta2;
            }
          if constexpr (dim == 2)
            b[m][0][1] = c[4] * inv_delta2;
          else
            {
              b[m][0][1] = c[6] * inv_delta2;
              b[m][1][2] = c[7] * inv_delta2;
              b[m][2][0] = c[8] * inv_delta2;
            }
        }
      return true;
    }

    template <int dim>
    Tensor<2, dim>
    PDLSM<dim>::divergence_block(const SymmetricTensor<2, dim> &b) const
    {
      Tensor<2, dim> G;
      const double   laplace = mu * dealii::trace(b);
      for (unsigned int i = 0; i < dim; ++i)
        {
          for (unsigned int j = 0; j < dim; ++j)
            G[i][j] = (lambda + mu) * b[i][j];
          G[i][i] += laplace;
        }
      return G;
    }

    template <int dim>
    Tensor<2, dim>
    PDLSM<dim>::traction_block(const Tensor<1, dim> &s,
                               const Tensor<1, dim> &a) const
    {
      Tensor<2, dim> T;
      const double   sa = s * a;
      for (unsigned int i = 0; i < dim; ++i)
        {
          for (unsigned int j = 0; j < dim; ++j)
            T[i][j] = lambda * s[i] * a[j] + mu * s[j] * a[i];
          T[i][i] += mu * sa;
        }
      return T;
    }

    template <int dim>
    SymmetricTensor<2, dim>
    PDLSM<dim>::stress(const Tensor<2, dim> &grad_u) const
    {
      const SymmetricTensor<2, dim> eps = dealii::symmetrize(grad_u);
      return lambda * dealii::trace(eps) *
               dealii::unit_symmetric_tensor<dim>() +
             2. * mu * eps;
    }

#define INSTANTIATE(dim)                                           \
  template struct FitWorkspace<dim>;                               \
  template class PDLSM<dim>;                                       \
  template void fit_every_family<dim>(                             \
    const Region<dim> &,                                           \
    const std::function<bool(std::size_t, FitWorkspace<dim> &)> &, \
    const std::string &,                                           \
    double,                                                        \
    const std::string &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem
