// SPDX-License-Identifier: LGPL-2.1-or-later
// RNP tangent assembly: analytic (specs/000 eqs. (33)-(34) corrected) against
// central finite differences of the nodal forces (each DoF perturbed both
// ways, the forces of the node and of its family recomputed: the usual
// "local" numerical tangent, O(N M^2 d) bond evaluations against O(N M)),
// on the pre-cracked plate of specs/000 §4.5 (76 x 76 = 5776 nodes,
// h = 0.2, horizon 0.8, 131100 bonds) in a softened state (the converged
// state of a force-controlled run past the onset of softening).
//
// usage: pdfem_rnp_tangent_benchmark [OUT.csv]   (prints a Markdown table)
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/drivers/newton_driver.h>
#include <pdfem/mesh/cracks.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>

using namespace pdfem;
using dealii::Point;

namespace
{
  double
  seconds(const std::function<void()> &f, const unsigned int repeat)
  {
    const auto start = std::chrono::steady_clock::now();
    for (unsigned int k = 0; k < repeat; ++k)
      f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
             .count() /
           repeat;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string out = argc > 1 ? argv[1] : "rnp_tangent.csv";

  // ---- the plate of specs/000 §4.5 (as tests/unit/rnp_test.cc)
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
  loads.prescribed = [](double, std::vector<double> &) {};
  PDModels::RNPSettings s;
  s.C       = 3e8;
  s.beta    = 10.;
  s.horizon = 0.8;

  // ---- a softened state: 8 load steps of 4e6 N (paper normalisation:
  // first softening at step 7, specs/000 §4.5)
  Drivers::Settings settings;
  settings.type               = "newton";
  settings.load_steps         = 1;
  settings.residual_tolerance = 1e-10;
  settings.max_iterations     = 20;
  Drivers::SystemInterface::Vector u;
  const double                     F_total = 8.;
  loads.external_force = [b, F_total](double t, std::vector<double> &f) {
    for (std::size_t d = 0; d < f.size(); ++d)
      f[d] = F_total * t * b[d];
  };
  Coupling::RNPSystem<2> loaded(
    x,
    V,
    s,
    [crack](const Point<2> &p, const Point<2> &q) { return crack.cuts(p, q); },
    loads);
  loaded.initialize_vector(u);
  settings.load_steps = 8;
  Drivers::NewtonDriver driver(settings);
  driver.run(
    loaded, u, [](const Drivers::StepRecord &) {}, &loaded);
  const std::vector<double> state(u.begin(), u.end());
  const auto                d     = loaded.damage(state);
  const double              max_d = *std::max_element(d.begin(), d.end());

  // ---- timings
  std::vector<double> f;
  const double t_force = seconds([&] { loaded.internal_force(state, f); }, 10);
  const double t_analytic = seconds(
    [&] { loaded.assemble_tangent(state, Coupling::RNPTangent::analytic); },
    10);
  Solvers::BandedLDLT analytic = loaded.matrix();
  const double        t_fd     = seconds(
    [&] {
      loaded.assemble_tangent(state, Coupling::RNPTangent::finite_difference);
    },
    1);
  const Solvers::BandedLDLT &fd   = loaded.matrix();
  double                     diff = 0., norm = 0.;
  for (std::size_t i = 0; i < analytic.size(); ++i)
    for (std::size_t j = i >= analytic.bandwidth() ? i - analytic.bandwidth() :
                                                     0;
         j <= i;
         ++j)
      {
        const double a = analytic(i, j), c = fd(i, j);
        diff += (a - c) * (a - c);
        norm += a * a;
      }
  Solvers::BandedLDLT factor   = analytic;
  const double        t_factor = seconds([&] { factor.factorize(); }, 1);

  const double  ratio = t_fd / t_analytic;
  std::ofstream csv(out);
  csv << "nodes,bonds,cut_bonds,free_dofs,bandwidth,max_damage,"
         "internal_force_s,analytic_tangent_s,fd_tangent_s,ratio,"
         "relative_difference,ldlt_factorisation_s\n"
      << x.size() << "," << loaded.n_bonds() << "," << loaded.n_cut_bonds()
      << "," << analytic.size() << "," << analytic.bandwidth() << "," << max_d
      << "," << t_force << "," << t_analytic << "," << t_fd << "," << ratio
      << "," << std::sqrt(diff / norm) << "," << t_factor << "\n";
  std::cout << "| nodes | bonds (cut) | free DoFs | band | max damage | "
               "f_int [s] | analytic K [s] | FD K [s] | FD / analytic | "
               "|K_FD - K|_F / |K|_F | LDL^T [s] |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|\n"
            << "| " << x.size() << " | " << loaded.n_bonds() << " ("
            << loaded.n_cut_bonds() << ") | " << analytic.size() << " | "
            << analytic.bandwidth() << " | " << max_d << " | " << t_force
            << " | " << t_analytic << " | " << t_fd << " | " << ratio << " | "
            << std::sqrt(diff / norm) << " | " << t_factor << " |\n";
  return 0;
}
