// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "lps fft" (pd_models/lps_fft.h, doc/user_guide.md §2a‴): the LPS
// model of "lps" evaluated for all nodes at once by FFT on the grid of an
// all-PD region.
// - the coupled system's internal force equals that of "lps" with Nodal
//   volumes = uniform on the same mesh, at a pseudo-random u, to 1e-12
//   relative: L-shaped bodies (grid points outside the body masked), 2D
//   (plane stress, plane strain, omega = 1, unequal spacings in x and y)
//   and 3D;
// - the grid is detected from the node positions, and the box leaves a gap
//   of more than a horizon;
// - the system stores no bonds, and the output's gradient (fitted on the
//   grid) is exact for affine fields, also on 2 ranks;
// - LPS/Traction layer: the tractions of an edge act on the nodes within
//   a horizon of it, each t V_k / l, with the exact resultant (lps and lps
//   fft, also on 2 ranks);
// - refused with one InputError naming Peridynamics/Model: nodes off a
//   uniform grid (jittered), FE cells, Nodal volumes = cells, broken bonds
//   and the tangent.
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/pd_models/lps_fft.h>

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <functional>
#include <string>

#include "pd_models_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;
  using Vector = TrilinosWrappers::MPI::Vector;

  /// The body: a box of @p repetitions cells from the origin to @p corner,
  /// with @p removed cells cut away at a corner (subdivided_hyper_L; none
  /// if empty), jittered by @p jitter of a cell; the cells with
  /// @p is_pd(centre) PD.
  template <int dim>
  struct Body
  {
    std::vector<unsigned int>               repetitions;
    Point<dim>                              corner;
    std::vector<int>                        removed;
    double                                  jitter = 0.;
    std::function<bool(const Point<dim> &)> is_pd  = [](const Point<dim> &) {
      return true;
    };
  };

  /// A coupled system on @p body with the model @p name and @p entries,
  /// E = 1e3, Poisson's ratio @p nu, horizon factor @p m.
  template <int dim>
  struct System
  {
    System(const Body<dim>                                        &body,
           const std::string                                      &name,
           const std::vector<std::pair<std::string, std::string>> &entries,
           const double                                            nu,
           const double                                            m,
           const bool plane_strain = false)
      : tria(MPI_COMM_WORLD)
    {
      if (body.removed.empty())
        GridGenerator::subdivided_hyper_rectangle(tria,
                                                  body.repetitions,
                                                  Point<dim>(),
                                                  body.corner);
      else
        GridGenerator::subdivided_hyper_L(
          tria, body.repetitions, Point<dim>(), body.corner, body.removed);
      if (body.jitter > 0.)
        GridTools::distort_random(body.jitter, tria, false, 5);
      std::vector<bool> pd(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        pd[cell->active_cell_index()] = body.is_pd(cell->center());
      Coupling::Settings<dim> settings =
        body_settings<dim>(nu, m, make_model<dim>(name, entries), plane_strain);
      settings.source_file = "test.prm";
      system =
        std::make_unique<Coupling::CoupledSystem<dim>>(tria, pd, settings);
    }

    /// The internal force at u_i = 1e-3 sin(12.9898 i + 1) for every DoF i.
    Vector
    internal_force()
    {
      Vector u, f;
      system->initialize_vector(u);
      system->initialize_vector(f);
      for (const auto i : u.locally_owned_elements())
        u[i] = 1e-3 * std::sin(12.9898 * double(i) + 1.);
      u.compress(VectorOperation::insert);
      system->internal_force(u, f);
      return f;
    }

    parallel::shared::Triangulation<dim>          tria;
    std::unique_ptr<Coupling::CoupledSystem<dim>> system;
  };

  const std::vector<std::pair<std::string, std::string>> uniform = {
    {"LPS/Nodal volumes", "uniform"}};

  /// max |f_fft - f_lps| / max |f_lps| on @p body.
  template <int dim>
  double
  fft_against_direct(
    const Body<dim>                                        &body,
    const double                                            nu,
    const double                                            m,
    const bool                                              plane_strain,
    const std::vector<std::pair<std::string, std::string>> &entries)
  {
    System<dim> direct(body, "lps", entries, nu, m, plane_strain);
    System<dim> fft(body, "lps fft", entries, nu, m, plane_strain);
    EXPECT_EQ(direct.system->size().n_nodes, fft.system->size().n_nodes);
    for (unsigned int k = 0; k < direct.system->size().n_nodes; ++k)
      EXPECT_EQ(direct.system->node_position(k), fft.system->node_position(k));
    const Vector f_direct = direct.internal_force();
    const Vector f_fft    = fft.internal_force();
    EXPECT_GT(f_direct.linfty_norm(), 0.);
    Vector difference = f_fft;
    difference -= f_direct;
    return difference.linfty_norm() / f_direct.linfty_norm();
  }

  TEST(LpsFft, EqualsLpsWithUniformVolumes2D)
  {
    // An L: 20 x 20 cells of 0.05, the 8 x 8 cells of the top right corner
    // removed (81 grid points of the box outside the body).
    Body<2> l_shape{{20, 20}, Point<2>(1., 1.), {-8, -8}};
    EXPECT_LT(fft_against_direct(l_shape, 0.3, 3.015, false, uniform), 1e-12)
      << "plane stress, nu = 0.3";
    EXPECT_LT(fft_against_direct(l_shape, 0.45, 3.015, true, uniform), 1e-12)
      << "plane strain, nu = 0.45";
    auto constant = uniform;
    constant.push_back({"LPS/Influence function", "1"});
    EXPECT_LT(fft_against_direct(l_shape, 0.2, 4., false, constant), 1e-12)
      << "omega = 1, m = 4";
    // Unequal spacings: 0.1 in x, 0.05 in y (delta = m sqrt(hx hy)).
    Body<2> stretched{{16, 12}, Point<2>(1.6, 0.6), {5, 4}};
    EXPECT_LT(fft_against_direct(stretched, 0.3, 3.015, false, uniform), 1e-12)
      << "hx = 2 hy";
  }

  TEST(LpsFft, EqualsLpsWithUniformVolumes3D)
  {
    Body<3> l_shape{{8, 8, 8}, Point<3>(1., 1., 1.), {-3, -3, 8}};
    EXPECT_LT(fft_against_direct(l_shape, 0.25, 2.015, false, uniform), 1e-12);
  }

  TEST(LpsFft, DetectsTheGridAndLeavesAGap)
  {
    Body<2>     body{{20, 10}, Point<2>(2., 1.), {-8, -4}};
    System<2>   s(body, "lps fft", uniform, 0.3, 3.015);
    const auto &model =
      dynamic_cast<const PDModels::LpsFft<2> &>(s.system->pd_model());
    const auto &grid = model.node_grid();
    for (unsigned int c = 0; c < 2; ++c)
      {
        EXPECT_NEAR(grid.spacing[c], 0.1, 1e-15);
        EXPECT_EQ(grid.origin[c], 0.);
        // 3 spacings of horizon: at least n + 3 + 1 box nodes.
        EXPECT_GE(model.box_size()[c], grid.n[c] + 4);
      }
    EXPECT_EQ(grid.n[0], 21u);
    EXPECT_EQ(grid.n[1], 11u);
    EXPECT_EQ(model.box_size()[0], 25u); // 5^2
    EXPECT_EQ(model.box_size()[1], 15u); // 3 5
  }

  /// The largest |grad u - G| over the nodes of @p body (lps fft, m =
  /// 3.015) at u = G x + c, and the number of bonds the system stores.
  template <int dim>
  std::pair<double, unsigned long>
  gradient_error_of_affine_field(const Body<dim>                &body,
                                 const std::vector<std::string> &u_of_x,
                                 const Tensor<2, dim>           &G)
  {
    System<dim> s(body, "lps fft", uniform, 0.3, 3.015);
    Vector      u;
    s.system->initialize_vector(u);
    s.system->interpolate(u_of_x, "test", u);
    const auto results = s.system->nodal_results(u);
    double     error   = 0.;
    for (const auto &grad : results.displacement_gradient)
      error = std::max(error, (grad - G).norm());
    return {error, s.system->size().n_bonds};
  }

  TEST(LpsFftWithoutBonds, StoresNoBondsAndFitsTheGradientOnItsGrid)
  {
    // No bonds: the families list their owners only, whatever the
    // horizon. The output's gradient, fitted over the grid's bonds within
    // the body, is exact for an affine field at every node, on every rank
    // (the neighbours' displacements come from the whole box).
    Body<2>      l_shape{{20, 10}, Point<2>(2., 1.), {-8, -4}};
    Tensor<2, 2> G2;
    G2[0][0] = 1e-3, G2[0][1] = -2e-3, G2[1][0] = 5e-4, G2[1][1] = 3e-3;
    const auto [error2, bonds2] = gradient_error_of_affine_field<2>(
      l_shape, {"1e-3*x - 2e-3*y + 0.1", "5e-4*x + 3e-3*y - 0.2"}, G2);
    EXPECT_LT(error2, 1e-14);
    EXPECT_EQ(bonds2, 0u);

    Body<3>      box{{6, 5, 4}, Point<3>(0.6, 0.5, 0.4), {}};
    Tensor<2, 3> G3;
    G3[0][0] = 1e-3, G3[0][2] = 2e-3, G3[1][1] = -1e-3, G3[2][0] = 4e-3;
    G3[2][1]                    = 5e-4;
    const auto [error3, bonds3] = gradient_error_of_affine_field<3>(
      box, {"1e-3*x + 2e-3*z", "-1e-3*y + 1", "4e-3*x + 5e-4*y"}, G3);
    EXPECT_LT(error3, 1e-14);
    EXPECT_EQ(bonds3, 0u);
  }

  /// External force at every node of a 2 x 1 plate of 20 x 10 cells (h =
  /// 0.1, all PD, model @p name, m = 3.015): normal traction 5 on the
  /// right edge, x traction -5 on the left one, `LPS/Traction layer` =
  /// @p layer.
  std::vector<Tensor<1, 2>>
  traction_forces(const std::string &name, const std::string &layer)
  {
    parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_rectangle(
      tria, {20, 10}, Point<2>(), Point<2>(2., 1.), true);
    Coupling::Settings<2> settings =
      body_settings<2>(0.3,
                       3.015,
                       make_model<2>(name,
                                     {{"LPS/Nodal volumes", "uniform"},
                                      {"LPS/Traction layer", layer}}));
    settings.source_file = "test.prm";
    Coupling::BoundaryCondition<2> right, left;
    right.name         = "right";
    right.boundary_ids = {1};
    right.component    = 2; // normal
    right.expression   = "5";
    left.name          = "left";
    left.boundary_ids  = {0};
    left.component     = 0;
    left.expression    = "-5";
    settings.traction  = {right, left};
    Coupling::CoupledSystem<2> system(
      tria, std::vector<bool>(tria.n_active_cells(), true), settings);
    Vector f;
    system.external_force(0., f);
    std::vector<Tensor<1, 2>> forces(system.size().n_nodes);
    for (unsigned int k = 0; k < forces.size(); ++k)
      forces[k] = system.node_displacement(f, k);
    return forces;
  }

  TEST(TractionLayer, CarriesTheResultantOnTheNodesWithinTheLayer)
  {
    // The layer: the 4 columns within delta = 0.3015 of each edge, 44
    // nodes of volume 0.01, thickness V / A = 0.44: f = 5 0.01 / 0.44 on
    // each, the resultant 5 A exactly; without a layer only the edges'
    // nodes are loaded, with the same resultant.
    for (const std::string name : {"lps fft", "lps"})
      for (const std::string layer : {"1", "0"})
        {
          const auto   forces = traction_forces(name, layer);
          const double f_node = 5. * 0.01 / 0.44;
          double       right = 0., left = 0., error = 0.;
          unsigned int loaded = 0;
          for (unsigned int k = 0; k < forces.size(); ++k)
            {
              // x of node k from the regular numbering is not known here:
              // classify by the force itself and check its size.
              const double fx = forces[k][0];
              EXPECT_EQ(forces[k][1], 0.) << name << ", layer " << layer;
              if (fx > 0.)
                right += fx;
              else
                left += fx;
              if (fx != 0.)
                ++loaded;
              if (layer == "1" && fx != 0.)
                error = std::max(error, std::abs(std::abs(fx) - f_node));
            }
          EXPECT_NEAR(right, 5., 1e-12) << name << ", layer " << layer;
          EXPECT_NEAR(left, -5., 1e-12) << name << ", layer " << layer;
          EXPECT_EQ(loaded, layer == "1" ? 88u : 22u) << name;
          EXPECT_LT(error, 1e-14) << name;
        }
  }

  /// The InputError's message of @p make(), "" if none is thrown.
  std::string
  input_error(const std::function<void()> &make)
  {
    try
      {
        make();
      }
    catch (const InputError &e)
      {
        EXPECT_EQ(e.parameter, "Peridynamics/Model") << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        return e.what();
      }
    return "";
  }

  TEST(LpsFft, RefusesWhatItCannotEvaluate)
  {
    Body<2> jittered{{8, 8}, Point<2>(1., 1.), {}, 0.1};
    EXPECT_NE(input_error([&] {
                System<2>(jittered, "lps fft", uniform, .3, 3.);
              }).find("off the grid"),
              std::string::npos);
    Body<2> coupled{{8, 8}, Point<2>(1., 1.), {}};
    coupled.is_pd = [](const Point<2> &p) { return p[0] < 0.5; };
    EXPECT_NE(input_error([&] {
                System<2>(coupled, "lps fft", uniform, .3, 3.);
              }).find("all-PD"),
              std::string::npos);
    EXPECT_NE(input_error([&] {
                make_model<2>("lps fft", {});
              }).find("Nodal volumes = cells"),
              std::string::npos);

    Body<2>   square{{8, 8}, Point<2>(1., 1.), {}};
    System<2> s(square, "lps fft", uniform, 0.3, 3.015);
    EXPECT_NE(input_error([&] {
                s.system->break_bonds_if(
                  [](unsigned int k, unsigned int m) { return k + m == 40; });
              }).find("single bonds"),
              std::string::npos);
    Field<2>                  u(s.system->size().n_nodes);
    std::vector<Tensor<2, 2>> blocks;
    EXPECT_NE(input_error([&] {
                s.system->pd_model().tangent_row(0, u.field(), blocks);
              }).find("without a tangent"),
              std::string::npos);
  }
} // namespace
