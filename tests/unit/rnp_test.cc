// SPDX-License-Identifier: LGPL-2.1-or-later
// The RNP bond model (specs/000 §7): potential derivatives, the analytic
// tangent against central differences of the nodal forces (1D/2D/3D, intact,
// softened, cut bonds), the block structure, the patch test, the
// calibration, the band solver and the stability check. The Newton solver's
// runs (specs/001 §6) are in rnp_solver_test.cc.
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/mesh/cracks.h>
#include <pdfem/pd_models/rnp.h>
#include <pdfem/solvers/banded_ldlt.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <random>

#include "rnp_test_lattice.h"
#include <gtest/gtest.h>

namespace
{
  using namespace pdfem;
  using Coupling::RNPSystem;
  using Coupling::RNPTangent;
  using dealii::Point;
  using PDModels::RNPPotential;
  using PDModels::RNPSettings;
  using test::lattice;

  TEST(RNPPotential, DerivativesMatchCentralDifferences)
  {
    for (const double beta : {0.1, 1., 10.})
      for (const double C : {1., 3e8})
        {
          const RNPPotential g(C, beta);
          const double       rc = g.r_c();
          EXPECT_NEAR(rc, 1. / std::sqrt(2. * beta), 1e-15 * rc);
          EXPECT_NEAR(g.d2g(rc), 0., 1e-12 * 2. * C * beta);
          EXPECT_NEAR(g.dg(rc),
                      C * std::sqrt(2. * beta) * std::exp(-0.5),
                      1e-14 * C * std::sqrt(2. * beta));
          EXPECT_EQ(g.dg(0.), 0.);
          EXPECT_DOUBLE_EQ(g.d2g(0.), 2. * C * beta);
          for (int k = -30; k <= 30; ++k)
            {
              const double r = 0.1 * k * rc;
              EXPECT_DOUBLE_EQ(g.g(-r), g.g(r));
              const double h  = 1e-5 * rc;
              auto         fd = [&](auto f) {
                return (f(r + h) - f(r - h)) / (2. * h);
              };
              const double d1 = fd([&](double s) { return g.g(s); });
              const double d2 = fd([&](double s) { return g.dg(s); });
              const double d3 = fd([&](double s) { return g.d2g(s); });
              // relative to the size of each derivative on [-3rc, 3rc]
              EXPECT_NEAR(d1, g.dg(r), 1e-7 * g.dg(rc));
              EXPECT_NEAR(d2, g.d2g(r), 1e-7 * g.d2g(0.));
              EXPECT_NEAR(d3, g.d3g(r), 1e-7 * std::abs(g.d3g(0.5 * rc)) * 4.);
            }
        }
  }

  TEST(RNPCalibration, ModuliAndFractureEnergy)
  {
    using PDModels::RNPInfluence;
    // J = 1: 1D E = C beta, 2D E = 4 C beta / 9, 3D E = C beta / 4.
    EXPECT_DOUBLE_EQ(PDModels::rnp_c_beta(1., RNPInfluence::constant, 1, false),
                     1.);
    EXPECT_DOUBLE_EQ(PDModels::rnp_c_beta(4., RNPInfluence::constant, 2, false),
                     9.);
    EXPECT_DOUBLE_EQ(PDModels::rnp_c_beta(1., RNPInfluence::constant, 3, false),
                     4.);
    // 2D plane strain: lambda = mu = C beta / 6, E = 5 mu / 2.
    EXPECT_DOUBLE_EQ(PDModels::rnp_c_beta(5., RNPInfluence::constant, 2, true),
                     12.);
    // G_c: 1D C / 2, 2D 4 C / (3 pi), 3D 3 C / 8.
    EXPECT_DOUBLE_EQ(
      PDModels::rnp_c_from_fracture_energy(1., RNPInfluence::constant, 1), 2.);
    EXPECT_NEAR(PDModels::rnp_c_from_fracture_energy(1.,
                                                     RNPInfluence::constant,
                                                     2),
                3. * M_PI / 4.,
                1e-14);
    EXPECT_NEAR(PDModels::rnp_c_from_fracture_energy(3.,
                                                     RNPInfluence::constant,
                                                     3),
                8.,
                1e-14);
    // J = 1 - r: M_d = 1 / ((d+1)(d+2)).
    EXPECT_NEAR(PDModels::rnp_moment(RNPInfluence::linear, 2), 1. / 12., 1e-16);
  }

  /// Random u scaled so that the largest bond damage is @p target.
  template <int dim>
  std::vector<double>
  state(const RNPSystem<dim> &system, const double target, unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> dist(-1., 1.);
    std::vector<double>                    u(system.n_dofs());
    for (auto &v : u)
      v = dist(gen);
    const auto   d    = system.damage(u);
    const double dmax = *std::max_element(d.begin(), d.end());
    for (auto &v : u)
      v *= target / dmax;
    return u;
  }

  /// |K - K_fd|_F / |K|_F with K_fd the central differences of f_int.
  template <int dim>
  double
  tangent_error(const RNPSystem<dim> &system, const std::vector<double> &u)
  {
    std::vector<double> K;
    system.dense_tangent(u, K, RNPTangent::analytic);
    const unsigned int n     = system.n_dofs();
    double             scale = 0.;
    for (const double v : u)
      scale = std::max(scale, std::abs(v));
    const double        tau  = 1e-6 * scale;
    std::vector<double> w    = u, fp, fm;
    double              diff = 0., norm = 0.;
    for (unsigned int c = 0; c < n; ++c)
      {
        w[c] = u[c] + tau;
        system.internal_force(w, fp);
        w[c] = u[c] - tau;
        system.internal_force(w, fm);
        w[c] = u[c];
        for (unsigned int r = 0; r < n; ++r)
          {
            const double fd = (fp[r] - fm[r]) / (2. * tau);
            const double k  = K[std::size_t(r) * n + c];
            diff += (fd - k) * (fd - k);
            norm += k * k;
          }
      }
    return std::sqrt(diff / norm);
  }

  template <int dim>
  void
  check_tangent(const unsigned int n, const double m, const bool with_crack)
  {
    const double            h = 0.1;
    std::vector<Point<dim>> x;
    std::vector<double>     V;
    lattice<dim>(n, h, x, V);
    RNPSettings s;
    s.C       = 3.;
    s.beta    = 2.;
    s.horizon = m * h;
    std::function<bool(const Point<dim> &, const Point<dim> &)> cut;
    if constexpr (dim == 2)
      if (with_crack)
        {
          Mesh::Crack<2> crack;
          crack.points = {
            {Point<2>(-0.01, 0.5 * (n - 1) * h + 0.01),
             Point<2>(0.5 * (n - 1) * h, 0.5 * (n - 1) * h + 0.01)}};
          cut = [crack](const Point<2> &a, const Point<2> &b) {
            return crack.cuts(a, b);
          };
        }
    RNPSystem<dim> system(x, V, s, cut, {});
    if (with_crack)
      {
        EXPECT_GT(system.n_cut_bonds(), 0u);
      }
    for (const double target : {0.4, 2.5})
      {
        const std::vector<double> u = state(system, target, 7 + dim);
        const auto                d = system.damage(u);
        // softened: some bonds past the inflection point, some not
        if (target > 1.)
          {
            EXPECT_GT(std::count_if(d.begin(),
                                    d.end(),
                                    [](double v) { return v > 1.; }),
                      0);
          }
        const double error = tangent_error(system, u);
        EXPECT_LT(error, 1e-6) << dim << "D, max damage " << target;
        EXPECT_GT(error, 0.); // the comparison is not vacuous

        // structure: symmetric, block rows sum to zero (before constraints)
        std::vector<double> K, Kfd;
        system.dense_tangent(u, K, RNPTangent::analytic);
        const unsigned int N    = system.n_dofs();
        double             kmax = 0.;
        for (const double v : K)
          kmax = std::max(kmax, std::abs(v));
        for (unsigned int r = 0; r < N; ++r)
          {
            for (unsigned int c = 0; c < N; ++c)
              EXPECT_NEAR(K[r * N + c], K[c * N + r], 1e-13 * kmax);
            for (unsigned int q = 0; q < dim; ++q)
              {
                double sum = 0.;
                for (unsigned int k = 0; k < system.n_nodes(); ++k)
                  sum += K[r * N + dim * k + q];
                EXPECT_NEAR(sum, 0., 1e-12 * kmax);
              }
          }
        // the finite-difference tangent option agrees too
        system.dense_tangent(u, Kfd, RNPTangent::finite_difference);
        double diff = 0., norm = 0.;
        for (std::size_t e = 0; e < K.size(); ++e)
          {
            diff += (K[e] - Kfd[e]) * (K[e] - Kfd[e]);
            norm += K[e] * K[e];
          }
        EXPECT_LT(std::sqrt(diff / norm), 1e-6);

        // K v without assembling K (arc length under hard loading): against
        // the central difference of f_int along v, and against the dense K
        std::vector<double> v(N), Kv, fp, fm, w = u;
        double              scale = 0.;
        for (unsigned int k = 0; k < N; ++k)
          {
            v[k]  = std::sin(1.7 * k + 0.3);
            scale = std::max(scale, std::abs(u[k]));
          }
        system.tangent_product(u, v, Kv);
        const double tau = 1e-6 * scale;
        for (unsigned int k = 0; k < N; ++k)
          w[k] = u[k] + tau * v[k];
        system.internal_force(w, fp);
        for (unsigned int k = 0; k < N; ++k)
          w[k] = u[k] - tau * v[k];
        system.internal_force(w, fm);
        double diff_fd = 0., diff_dense = 0., norm_kv = 0.;
        for (unsigned int r = 0; r < N; ++r)
          {
            double dense = 0.;
            for (unsigned int c = 0; c < N; ++c)
              dense += K[r * N + c] * v[c];
            const double fd = (fp[r] - fm[r]) / (2. * tau);
            diff_fd += (fd - Kv[r]) * (fd - Kv[r]);
            diff_dense += (dense - Kv[r]) * (dense - Kv[r]);
            norm_kv += Kv[r] * Kv[r];
          }
        EXPECT_GT(norm_kv, 0.);
        EXPECT_LT(std::sqrt(diff_fd / norm_kv), 1e-6);
        EXPECT_LT(std::sqrt(diff_dense / norm_kv), 1e-12);
      }
  }

  TEST(RNPTangent, MatchesFiniteDifferences1D)
  {
    check_tangent<1>(12, 3., false);
  }
  TEST(RNPTangent, MatchesFiniteDifferences2D)
  {
    check_tangent<2>(7, 2.6, false);
  }
  TEST(RNPTangent, MatchesFiniteDifferences2DPreCrack)
  {
    check_tangent<2>(8, 2.6, true);
  }
  TEST(RNPTangent, MatchesFiniteDifferences3D)
  {
    check_tangent<3>(4, 1.8, false);
  }

  TEST(RNPTangent, MatchesFiniteDifferencesWithFiniteElements)
  {
    // An RNP region (x < 0.35) next to linear elements (the cells with
    // x >= 0.25), FE nodes as family members: bonds PD-FE act on both.
    const unsigned int    n = 7;
    std::vector<Point<2>> x;
    std::vector<double>   V;
    lattice<2>(n, 0.1, x, V);
    std::vector<std::uint8_t> pd(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      pd[i] = x[i][0] < 0.35;
    RNPSystem<2>::LinearElements           elements;
    std::mt19937                           gen(3);
    std::uniform_real_distribution<double> dist(-1., 1.);
    for (unsigned int j = 0; j + 1 < n; ++j)
      for (unsigned int i = 0; i + 1 < n; ++i)
        if (0.1 * i > 0.24)
          {
            const unsigned int        nodes[4] = {j * n + i,
                                                  j * n + i + 1,
                                                  (j + 1) * n + i,
                                                  (j + 1) * n + i + 1};
            std::vector<unsigned int> dofs;
            for (const unsigned int k : nodes)
              for (unsigned int c = 0; c < 2; ++c)
                dofs.push_back(2 * k + c);
            std::vector<double> A(64), K(64, 0.);
            for (auto &a : A)
              a = dist(gen);
            for (unsigned int r = 0; r < 8; ++r)
              for (unsigned int c = 0; c < 8; ++c)
                for (unsigned int k = 0; k < 8; ++k)
                  K[r * 8 + c] += 1e3 * A[k * 8 + r] * A[k * 8 + c];
            elements.dofs.push_back(dofs);
            elements.matrices.push_back(K);
          }
    RNPSettings s;
    s.C       = 3.;
    s.beta    = 2.;
    s.horizon = 0.26;
    for (const bool fe_members : {false, true})
      {
        RNPSystem<2> system(
          x, V, s, {}, {}, RNPTangent::analytic, pd, elements, fe_members);
        for (const double target : {0.4, 2.5})
          {
            const std::vector<double> u = state(system, target, 5);
            EXPECT_LT(tangent_error(system, u), 1e-6);
            std::vector<double> K, Kfd;
            system.dense_tangent(u, K, RNPTangent::analytic);
            system.dense_tangent(u, Kfd, RNPTangent::finite_difference);
            double diff = 0., norm = 0.;
            for (std::size_t e = 0; e < K.size(); ++e)
              {
                diff += (K[e] - Kfd[e]) * (K[e] - Kfd[e]);
                norm += K[e] * K[e];
              }
            EXPECT_LT(std::sqrt(diff / norm), 1e-6);
            // K v with the FE matrices included
            const unsigned int  N = system.n_dofs();
            std::vector<double> v(N), Kv;
            for (unsigned int k = 0; k < N; ++k)
              v[k] = std::cos(0.9 * k);
            system.tangent_product(u, v, Kv);
            double d2 = 0., n2 = 0.;
            for (unsigned int r = 0; r < N; ++r)
              {
                double dense = 0.;
                for (unsigned int c = 0; c < N; ++c)
                  dense += K[std::size_t(r) * N + c] * v[c];
                d2 += (dense - Kv[r]) * (dense - Kv[r]);
                n2 += dense * dense;
              }
            EXPECT_LT(std::sqrt(d2 / n2), 1e-12);
          }
        // the energy partition (bonds weighted by the mean PD share of their
        // nodes) keeps the tangent exact
        {
          std::vector<double> w(x.size());
          for (unsigned int i = 0; i < x.size(); ++i)
            w[i] = pd[i] ? (x[i][0] > 0.25 ? 0.5 : 1.) : 0.;
          RNPSystem<2> weighted(
            x, V, s, {}, {}, RNPTangent::analytic, pd, elements, fe_members, w);
          const std::vector<double> u = state(weighted, 2.5, 9);
          EXPECT_LT(tangent_error(weighted, u), 1e-6);
          // and it scales the bonds: f_int differs from the full bonds'
          std::vector<double> f_full, f_weighted;
          system.internal_force(u, f_full);
          weighted.internal_force(u, f_weighted);
          double diff = 0.;
          for (std::size_t k = 0; k < f_full.size(); ++k)
            diff = std::max(diff, std::abs(f_full[k] - f_weighted[k]));
          EXPECT_GT(diff, 0.);
        }
        // the PD-FE bonds exist only with FE members
        unsigned int fe_bonds = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          if (!pd[i])
            fe_bonds += system.family_size(i);
        EXPECT_EQ(fe_bonds > 0, fe_members);
      }
  }

  TEST(RNPSystem, AffineFieldLeavesInteriorNodesInEquilibrium)
  {
    // specs/000 §7.4: u = G x gives zero force at nodes farther than the
    // horizon from the boundary, in the nonlinear regime too.
    std::vector<Point<2>> x;
    std::vector<double>   V;
    lattice<2>(13, 0.1, x, V);
    RNPSettings s;
    s.C       = 1.;
    s.beta    = 1.;
    s.horizon = 0.3;
    RNPSystem<2>        system(x, V, s, {}, {});
    std::vector<double> u(system.n_dofs()), f;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        u[2 * i]     = 0.3 * x[i][0] + 0.2 * x[i][1];
        u[2 * i + 1] = -0.1 * x[i][0] + 0.4 * x[i][1];
      }
    const auto d = system.damage(u);
    EXPECT_GT(*std::max_element(d.begin(), d.end()), 0.1);
    system.internal_force(u, f);
    double boundary = 0.;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const bool interior =
          x[i][0] > 0.31 && x[i][0] < 0.89 && x[i][1] > 0.31 && x[i][1] < 0.89;
        for (unsigned int c = 0; c < 2; ++c)
          if (interior)
            EXPECT_NEAR(f[2 * i + c], 0., 1e-12 * 1e-2);
          else
            boundary = std::max(boundary, std::abs(f[2 * i + c]));
      }
    EXPECT_GT(boundary, 1e-4); // the surface effect is there
  }

  TEST(BandedLDLT, SolvesAndCountsNegativeEigenvalues)
  {
    // T = tridiag(-1, 2, -1) - sigma I (n = 50, stored with band 3): the
    // eigenvalues are 2 - 2 cos(k pi / 51) - sigma. Positive definite:
    // LAPACK's Cholesky; indefinite: the LDL^T, whose negative pivots count
    // the negative eigenvalues. Both must solve T x = b.
    const unsigned int n = 50;
    for (const double sigma : {-0.5, 0.013, 0.5, 1.7})
      {
        pdfem::Solvers::BandedLDLT T;
        T.reinit(n, 3);
        for (unsigned int i = 0; i < n; ++i)
          {
            T.add(i, i, 2. - sigma);
            if (i > 0)
              T.add(i, i - 1, -1.);
          }
        unsigned int expected = 0;
        for (unsigned int k = 1; k <= n; ++k)
          expected += 2. - 2. * std::cos(k * M_PI / (n + 1)) - sigma < 0.;
        ASSERT_TRUE(T.factorize());
        EXPECT_EQ(T.n_negative_pivots(), expected) << "sigma " << sigma;
        if (sigma > 0.) // the indefinite cases are indefinite
          {
            EXPECT_GT(expected, 0u);
          }
        std::vector<double> x(n);
        for (unsigned int i = 0; i < n; ++i)
          x[i] = std::sin(0.3 * i) + 1.;
        const std::vector<double> b = x;
        T.solve(x);
        for (unsigned int i = 0; i < n; ++i)
          {
            double Tx = (2. - sigma) * x[i];
            if (i > 0)
              Tx -= x[i - 1];
            if (i + 1 < n)
              Tx -= x[i + 1];
            EXPECT_NEAR(Tx, b[i], 1e-10 * (1. + std::abs(b[i])));
          }
      }
  }

  TEST(RNPSystem, NodeCutFreeByCracksIsHeld)
  {
    // A closed square crack around the centre node of a 5 x 5 lattice
    // (horizon 1.5 h) cuts all its bonds: it is held, K stays regular.
    std::vector<Point<2>> x;
    std::vector<double>   V;
    lattice<2>(5, 1., x, V);
    std::vector<Mesh::Crack<2>> square;
    const double                a = 0.5;
    const Point<2> c0(2. - a, 2. - a), c1(2. + a, 2. - a), c2(2. + a, 2. + a),
      c3(2. - a, 2. + a);
    for (const auto &[p, q] :
         {std::pair<Point<2>, Point<2>>{c0, c1}, {c1, c2}, {c2, c3}, {c3, c0}})
      {
        Mesh::Crack<2> crack;
        crack.points = {{p, q}};
        square.push_back(crack);
      }
    RNPSettings s;
    s.horizon = 1.5;
    RNPSystem<2>::Loads loads;
    loads.constrained.assign(2 * x.size(), 0);
    for (unsigned int i = 0; i < x.size(); ++i)
      if (x[i][0] == 0.)
        loads.constrained[2 * i] = loads.constrained[2 * i + 1] = 1;
    loads.prescribed = [](double, std::vector<double> &) {};
    RNPSystem<2> system(
      x,
      V,
      s,
      [&square](const Point<2> &p, const Point<2> &q) {
        return Mesh::cut_by_any<2>(square, p, q);
      },
      loads);
    EXPECT_EQ(system.n_decoupled_nodes(), 1u);
    EXPECT_EQ(system.family_size(12), 0u);
    Drivers::SystemInterface::Vector u, r;
    system.initialize_vector(u);
    system.residual(u, 1., r, true);
    EXPECT_TRUE(system.check_stability().stable());
  }

  TEST(RNPSystem, SoftenedBondMakesTheTangentIndefinite)
  {
    // Two nodes, one clamped: one bond past r_c has a negative stiffness.
    std::vector<Point<1>> x = {Point<1>(0.), Point<1>(1.)};
    RNPSettings           s;
    s.C       = 1.;
    s.beta    = 1.;
    s.horizon = 1.5;
    RNPSystem<1>::Loads loads;
    loads.constrained = {1, 0};
    RNPSystem<1>                     system(x, {1., 1.}, s, {}, loads);
    Drivers::SystemInterface::Vector u, r;
    system.initialize_vector(u);
    for (const double stretch : {0.5, 1.5})
      {
        u[1] = stretch * s.C / std::sqrt(2. * s.beta); // r = sqrt(1) S
        system.residual(u, 1., r, true);
        const auto report = system.check_stability();
        EXPECT_EQ(report.stable(), stretch < 1.);
        EXPECT_EQ(report.n_negative, stretch < 1. ? 0u : 1u);
      }
  }
} // namespace
