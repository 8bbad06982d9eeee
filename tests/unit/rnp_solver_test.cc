// SPDX-License-Identifier: LGPL-2.1-or-later
// The RNP Newton solver (specs/000 §7, specs/001 §6): the 1D bar (A3/A4), its
// limit load under force control (A7/A8), displacement control and the arc
// length through the limit load, and the pre-cracked plate's reference run.
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/drivers/newton_driver.h>
#include <pdfem/mesh/cracks.h>
#include <pdfem/pd_models/rnp.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>

#include "rnp_test_lattice.h"
#include <gtest/gtest.h>

namespace
{
  using namespace pdfem;
  using Coupling::RNPSystem;
  using dealii::Point;
  using PDModels::RNPSettings;
  using test::lattice;

  /// The 1D bar of specs/001 §3.1: L = 16, m = 3, C = 4000, beta = 1,
  /// end volumes h/2, node 0 clamped, force F at the last node.
  struct Bar
  {
    Bar(const double h, const double C, const double F_max)
    {
      const unsigned int n = std::lround(16. / h) + 1;
      for (unsigned int i = 0; i < n; ++i)
        x.emplace_back(i * h);
      V.assign(n, h);
      V.front() = V.back() = 0.5 * h;
      s.C                  = C;
      s.beta               = 1.;
      s.horizon            = 3. * h;
      loads.constrained.assign(n, 0);
      loads.constrained[0] = 1;
      loads.prescribed     = [](double, std::vector<double> &u) { u[0] = 0.; };
      loads.external_force = [F_max](double t, std::vector<double> &f) {
        f.back() = t * F_max;
      };
    }
    std::vector<Point<1>> h_x;
    std::vector<Point<1>> x;
    std::vector<double>   V;
    RNPSettings           s;
    RNPSystem<1>::Loads   loads;
  };

  struct BarResult
  {
    double       interior_strain;
    double       end_strain;
    unsigned int iterations;
  };

  BarResult
  solve_bar(const double h, const double C)
  {
    Bar               bar(h, C, 40.);
    RNPSystem<1>      system(bar.x, bar.V, bar.s, {}, bar.loads);
    Drivers::Settings settings;
    settings.type               = "newton";
    settings.load_steps         = 1;
    settings.residual_tolerance = 1e-13;
    settings.max_iterations     = 10;
    Drivers::NewtonDriver            driver(settings);
    Drivers::SystemInterface::Vector u;
    system.initialize_vector(u);
    unsigned int iterations = 0;
    driver.run(
      system,
      u,
      [&](const Drivers::StepRecord &r) { iterations = r.newton_iterations; },
      &system);
    const unsigned int n       = bar.x.size();
    const double       quarter = u[(n - 1) / 4], three = u[3 * (n - 1) / 4];
    return {(three - quarter) / 8., u[n - 1] / 16., iterations};
  }

  TEST(RNPBar, InteriorStrainAndEndDisplacement)
  {
    // specs/001 A3/A4 (uncalibrated: lattice factor m/(m+1) = 3/4 and the
    // small nonlinearity of g), h = 0.5 and 0.25.
    const BarResult coarse = solve_bar(0.5, 4000.);
    EXPECT_NEAR(coarse.interior_strain, 7.5005e-3, 1e-4 * 7.5005e-3);
    EXPECT_NEAR(coarse.end_strain, 9.7792e-3, 1e-4 * 9.7792e-3);
    EXPECT_LE(coarse.iterations, 3u);
    const BarResult fine = solve_bar(0.25, 4000.);
    EXPECT_NEAR(fine.end_strain, 8.639e-3, 1e-4 * 8.639e-3);
    EXPECT_LE(fine.iterations, 3u);
    // discrete calibration C * m/(m+1): the classical strain F/(AE) = 0.01
    const BarResult calibrated = solve_bar(0.5, 3000.);
    EXPECT_NEAR(calibrated.interior_strain, 1.000117e-2, 1e-4 * 1e-2);
    EXPECT_NEAR(calibrated.end_strain, 1.30419e-2, 1e-4 * 1.30419e-2);
  }

  TEST(RNPBar, ForceControlEndsUnstableAtTheLimitLoad)
  {
    // specs/001 A7: the last stable load of the h = 0.5 bar is 598.9. Load
    // to 1000 in 10 steps, cuts by 1/4: the run must stop 'unstable' with
    // the limit load between the last stable and the failed load.
    Bar               bar(0.5, 4000., 1000.);
    RNPSystem<1>      system(bar.x, bar.V, bar.s, {}, bar.loads);
    Drivers::Settings settings;
    settings.type               = "newton";
    settings.load_steps         = 10;
    settings.residual_tolerance = 1e-10;
    settings.max_iterations     = 25;
    settings.max_step_cuts      = 4;
    settings.step_cut_factor    = 0.25;
    Drivers::NewtonDriver            driver(settings);
    Drivers::SystemInterface::Vector u;
    system.initialize_vector(u);
    std::string state;
    try
      {
        driver.run(
          system, u, [](const Drivers::StepRecord &) {}, &system);
      }
    catch (const RunFailure &e)
      {
        state = e.exit_state;
      }
    EXPECT_EQ(state, "unstable");
    const auto &out = driver.outcome();
    EXPECT_LE(1000. * out.last_stable_load, 598.9 * 1.001);
    EXPECT_GE(1000. * out.failure_load, 598.9 * 0.999);
    EXPECT_LT(1000. * (out.failure_load - out.last_stable_load), 1.);
    // the solution is the last stable state: positive definite tangent
    Drivers::SystemInterface::Vector r;
    system.residual(u, out.last_stable_load, r, true);
    EXPECT_TRUE(system.check_stability().stable());
    const auto d = system.damage(std::vector<double>(u.begin(), u.end()));
    EXPECT_GT(*std::max_element(d.begin(), d.end()), 1.);
  }

  TEST(RNPBar, DisplacementControlFlagsUnstableEquilibria)
  {
    // specs/001 A7/A8: the end displacement prescribed, the reaction peaks
    // at 599.0 (U = 2.83); past it Newton still converges, but to states
    // whose reduced tangent is indefinite: the driver must reject them and
    // stop 'unstable' near the peak.
    Bar                bar(0.5, 4000., 0.);
    const unsigned int n         = bar.x.size();
    bar.loads.constrained[n - 1] = 1;
    bar.loads.prescribed         = [n](double t, std::vector<double> &u) {
      u[0]     = 0.;
      u[n - 1] = 4. * t;
    };
    RNPSystem<1>      system(bar.x, bar.V, bar.s, {}, bar.loads);
    Drivers::Settings settings;
    settings.type               = "newton";
    settings.load_steps         = 20;
    settings.residual_tolerance = 1e-10;
    settings.max_iterations     = 25;
    settings.max_step_cuts      = 3;
    settings.step_cut_factor    = 0.25;
    Drivers::NewtonDriver            driver(settings);
    Drivers::SystemInterface::Vector u;
    system.initialize_vector(u);
    double      peak = 0.;
    std::string state;
    try
      {
        driver.run(
          system,
          u,
          [&](const Drivers::StepRecord &) {
            peak = std::max(peak, system.last_internal_force()[n - 1]);
          },
          &system);
      }
    catch (const RunFailure &e)
      {
        state = e.exit_state;
      }
    EXPECT_EQ(state, "unstable");
    EXPECT_GT(driver.outcome().n_unstable_states, 0u);
    EXPECT_NEAR(peak, 599.0, 0.005 * 599.0);
    EXPECT_NEAR(4. * driver.outcome().last_stable_load, 2.83, 0.1);
  }

  TEST(RNPPlate, PreCrackedPlateMatchesTheReferenceRun)
  {
    // specs/000 §7.6 and §7.11 (the independent re-run of §4.5): the
    // 76 x 76 lattice, h = 0.2, horizon 0.8, pre-crack (0, 7.5)--(7.5, 7.5);
    // C = 3e8, beta = 10; 208 nodes per side loaded by b_y = +-3.125e6
    // (one load step of 4e6 N), 32 clamped. Bond counts, and max damage and
    // max |u_y| of the first step in both force normalisations.
    std::vector<Point<2>> x;
    std::vector<double>   V;
    lattice<2>(76, 0.2, x, V);
    Mesh::Crack<2> crack;
    crack.points   = {{Point<2>(0., 7.5), Point<2>(7.5, 7.5)}};
    const auto cut = [crack](const Point<2> &a, const Point<2> &b) {
      return crack.cuts(a, b);
    };
    RNPSystem<2>::Loads loads;
    loads.constrained.assign(2 * x.size(), 0);
    std::vector<double> b(2 * x.size(), 0.);
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const bool bottom = x[i][1]<0.7, top = x[i][1]> 14.3;
        if ((bottom || top) && x[i][0] > 14.3)
          loads.constrained[2 * i] = loads.constrained[2 * i + 1] = 1;
        if ((bottom || top) && x[i][0] < 10.3)
          b[2 * i + 1] = (top ? 1. : -1.) * 3.125e6 * V[i];
      }
    EXPECT_EQ(std::count(loads.constrained.begin(),
                         loads.constrained.end(),
                         std::uint8_t(1)),
              64);
    EXPECT_EQ(std::count_if(b.begin(), b.end(), [](double v) { return v; }),
              416);
    loads.prescribed     = [](double, std::vector<double> &) {};
    loads.external_force = [b](double t, std::vector<double> &f) {
      for (std::size_t d = 0; d < f.size(); ++d)
        f[d] = t * b[d];
    };
    for (const auto scaling : {PDModels::RNPForceScaling::paper,
                               PDModels::RNPForceScaling::prototype})
      {
        RNPSettings s;
        s.C       = 3e8;
        s.beta    = 10.;
        s.horizon = 0.8;
        s.scaling = scaling;
        RNPSystem<2> system(x, V, s, cut, loads);
        EXPECT_EQ(system.n_bonds(), 131100u);
        EXPECT_EQ(system.n_cut_bonds(), 1498u);
        Drivers::Settings settings;
        settings.type               = "newton";
        settings.residual_tolerance = 1e-10;
        Drivers::NewtonDriver            driver(settings);
        Drivers::SystemInterface::Vector u;
        system.initialize_vector(u);
        unsigned int iterations = 0;
        driver.run(
          system,
          u,
          [&](const Drivers::StepRecord &r) {
            iterations = r.newton_iterations;
          },
          &system);
        EXPECT_LE(iterations, 4u);
        const std::vector<double> uu(u.begin(), u.end());
        const auto                d = system.damage(uu);
        const auto at = std::max_element(d.begin(), d.end()) - d.begin();
        double     uy = 0.;
        for (unsigned int i = 0; i < x.size(); ++i)
          uy = std::max(uy, std::abs(uu[2 * i + 1]));
        const bool paper = scaling == PDModels::RNPForceScaling::paper;
        EXPECT_NEAR(d[at], paper ? 0.1214 : 0.0906, 0.005 * d[at]);
        EXPECT_NEAR(uy, paper ? 0.19049 : 0.14150, 1e-4 * uy);
        EXPECT_NEAR(x[at][0], 7.4, 1e-9);
        EXPECT_NEAR(std::abs(x[at][1] - 7.5), 0.3, 1e-9);
      }
  }

  TEST(RNPBar, ArcLengthFollowsThePathThroughTheLimitLoad)
  {
    // The bar of ForceControlEndsUnstableAtTheLimitLoad with the load
    // factor as an unknown: the path passes the peak 598.9 (specs/001 A7)
    // and comes down on the softening branch, whose states are unstable
    // (measured: 598.2 at step 14, then 582, 484, 361, ... down to 2.4 at
    // step 30 with the end displacement still growing).
    Bar               bar(0.5, 4000., 1000.);
    RNPSystem<1>      system(bar.x, bar.V, bar.s, {}, bar.loads);
    Drivers::Settings settings;
    settings.type               = "newton";
    settings.load_steps         = 20;
    settings.residual_tolerance = 1e-10;
    settings.max_iterations     = 25;
    settings.max_step_cuts      = 6;
    Drivers::NewtonDriver            driver(settings);
    Drivers::SystemInterface::Vector u, q;
    system.initialize_vector(u);
    system.initialize_vector(q);
    q[bar.x.size() - 1] = 1000.;
    double       peak = 0., after = 1e300, u_end_at_peak = 0.;
    unsigned int n_unstable = 0, n_steps = 0;
    driver.run_arc_length(
      system,
      u,
      q,
      30,
      [&](const Drivers::StepRecord &r) {
        ++n_steps;
        if (r.load_factor > peak)
          {
            peak          = r.load_factor;
            u_end_at_peak = u[bar.x.size() - 1];
            after         = 1e300;
          }
        else
          after = std::min(after, r.load_factor);
      },
      &system,
      [&](const Drivers::StabilityReport &report) {
        n_unstable += !report.stable();
      });
    EXPECT_EQ(n_steps, 30u);
    EXPECT_NEAR(1000. * peak, 598.9, 0.005 * 598.9);
    EXPECT_LT(after, 0.9 * peak); // well down the softening branch
    EXPECT_GT(n_unstable, 0u);
    EXPECT_GT(u_end_at_peak, 0.);
  }
} // namespace
