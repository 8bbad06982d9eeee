// SPDX-License-Identifier: LGPL-2.1-or-later
// The soft-loaded pre-cracked plate of specs/000 §4.5 at the paper's
// resolution (76 x 76 nodes, h = 0.2, horizon 0.8, C = 3e8, beta = 10, J = 1;
// 208 nodes per side loaded by b_y = +-3.125e6 per 4e6 N, 32 clamped), run by
// the Newton driver to the end of the stable branch: steps of 4e6 N, cut by
// 10 (twice) when a step fails or is unstable. Prints one line per converged
// step (load, iterations, max damage, softened nodes) and the failure
// bracket, to compare with the spec's re-run (§7.11: paper normalisation
// first d > 1 at 28e6, failure in (39.2e6, 39.6e6); prototype first d > 1 at
// 40e6, failure in (53.24e6, 53.64e6)).
//
// usage: pdfem_rnp_plate_soft [paper|prototype]
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/drivers/newton_driver.h>
#include <pdfem/mesh/cracks.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

using namespace pdfem;
using dealii::Point;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool prototype    = argc > 1 && std::string(argv[1]) == "prototype";
  const unsigned int    n = 76;
  const double          h = 0.2;
  std::vector<Point<2>> x;
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      x.emplace_back(i * h, j * h);
  const std::vector<double> V(x.size(), h * h);
  Mesh::Crack<2>            crack;
  crack.points = {{Point<2>(0., 7.5), Point<2>(7.5, 7.5)}};
  Coupling::RNPSystem<2>::Loads loads;
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
  const unsigned int n_steps = prototype ? 16 : 12; // of 4e6 N
  loads.prescribed           = [](double, std::vector<double> &) {};
  loads.external_force       = [b, n_steps](double t, std::vector<double> &f) {
    for (std::size_t d = 0; d < f.size(); ++d)
      f[d] = n_steps * t * b[d];
  };
  PDModels::RNPSettings s;
  s.C       = 3e8;
  s.beta    = 10.;
  s.horizon = 0.8;
  s.scaling = prototype ? PDModels::RNPForceScaling::prototype :
                          PDModels::RNPForceScaling::paper;
  Coupling::RNPSystem<2> system(
    x,
    V,
    s,
    [crack](const Point<2> &p, const Point<2> &q) { return crack.cuts(p, q); },
    loads);
  Drivers::Settings settings;
  settings.type               = "newton";
  settings.load_steps         = n_steps;
  settings.residual_tolerance = 1e-10;
  settings.max_iterations     = 15;
  settings.max_step_cuts      = 2;
  settings.step_cut_factor    = 0.1;
  Drivers::NewtonDriver            driver(settings);
  Drivers::SystemInterface::Vector u;
  system.initialize_vector(u);
  std::printf(
    "%s normalisation\n  F [N]       iterations  max d     d>1 nodes\n",
    prototype ? "prototype" : "paper");
  try
    {
      driver.run(
        system,
        u,
        [&](const Drivers::StepRecord &r) {
          const std::vector<double> uu(u.begin(), u.end());
          system.update_damage_history(uu);
          const auto &d = system.damage_history();
          std::printf("  %.6g  %u  %.4f  %ld\n",
                      4e6 * n_steps * r.load_factor,
                      r.newton_iterations,
                      *std::max_element(d.begin(), d.end()),
                      std::count_if(d.begin(), d.end(), [](double v) {
                        return v > 1.;
                      }));
          std::fflush(stdout);
        },
        &system);
      std::printf("completed\n");
    }
  catch (const RunFailure &e)
    {
      std::printf("%s: last stable F = %.6g, failed F = %.6g\n",
                  e.exit_state.c_str(),
                  4e6 * n_steps * driver.outcome().last_stable_load,
                  4e6 * n_steps * driver.outcome().failure_load);
    }
  return 0;
}
