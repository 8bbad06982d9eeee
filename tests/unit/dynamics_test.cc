// SPDX-License-Identifier: LGPL-2.1-or-later
// The dynamic drivers on a chain of springs and masses (no mesh): exact
// critical step, energy conservation, instability classification, the
// after-step hook (dissipated energy, refactorisation).
#include <pdfem/base/exceptions.h>
#include <pdfem/drivers/central_difference.h>
#include <pdfem/drivers/newmark.h>

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>

#include <gtest/gtest.h>

namespace
{
  using pdfem::Drivers::DynamicRecord;
  using Vector = pdfem::Drivers::SystemInterface::Vector;

  /**
   * n masses m in a chain, joined by springs k, the first one tied to a
   * wall (u_0 = 0 is the wall, not a DoF): K is the tridiagonal
   * k [2 -1; -1 2 -1; ...; -1 1]. ω_max^2 < 4 k / m, approached for large
   * n; for n = 1, ω^2 = k/m exactly. "Breaking" halves every spring.
   */
  class Chain : public pdfem::Drivers::DynamicSystemInterface
  {
  public:
    Chain(const unsigned int n, const double k, const double m)
      : n(n)
      , k(k)
      , owned(dealii::complete_index_set(n))
    {
      mass.reinit(owned, MPI_COMM_WORLD);
      mass = m;
    }
    void
    initialize_vector(Vector &v) const override
    {
      v.reinit(owned, MPI_COMM_WORLD);
    }
    void
    apply_dirichlet(Vector &, double) const override
    {}
    double
    residual(const Vector &, double, Vector &, bool) override
    {
      return 0.;
    }
    double
    force_scale() const override
    {
      return 0.;
    }
    unsigned int
    solve_linear(Vector &, const Vector &) override
    {
      return 0;
    }
    const Vector &
    lumped_mass() override
    {
      return mass;
    }
    void
    internal_force(const Vector &u, Vector &f) override
    {
      initialize_vector(f);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double left  = i == 0 ? 0. : u[i - 1];
          const double right = i + 1 < n ? u[i + 1] : u[i];
          f[i]               = k * ((u[i] - left) + (u[i] - right));
        }
    }
    void
    external_force(double, Vector &f) override
    {
      initialize_vector(f);
    }
    const std::vector<unsigned int> &
    held_dofs() const override
    {
      return held;
    }
    void
    factorize_effective(const double cm, const double ck, bool) override
    {
      // Solves by Jacobi iterations are enough here: K_N is diagonally
      // dominant for the small steps used.
      c_m = cm;
      c_k = ck;
      ++factorizations;
    }
    unsigned int
    solve_effective(Vector &x, const Vector &b) override
    {
      initialize_vector(x);
      Vector y;
      for (unsigned int it = 0; it < 200; ++it)
        {
          internal_force(x, y);
          for (unsigned int i = 0; i < n; ++i)
            {
              const double diagonal = c_m * mass[i] + c_k * 2. * k;
              const double off      = c_m * mass[i] * x[i] + c_k * y[i];
              x[i] += (b[i] - off) / diagonal;
            }
        }
      return 200;
    }
    void
    mass_vmult(Vector &y, const Vector &x) override
    {
      y = x;
      y.scale(mass);
    }
    double
    thickness() const override
    {
      return 1.;
    }
    void
    pseudo_random(Vector &x) const override
    {
      initialize_vector(x);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = std::sin(12345.678 * (i + 1));
    }

    unsigned int              n;
    double                    k;
    double                    c_m = 1., c_k = 0.;
    unsigned int              factorizations = 0;
    dealii::IndexSet          owned;
    Vector                    mass;
    std::vector<unsigned int> held;
  };

  pdfem::Drivers::Settings
  driver(const std::string &type, const double end_time)
  {
    pdfem::Drivers::Settings d;
    d.type     = type;
    d.end_time = end_time;
    return d;
  }

  struct Collect
  {
    std::vector<DynamicRecord> records;
    void
    operator()(const DynamicRecord &r)
    {
      records.push_back(r);
    }
  };
} // namespace

TEST(Dynamics, CriticalStepOfOneMassIsExact)
{
  // One mass on one spring: omega^2 = k/m, dt_crit = 2 sqrt(m/k).
  Chain  chain(1, 4e6, 1.);
  Vector u, v0;
  chain.initialize_vector(u);
  chain.initialize_vector(v0);
  v0[0] = 1.;
  pdfem::Drivers::CentralDifference cd(driver("explicit", 1.));
  Collect                           c;
  cd.run(chain, u, v0, std::ref(c));
  EXPECT_NEAR(cd.stability().critical_time_step, 2. / std::sqrt(4e6), 1e-15);
  EXPECT_NEAR(cd.time_step(), 0.9 * 1e-3, 1e-15);
  // At omega dt = 1.8 the whole-step energy of the mode oscillates (the
  // conserved one is 1/2 v^n+1/2 M v^n+1/2 + 1/2 u^n K u^n+1), but it does
  // not grow: the same range at the start and at the end of 100 periods.
  ASSERT_GT(c.records.size(), 1000u);
  const double e0    = c.records[0].kinetic_energy;
  auto         range = [&](const std::size_t from, const std::size_t to) {
    double top = 0.;
    for (std::size_t i = from; i < to; ++i)
      top =
        std::max(top, c.records[i].kinetic_energy + c.records[i].strain_energy);
    return top;
  };
  const std::size_t n = c.records.size();
  EXPECT_LT(range(0, 200), 6. * e0); // 1/cos^2(asin 0.9) = 5.3
  EXPECT_NEAR(range(n - 200, n), range(0, 200), 1e-2 * range(0, 200));
}

TEST(Dynamics, CentralDifferenceStableBelowAndStoppedAboveTheLimit)
{
  // 50 masses: omega_max^2 just below 4 k/m; the power iteration's
  // estimate is a lower bound close to it.
  const double k = 1e6, m = 2.;
  for (const double factor : {0.9, 1.2})
    {
      Chain  chain(50, k, m);
      Vector u, v0;
      chain.initialize_vector(u);
      chain.initialize_vector(v0);
      v0[49]          = 1.; // a kick at the free end excites every mode
      auto d          = driver("explicit", 2.);
      d.safety_factor = factor;
      pdfem::Drivers::CentralDifference cd(d);
      Collect                           c;
      const double                      omega_bound = std::sqrt(4. * k / m);
      if (factor < 1.)
        {
          cd.run(chain, u, v0, std::ref(c));
          EXPECT_LE(cd.stability().omega_max, omega_bound);
          EXPECT_GT(cd.stability().omega_max, 0.99 * omega_bound);
          EXPECT_GT(c.records.size(), 1000u);
        }
      else
        {
          try
            {
              cd.run(chain, u, v0, std::ref(c));
              ADD_FAILURE() << "1.2 dt_crit was not detected";
            }
          catch (const pdfem::RunFailure &e)
            {
              EXPECT_EQ(e.exit_state, "time step too large");
              EXPECT_NEAR(cd.instability().recommended_factor, 0.75, 1e-12);
              EXPECT_LT(c.records.size(), 100u);
            }
        }
    }
}

TEST(Dynamics, NewmarkConservesEnergyAndRefactorisesOnlyAfterBreaks)
{
  const double k = 1e6, m = 2.;
  Chain        chain(20, k, m);
  Vector       u, v0;
  chain.initialize_vector(u);
  chain.initialize_vector(v0);
  for (unsigned int i = 0; i < 20; ++i)
    v0[i] = 0.01 * (i + 1);
  auto d      = driver("newmark", 200 * 1e-4);
  d.time_step = 1e-4;
  pdfem::Drivers::Newmark nm(d);
  Collect                 c;
  // "Break" every spring to half its stiffness after step 100: the strain
  // energy released at fixed u is booked as dissipated.
  unsigned int calls      = 0;
  auto         after_step = [&](const Vector &, double) {
    if (++calls != 100)
      return false;
    chain.k *= 0.5;
    return true;
  };
  nm.run(chain, u, v0, std::ref(c), after_step);
  ASSERT_EQ(c.records.size(), 201u);
  EXPECT_EQ(nm.n_factorizations(), 2u); // once, and once after the break
  EXPECT_EQ(chain.factorizations, 2u);
  EXPECT_EQ(c.records[99].dissipated_energy, 0.);
  EXPECT_TRUE(c.records[100].bonds_broke);
  EXPECT_GT(c.records[100].dissipated_energy, 0.);
  EXPECT_NEAR(c.records[100].dissipated_energy,
              c.records[100].strain_energy,
              1e-9 * c.records[100].strain_energy); // half of it released
  for (const auto &r : c.records)
    EXPECT_LT(std::abs(r.energy_error), 1e-10);
}

TEST(Dynamics, CentralDifferenceBooksBrokenBondsAsDissipated)
{
  const double k = 1e6, m = 2.;
  Chain        chain(20, k, m);
  Vector       u, v0;
  chain.initialize_vector(u);
  chain.initialize_vector(v0);
  for (unsigned int i = 0; i < 20; ++i)
    v0[i] = 0.01 * (i + 1); // smooth: low modes, small O(dt^2) error
  auto d          = driver("explicit", 0.2);
  d.safety_factor = 0.5;
  pdfem::Drivers::CentralDifference cd(d);
  Collect                           c;
  unsigned int                      calls      = 0;
  auto                              after_step = [&](const Vector &, double) {
    if (++calls != 50)
      return false;
    chain.k *= 0.5;
    return true;
  };
  cd.run(chain, u, v0, std::ref(c), after_step);
  ASSERT_GT(c.records.size(), 100u);
  EXPECT_TRUE(c.records[50].bonds_broke);
  EXPECT_EQ(c.records[49].dissipated_energy, 0.);
  EXPECT_NEAR(c.records[50].dissipated_energy,
              c.records[50].strain_energy,
              1e-9 * c.records[50].strain_energy);
  // The balance holds across the break up to the O(dt^2) oscillation of a
  // stable central difference.
  for (const auto &r : c.records)
    EXPECT_LT(std::abs(r.energy_error), 2e-2);
}

TEST(Dynamics, GrowthBelowTheLimitIsReportedAsUnstableNotAsTheStep)
{
  // Negative springs: every mode of M a + K u = 0 grows like exp(|omega| t)
  // whatever the step; successive velocities are in phase. The run must
  // stop with "unstable" (a smaller dt would not help), not with "time step
  // too large".
  Chain  chain(10, -1e4, 1.);
  Vector u, v0;
  chain.initialize_vector(u);
  chain.initialize_vector(v0);
  v0[9]           = 1e-3;
  auto d          = driver("explicit", 10.);
  d.safety_factor = 0.1;
  pdfem::Drivers::CentralDifference cd(d);
  Collect                           c;
  try
    {
      cd.run(chain, u, v0, std::ref(c));
      ADD_FAILURE() << "the growth was not detected";
    }
  catch (const pdfem::RunFailure &e)
    {
      EXPECT_EQ(e.exit_state, "unstable");
      EXPECT_NE(std::string(e.what()).find(
                  "a smaller time step does not remove"),
                std::string::npos);
    }
}

TEST(Dynamics, CentralDifferenceConservesItsLeapfrogEnergyAcrossBreaks)
{
  // A kick at the free end excites every mode at 0.9 dt_crit: the energy
  // at whole steps oscillates by percent, the leapfrog energy balance
  // (energy_drift) stays at round-off, also after every spring loses half
  // its stiffness at step 500 (booked as dissipated at the old u^n).
  const double k = 1e6, m = 2.;
  Chain        chain(50, k, m);
  Vector       u, v0;
  chain.initialize_vector(u);
  chain.initialize_vector(v0);
  v0[49]          = 1.;
  auto d          = driver("explicit", 2.);
  d.safety_factor = 0.9;
  pdfem::Drivers::CentralDifference cd(d);
  Collect                           c;
  unsigned int                      calls      = 0;
  auto                              after_step = [&](const Vector &, double) {
    if (++calls != 500)
      return false;
    chain.k *= 0.5;
    return true;
  };
  cd.run(chain, u, v0, std::ref(c), after_step);
  ASSERT_GT(c.records.size(), 1000u);
  EXPECT_TRUE(c.records[500].bonds_broke);
  EXPECT_GT(c.records[500].dissipated_energy, 0.);
  double largest_error = 0., largest_drift = 0.;
  for (const auto &r : c.records)
    {
      largest_error = std::max(largest_error, std::abs(r.energy_error));
      largest_drift = std::max(largest_drift, std::abs(r.energy_drift));
    }
  EXPECT_GT(largest_error, 1e-3);
  EXPECT_LT(largest_drift, 1e-12);
  EXPECT_GT(largest_drift, 0.); // computed, not left at its initial 0
}
