// SPDX-License-Identifier: LGPL-2.1-or-later
//
// step-2: quasi-static crack growth with a crack criterion of your own
// ====================================================================
//
// Introduction
// ------------
//
// pdfem decides where bonds break with a crack criterion: after every
// converged equilibrium, the Simulator hands the criterion the coupled
// system and the nodal results, and the criterion breaks bonds. The library
// comes with three (`pdfem --list-plugins`): `mcts` (K_I, K_II by the
// interaction integral and the maximum circumferential tensile stress),
// `max principal stress` (virtual cracks through the most stressed bonds)
// and `critical stretch` (a bond breaks when it is stretched too far).
//
// Criteria are plugins. Each one is a class derived from
// pdfem::Fracture::Criterion<dim> that registers itself under a name with
// PDFEM_REGISTER_CRITERION at the end of its own file; a run then selects it
// by that name (`Fracture/Criterion` in a scene file, RunSetup::fracture in
// a program), and the registry lists it with the others. A program linked
// against pdfem registers its own criteria the same way: the registration
// runs when the program starts, before main(). This tutorial writes one.
//
// The criterion: bond strain energy
// ---------------------------------
//
// In bond-based peridynamics (the prototype microelastic brittle model of
// Silling & Askari, Comput. Struct. 2005) a bond xi = x_m - x_k with the
// stretch
//
//   s = (|xi + eta| - |xi|) / |xi|,        eta = u_m - u_k,
//
// stores the elastic energy (the micropotential)
//
//   w = c s^2 |xi| / 2.
//
// The built-in `critical stretch` criterion breaks a bond when s exceeds a
// critical stretch s_0, the same for every bond. This tutorial's criterion
// breaks a bond when its ENERGY w exceeds a critical energy w_0, the same
// for every bond of a family: long bonds, which store more energy at the
// same stretch, break first. Writing w_0 as the energy of a bond as long as
// the horizon delta at the stretch s_c,
//
//   w > w_0 = c s_c^2 delta / 2   <=>   s > s_c sqrt(delta / |xi|),
//
// so that the micromodulus c (and with it E) drops out: the criterion needs
// only s_c, which is `Fracture/Critical stretch`. The energy a crack needs
// follows as in Silling & Askari: break every bond that crosses a unit
// length of crack (in 2D, per unit thickness),
//
//   G_c = 2 int_0^delta int_z^delta int_0^acos(z/xi) w_0 xi dtheta dxi dz
//       = 2 w_0 delta^3 / 3,  and with c = 9 E / (pi delta^3) (plane
//                             stress, Ha & Bobaru, IJF 2010)
//   G_c = 3 E delta s_c^2 / pi,   i.e.   s_c = sqrt(pi G_c / (3 E delta)).
//
// (For the uniform s_0 the same integral gives Ha & Bobaru's
// s_0 = sqrt(4 pi G_c / (9 E delta)): both criteria agree for bonds of
// length 3 delta / 4.) PDLSM, the PD model of pdfem, has no bond energies of
// its own, so here, as in the built-in criterion, the bond-based energy is
// a measure of failure, not the model's energy. Only the present state
// enters: the threshold depends on no load history, and a bond once broken
// stays broken.
//
// The criterion also tells the driver how far the load is from the next
// break. For a load proportional to the load factor t, linear elasticity
// makes every stretch proportional to t, so bonds first break at
//
//   t_c = t / max_bonds (s / s_c(xi)),   s_c(xi) = s_c sqrt(delta / |xi|),
//
// (critical_load_ratio = t_c / t), and the `quasi-static` driver jumps
// straight there (PDLSM-FEM's rule) instead of creeping up in small
// increments. Once bonds break, the driver holds the load and finds
// equilibrium again, which may break more bonds: the crack grows at constant
// load until it arrests or cuts the body in two.
//
// The problem
// -----------
//
// A square plate [-0.5, 0.5]^2 (aluminium: E = 70 GPa, nu = 0.33, plane
// stress; G_c = 10 kJ/m^2) with an edge crack of length a = 0.2 from
// (-0.5, 0), its top and bottom edges pulled by a normal traction
// sigma = 10 t MPa. The band |y| < 0.15 around the crack's plane is PD; the
// rest is FE. The mesh is deal.II's GridGenerator::subdivided_hyper_rectangle
// (40 x 41 cells, an odd number across so that the crack on y = 0 runs
// between rows of nodes), which shows the second way to make a mesh besides
// gmsh: any deal.II triangulation will do.
//
// Linear elastic fracture mechanics predicts when the crack starts: at
// K_I = sigma sqrt(pi a) F(a/W) = sqrt(E G_c), with the handbook factor of
// an edge crack in a long strip (Brown & Srawley, in Tada, Paris & Irwin,
// The Stress Analysis of Cracks Handbook, 3rd ed., 2000, p. 2.10)
//
//   F(l) = 1.12 - 0.231 l + 10.55 l^2 - 21.72 l^3 + 30.39 l^4,  F(0.2) = 1.37,
//
// i.e. at sigma_c = 24.4 MPa, t = 2.44 (an estimate: this plate is square,
// not a long strip). Under a constant traction K_I grows with the crack, so
// once it runs, it runs through the plate at that load.
//
// The program prints the registered criteria (its own among the built-in
// ones), runs the plate, and reads back how many bonds its criterion broke.

#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/mpi_startup.h>
#include <pdfem/fracture/criterion.h>
#include <pdfem/pd/families.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace Step2
{
  using namespace dealii;
  namespace Fracture = pdfem::Fracture;

  // The criterion class
  // -------------------
  //
  // A criterion is a class template on the dimension, because the registry
  // holds one for 2D and one for 3D (register_criterion() instantiates
  // both). It overrides evaluate(), the one pure virtual function, and
  // optionally what it adds to the outputs: history.csv columns, a fragment
  // of the progress line and members of summary.json's "final" object.
  template <int dim>
  class BondStrainEnergy : public Fracture::Criterion<dim>
  {
  public:
    // initialize() receives the parsed `subsection Fracture` (here: filled
    // by the program). A criterion validates what it needs and throws
    // InputError naming the parameter otherwise, before any work is done.
    // This one needs `Critical stretch`.
    void
    initialize(const Fracture::Settings &settings,
               const std::string        &file) override
    {
      Fracture::Criterion<dim>::initialize(settings, file);
      if (!(settings.critical_stretch > 0.))
        throw pdfem::InputError(file,
                                "Fracture/Critical stretch",
                                "is not positive (the bond strain energy "
                                "criterion needs it)",
                                "s_c > 0: the critical stretch of a bond as "
                                "long as the horizon");
    }

    // evaluate() is called after every converged equilibrium (and, in
    // dynamic runs, after every time step) on every rank. Each rank holds
    // the families of the PD nodes it owns: system.families() lists them in
    // compressed rows (owner k, then its members m with a flag `intact` per
    // bond). The nodal results (reference positions, displacements,
    // stresses) are replicated, so any node can be read, and so are the
    // horizons. The largest s / s_c(xi) is reduced over the ranks; bonds are
    // broken by system.break_bonds_if(), which applies a predicate to this
    // rank's intact bonds and returns the number broken on all ranks. Both
    // are collective: every rank must call them.
    Fracture::Assessment
    evaluate(Fracture::CrackGrowth<dim> &,
             pdfem::Coupling::CoupledSystem<dim>      &system,
             const pdfem::Coupling::NodalResults<dim> &results,
             const bool                                allow_growth) override
    {
      const double               s_c   = this->settings().critical_stretch;
      const std::vector<double> &delta = system.horizons(); // 0 at FE nodes

      // sqrt(w / w_0) = s / s_c(xi) of the bond (k, m); w_0 with the larger
      // of the two horizons, so that the value is symmetric in k and m and
      // both directions of a bond between two PD nodes break together.
      const auto energy_ratio = [&](const unsigned int k,
                                    const unsigned int m) {
        const Tensor<1, dim> xi = results.position[m] - results.position[k];
        const Tensor<1, dim> eta =
          results.displacement[m] - results.displacement[k];
        const double stretch = ((xi + eta).norm() - xi.norm()) / xi.norm();
        const double horizon = std::max(delta[k], delta[m]);
        return stretch / (s_c * std::sqrt(horizon / xi.norm()));
      };

      const pdfem::PD::Families &f         = system.families();
      double                     max_ratio = 0.;
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
          if (f.intact[b])
            max_ratio =
              std::max(max_ratio, energy_ratio(f.owners[o], f.members[b]));
      const MPI_Comm comm =
        system.dof_handler().get_triangulation().get_communicator();

      Fracture::Assessment a;
      a.max_driving_value   = Utilities::MPI::max(max_ratio, comm);
      a.critical_load_ratio = a.max_driving_value > 0. ?
                                1. / a.max_driving_value :
                                std::numeric_limits<double>::infinity();
      // Which bonds break: those above the threshold, but of them only the
      // most critical, whose ratio is at least `window` times the largest.
      // Breaking every bond above the threshold at once lets damage spread over
      // the whole region that is critical in this state; breaking the worst
      // ones and finding equilibrium again (the driver holds the load while
      // bonds break, and raises it only when nothing breaks) lets the crack
      // tip, where the stretch concentrates anew after every break, lead. This
      // is how lattice models of fracture break their elements (Schlangen &
      // Garboczi, Eng. Fract. Mech. 1997). Either way, at every load the
      // final state has no bond above the threshold. allow_growth is false
      // where the driver only wants to know how close the state is to
      // breaking.
      const double window    = 0.75;
      const double threshold = std::max(1., window * a.max_driving_value);
      if (allow_growth)
        a.broken_bonds = system.break_bonds_if(
          [&](const unsigned int k, const unsigned int m) {
            return energy_ratio(k, m) > threshold;
          });
      bonds_broken += a.broken_bonds;
      return a;
    }

    // The outputs. history.csv gets a column with the largest s / s_c(xi)
    // at every step (it reaches 1 where bonds break), the progress line the
    // same number, and summary.json's "final" the number of bonds this
    // criterion broke (those cut by the initial crack are not counted).
    std::vector<std::string>
    history_columns(const Fracture::CrackGrowth<dim> &) const override
    {
      return {"max_energy_stretch_ratio"};
    }

    void
    history_values(const Fracture::CrackGrowth<dim> &,
                   const Fracture::Assessment &assessment,
                   std::vector<double>        &row) const override
    {
      row.push_back(assessment.max_driving_value);
    }

    std::string
    progress(const Fracture::CrackGrowth<dim> &,
             const Fracture::Assessment &assessment) const override
    {
      std::ostringstream s;
      s << "  s/s_c(xi) " << std::setprecision(3)
        << assessment.max_driving_value;
      return s.str();
    }

    void
    write_final(const Fracture::CrackGrowth<dim> &,
                const Fracture::Assessment &assessment,
                pdfem::IO::JsonWriter      &json) const override
    {
      json.value("max_energy_stretch_ratio", assessment.max_driving_value);
      json.value("bonds_broken_by_criterion", bonds_broken);
    }

    // What the program reads back after the run.
    unsigned long
    n_bonds_broken() const
    {
      return bonds_broken;
    }

  private:
    unsigned long bonds_broken = 0;
  };
} // namespace Step2

// The registration: at namespace scope, once, in the file that defines the
// criterion. The name is what `Fracture/Criterion` takes; the description
// is the line `pdfem --list-plugins` (and the listing below) prints.
PDFEM_REGISTER_CRITERION(Step2::BondStrainEnergy,
                         "bond strain energy",
                         "(tutorial step-2) a bond breaks when its energy "
                         "c s^2 |xi| / 2 exceeds that of a bond as long as the "
                         "horizon at 'Critical stretch'.")


namespace Step2
{
  // The run
  // -------
  //
  // The set-up follows step-1: a RunSetup filled in code. New here are the
  // deal.II mesh (boundary ids from `colorize`: 0 left, 1 right, 2 bottom,
  // 3 top), the initial crack and the `Fracture` settings.
  //
  // The material: aluminium, with a fracture energy G_c [J/m^2].
  constexpr double youngs_modulus  = 70e9;
  constexpr double poissons_ratio  = 0.33;
  constexpr double fracture_energy = 1e4;

  pdfem::RunSetup<2>
  make_setup(MPI_Comm comm)
  {
    pdfem::RunSetup<2> setup;
    setup.file    = "step-2";
    setup.name    = "step-2";
    setup.out_dir = "output-step-2";

    GridGenerator::subdivided_hyper_rectangle(setup.create_triangulation(comm),
                                              {40, 41},
                                              Point<2>(-0.5, -0.5),
                                              Point<2>(0.5, 0.5),
                                              /*colorize=*/true);
    setup.cell_is_pd.assign(setup.tria->n_active_cells(), false);
    for (const auto &cell : setup.tria->active_cell_iterators())
      setup.cell_is_pd[cell->active_cell_index()] =
        std::abs(cell->center()[1]) < 0.15;

    auto &settings                   = setup.settings;
    settings.source_file             = setup.file;
    settings.material.youngs_modulus = youngs_modulus;
    settings.material.poissons_ratio = poissons_ratio;
    settings.material.plane_stress   = true;
    settings.horizon_factor          = 3.;

    // The initial crack: a segment from the left edge; every bond that
    // crosses it is cut before the run (Mesh::Crack, as `Peridynamics/
    // Pre-existing cracks` gives it).
    pdfem::Mesh::Crack<2> crack;
    crack.points = {{Point<2>(-0.5, 0.), Point<2>(-0.3, 0.)}};
    settings.cracks.push_back(crack);

    // Loads: the top and bottom edges are pulled by a normal traction of
    // 10 t MPa each. The loads balance, so the two nodes that remove the
    // rigid-body motions, the mid-points of the bottom edge (held in x and
    // y) and of the top edge (held in x), carry no force. The load is
    // proportional to t, as the jump to the critical load assumes.
    // (The name of a point condition is what history.csv and summary.json
    // call its reaction.)
    const auto pin = [](const std::string &name,
                        const Point<2>    &p,
                        const unsigned int component) {
      pdfem::Coupling::BoundaryCondition<2> bc;
      bc.name       = name;
      bc.at_point   = true; // a mesh node must be there
      bc.point      = p;
      bc.component  = component;
      bc.expression = "0";
      return bc;
    };
    settings.dirichlet.push_back(pin("bottom mid", Point<2>(0., -0.5), 0));
    settings.dirichlet.push_back(pin("bottom mid", Point<2>(0., -0.5), 1));
    settings.dirichlet.push_back(pin("top mid", Point<2>(0., 0.5), 0));
    for (const unsigned int edge : {2, 3}) // bottom, top
      {
        pdfem::Coupling::BoundaryCondition<2> pull;
        pull.name         = edge == 2 ? "bottom" : "top";
        pull.boundary_ids = {edge};
        pull.component    = 2; // the outward normal
        pull.expression   = "1e7 * t";
        settings.traction.push_back(pull);
      }

    // The criterion, by its name, exactly as a built-in one is chosen; and
    // its parameter, s_c = sqrt(pi G_c / (3 E delta)) for G_c = 10 kJ/m^2
    // and the horizon of the interior nodes, delta = 3 sqrt(h_x h_y).
    const double delta       = 3. * std::sqrt(1. / 40. * 1. / 41.);
    setup.fracture.criterion = "bond strain energy";
    setup.fracture.critical_stretch =
      std::sqrt(M_PI * fracture_energy / (3. * youngs_modulus * delta));

    // The `quasi-static` driver: at most 150 equilibria ("steps"), the load
    // factor growing by 0.5 where nothing breaks (or jumping to the
    // critical load when that is nearer), held where bonds broke. The run
    // ends when the plate is cut in two (exit state "separated"). Fields
    // are written every 10th step, so that ParaView can show the crack
    // growing (solution.pvd).
    setup.driver.type                    = "quasi-static";
    setup.driver.load_steps              = 150;
    setup.driver.load_increment          = 0.5;
    setup.driver.jump_to_critical_load   = true;
    setup.driver.hold_load_while_growing = true;
    setup.write_vtu                      = true;
    setup.write_every                    = 10; // fields every 10th step
    return setup;
  }
} // namespace Step2


int
main(int argc, char **argv)
{
  using namespace dealii;
  pdfem::prepare_mpi_singleton_startup();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
  ConditionalOStream pcout(std::cout, root);

  // The registry now holds the program's criterion next to the library's:
  // the same listing `pdfem --list-plugins` prints.
  if (root)
    {
      std::cout << "Crack criteria (Fracture/Criterion; also 'none'):\n";
      pdfem::Fracture::registry<2>().list(std::cout);
    }

  try
    {
      pdfem::Simulator<2> simulator(Step2::make_setup(comm), comm);
      simulator.set_quiet(argc > 1 && std::string(argv[1]) == "--quiet");
      const int status = simulator.run();

      // The criterion the Simulator created by name is the program's own
      // class: read its count back through the Simulator.
      const auto *criterion = dynamic_cast<const Step2::BondStrainEnergy<2> *>(
        simulator.get_criterion());
      if (criterion == nullptr)
        {
          pcout << "step-2: error: the run's criterion is not this program's "
                << "'bond strain energy'" << std::endl;
          return 1;
        }
      const pdfem::Coupling::CoupledSystem<2> &system = simulator.get_system();
      const unsigned long n_broken = criterion->n_bonds_broken();
      const unsigned long n_all    = system.size().n_broken_bonds;
      const unsigned int  pieces   = simulator.get_assessment().pieces;
      pcout << "step-2: the criterion 'bond strain energy' broke " << n_broken
            << " bonds (" << n_all - n_broken << " more were cut by the "
            << "initial crack); max damage " << std::setprecision(3)
            << system.max_damage() << "; load factor "
            << simulator.get_load_factor() << "; the plate is in " << pieces
            << (pieces == 1 ? " piece" : " pieces") << "\n"
            << "  results in output-step-2/" << std::endl;
      return status;
    }
  catch (const pdfem::InputError &e)
    {
      pcout << "step-2: error: " << e.what() << std::endl;
      return 2;
    }
}
