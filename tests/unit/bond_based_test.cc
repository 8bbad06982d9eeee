// SPDX-License-Identifier: LGPL-2.1-or-later
// The bond-based model with smooth degradation (pd_models/bond_based.h,
// specs/003 §1, §3):
// - the degradation T(s) and T'(s) at the values specs/003 §7 lists;
// - the micromoduli of specs/003 §1.2;
// - one bond's stiffness = central differences of its force, 2D and 3D,
//   for intact, degrading and compressed bonds;
// - the model's tangent rows = central differences of its force rows on a
//   plate whose bonds are intact, degrading and compressed, with and
//   without broken bonds, loading and unloading (after a committed state),
//   and the matrix-free tangent_products() = those rows times a vector;
// - the history: committed stretches keep bonds softened, bonds past s_c
//   are reported failed, a reversible model forgets.
#include <pdfem/base/exceptions.h>
#include <pdfem/pd_models/bond_based.h>

#include <cmath>
#include <random>

#include "pd_models_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;
  using PDModels::BondBasedBond;
  using PDModels::BondDegradation;

  BondDegradation
  degradation(const double s_m, const double s_c, const double beta = 3.)
  {
    BondDegradation d;
    d.active   = true;
    d.onset    = s_m;
    d.critical = s_c;
    d.rate     = beta;
    return d;
  }

  TEST(BondBased, DegradationHasThePapersValues)
  {
    const BondDegradation T = degradation(0.01, 0.02);
    EXPECT_NEAR(T.factor(0.01 + 1e-14), 0.997527, 1e-6);
    EXPECT_NEAR(T.factor(0.02 - 1e-14), 0.002473, 1e-6);
    EXPECT_NEAR(T.factor(0.015), 0.5, 1e-14);
    EXPECT_EQ(T.factor(0.01), 1.);
    EXPECT_EQ(T.factor(-1.), 1.);
    EXPECT_EQ(T.factor(0.02), 0.);
    EXPECT_EQ(T.derivative(0.005), 0.);
    EXPECT_EQ(T.derivative(0.03), 0.);
    // T' peaks at beta / (s_m - s_c) at the midpoint.
    EXPECT_NEAR(T.derivative(0.015), 3. / (0.01 - 0.02), 1e-10);
    for (const double s : {0.0105, 0.012, 0.015, 0.0177, 0.0199})
      {
        const double h  = 1e-9;
        const double fd = (T.factor(s + h) - T.factor(s - h)) / (2. * h);
        EXPECT_NEAR(T.derivative(s), fd, 1e-7 * std::abs(T.derivative(s))) << s;
      }
    BondDegradation none;
    EXPECT_EQ(none.factor(10.), 1.);
    EXPECT_EQ(none.derivative(10.), 0.);
  }

  TEST(BondBased, MicromoduliAreThoseOfTheSpec)
  {
    // specs/003 §1.2 (c per unit volume; pdfem's 2D c is per unit
    // thickness, the paper's c times its thickness h = dx).
    EXPECT_NEAR(PDModels::bond_based_micromodulus(2e11, 0.03015, 3, false),
                9.2451e17,
                1e-4 * 9.2451e17);
    EXPECT_NEAR(PDModels::bond_based_micromodulus(2e11, 0.015075, 2, false) /
                  0.005,
                3.3449e19,
                1e-4 * 3.3449e19);
    EXPECT_NEAR(PDModels::bond_based_micromodulus(192e9, 3.015e-3, 2, false) /
                  1e-3,
                2.0069e22,
                1e-4 * 2.0069e22);
    EXPECT_NEAR(PDModels::bond_based_micromodulus(1., 1., 2, true) /
                  PDModels::bond_based_micromodulus(1., 1., 2, false),
                48. / 45.,
                1e-15);
  }

  TEST(BondBased, BarMicromodulusIsTwoEOverADeltaSquared)
  {
    // specs/003 §1.2, §7 item 1: the 1D bar's c = 2 E / (A delta^2) (the
    // paper's pi is a typo), case A: E = 2e11 Pa, A = 1e-6 m^2, delta =
    // 3.015 dx over the paper's spacings.
    for (const double dx : {0.1, 0.01, 1e-3, 1e-4, 5e-5})
      {
        const double delta    = 3.015 * dx;
        const double expected = 2. * 2e11 / (1e-6 * delta * delta);
        EXPECT_NEAR(PDModels::bond_based_bar_micromodulus(2e11, delta, 1e-6),
                    expected,
                    1e-12 * expected);
      }

    // The model with Body = uniaxial bar on a strip one cell h tall: each
    // line of nodes is a bar of A = h/2 (per unit thickness), so c =
    // 2 E / (h/2 delta^2); only its bonds along x act, so at u = 0 every
    // tangent block is axial (the bonds across the strip carry nothing,
    // the bonds along x nothing in y).
    auto model =
      make_model("bond based", {{"Bond based/Body", "uniaxial bar"}});
    const double                       h = 0.05, E = 2e11;
    parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {20, 1},
                                              Point<2>(0., 0.),
                                              Point<2>(1., h));
    Coupling::Settings<2> settings;
    settings.material.youngs_modulus = E;
    settings.material.poissons_ratio = 0.;
    settings.material.plane_stress   = true;
    settings.horizon_factor          = 3.015;
    settings.pd_model                = model;
    settings.linear_solver.type      = "direct";
    Coupling::CoupledSystem<2> system(
      tria, std::vector<bool>(tria.n_active_cells(), true), settings);
    double c = 0.;
    for (const auto &[name, value] : model->constants())
      if (name == "micromodulus")
        c = value;
    const double delta    = 3.015 * h,
                 expected = 2. * E / (0.5 * h * delta * delta);
    EXPECT_NEAR(c, expected, 1e-12 * expected);

    Field<>                   u(system.size().n_nodes);
    std::vector<Tensor<2, 2>> blocks;
    double                    axial = 0., other = 0.;
    std::size_t               n_axial = 0, n_along_x = 0, n_bonds = 0;
    const PD::Families       &f = system.families();
    for (std::size_t o = 0; o < f.owners.size(); ++o)
      {
        model->tangent_row(o, u.field(), blocks);
        ASSERT_EQ(blocks.size(), 1 + f.offsets[o + 1] - f.offsets[o]);
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          {
            ++n_bonds;
            n_along_x += system.node_position(f.members[j])[1] ==
                         system.node_position(f.owners[o])[1];
            n_axial += blocks[1 + j - f.offsets[o]][0][0] != 0.;
          }
        for (const auto &B : blocks)
          {
            axial = std::max(axial, std::abs(B[0][0]));
            other = std::max(
              {other, std::abs(B[0][1]), std::abs(B[1][0]), std::abs(B[1][1])});
          }
      }
    EXPECT_GT(axial, 0.);
    EXPECT_EQ(other, 0.);
    // Exactly the bonds along x are stiff; the strip has bonds across too.
    EXPECT_EQ(n_axial, n_along_x);
    EXPECT_LT(n_along_x, n_bonds);
  }

  /// max |dt/du_m - central differences of t(eta)| / max |dt/du_m| for
  /// one bond with reversible degradation T(s(eta)).
  template <int dim>
  double
  bond_tangent_error(const Tensor<1, dim>  &xi,
                     const Tensor<1, dim>  &eta,
                     const BondDegradation &T)
  {
    const double c     = 2.5e3;
    const auto   force = [&](const Tensor<1, dim> &e) {
      return BondBasedBond<dim>::force(
        xi, e, c * T.factor(BondBasedBond<dim>::stretch(xi, e)));
    };
    const double         s = BondBasedBond<dim>::stretch(xi, eta);
    const Tensor<2, dim> K =
      BondBasedBond<dim>::stiffness(xi, eta, c, T.factor(s), T.derivative(s));
    const double h     = 1e-7 * xi.norm();
    double       error = 0.;
    for (unsigned int q = 0; q < dim; ++q)
      {
        Tensor<1, dim> step;
        step[q] = h;
        const Tensor<1, dim> dfd =
          (force(eta + step) - force(eta - step)) / (2. * h);
        for (unsigned int p = 0; p < dim; ++p)
          error = std::max(error, std::abs(dfd[p] - K[p][q]));
      }
    return error / K.norm();
  }

  template <int dim>
  void
  check_bond_tangents()
  {
    const BondDegradation            T = degradation(0.01, 0.05);
    std::mt19937                     random(11);
    std::normal_distribution<double> normal;
    unsigned int count[3] = {0, 0, 0}; // compressed, intact, degrading
    for (unsigned int trial = 0; trial < 300; ++trial)
      {
        Tensor<1, dim> xi, direction;
        for (unsigned int d = 0; d < dim; ++d)
          {
            xi[d]        = normal(random);
            direction[d] = normal(random);
          }
        // A stretch in [-0.05, 0.06] and a rotation of the bond.
        const double   target = -0.05 + 0.11 * (trial % 100) / 99.;
        Tensor<1, dim> eta    = target * xi + 0.02 * xi.norm() * direction;
        const double   s      = BondBasedBond<dim>::stretch(xi, eta);
        if (std::abs(s - T.onset) < 1e-5 || std::abs(s - T.critical) < 1e-5 ||
            s >= T.critical)
          continue; // the kinks of T, or no force at all
        ++count[s < 0. ? 0 : (s <= T.onset ? 1 : 2)];
        EXPECT_LT(bond_tangent_error(xi, eta, T), 1e-6)
          << dim << "D, stretch " << s;
      }
    for (const unsigned int n : count)
      EXPECT_GT(n, 10u);
  }

  TEST(BondBased, BondStiffnessIsCentralDifferencesOfTheBondForce)
  {
    check_bond_tangents<2>();
    check_bond_tangents<3>();
  }

  std::shared_ptr<PDModels::Interface<2>>
  make_bond_based(const std::string &history = "irreversible")
  {
    return make_model("bond based",
                      {{"Bond based/Degradation", "tanh"},
                       {"Bond based/Onset stretch", "0.004"},
                       {"Bond based/Critical stretch", "0.04"},
                       {"Bond based/Damage history", history}});
  }

  /// How many intact bonds of @p f are compressed, below s_m, degrading
  /// (s_m < s < s_c) and past s_c at @p u.
  std::array<unsigned int, 4>
  stretch_census(const Coupling::CoupledSystem<2> &system,
                 const PD::Families               &f,
                 const Field<>                    &u)
  {
    std::array<unsigned int, 4> n{{0, 0, 0, 0}};
    const auto                  field = u.field();
    for (std::size_t o = 0; o < f.owners.size(); ++o)
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (f.intact[j])
          {
            const unsigned int k = f.owners[o], m = f.members[j];
            const double       s =
              BondBasedBond<2>::stretch(system.node_position(m) -
                                          system.node_position(k),
                                        field[m] - field[k]);
            ++n[s < 0. ? 0 : s <= 0.004 ? 1 : s < 0.04 ? 2 : 3];
          }
    return n;
  }

  /// max |tangent_products(u, v) - tangent rows times v| relative to the
  /// largest product, at a random v: the matrix-free products apply the
  /// rows that the central differences check.
  double
  products_error(const PDModels::Interface<2> &model,
                 const PD::Families           &f,
                 const Field<>                &u)
  {
    const std::size_t                      n = f.owners.size();
    Field<>                                v(u.values.size() / 2);
    std::mt19937                           random(5);
    std::uniform_real_distribution<double> value(-1., 1.);
    for (double &x : v.values)
      x = value(random);
    std::vector<double> products(2 * n);
    model.tangent_products(0, n, u.field(), v.field(), products.data());
    std::vector<Tensor<2, 2>> blocks;
    double                    error = 0., scale = 0.;
    for (std::size_t o = 0; o < n; ++o)
      {
        model.tangent_row(o, u.field(), blocks);
        Tensor<1, 2> Kv = blocks[0] * v.field()[f.owners[o]];
        std::size_t  b  = 0;
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            Kv += blocks[++b] * v.field()[f.members[j]];
        for (unsigned int c = 0; c < 2; ++c)
          {
            error = std::max(error, std::abs(products[2 * o + c] - Kv[c]));
            scale = std::max(scale, std::abs(Kv[c]));
          }
      }
    return error / scale;
  }

  TEST(BondBased, TangentRowsAreCentralDifferencesOfTheForceRows)
  {
    for (const bool broken : {false, true})
      {
        auto  model = make_bond_based();
        Plate plate(model, 0.6); // PD left of x = 0.6, FE right of it
        if (broken)
          break_some_bonds(*plate.system);
        const auto &f = plate.system->families();
        Field<>     u(plate.system->size().n_nodes);
        deform(*plate.system, u, 4e-3);
        const auto census = stretch_census(*plate.system, f, u);
        EXPECT_GT(census[0], 50u); // compressed
        EXPECT_GT(census[1], 50u); // intact
        EXPECT_GT(census[2], 50u); // degrading
        EXPECT_LT(tangent_error(*model, f, u, 1e-9), 1e-6)
          << (broken ? "with broken bonds" : "");
        EXPECT_LT(products_error(*model, f, u), 1e-12)
          << (broken ? "with broken bonds" : "");

        // After a committed state 1.5 times larger, the bonds unload (no
        // T' term) and keep the softening of their largest stretch.
        Field<> larger = u;
        for (double &v : larger.values)
          v *= 1.5;
        model->commit_state(larger.field());
        EXPECT_LT(tangent_error(*model, f, u, 1e-9), 1e-6)
          << "unloading" << (broken ? ", with broken bonds" : "");
        EXPECT_LT(products_error(*model, f, u), 1e-12)
          << "unloading" << (broken ? ", with broken bonds" : "");
      }
  }

  TEST(BondBased, HistoryKeepsSofteningAndFailsBondsPastTheCriticalStretch)
  {
    for (const std::string history : {"irreversible", "reversible"})
      {
        auto        model = make_bond_based(history);
        Plate       plate(model);
        const auto &f = plate.system->families();
        Field<>     u(plate.system->size().n_nodes);
        deform(*plate.system, u, 0.03);
        const auto census = stretch_census(*plate.system, f, u);
        EXPECT_GT(census[3], 10u); // past s_c
        model->commit_state(u.field());
        unsigned int failed = 0;
        for (std::size_t j = 0; j < f.n_bonds(); ++j)
          failed += model->bond_failed(j);
        Field<> rest(u.values.size() / 2);
        double  damage = 0.;
        for (std::size_t o = 0; o < f.owners.size(); ++o)
          damage = std::max(damage, model->damage(o, rest.field()));
        if (history == "irreversible")
          {
            EXPECT_EQ(failed, census[3]);
            EXPECT_GT(damage, 0.1);
          }
        else
          {
            EXPECT_EQ(failed, 0u);
            EXPECT_EQ(damage, 0.);
          }
      }
  }

  TEST(BondBased, RefusesWhatItCannotRepresent)
  {
    using Entries   = std::vector<std::pair<std::string, std::string>>;
    const auto tanh = [](const std::string &s_m,
                         const std::string &s_c,
                         const std::string &beta) {
      return Entries{{"Bond based/Degradation", "tanh"},
                     {"Bond based/Onset stretch", s_m},
                     {"Bond based/Critical stretch", s_c},
                     {"Bond based/Degradation rate", beta}};
    };
    EXPECT_THROW(make_model("bond based", tanh("0.02", "0.02", "3")),
                 InputError);
    EXPECT_THROW(make_model("bond based", tanh("0.03", "0.02", "3")),
                 InputError);
    EXPECT_THROW(make_model("bond based", tanh("0", "0.02", "3")), InputError);
    EXPECT_THROW(make_model("bond based", tanh("0.01", "0.02", "0")),
                 InputError);
    EXPECT_THROW(make_model("bond based", tanh("0.01", "0.02", "-1")),
                 InputError);
    EXPECT_NO_THROW(make_model("bond based", tanh("0.01", "0.02", "3")));
    // No degradation: the stretches are not read.
    EXPECT_NO_THROW(make_model("bond based", {}));
  }
} // namespace
