// SPDX-License-Identifier: LGPL-2.1-or-later
// The maximum circumferential tensile stress criterion (specs/004 §3.1 eq.
// 41-42).
#include <pdfem/fracture/crack_growth.h>

#include <cmath>

#include <gtest/gtest.h>

namespace
{
  using pdfem::Fracture::mcts_angle_and_keq;

  TEST(Mcts, PureModeIGrowsStraight)
  {
    const auto [theta, K_eq] = mcts_angle_and_keq(2e6, 0.);
    EXPECT_EQ(theta, 0.);
    EXPECT_DOUBLE_EQ(K_eq, 2e6);
  }

  TEST(Mcts, PureModeIIKinksBySeventyDegrees)
  {
    // theta_c = -2 atan(1 / sqrt(2)) = -70.53 degrees for K_II > 0, where
    // cos(theta/2) = sqrt(2/3), sin(theta) = -2 sqrt(2) / 3, so that
    // K_eq = -3/2 K_II cos(theta/2) sin(theta) = (2 / sqrt(3)) K_II.
    const double expected    = -2. * std::atan(1. / std::sqrt(2.));
    const auto [theta, K_eq] = mcts_angle_and_keq(0., 1e6);
    EXPECT_NEAR(theta, expected, 1e-12);
    EXPECT_NEAR(theta * 180. / M_PI, -70.5288, 1e-4);
    EXPECT_NEAR(K_eq / 1e6, 2. / std::sqrt(3.), 1e-12);
    // The opposite sign of K_II kinks the other way with the same K_eq.
    const auto [theta_minus, K_eq_minus] = mcts_angle_and_keq(0., -1e6);
    EXPECT_NEAR(theta_minus, -expected, 1e-12);
    EXPECT_NEAR(K_eq_minus, K_eq, 1e-6);
  }

  TEST(Mcts, AngleIsContinuousThroughPureModeI)
  {
    // theta_c -> -2 K_II / K_I as K_II -> 0: no jump between the branches.
    for (const double r : {1e-3, -1e-3})
      {
        const auto [theta, K_eq] = mcts_angle_and_keq(1., r);
        EXPECT_NEAR(theta, -2. * r, 1e-8);
        EXPECT_NEAR(K_eq, 1., 1e-5);
      }
  }

  TEST(Mcts, MaximisesTheHoopStress)
  {
    // sigma_thetatheta sqrt(2 pi r) = cos(t/2) [K_I cos^2(t/2) - 3/2 K_II
    // sin t]: the kink angle is its maximum and K_eq its value there.
    const double K_I = 1.3e6, K_II = 0.7e6;
    const auto   hoop = [&](const double t) {
      const double c = std::cos(0.5 * t);
      return c * (K_I * c * c - 1.5 * K_II * std::sin(t));
    };
    const auto [theta, K_eq] = mcts_angle_and_keq(K_I, K_II);
    EXPECT_NEAR(K_eq, hoop(theta), 1e-6);
    for (double t = -M_PI + 1e-3; t < M_PI; t += 1e-3)
      EXPECT_LE(hoop(t), K_eq * (1. + 1e-12));
  }
} // namespace
