// SPDX-License-Identifier: LGPL-2.1-or-later
// Nodal results and the maximum principal stress criterion that reads them.
// - The FE cells' vertex gradients (cached weights, no FEValues per call)
//   reproduce fields the elements represent exactly: a linear field on
//   curved quadrilaterals and on triangles, and x y on rectangles, where the
//   gradient varies from vertex to vertex. Meshes of one kind of cell
//   get one element (Q1 or P1) and DoFHandlers without hp.
// - The criterion skips the bonds whose bound cannot matter; what it
//   reports must equal the largest principal stress over every intact bond.
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/fracture/crack_growth.h>
#include <pdfem/pd/families.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;

  Coupling::Settings<2>
  plate_settings()
  {
    Coupling::Settings<2> settings;
    settings.material.youngs_modulus = 2e11;
    settings.material.poissons_ratio = 0.3;
    settings.material.plane_stress   = true;
    return settings;
  }

  /// Cells left of x = @p pd_left_of are PD.
  std::vector<bool>
  pd_cells(const Triangulation<2> &tria, const double pd_left_of)
  {
    std::vector<bool> pd(tria.n_active_cells(), false);
    for (const auto &cell : tria.active_cell_iterators())
      pd[cell->active_cell_index()] = cell->center()[0] < pd_left_of;
    return pd;
  }

  /// Max over the nodes of kind @p kinds of |grad u - expected(x)|; fails
  /// the test if there are no such nodes.
  double
  gradient_error(const Coupling::NodalResults<2>                    &r,
                 const std::function<Tensor<2, 2>(const Point<2> &)> expected,
                 const std::vector<std::uint8_t>                    &kinds)
  {
    double       error   = 0.;
    unsigned int checked = 0;
    for (std::size_t k = 0; k < r.position.size(); ++k)
      if (std::find(kinds.begin(), kinds.end(), r.kind[k]) != kinds.end())
        {
          ++checked;
          const Tensor<2, 2> difference =
            r.displacement_gradient[k] - expected(r.position[k]);
          error = std::max(error, difference.norm());
        }
    EXPECT_GT(checked, 0u);
    return error;
  }

  TEST(NodalResults, LinearFieldExactOnCurvedQuadsAndTriangles)
  {
    Tensor<2, 2> A;
    A[0][0]             = 1e-3;
    A[0][1]             = 2e-3;
    A[1][0]             = -5e-4;
    A[1][1]             = 3e-3;
    const auto constant = [&](const Point<2> &) { return A; };
    for (const bool simplices : {false, true})
      {
        parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
        if (simplices)
          GridGenerator::subdivided_hyper_cube_with_simplices(tria, 6);
        else
          {
            GridGenerator::subdivided_hyper_cube(tria, 6);
            // Curved, so that no cell is a parallelogram.
            GridTools::transform(
              [](const Point<2> &p) {
                return Point<2>(p[0] + 0.08 * std::sin(M_PI * p[0]) *
                                         std::sin(M_PI * p[1]),
                                p[1] + 0.05 * p[0] * p[1]);
              },
              tria);
          }
        Coupling::CoupledSystem<2> system(tria,
                                          pd_cells(tria, 0.4),
                                          plate_settings());
        // A mesh of one kind of cell is numbered without hp: one element.
        EXPECT_FALSE(system.dof_handler().has_hp_capabilities());
        EXPECT_EQ(system.dof_handler().get_fe_collection().size(), 1u);
        EXPECT_EQ(system.node_dof_handler().get_fe(0).reference_cell(),
                  tria.begin_active()->reference_cell());
        TrilinosWrappers::MPI::Vector u;
        system.initialize_vector(u);
        system.interpolate({"1e-3*x+2e-3*y", "-5e-4*x+3e-3*y"}, "test", u);
        const auto r     = system.nodal_results(u);
        const auto scale = A.norm();
        EXPECT_LT(gradient_error(r, constant, {2}), 1e-12 * scale)
          << (simplices ? "triangles" : "quadrilaterals") << ", FE nodes";
        EXPECT_LT(gradient_error(r, constant, {1, 3}), 1e-9 * scale)
          << (simplices ? "triangles" : "quadrilaterals") << ", PD nodes";
        // The stress is C : sym(A) everywhere.
        const SymmetricTensor<2, 2> eps = symmetrize(A);
        const auto                 &m   = plate_settings().material;
        const SymmetricTensor<2, 2> sigma =
          m.lambda() * trace(eps) * unit_symmetric_tensor<2>() +
          2. * m.mu() * eps;
        double stress_error = 0.;
        for (std::size_t k = 0; k < r.stress.size(); ++k)
          if (r.kind[k] == 2)
            stress_error = std::max(stress_error, (r.stress[k] - sigma).norm());
        EXPECT_LT(stress_error, 1e-12 * sigma.norm());
      }
  }

  TEST(NodalResults, BilinearFieldExactAtVerticesOfRectangles)
  {
    // u = (x y, 0): grad u = [[y, x], [0, 0]], different at every vertex.
    // Q1 holds x y on rectangles, so each cell's extrapolated Gauss-point
    // gradient equals it at the cell's vertices.
    parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {5, 3},
                                              Point<2>(0., 0.),
                                              Point<2>(2., 1.5));
    Coupling::CoupledSystem<2>    system(tria,
                                      pd_cells(tria, -1.),
                                      plate_settings());
    TrilinosWrappers::MPI::Vector u;
    system.initialize_vector(u);
    system.interpolate({"x*y", "0"}, "test", u);
    const auto r = system.nodal_results(u);
    EXPECT_LT(gradient_error(r,
                             [](const Point<2> &p) {
                               Tensor<2, 2> g;
                               g[0][0] = p[1];
                               g[0][1] = p[0];
                               return g;
                             },
                             {2}),
              1e-13);
  }

  TEST(PrincipalStressCriterion, LargestStressOverEveryIntactBond)
  {
    parallel::shared::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 8);
    Coupling::Settings<2>      settings = plate_settings();
    Coupling::CoupledSystem<2> system(tria, pd_cells(tria, 0.6), settings);
    // A crack across the PD region breaks some bonds first.
    Mesh::Crack<2> crack;
    crack.points = {{Point<2>(0.1, 0.52), Point<2>(0.45, 0.52)}};
    system.break_bonds({crack});
    TrilinosWrappers::MPI::Vector u;
    system.initialize_vector(u);
    system.interpolate({"1e-3*x*x*y + 2e-4*y", "-3e-3*x*y*y + 1e-4*x"},
                       "test",
                       u);
    const auto r = system.nodal_results(u);

    // Every intact bond, without skipping any.
    const PD::Families &f        = system.families();
    double              largest  = 0.;
    std::size_t         n_intact = 0;
    for (std::size_t o = 0; o < f.owners.size(); ++o)
      for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
        if (f.intact[b])
          {
            ++n_intact;
            const unsigned int k = f.owners[o], m = f.members[b];
            largest =
              std::max(largest,
                       eigenvalues(0.5 * (r.stress[k] + r.stress[m]))[0]);
          }
    ASSERT_LT(n_intact, f.n_bonds());
    ASSERT_GT(largest, 0.);

    // Strengths above the largest stress (nothing breaks, the bonds that
    // can raise the largest so far count) and below it (the bonds that can
    // exceed the strength count).
    for (const double fraction : {2., 0.5})
      {
        Fracture::Settings fracture;
        fracture.criterion        = "max principal stress";
        fracture.tensile_strength = fraction * largest;
        Fracture::CrackGrowth<2> growth(fracture,
                                        settings.material,
                                        {crack},
                                        system);
        const auto a = growth.grow_by_principal_stress(system, r, false);
        EXPECT_EQ(a.max_driving_value, largest) << "strength " << fraction;
        EXPECT_EQ(a.critical_load_ratio, fraction);
      }
  }
} // namespace
