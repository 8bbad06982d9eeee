// SPDX-License-Identifier: LGPL-2.1-or-later
// PDLSM kernel: exactness of the Taylor fit, detection of degenerate
// families, and the analytic blocks (divergence and boundary traction)
// against central finite differences of the residual they linearise, for
// intact and damaged families.
#include <pdfem/pd_models/pdlsm.h>

#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

namespace
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  /// A jittered grid family of radius delta around the origin.
  template <int dim>
  void
  make_family(const double                 delta,
              const double                 h,
              std::vector<Tensor<1, dim>> &xi,
              std::vector<double>         &volume,
              const unsigned int           seed,
              const bool                   half = false)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> jitter(-0.2 * h, 0.2 * h);
    const int                              n = int(std::ceil(delta / h));
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = (dim == 3 ? -n : 0); k <= (dim == 3 ? n : 0); ++k)
          {
            Tensor<1, dim> p;
            p[0] = i * h + jitter(gen);
            p[1] = j * h + jitter(gen);
            if (dim == 3)
              p[dim - 1] = k * h + jitter(gen);
            if (p.norm() > delta || p.norm() < 1e-12 || (half && p[0] < 0.))
              continue;
            xi.push_back(p);
            volume.push_back(std::pow(h, dim) * (1. + 0.1 * jitter(gen) / h));
          }
  }

  template <int dim>
  void
  check_quadratic_exactness(const bool half)
  {
    const double                         h = 0.1, delta = 3.1 * h;
    std::vector<Tensor<1, dim>>          xi, a;
    std::vector<double>                  volume;
    std::vector<SymmetricTensor<2, dim>> b;
    make_family<dim>(delta, h, xi, volume, 7, half);
    const pdfem::PDModels::PDLSM<dim> pdlsm(1., 1., 0.33);
    ASSERT_TRUE(pdlsm.compute_weights(xi, volume, delta, a, b));

    // f(x) = g . x + 1/2 x . H x: the fit returns g and H exactly.
    Tensor<1, dim>          g;
    SymmetricTensor<2, dim> H;
    for (unsigned int i = 0; i < dim; ++i)
      {
        g[i] = 0.3 + i;
        for (unsigned int j = i; j < dim; ++j)
          H[i][j] = 1.7 - 0.4 * i + 0.9 * j;
      }
    Tensor<1, dim>          grad;
    SymmetricTensor<2, dim> hess;
    for (std::size_t m = 0; m < xi.size(); ++m)
      {
        const double df = g * xi[m] + 0.5 * xi[m] * (H * xi[m]);
        grad += df * a[m];
        hess += df * b[m];
      }
    for (unsigned int i = 0; i < dim; ++i)
      {
        EXPECT_NEAR(grad[i], g[i], 1e-11 * g.norm());
        for (unsigned int j = 0; j < dim; ++j)
          EXPECT_NEAR(hess[i][j], H[i][j], 1e-9 * H.norm());
      }
  }
} // namespace

TEST(PDLSM, ReproducesQuadraticFields2D)
{
  check_quadratic_exactness<2>(false);
}
TEST(PDLSM, ReproducesQuadraticFields3D)
{
  check_quadratic_exactness<3>(false);
}
TEST(PDLSM, ReproducesQuadraticFieldsOneSidedFamily2D)
{
  check_quadratic_exactness<2>(true);
}
TEST(PDLSM, ReproducesQuadraticFieldsOneSidedFamily3D)
{
  check_quadratic_exactness<3>(true);
}

TEST(PDLSM, DetectsFamiliesThatCannotCarryTheFit)
{
  const pdfem::PDModels::PDLSM<2>    pdlsm(1., 1., 0.33);
  std::vector<Tensor<1, 2>>          xi, a;
  std::vector<SymmetricTensor<2, 2>> b;
  // Collinear members: no information across the line.
  for (int i = 1; i <= 6; ++i)
    xi.push_back(Tensor<1, 2>({0.1 * i, 0.}));
  std::vector<double> volume(xi.size(), 0.01);
  EXPECT_FALSE(pdlsm.compute_weights(xi, volume, 0.6, a, b));
  // Too few members for five coefficients.
  xi = {Tensor<1, 2>({0.1, 0.}),
        Tensor<1, 2>({0., 0.1}),
        Tensor<1, 2>({0.1, 0.1})};
  volume.assign(3, 0.01);
  EXPECT_FALSE(pdlsm.compute_weights(xi, volume, 0.3, a, b));
}

namespace
{
  /**
   * The internal force of one PD node written from its definition,
   * independently of the analytic blocks:
   *   f(u) = -V sum_m G_m (u_m - u_k) + sigma(grad u_k) s,
   *   grad u_k = sum_m (u_m - u_k) (x) a_m,
   * and its Jacobian from divergence_block / traction_block, compared with
   * central differences of r.
   */
  template <int dim>
  void
  check_tangent(const bool damaged)
  {
    const double                         h = 0.1, delta = 3.05 * h;
    std::vector<Tensor<1, dim>>          xi, a;
    std::vector<double>                  volume;
    std::vector<SymmetricTensor<2, dim>> b;
    make_family<dim>(delta, h, xi, volume, 11);
    if (damaged) // break every bond crossing the plane x = 0.05
      for (std::size_t m = xi.size(); m-- > 0;)
        if (xi[m][0] > 0.05)
          {
            xi.erase(xi.begin() + m);
            volume.erase(volume.begin() + m);
          }
    const double E = 70e9, nu = 0.3;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));
    const pdfem::PDModels::PDLSM<dim> pdlsm(lambda, mu, 0.33);
    ASSERT_TRUE(pdlsm.compute_weights(xi, volume, delta, a, b));
    Tensor<1, dim> s;
    s[0]                  = 0.02;
    s[1]                  = -0.013; // a boundary node's area vector
    const double       Vk = 0.004;
    const unsigned int n  = xi.size() + 1; // owner first

    auto residual = [&](const std::vector<Tensor<1, dim>> &u) {
      Tensor<1, dim> L;
      Tensor<2, dim> grad;
      for (std::size_t m = 0; m < xi.size(); ++m)
        {
          const Tensor<1, dim> du = u[m + 1] - u[0];
          L += pdlsm.divergence_block(b[m]) * du;
          grad += dealii::outer_product(du, a[m]);
        }
      return Tensor<1, dim>(-Vk * L + pdlsm.stress(grad) * s);
    };

    std::mt19937                           gen(3);
    std::uniform_real_distribution<double> r(-1e-4, 1e-4);
    std::vector<Tensor<1, dim>>            u(n);
    for (auto &v : u)
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = r(gen);

    double max_error = 0., max_entry = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        // Analytic block d r / d u_j.
        Tensor<2, dim> K;
        if (j == 0)
          for (std::size_t m = 0; m < xi.size(); ++m)
            K +=
              Vk * pdlsm.divergence_block(b[m]) - pdlsm.traction_block(s, a[m]);
        else
          K = -Vk * pdlsm.divergence_block(b[j - 1]) +
              pdlsm.traction_block(s, a[j - 1]);
        // residual() is this node's f_int, so d f_int / d u_j = K.
        for (unsigned int c = 0; c < dim; ++c)
          {
            const double eps = 1e-7;
            auto         up = u, um = u;
            up[j][c] += eps;
            um[j][c] -= eps;
            const Tensor<1, dim> fd = (residual(up) - residual(um)) / (2 * eps);
            for (unsigned int i = 0; i < dim; ++i)
              {
                max_error = std::max(max_error, std::abs(fd[i] - K[i][c]));
                max_entry = std::max(max_entry, std::abs(K[i][c]));
              }
          }
      }
    EXPECT_LT(max_error, 1e-6 * max_entry);
    EXPECT_GT(max_entry, 0.);
  }
} // namespace

TEST(PDLSM, TangentMatchesFiniteDifferences2D)
{
  check_tangent<2>(false);
}
TEST(PDLSM, TangentMatchesFiniteDifferences3D)
{
  check_tangent<3>(false);
}
TEST(PDLSM, TangentMatchesFiniteDifferencesDamaged2D)
{
  check_tangent<2>(true);
}
TEST(PDLSM, TangentMatchesFiniteDifferencesDamaged3D)
{
  check_tangent<3>(true);
}
