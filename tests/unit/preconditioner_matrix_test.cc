// SPDX-License-Identifier: LGPL-2.1-or-later
// The "amg fe" preconditioner's matrix follows broken bonds in place: cells
// a crack cuts are weakened, and a node that loses every bond gets its held
// diagonal. Updated in place after break_bonds(), it must equal the matrix
// assembled from scratch for a body that had the same cracks from the start.
// Built at set-up (Settings::prepare_solver, before the PD model's data), it
// gives the solve that builds it at the first solve, and the model still
// meets its whole initial families before the pre-existing cracks cut them.
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/fe/elastic_material.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <set>

#include <Epetra_CrsMatrix.h>
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;

  /// A 1 x 1 plate of 8 x 8 PD cells (or the mesh @p mesh makes), fixed at
  /// its left edge (boundary id 0).
  struct Plate
  {
    parallel::shared::Triangulation<2>          tria{MPI_COMM_WORLD};
    std::unique_ptr<Coupling::CoupledSystem<2>> system;

    explicit Plate(
      const std::vector<Mesh::Crack<2>>                 &initial_cracks,
      const bool                                         prepare_solver = false,
      std::shared_ptr<PDModels::Interface<2>>            model  = nullptr,
      const std::vector<Coupling::BoundaryCondition<2>> &pulled = {},
      const std::function<void(Triangulation<2> &)>     &mesh   = {})
    {
      if (mesh)
        mesh(tria);
      else
        GridGenerator::subdivided_hyper_cube(tria, 8, 0., 1., true);
      Coupling::Settings<2> settings;
      settings.material.youngs_modulus = 1e9;
      settings.material.poissons_ratio = 0.25;
      settings.material.plane_stress   = true;
      settings.cracks                  = initial_cracks;
      for (unsigned int c = 0; c < 2; ++c)
        {
          Coupling::BoundaryCondition<2> fixed;
          fixed.name         = "left";
          fixed.boundary_ids = {0};
          fixed.component    = c;
          fixed.expression   = "0";
          settings.dirichlet.push_back(fixed);
        }
      settings.dirichlet.insert(settings.dirichlet.end(),
                                pulled.begin(),
                                pulled.end());
      settings.linear_solver.type           = "gmres";
      settings.linear_solver.preconditioner = "amg fe";
      settings.linear_solver.tolerance      = 1e-12;
      settings.prepare_solver               = prepare_solver;
      settings.pd_model                     = model;
      system = std::make_unique<Coupling::CoupledSystem<2>>(
        tria, std::vector<bool>(tria.n_active_cells(), true), settings);
    }
  };

  /// Two cracks: one across the middle of the plate (cuts cells), one
  /// across the corner (1, 1) that cuts every bond of the corner node.
  std::vector<Mesh::Crack<2>>
  test_cracks()
  {
    Mesh::Crack<2> middle, corner;
    middle.points = {{Point<2>(0.3, 0.47), Point<2>(0.8, 0.47)}};
    corner.points = {{Point<2>(0.9, 1.05), Point<2>(1.05, 0.9)}};
    return {middle, corner};
  }

  /// max |A - B| over all entries of A and B, and max |A|.
  std::pair<double, double>
  difference(const TrilinosWrappers::SparseMatrix &A,
             const TrilinosWrappers::SparseMatrix &B)
  {
    const Epetra_CrsMatrix &a = A.trilinos_matrix(), &b = B.trilinos_matrix();
    double                  diff = 0., largest = 0.;
    EXPECT_EQ(a.NumMyRows(), b.NumMyRows());
    for (int row = 0; row < a.NumMyRows(); ++row)
      {
        const int             g = a.GRID(row);
        std::map<int, double> entries;
        for (const auto *m : {&a, &b})
          {
            int     n = 0;
            double *v = nullptr;
            int    *c = nullptr;
            m->ExtractMyRowView(m->LRID(g), n, v, c);
            for (int e = 0; e < n; ++e)
              entries[m->GCID(c[e])] += (m == &a ? 1. : -1.) * v[e];
            if (m == &a)
              for (int e = 0; e < n; ++e)
                largest = std::max(largest, std::abs(v[e]));
          }
        for (const auto &[col, d] : entries)
          diff = std::max(diff, std::abs(d));
      }
    return {diff, largest};
  }

  TEST(PreconditionerMatrix, UpdatedInPlaceEqualsAssembledFromScratch)
  {
    Plate      cracked_later({});
    Plate      cracked_from_start(test_cracks());
    const auto before =
      difference(cracked_later.system->preconditioner_matrix(),
                 cracked_from_start.system->preconditioner_matrix());

    EXPECT_GT(cracked_later.system->break_bonds(test_cracks()), 0u);
    const auto later = cracked_later.system->size();
    const auto start = cracked_from_start.system->size();
    EXPECT_EQ(later.n_broken_bonds, start.n_broken_bonds);
    EXPECT_EQ(later.n_decoupled_nodes, 1u); // the corner node
    EXPECT_EQ(start.n_decoupled_nodes, 1u);

    const auto after =
      difference(cracked_later.system->preconditioner_matrix(),
                 cracked_from_start.system->preconditioner_matrix());
    // Before the cracks the matrices differ (cut cells, the held corner)...
    EXPECT_GT(before.first, 0.1 * before.second);
    // ... after them, only by round-off.
    EXPECT_LT(after.first, 1e-12 * after.second);
  }

  /// A PD model of no stiffness that records what the system shows it: the
  /// intact bonds when it is initialised, and the families it is told the
  /// pre-existing cracks cut.
  class Recorder : public PDModels::Interface<2>
  {
  public:
    void
    initialize(const PDModels::Region<2> &r) override
    {
      this->region       = r;
      const auto &intact = r.families->intact;
      n_bonds            = intact.size();
      n_intact_at_start  = std::count(intact.begin(), intact.end(), 1);
    }

    void
    bonds_changed(const std::vector<std::size_t> &changed, bool) override
    {
      n_families_cut += changed.size();
    }

    bool
    linear() const override
    {
      return true;
    }

    bool
    symmetric() const override
    {
      return true;
    }

    Tensor<2, 2>
    displacement_gradient(std::size_t,
                          const PDModels::NodalField<2> &) const override
    {
      return {};
    }

    std::size_t n_bonds = 0, n_intact_at_start = 0, n_families_cut = 0;
  };

  TEST(PreconditionerMatrix, CellsOfOneShapeShareTheirStiffness)
  {
    // 16 x 16 cells with widths 1, 2, 1, 2, ... and heights 1, 2, 4, 1, ...:
    // integer coordinates, so six shapes, each cell a translate of one of
    // them to the bit. The cell matrices are computed once per shape
    // (add_cell_stiffness(): 256 cells or more, at most a quarter of them
    // shapes); the matrix must be the sum of every cell's own stiffness.
    std::vector<std::vector<double>> steps(2);
    for (unsigned int i = 0; i < 16; ++i)
      {
        steps[0].push_back(1. + i % 2);
        steps[1].push_back(double(1u << (i % 3)));
      }
    Point<2> far;
    for (unsigned int d = 0; d < 2; ++d)
      for (const double h : steps[d])
        far[d] += h;
    Plate plate(
      {}, false, std::make_shared<Recorder>(), {}, [&](Triangulation<2> &tria) {
        GridGenerator::subdivided_hyper_rectangle(
          tria, steps, Point<2>(), far, true);
      });
    const auto &dofs = plate.system->dof_handler();
    ASSERT_EQ(dofs.get_triangulation().n_active_cells(), 256u);

    // Each cell's own stiffness (deal.II's FEValues on the cell itself),
    // summed; DoFs at x = 0 are held, their rows and columns left out.
    FE::ElasticMaterial material;
    material.youngs_modulus = 1e9;
    material.poissons_ratio = 0.25;
    material.plane_stress   = true;
    std::map<std::pair<types::global_dof_index, types::global_dof_index>,
             double>
                                         reference;
    std::set<types::global_dof_index>    held;
    std::vector<double>                  K;
    std::vector<types::global_dof_index> cell_dofs;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        const auto &fe = cell->get_fe();
        FEValues<2> fv(plate.system->mapping()[cell->active_fe_index()],
                       fe,
                       QGauss<2>(2),
                       update_gradients | update_JxW_values);
        fv.reinit(cell);
        FE::cell_stiffness(fv, material, K);
        cell_dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(cell_dofs);
        for (unsigned int i = 0; i < cell_dofs.size(); ++i)
          {
            if (cell->vertex(fe.system_to_component_index(i).second)[0] == 0.)
              held.insert(cell_dofs[i]);
            for (unsigned int j = 0; j < cell_dofs.size(); ++j)
              reference[{cell_dofs[i], cell_dofs[j]}] +=
                K[i * cell_dofs.size() + j];
          }
      }
    ASSERT_FALSE(held.empty());

    const Epetra_CrsMatrix &A =
      plate.system->preconditioner_matrix().trilinos_matrix();
    double largest = 0., difference = 0.;
    for (const auto &[entry, value] : reference)
      {
        if (held.count(entry.first) || held.count(entry.second))
          continue;
        int     n = 0;
        double *v = nullptr;
        int    *c = nullptr;
        A.ExtractMyRowView(A.LRID(int(entry.first)), n, v, c);
        double found = 0.;
        for (int e = 0; e < n; ++e)
          if (A.GCID(c[e]) == int(entry.second))
            found = v[e];
        largest    = std::max(largest, std::abs(value));
        difference = std::max(difference, std::abs(found - value));
      }
    EXPECT_GT(largest, 0.);
    EXPECT_LT(difference, 1e-13 * largest);
  }

  TEST(PreconditionerMatrix, PreparedAtSetUpTheModelSeesItsWholeFamilies)
  {
    for (const bool prepared : {false, true})
      {
        auto  recorder = std::make_shared<Recorder>();
        Plate plate(test_cracks(), prepared, recorder);
        EXPECT_GT(recorder->n_bonds, 0u) << prepared;
        EXPECT_EQ(recorder->n_intact_at_start, recorder->n_bonds) << prepared;
        EXPECT_GT(recorder->n_families_cut, 0u) << prepared;
        EXPECT_GT(plate.system->size().n_broken_bonds, 0u) << prepared;
      }
  }

  TEST(PreconditionerMatrix, PreparedAtSetUpGivesTheSameSolve)
  {
    // The cracked plate pulled at its right edge, one linear solve, with
    // the AMG built at set-up and at the first solve: the same iterations
    // and the same displacements, bit for bit.
    Coupling::BoundaryCondition<2> pull;
    pull.name         = "right";
    pull.boundary_ids = {1};
    pull.component    = 0;
    pull.expression   = "1e-3";
    std::vector<TrilinosWrappers::MPI::Vector> u(2);
    std::vector<unsigned int>                  iterations(2);
    for (const bool prepared : {false, true})
      {
        Plate plate(test_cracks(), prepared, nullptr, {pull});
        auto &system = *plate.system;
        TrilinosWrappers::MPI::Vector r, du;
        system.initialize_vector(u[prepared]);
        system.initialize_vector(r);
        system.apply_dirichlet(u[prepared], 1.);
        const double first   = system.residual(u[prepared], 1., r, true);
        iterations[prepared] = system.solve_linear(du, r);
        u[prepared] += du;
        EXPECT_LT(system.residual(u[prepared], 1., r, false), 1e-10 * first)
          << prepared;
      }
    EXPECT_GT(iterations[0], 0u);
    EXPECT_EQ(iterations[0], iterations[1]);
    EXPECT_GT(u[0].linfty_norm(), 0.);
    u[1] -= u[0];
    EXPECT_EQ(u[1].linfty_norm(), 0.);
  }
} // namespace
