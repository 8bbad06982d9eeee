// SPDX-License-Identifier: LGPL-2.1-or-later
// The cell-list neighbour search finds exactly the families of the brute-force
// search, on random and graded point sets, with and without a member mask.
#include <pdfem/pd/families.h>

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace
{
  using pdfem::PD::Families;

  template <int dim>
  void
  expect_same_families(const std::vector<dealii::Point<dim>> &x,
                       const std::vector<double>             &horizon,
                       const std::vector<std::uint8_t>       &mask)
  {
    std::vector<unsigned int> owners;
    for (unsigned int k = 0; k < x.size(); k += 3) // every third node
      owners.push_back(k);
    const Families fast =
      pdfem::PD::find_families<dim>(x, horizon, owners, mask);
    const Families reference =
      pdfem::PD::find_families_brute_force<dim>(x, horizon, owners, mask);
    ASSERT_EQ(fast.offsets, reference.offsets);
    EXPECT_EQ(fast.members, reference.members);
    EXPECT_GT(fast.n_bonds(), owners.size()); // the test is not vacuous
  }

  template <int dim>
  std::vector<dealii::Point<dim>>
  random_points(const unsigned int n, const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> u(-1., 1.);
    std::vector<dealii::Point<dim>>        x(n);
    for (auto &p : x)
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = u(gen);
    return x;
  }
} // namespace

TEST(Families, RandomPointsUniformHorizon2D)
{
  const auto x = random_points<2>(2000, 1);
  expect_same_families<2>(x,
                          std::vector<double>(x.size(), 0.1),
                          std::vector<std::uint8_t>(x.size(), 1));
}

TEST(Families, RandomPointsUniformHorizon3D)
{
  const auto x = random_points<3>(3000, 2);
  expect_same_families<3>(x,
                          std::vector<double>(x.size(), 0.25),
                          std::vector<std::uint8_t>(x.size(), 1));
}

TEST(Families, GradedGridVariableHorizon2D)
{
  // A grid graded towards x = 0 (spacing grows 8x), horizon = 3 local
  // spacings: the paired rule (delta_k or delta_m) matters here.
  std::vector<dealii::Point<2>> x;
  std::vector<double>           horizon;
  const unsigned int            n = 40;
  for (unsigned int i = 0; i <= n; ++i)
    for (unsigned int j = 0; j <= n; ++j)
      {
        const double s = double(i) / n;
        x.emplace_back(s * s * s, double(j) / n);
        const double h = std::max(3. * s * s / n, 1e-3);
        horizon.push_back(3. * std::max(h, 1. / n * 0.1));
      }
  std::vector<std::uint8_t> mask(x.size(), 1);
  expect_same_families<2>(x, horizon, mask);
}

TEST(Families, GradedRandomWithMask3D)
{
  auto                      x = random_points<3>(2500, 3);
  std::vector<double>       horizon(x.size());
  std::vector<std::uint8_t> mask(x.size());
  for (unsigned int k = 0; k < x.size(); ++k)
    {
      horizon[k] = 0.1 + 0.2 * (x[k][0] + 1.); // 0.1 .. 0.5
      mask[k]    = k % 4 != 0;                 // some nodes never members
    }
  expect_same_families<3>(x, horizon, mask);
}

TEST(Families, PairedRuleIsSymmetric)
{
  // Two nodes with different horizons: each is in the other's family when
  // the distance is within the larger horizon.
  const std::vector<dealii::Point<2>> x       = {dealii::Point<2>(0., 0.),
                                                 dealii::Point<2>(1., 0.)};
  const std::vector<double>           horizon = {0.5, 1.5};
  const Families                      f       = pdfem::PD::find_families<2>(
    x, horizon, {0, 1}, std::vector<std::uint8_t>(2, 1));
  EXPECT_EQ(f.members, (std::vector<unsigned int>{1, 0}));
}

TEST(Families, NodesAtExactlyTheHorizonAreMembers)
{
  std::vector<dealii::Point<2>> x;
  for (int i = -4; i <= 4; ++i)
    x.emplace_back(0.1 * i, 0.);
  const Families f =
    pdfem::PD::find_families<2>(x,
                                std::vector<double>(x.size(), 0.4),
                                {4},
                                std::vector<std::uint8_t>(x.size(), 1));
  EXPECT_EQ(f.n_bonds(), 8u); // +-0.1 .. +-0.4, the ends included
}
