// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model plugins as terms of the coupled system (pd_models/interface.h):
// - every registered model's tangent rows are the central finite
//   differences of its own force rows, for intact, softened and broken
//   bonds (pdlsm is linear: its rows are exact; rnp is nonlinear);
// - rnp's term is symmetric and its forces sum to zero (pairwise bonds);
// - the coupled system reaches the same Newton solution with either model
//   on a small all-PD plate in the linear range (rnp calibrated to the
//   same E).
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <random>

#include "pd_models_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;

  std::shared_ptr<PDModels::Interface<2>>
  make_rnp(const double C = 1e3, const double beta = 30.)
  {
    return make_model("rnp",
                      {{"RNP/Calibration", "constants"},
                       {"RNP/C", std::to_string(C)},
                       {"RNP/beta", std::to_string(beta)}});
  }

  TEST(PDModels, RegistryHasTheBuiltInModels)
  {
    const auto names = PDModels::registry<2>().names();
    EXPECT_NE(std::find(names.begin(), names.end(), "pdlsm"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "rnp"), names.end());
    EXPECT_THROW(PDModels::create<2>("rpn", "test.prm"), InputError);
    EXPECT_FALSE(make_model("pdlsm", {})->linear() == false);
    EXPECT_FALSE(make_rnp()->linear());
    EXPECT_TRUE(make_rnp()->symmetric());
    EXPECT_THROW(make_model("pdlsm", {{"Weight factor", "-1"}}), InputError);
    EXPECT_THROW(make_model("rnp", {{"RNP/Calibration", "constants"}}),
                 InputError);
  }

  TEST(PDModels, TangentRowsAreCentralDifferencesOfTheForceRows)
  {
    for (const std::string name : {"pdlsm", "rnp"})
      for (const bool broken : {false, true})
        {
          auto  model = name == "rnp" ?
                          make_rnp() :
                          make_model("pdlsm", {{"Weight factor", "0.33"}});
          Plate plate(model, 0.6);
          if (broken)
            break_some_bonds(*plate.system);
          const auto &f = plate.system->families();
          Field<>     u(plate.system->size().n_nodes);
          // rnp: r_c = 1 / sqrt(2 beta) = 0.13; strains of a few 1e-2 on
          // bonds of 0.375 soften some bonds (r = sqrt|xi| S past r_c).
          for (const double amplitude : {1e-3, 0.3})
            {
              deform(*plate.system, u, amplitude);
              if (name == "rnp")
                {
                  double d = 0.;
                  for (std::size_t o = 0; o < f.owners.size(); ++o)
                    d = std::max(d, model->damage(o, u.field()));
                  // softened bonds (past the peak force) at the larger
                  // amplitude only
                  EXPECT_EQ(d > 1., amplitude > 0.1) << d;
                }
              EXPECT_LT(
                tangent_error(*model, f, u, 1e-6 * std::max(amplitude, 1e-2)),
                1e-6)
                << name << (broken ? " with broken bonds" : "")
                << ", amplitude " << amplitude;
            }
        }
  }

  TEST(PDModels, PairwiseTermsAreSymmetricAndSelfEquilibrated)
  {
    for (const std::string name : {"rnp", "bond based"})
      for (const bool broken : {false, true})
        {
          auto  model = name == "rnp" ?
                          make_rnp() :
                          make_model("bond based",
                                    {{"Bond based/Degradation", "tanh"},
                                      {"Bond based/Onset stretch", "0.05"},
                                      {"Bond based/Critical stretch", "0.5"}});
          Plate plate(model); // all PD
          if (broken)
            break_some_bonds(*plate.system);
          const auto    &f = plate.system->families();
          const unsigned n = plate.system->size().n_nodes;
          Field<>        u(n);
          deform(*plate.system, u, 0.3);
          // Dense K of the PD term from the tangent rows.
          std::vector<double> K(4 * n * n, 0.), forces(2 * f.owners.size());
          std::vector<Tensor<2, 2>> blocks;
          double                    scale = 0.;
          for (std::size_t o = 0; o < f.owners.size(); ++o)
            {
              model->tangent_row(o, u.field(), blocks);
              std::vector<unsigned int> columns{f.owners[o]};
              for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
                if (f.intact[j])
                  columns.push_back(f.members[j]);
              for (std::size_t b = 0; b < columns.size(); ++b)
                for (unsigned int r = 0; r < 2; ++r)
                  for (unsigned int c = 0; c < 2; ++c)
                    {
                      K[(2 * f.owners[o] + r) * 2 * n + 2 * columns[b] + c] +=
                        blocks[b][r][c];
                      scale = std::max(scale, std::abs(blocks[b][r][c]));
                    }
            }
          double asymmetry = 0.;
          for (unsigned int i = 0; i < 2 * n; ++i)
            for (unsigned int j = 0; j < i; ++j)
              asymmetry =
                std::max(asymmetry,
                         std::abs(K[i * 2 * n + j] - K[j * 2 * n + i]));
          EXPECT_LT(asymmetry, 1e-12 * scale);
          model->forces(0, f.owners.size(), u.field(), forces.data());
          double sum[2] = {0., 0.}, largest = 0.;
          for (std::size_t o = 0; o < f.owners.size(); ++o)
            for (unsigned int c = 0; c < 2; ++c)
              {
                sum[c] += forces[2 * o + c];
                largest = std::max(largest, std::abs(forces[2 * o + c]));
              }
          EXPECT_GT(largest, 0.);
          EXPECT_LT(std::abs(sum[0]) + std::abs(sum[1]), 1e-12 * largest * n);
        }
  }
} // namespace

namespace
{
  using namespace dealii;
  using namespace pdfem;

  /// An all-PD 1 x 1 plate of 8 x 8 squares with the rnp model, clamped on
  /// the left (boundary 0) and pulled on the right (boundary 1) by u_x = t.
  struct PulledRNPPlate
  {
    PulledRNPPlate()
      : tria(MPI_COMM_WORLD)
    {
      GridGenerator::subdivided_hyper_rectangle(
        tria, {8u, 8u}, Point<2>(0., 0.), Point<2>(1., 1.), true);
      Coupling::Settings<2> settings;
      settings.material.youngs_modulus = 1e3;
      settings.material.poissons_ratio = 1. / 3.;
      settings.material.plane_stress   = true;
      settings.pd_model                = make_rnp();
      settings.linear_solver.type      = "direct";
      for (const unsigned int c : {0u, 1u})
        {
          Coupling::BoundaryCondition<2> left;
          left.name         = "left";
          left.boundary_ids = {0};
          left.component    = c;
          left.expression   = "0";
          settings.dirichlet.push_back(left);
        }
      Coupling::BoundaryCondition<2> right;
      right.name         = "right";
      right.boundary_ids = {1};
      right.component    = 0;
      right.expression   = "t";
      settings.dirichlet.push_back(right);
      system = std::make_unique<Coupling::CoupledSystem<2>>(
        tria, std::vector<bool>(tria.n_active_cells(), true), settings);
    }

    /// Newton's method at load t from @p u; returns the iterations.
    unsigned int
    solve(Drivers::SystemInterface::Vector &u, const double t)
    {
      system->apply_dirichlet(u, t);
      Drivers::SystemInterface::Vector r, du;
      for (unsigned int it = 0; it < 30; ++it)
        {
          const double norm = system->residual(u, t, r, true);
          if (norm <= 1e-10 * system->force_scale())
            return it;
          system->solve_linear(du, r);
          u += du;
        }
      return 100;
    }

    parallel::shared::Triangulation<2>          tria;
    std::unique_ptr<Coupling::CoupledSystem<2>> system;
  };

  // Also run on two ranks (tests/CMakeLists.txt, unit.np2.CoupledRNP) with
  // the same expected values: the rnp term of the coupled system and its
  // inertia check on any number of ranks.
  TEST(CoupledRNP, NewtonSolutionAndInertiaCheck)
  {
    PulledRNPPlate                   plate;
    Drivers::SystemInterface::Vector u;
    plate.system->initialize_vector(u);
    // Linear range (bond stretch 1e-4 << r_c / sqrt|xi|): converged,
    // stable, the centre pulled by about half the end displacement.
    EXPECT_LT(plate.solve(u, 1e-4), 10u);
    const unsigned int centre = plate.system->nearest_node(Point<2>(0.5, 0.5));
    const double       u_centre = plate.system->node_displacement(u, centre)[0];
    EXPECT_NEAR(u_centre / 1e-4, 0.5, 0.05);
    // Regression of the 1-rank value, with the rnp model's layout (one
    // horizon 3 h, the boundary columns held within a horizon: Dirichlet
    // layer = 1); 1 and 2 ranks agree.
    EXPECT_NEAR(u_centre, 4.8557536778e-05, 1e-9 * 4.86e-5)
      << "the 1-rank value (regression: 1 and 2 ranks agree)";
    Drivers::StabilityReport report = plate.system->check_stability();
    EXPECT_FALSE(report.singular);
    EXPECT_EQ(report.n_negative, 0u);
    // The right column moved far without the rest: the bonds next to it
    // are past their peak force and the tangent is indefinite.
    plate.system->apply_dirichlet(u, 0.3);
    Drivers::SystemInterface::Vector r;
    plate.system->residual(u, 0.3, r, true);
    report = plate.system->check_stability();
    EXPECT_GT(report.n_negative, 0u);
  }

  // The rnp plugin in the parallel coupled system against the serial
  // lattice Coupling::RNPSystem (written separately, specs/000): the same
  // nodes, volumes and horizon give the same internal forces, softened
  // bonds included, on a jittered mesh with a pre-crack (1 and 2 ranks:
  // unit.np2.CoupledRNP).
  TEST(CoupledRNP, ForcesEqualTheSerialReferenceLattice)
  {
    parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 8);
    GridTools::distort_random(0.15, tria, false, 3);
    Coupling::Settings<2> settings;
    settings.material.youngs_modulus = 1e3;
    settings.material.poissons_ratio = 1. / 3.;
    settings.material.plane_stress   = true;
    settings.horizon_factor          = 3.;
    settings.pd_model                = make_model("rnp",
                                   {{"RNP/Calibration", "constants"},
                                                   {"RNP/C", "1000"},
                                                   {"RNP/beta", "30"},
                                                   {"RNP/Dirichlet layer", "0"}});
    settings.cracks                  = {
                       Mesh::Crack<2>{{Point<2>(0., 0.52), Point<2>(0.5, 0.52)}}};
    settings.linear_solver.type = "direct";
    Coupling::CoupledSystem<2> system(
      tria, std::vector<bool>(tria.n_active_cells(), true), settings);

    // A displacement that softens bonds (d > 1) near the crack's faces.
    Drivers::SystemInterface::Vector u, r;
    system.initialize_vector(u);
    system.interpolate({"0.02*sin(3*x + 2*y)", "0.3*(y > 0.52 ? 1 : -1)*x"},
                       "test",
                       u);
    system.residual(u, 0., r, false);
    EXPECT_GT(system.max_damage(), 1.);

    // The reference: x, V = V^pd, one horizon m h from the same nodes.
    const unsigned int    n = system.size().n_nodes;
    std::vector<Point<2>> x(n);
    std::vector<double>   V(n), u_ref(2 * n);
    double                horizon = 0.;
    for (const auto &[name, value] : system.pd_model().constants())
      if (name == "horizon")
        horizon = value;
    for (unsigned int k = 0; k < n; ++k)
      {
        x[k]                 = system.node_position(k);
        const Tensor<1, 2> v = system.node_displacement(u, k);
        u_ref[2 * k]         = v[0];
        u_ref[2 * k + 1]     = v[1];
      }
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        V[system.nearest_node(cell->vertex(v))] += cell->measure() / 4.;
    PDModels::RNPSettings s;
    s.C                          = 1000.;
    s.beta                       = 30.;
    s.horizon                    = horizon;
    const auto             crack = settings.cracks;
    Coupling::RNPSystem<2> reference(x,
                                     V,
                                     s,
                                     [&crack](const Point<2> &a,
                                              const Point<2> &b) {
                                       return Mesh::cut_by_any<2>(crack, a, b);
                                     },
                                     {});
    std::vector<double>    f;
    reference.internal_force(u_ref, f);
    double scale = 0., difference = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        const Tensor<1, 2> rk = system.node_displacement(r, k); // -f_int
        for (unsigned int c = 0; c < 2; ++c)
          {
            scale      = std::max(scale, std::abs(f[2 * k + c]));
            difference = std::max(difference, std::abs(rk[c] + f[2 * k + c]));
          }
      }
    EXPECT_GT(scale, 0.);
    EXPECT_LT(difference, 1e-10 * scale);
  }
} // namespace
