// SPDX-License-Identifier: LGPL-2.1-or-later
// The energy criterion of "lps fft" (LPS fft/Damage = energy; pd_models/
// lps_fft.h, doc/theory.md §14.5, specs/002 §1.6): after an accepted state
// the nodes whose strain energy density W exceeds W_c = G_0 / delta fail for
// good (integrity lambda = 0), and the forces and the damage index follow
// the masks chi_B lambda.
// - W of the model = FFT::DirectOperator::energy_density() on the same
//   field (the neighbour sum, an independent implementation) to 1e-12;
// - exactly the body nodes with W > W_c fail; a later state with u = 0
//   revives none (irreversible);
// - the coupled system's internal force then equals -Delta V L of the
//   direct operator with the masks chi_B and lambda to 1e-12, and the
//   damage the direct operator's index to 1e-12;
// - an intact body has damage 0 (body normalisation) at every node, free
//   surfaces included;
// - bad input: G_0 <= 0 with Damage = energy, one InputError line naming
//   the parameter (a static driver: the scene lps_fft_damage_bad_static).
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/fft/direct_operator.h>
#include <pdfem/fft/fft_operator.h>
#include <pdfem/pd_models/lps_fft.h>

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "pd_models_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;
  using Vector  = TrilinosWrappers::MPI::Vector;
  using Entries = std::vector<std::pair<std::string, std::string>>;

  /// An L-shaped all-PD body (20 x 20 cells of 0.05, the 8 x 8 of the top
  /// right corner removed) with "lps fft", E = 1e3, nu = 0.25 plane stress,
  /// delta = 3.015 h and the model's @p entries.
  struct System
  {
    explicit System(const Entries &entries)
      : tria(MPI_COMM_WORLD)
    {
      GridGenerator::subdivided_hyper_L(
        tria, {20u, 20u}, Point<2>(), Point<2>(1., 1.), {-8, -8});
      const std::vector<bool> pd(tria.n_active_cells(), true);
      Entries                 all = {{"LPS/Nodal volumes", "uniform"}};
      all.insert(all.end(), entries.begin(), entries.end());
      Coupling::Settings<2> settings =
        body_settings<2>(0.25, 3.015, make_model<2>("lps fft", all));
      settings.source_file = "test.prm";
      system = std::make_unique<Coupling::CoupledSystem<2>>(tria, pd, settings);
      system->initialize_vector(u);
    }

    const PDModels::LpsFft<2> &
    model() const
    {
      return dynamic_cast<const PDModels::LpsFft<2> &>(system->pd_model());
    }

    /// u_i = @p scale sin(12.9898 i + 1) for every DoF i.
    void
    set_u(const double scale)
    {
      for (const auto i : u.locally_owned_elements())
        u[i] = scale * std::sin(12.9898 * double(i) + 1.);
      u.compress(VectorOperation::insert);
    }

    /// u on the FFT box (component-major, 0 off the body).
    std::vector<double>
    box_field(const Vector &v) const
    {
      const auto         &op = model().fft_operator();
      const std::size_t   N  = op.grid().n_nodes();
      std::vector<double> field(2 * N, 0.);
      const auto         &index = model().node_grid().index;
      for (unsigned int k = 0; k < system->size().n_nodes; ++k)
        {
          const Tensor<1, 2> d = system->node_displacement(v, k);
          for (unsigned int c = 0; c < 2; ++c)
            field[c * N + op.grid().node(index[k])] = d[c];
        }
      return field;
    }

    /// The direct neighbour sum on the model's grid, material and masks.
    std::unique_ptr<FFT::DirectOperator<2>>
    direct() const
    {
      const auto &op = model().fft_operator();
      auto        d =
        std::make_unique<FFT::DirectOperator<2>>(op.grid(), op.material());
      d->set_masks(model().body_mask(), model().integrity());
      return d;
    }

    parallel::shared::Triangulation<2>          tria;
    std::unique_ptr<Coupling::CoupledSystem<2>> system;
    Vector                                      u;
  };

  /// max |a - b| over the body nodes of the box, relative to max |b|.
  double
  body_difference(const std::vector<double> &a,
                  const std::vector<double> &b,
                  const std::vector<double> &body)
  {
    double            diff = 0., scale = 0.;
    const std::size_t N = body.size();
    for (std::size_t i = 0; i < b.size(); ++i)
      if (body[i % N] > 0.)
        {
          diff  = std::max(diff, std::abs(a[i] - b[i]));
          scale = std::max(scale, std::abs(b[i]));
        }
    EXPECT_GT(scale, 0.);
    return diff / scale;
  }

  const Entries
  damage_on(const double G0)
  {
    std::ostringstream text;
    text << std::setprecision(17) << G0;
    return {{"LPS fft/Damage", "energy"},
            {"LPS fft/Fracture energy", text.str()}};
  }

  TEST(LpsFftDamage, IntactBodyHasNoDamage)
  {
    System s(damage_on(1.));
    EXPECT_TRUE(s.system->pd_model().layout().history);
    s.set_u(1e-3);
    Vector f;
    s.system->initialize_vector(f);
    s.system->internal_force(s.u, f);
    // Far below W_c: nobody fails; d = 0 (round-off of the FFT) at every
    // node, the corners and edges of the L included.
    s.system->accept_state(s.u);
    EXPECT_EQ(s.model().last_failed(), 0u);
    EXPECT_LT(std::abs(s.system->max_damage()), 1e-12);
    Field<2> zero(s.system->size().n_nodes);
    double   largest = 0.;
    for (std::size_t o = 0; o < s.system->families().owners.size(); ++o)
      largest =
        std::max(largest,
                 std::abs(s.system->pd_model().damage(o, zero.field())));
    EXPECT_LT(largest, 1e-12);
    EXPECT_EQ(s.system->size().n_broken_bonds, 0u);
  }

  TEST(LpsFftDamage, NodesAboveTheCriticalEnergyFailForGood)
  {
    // W of a pseudo-random field without failures (G_0 huge) ...
    System intact(damage_on(1e30));
    intact.set_u(1e-3);
    intact.system->accept_state(intact.u);
    const std::vector<double> W     = intact.model().energy_density();
    const std::vector<double> u_box = intact.box_field(intact.u);
    std::vector<double>       W_direct;
    intact.direct()->energy_density(u_box, W_direct);
    const std::vector<double> &body = intact.model().body_mask();
    EXPECT_LT(body_difference(W, W_direct, body), 1e-12);
    EXPECT_EQ(intact.model().last_failed(), 0u);

    // ... W_c = G_0 / delta between the 90th percentile and the next value
    // (no node within round-off of it).
    std::vector<double> body_W;
    for (std::size_t i = 0; i < W.size(); ++i)
      if (body[i] > 0.)
        body_W.push_back(W[i]);
    std::sort(body_W.begin(), body_W.end());
    const std::size_t p = 9 * body_W.size() / 10;
    ASSERT_GT(body_W[p + 1], (1. + 1e-6) * body_W[p]);
    const double W_c   = 0.5 * (body_W[p] + body_W[p + 1]);
    const double delta = 3.015 * 0.05;
    System       s(damage_on(W_c * delta));
    EXPECT_NEAR(s.model().critical_energy_density(), W_c, 1e-12 * W_c);
    s.set_u(1e-3);
    s.system->accept_state(s.u);
    EXPECT_LT(body_difference(s.model().energy_density(), W_direct, body),
              1e-12);
    const double W_crit = s.model().critical_energy_density();
    const auto  &lambda = s.model().integrity();
    std::size_t  n_dead = 0;
    for (std::size_t i = 0; i < W.size(); ++i)
      if (body[i] > 0.)
        {
          EXPECT_EQ(lambda[i], W_direct[i] > W_crit ? 0. : 1.) << i;
          n_dead += lambda[i] == 0.;
        }
    EXPECT_GT(n_dead, body_W.size() / 20);
    EXPECT_EQ(s.model().last_failed(), n_dead);

    // The forces see the dead nodes: -Delta V L of the direct operator
    // with chi_B lambda.
    auto                direct = s.direct();
    std::vector<double> L, d_direct;
    direct->apply(u_box, L);
    Vector f;
    s.system->initialize_vector(f);
    s.system->internal_force(s.u, f);
    const std::vector<double> f_box = s.box_field(f);
    for (double &l : L)
      l *= -0.05 * 0.05;
    EXPECT_LT(body_difference(f_box, L, body), 1e-12);
    for (std::size_t i = 0; i < W.size(); ++i)
      {
        if (body[i] > 0. && lambda[i] == 0.)
          {
            EXPECT_EQ(f_box[i], 0.) << "a dead node carries no force";
          }
      }

    // The damage index is the direct operator's (body normalisation).
    direct->damage(d_direct, FFT::DamageNormalisation::body);
    Field<2>    zero(s.system->size().n_nodes);
    const auto &index    = s.model().node_grid().index;
    const auto &f_owners = s.system->families().owners;
    for (std::size_t o = 0; o < f_owners.size(); ++o)
      {
        const std::size_t i =
          s.model().fft_operator().grid().node(index[f_owners[o]]);
        EXPECT_NEAR(s.system->pd_model().damage(o, zero.field()),
                    d_direct[i],
                    1e-12);
      }
    EXPECT_NEAR(s.system->max_damage(), 1., 1e-12);
    EXPECT_EQ(s.system->size().n_broken_bonds, 0u);

    // Irreversible: unloaded, nobody revives.
    const std::vector<double> before = lambda;
    s.set_u(0.);
    s.system->accept_state(s.u);
    EXPECT_EQ(s.model().last_failed(), 0u);
    EXPECT_EQ(s.model().integrity(), before);
  }

  TEST(LpsFftDamage, FailedNodesReleaseTheirStrainEnergy)
  {
    // W_c at the 90th percentile of W of a pseudo-random field: about a
    // tenth of the nodes fail when the state is accepted. The released
    // energy is E(u) = 1/2 u . f_int(u) with the old masks minus with the
    // new ones, at the same u.
    System intact(damage_on(1e30));
    intact.set_u(1e-3);
    intact.system->accept_state(intact.u);
    EXPECT_EQ(intact.system->released_energy(), 0.);
    std::vector<double> W;
    for (std::size_t i = 0; i < intact.model().energy_density().size(); ++i)
      if (intact.model().body_mask()[i] > 0.)
        W.push_back(intact.model().energy_density()[i]);
    std::sort(W.begin(), W.end());
    const std::size_t p = 9 * W.size() / 10;
    System            s(damage_on(0.5 * (W[p] + W[p + 1]) * 3.015 * 0.05));
    s.set_u(1e-3);
    Vector f;
    s.system->initialize_vector(f);
    s.system->internal_force(s.u, f);
    const double before = 0.5 * (s.u * f);
    s.system->accept_state(s.u);
    ASSERT_GT(s.model().last_failed(), 0u);
    s.system->internal_force(s.u, f);
    const double after = 0.5 * (s.u * f);
    EXPECT_GT(before - after, 0.);
    EXPECT_NEAR(s.system->released_energy(), before - after, 1e-10 * before);
    // Unloaded, nothing fails: nothing is released.
    s.set_u(0.);
    s.system->accept_state(s.u);
    EXPECT_EQ(s.model().last_failed(), 0u);
    EXPECT_EQ(s.system->released_energy(), 0.);
  }

  /// The InputError of @p make(): its parameter, and one line.
  std::string
  error_parameter(const std::function<void()> &make)
  {
    try
      {
        make();
      }
    catch (const InputError &e)
      {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        return e.parameter;
      }
    return "";
  }

  TEST(LpsFftDamage, RefusesBadInput)
  {
    for (const char *G0 : {"0", "-3.8"})
      EXPECT_EQ(error_parameter([&] {
                  make_model<2>("lps fft",
                                {{"LPS/Nodal volumes", "uniform"},
                                 {"LPS fft/Damage", "energy"},
                                 {"LPS fft/Fracture energy", G0}});
                }),
                "Peridynamics/LPS fft/Fracture energy")
        << G0;
    // Without damage the fracture energy is not read.
    EXPECT_EQ(error_parameter([&] {
                make_model<2>("lps fft",
                              {{"LPS/Nodal volumes", "uniform"},
                               {"LPS fft/Fracture energy", "-1"}});
              }),
              "");
  }
} // namespace
