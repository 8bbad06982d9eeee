// SPDX-License-Identifier: LGPL-2.1-or-later
// Helpers of the PD model tests (pd_models_test.cc, pdlsm_energy_test.cc):
// a model from Peridynamics parameters, a small coupled plate, a nodal
// field over every node.
#ifndef PDFEM_TESTS_UNIT_PD_MODELS_TEST_TOOLS_H
#define PDFEM_TESTS_UNIT_PD_MODELS_TEST_TOOLS_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;

  /// The model @p name with its parameters from @p entries (Peridynamics
  /// subsection, "RNP/C" style paths for its own subsections).
  template <int dim = 2>
  std::shared_ptr<PDModels::Interface<dim>>
  make_model(const std::string                                      &name,
             const std::vector<std::pair<std::string, std::string>> &entries)
  {
    ParameterHandler prm;
    prm.enter_subsection("Peridynamics");
    PDModels::registry<dim>().declare_parameters(prm);
    for (const auto &[path, value] : entries)
      {
        const auto slash = path.find('/');
        if (slash == std::string::npos)
          prm.set(path, value);
        else
          {
            prm.enter_subsection(path.substr(0, slash));
            prm.set(path.substr(slash + 1), value);
            prm.leave_subsection();
          }
      }
    std::shared_ptr<PDModels::Interface<dim>> model =
      PDModels::create<dim>(name, "test.prm");
    model->parse_parameters(prm, "test.prm");
    prm.leave_subsection();
    return model;
  }

  /// The settings of the tests' PD bodies: E = 1e3, Poisson's ratio @p nu,
  /// density 1, plane stress (plane strain with @p plane_strain), horizon
  /// factor @p m, the PD model @p model, the direct solver.
  template <int dim>
  Coupling::Settings<dim>
  body_settings(const double                                     nu,
                const double                                     m,
                const std::shared_ptr<PDModels::Interface<dim>> &model,
                const bool plane_strain = false)
  {
    Coupling::Settings<dim> settings;
    settings.material.youngs_modulus = 1e3;
    settings.material.poissons_ratio = nu;
    settings.material.plane_stress   = !plane_strain;
    settings.material.density        = 1.;
    settings.horizon_factor          = m;
    settings.pd_model                = model;
    settings.linear_solver.type      = "direct";
    return settings;
  }

  /// A 1 x 1 plate of 8 x 8 jittered quads, cells left of @p pd_left_of
  /// PD, nu = 1/3 (the bond-based value), with @p model.
  struct Plate
  {
    Plate(std::shared_ptr<PDModels::Interface<2>> model,
          const double                            pd_left_of = 2.)
      : tria(MPI_COMM_WORLD)
    {
      GridGenerator::subdivided_hyper_cube(tria, 8);
      GridTools::distort_random(0.15, tria, false, 7);
      std::vector<bool> pd(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        pd[cell->active_cell_index()] = cell->center()[0] < pd_left_of;
      Coupling::Settings<2> settings;
      settings.material.youngs_modulus = 1e3;
      settings.material.poissons_ratio = 1. / 3.;
      settings.material.plane_stress   = true;
      settings.horizon_factor          = 3.;
      settings.pd_model                = model;
      settings.linear_solver.type      = "direct";
      system = std::make_unique<Coupling::CoupledSystem<2>>(tria, pd, settings);
    }
    parallel::shared::Triangulation<2>          tria;
    std::unique_ptr<Coupling::CoupledSystem<2>> system;
  };

  /// A nodal field over every node, stored node by node.
  template <int dim = 2>
  struct Field
  {
    explicit Field(const unsigned int n_nodes)
      : values(dim * n_nodes)
      , index(n_nodes)
    {
      for (unsigned int k = 0; k < n_nodes; ++k)
        for (unsigned int c = 0; c < dim; ++c)
          index[k][c] = dim * k + c;
    }
    PDModels::NodalField<dim>
    field() const
    {
      return {values.data(), index.data()};
    }
    std::vector<double>                        values;
    std::vector<std::array<unsigned int, dim>> index;
  };

  /// max |tangent row - central differences of the force rows| relative to
  /// the largest tangent entry, over every owner and intact bond.
  inline double
  tangent_error(const PDModels::Interface<2> &model,
                const PD::Families           &f,
                Field<>                      &u,
                const double                  h)
  {
    const std::size_t         n = f.owners.size();
    std::vector<double>       fp(2 * n), fm(2 * n);
    std::vector<Tensor<2, 2>> blocks;
    double                    error = 0., scale = 0.;
    for (std::size_t o = 0; o < n; ++o)
      {
        model.tangent_row(o, u.field(), blocks);
        std::vector<unsigned int> columns{f.owners[o]};
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            columns.push_back(f.members[j]);
        EXPECT_EQ(blocks.size(), columns.size());
        for (std::size_t b = 0; b < columns.size(); ++b)
          for (unsigned int c = 0; c < 2; ++c)
            {
              double &x = u.values[2 * columns[b] + c];
              x += h;
              model.forces(o, o + 1, u.field(), fp.data());
              x -= 2. * h;
              model.forces(o, o + 1, u.field(), fm.data());
              x += h;
              for (unsigned int r = 0; r < 2; ++r)
                {
                  const double fd = (fp[2 * o + r] - fm[2 * o + r]) / (2. * h);
                  error = std::max(error, std::abs(fd - blocks[b][r][c]));
                  scale = std::max(scale, std::abs(blocks[b][r][c]));
                }
            }
      }
    EXPECT_GT(scale, 0.);
    return error / scale;
  }

  /// u = @p amplitude times a smooth field plus a random part.
  inline void
  deform(const Coupling::CoupledSystem<2> &system,
         Field<>                          &u,
         const double                      amplitude)
  {
    std::mt19937                           random(3);
    std::uniform_real_distribution<double> noise(-0.2, 0.2);
    for (unsigned int k = 0; k < u.index.size(); ++k)
      {
        const Point<2> p = system.node_position(k);
        u.values[2 * k]  = amplitude * (p[0] * p[1] + noise(random));
        u.values[2 * k + 1] =
          amplitude * (0.5 * p[0] * p[0] - p[1] + noise(random));
      }
  }

  /// Break every fifth intact bond of the PD nodes (both directions).
  inline void
  break_some_bonds(Coupling::CoupledSystem<2> &system)
  {
    system.break_bonds_if([](const unsigned int k, const unsigned int m) {
      return (k + m) % 5 == 0;
    });
    EXPECT_GT(system.families().n_broken(), 0u);
  }
} // namespace

#endif
