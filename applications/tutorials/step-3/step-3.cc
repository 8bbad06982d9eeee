// SPDX-License-Identifier: LGPL-2.1-or-later
//
// step-3: explicit dynamics and a postprocessor of your own
// =========================================================
//
// Introduction
// ------------
//
// What a run writes besides its solution comes from postprocessors: the
// VTU fields, the support reactions, the energy balance of a dynamic run,
// the monitor points. Each is a plugin, a class derived from
// pdfem::Postprocess::Interface<dim> that registers itself with
// PDFEM_REGISTER_POSTPROCESSOR at the end of its own file. Unlike drivers and
// crack criteria, which a run selects by name, every registered
// postprocessor is offered to every run, and its initialize() decides
// whether it takes part. A postprocessor reads the run through
// SimulatorAccess (the mesh, the coupled system, the solution, the step or
// time step, the output folder) and contributes
//
//   - columns of history.csv: history_columns() once, history_values() at
//     every recorded step or time step;
//   - members of summary.json: write_final() (into "final") and
//     write_sections() (top-level objects);
//   - files of its own: write_fields() at output times, finish() at the end.
//
// This tutorial writes one for explicit dynamics: the kinetic energy of the
// PD region, and that of the FE region, at every time step.
//
// Kinetic energy from displacements
// ---------------------------------
//
// The Simulator gives a postprocessor the displacement u^n after every time
// step (every_time_step()), but not the velocity. The `explicit` driver is
// the central difference method (Belytschko et al., Nonlinear Finite
// Elements, §6.2), which advances
//
//   v^{n+1/2} = v^{n-1/2} + dt a^n,     u^{n+1} = u^n + dt v^{n+1/2},
//
// so the difference of two successive displacements IS its half-step
// velocity: v^{n-1/2} = (u^n - u^{n-1}) / dt, exactly. With the lumped mass
// M (one value per DoF, CoupledSystem::lumped_mass()) the kinetic energy of
// a set S of DoFs is
//
//   T_S^{n-1/2} = 1/2 sum_{i in S} M_i (v_i^{n-1/2})^2   (times the thickness
//                                                         in 2D).
//
// S is either the DoFs of the nodes of PD cells (interface nodes included)
// or the rest. The driver's own `kinetic_energy` column (the `energy
// balance` postprocessor) uses the velocity at full steps, v^n, so the two
// sums differ by O(dt).
//
// The problem
// -----------
//
// A strip [-0.5, 0.5] x [-0.125, 0.125] (aluminium, plane stress, 2700
// kg/m^3), its left end held (rollers, and the mid-point pinned in y), is
// suddenly pulled at its right end by a normal traction sigma = 7 MPa from
// t = 0. A tension wave runs to the left at the bar speed
// c = sqrt(E / rho) = 5092 m/s; behind its front the material moves at
// v = sigma / (rho c) = 0.51 m/s, with the kinetic energy density
// rho v^2 / 2 = sigma^2 / (2 E) = 350 J/m^3 (the elementary theory of rods,
// e.g. Graff, Wave Motion in Elastic Solids, ch. 2). The band |x| < 0.1 is
// PD. So:
//
//   - until the front reaches x = 0.1, at t = 0.4 / c = 79 us, the PD
//     region is at rest;
//   - by t = 0.6 / c = 118 us the front has crossed it, and its kinetic
//     energy is 350 J/m^3 x 0.05 m^3 = 17.5 J;
//   - the wave reflects from the held end (t = 196 us), where the velocity
//     is zero and the stress doubles; the reflected front crosses the band
//     between 275 and 314 us and leaves it at rest again.
//
// The run ends at 350 us. The program runs the strip with the `explicit`
// driver, chosen by name; the postprocessor, registered below, takes part
// by itself.

#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/mpi_startup.h>
#include <pdfem/simulator/postprocess.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <iomanip>
#include <iostream>

namespace Step3
{
  using namespace dealii;

  // The postprocessor
  // -----------------
  //
  // Like a criterion, a postprocessor is a class template on the dimension:
  // PDFEM_REGISTER_POSTPROCESSOR registers it for 2D and 3D.
  template <int dim>
  class PDKineticEnergy : public pdfem::Postprocess::Interface<dim>
  {
  public:
    // initialize() is called once the coupled system exists. Returning false
    // leaves the postprocessor out of the run: this one takes part in
    // dynamic runs that have a PD region. It marks the DoFs of the PD nodes:
    // every DoF of a PD cell (the coupled system's DoFHandler knows every
    // cell on every rank, its triangulation being a shared one).
    bool
    initialize() override
    {
      const auto &system = this->get_system();
      if (!this->is_dynamic() || system.size().n_pd_cells == 0)
        return false;
      const DoFHandler<dim> &dofs = system.dof_handler();
      in_pd.assign(dofs.n_dofs(), false);
      std::vector<types::global_dof_index> indices;
      for (const auto &cell : dofs.active_cell_iterators())
        if (system.cell_is_pd()[cell->active_cell_index()])
          {
            indices.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(indices);
            for (const auto i : indices)
              in_pd[i] = true;
          }
      return true;
    }

    // Two history.csv columns. They come after the Simulator's own and the
    // other postprocessors' columns; a name must be unique in the file.
    std::vector<std::string>
    history_columns() override
    {
      return {"kinetic_energy_pd", "kinetic_energy_fe"};
    }

    // Every time step (recorded in history.csv or not, see `Driver/History
    // interval`): the half-step velocities from this displacement and the
    // last one, and the two sums. Only this rank's DoFs are summed; the
    // total over the ranks is a collective reduction, which every rank
    // reaches because every rank calls every_time_step().
    void
    every_time_step() override
    {
      const auto &record                         = this->get_time_step_record();
      const TrilinosWrappers::MPI::Vector &u     = this->get_solution();
      const IndexSet                       owned = u.locally_owned_elements();
      if (record.step == 0) // t = 0: at rest (no initial velocity here)
        {
          previous.resize(owned.n_elements());
          energy_pd = energy_fe = 0.;
        }
      else
        {
          // M is per unit thickness in 2D, as the driver's energies are.
          const auto  &mass = this->get_mutable_system().lumped_mass();
          double       pd = 0., fe = 0.;
          unsigned int local = 0;
          for (const auto i : owned)
            {
              const double v = (u[i] - previous[local]) / record.time_step;
              (in_pd[i] ? pd : fe) += 0.5 * mass[i] * v * v;
              ++local;
            }
          const double   thickness = this->get_system().thickness();
          const MPI_Comm comm      = this->get_mpi_communicator();
          energy_pd                = thickness * Utilities::MPI::sum(pd, comm);
          energy_fe                = thickness * Utilities::MPI::sum(fe, comm);
          // The largest, and when (half a step before the record's time).
          if (energy_pd > peak)
            {
              peak      = energy_pd;
              peak_time = record.time - 0.5 * record.time_step;
            }
        }
      unsigned int local = 0;
      for (const auto i : owned)
        previous[local++] = u[i];
    }

    // The values of a recorded step, in the order of history_columns().
    void
    history_values(std::vector<double> &row) override
    {
      row.push_back(energy_pd);
      row.push_back(energy_fe);
    }

    // Members of summary.json's "final" object (called on rank 0 only).
    void
    write_final(pdfem::IO::JsonWriter &json) const override
    {
      json.value("kinetic_energy_pd", energy_pd);
      json.value("kinetic_energy_pd_max", peak);
      json.value("kinetic_energy_pd_max_time", peak_time);
    }

    // The end of the run: a line on the terminal (rank 0), where a
    // postprocessor would also write a file of its own into
    // this->get_output_directory().
    void
    finish() override
    {
      if (this->is_root())
        std::cout << "pd kinetic energy: peak " << std::setprecision(4) << peak
                  << " J at t = " << peak_time << " s; at the end " << energy_pd
                  << " J" << std::endl;
    }

  private:
    std::vector<bool>   in_pd;    // by global DoF index
    std::vector<double> previous; // u^{n-1}, this rank's DoFs
    double              energy_pd = 0., energy_fe = 0.;
    double              peak = 0., peak_time = 0.;
  };
} // namespace Step3

// The registration. The name is what `pdfem --list-plugins` (and the
// registry) shows; the description one line of it.
PDFEM_REGISTER_POSTPROCESSOR(Step3::PDKineticEnergy,
                             "pd kinetic energy",
                             "(tutorial step-3) dynamic runs: kinetic energy "
                             "of the PD and the FE nodes, from half-step "
                             "velocities.")


namespace Step3
{
  // The run
  // -------
  //
  // A strip of 80 x 20 square cells (h = 0.0125 m) from deal.II's
  // GridGenerator (boundary ids: 0 left, 1 right, 2 bottom, 3 top), PD
  // where |x| < 0.1.
  pdfem::RunSetup<2>
  make_setup(MPI_Comm comm)
  {
    pdfem::RunSetup<2> setup;
    setup.file    = "step-3";
    setup.name    = "step-3";
    setup.out_dir = "output-step-3";

    GridGenerator::subdivided_hyper_rectangle(setup.create_triangulation(comm),
                                              {80, 20},
                                              Point<2>(-0.5, -0.125),
                                              Point<2>(0.5, 0.125),
                                              /*colorize=*/true);
    setup.cell_is_pd.assign(setup.tria->n_active_cells(), false);
    for (const auto &cell : setup.tria->active_cell_iterators())
      setup.cell_is_pd[cell->active_cell_index()] =
        std::abs(cell->center()[0]) < 0.1;

    auto &settings                   = setup.settings;
    settings.source_file             = setup.file;
    settings.material.youngs_modulus = 70e9;
    settings.material.poissons_ratio = 0.33;
    settings.material.density        = 2700; // a mass: dynamics needs it
    settings.material.plane_stress   = true;
    settings.horizon_factor          = 3.;

    pdfem::Coupling::BoundaryCondition<2> rollers;
    rollers.name         = "left";
    rollers.boundary_ids = {0};
    rollers.component    = 0;
    rollers.expression   = "0";
    settings.dirichlet.push_back(rollers);
    pdfem::Coupling::BoundaryCondition<2> pin;
    pin.name       = "(-0.5, 0)";
    pin.at_point   = true;
    pin.point      = Point<2>(-0.5, 0.);
    pin.component  = 1;
    pin.expression = "0";
    settings.dirichlet.push_back(pin);
    // In a dynamic run t is the physical time: a constant traction is a
    // step load applied at t = 0.
    pdfem::Coupling::BoundaryCondition<2> pull;
    pull.name         = "right";
    pull.boundary_ids = {1};
    pull.component    = 2; // normal
    pull.expression   = "7e6";
    settings.traction.push_back(pull);

    // The `explicit` driver (central difference, lumped mass). Time step
    // 0 = automatic: 0.9 times the critical step 2 / omega_max, omega_max^2
    // the largest eigenvalue of M^-1 K by power iterations. A history row
    // every step.
    setup.driver.type             = "explicit";
    setup.driver.time_step        = 0.;
    setup.driver.safety_factor    = 0.9;
    setup.driver.end_time         = 3.5e-4;
    setup.driver.history_interval = 1;
    setup.write_vtu               = false;
    return setup;
  }
} // namespace Step3


int
main(int argc, char **argv)
{
  using namespace dealii;
  pdfem::prepare_mpi_singleton_startup();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  ConditionalOStream               pcout(std::cout,
                           Utilities::MPI::this_mpi_process(comm) == 0);

  pcout << "Postprocessors (each takes part where it applies):\n";
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    pdfem::Postprocess::registry<2>().list(std::cout);

  try
    {
      pdfem::Simulator<2> simulator(Step3::make_setup(comm), comm);
      simulator.set_quiet(argc > 1 && std::string(argv[1]) == "--quiet");
      const int status = simulator.run();

      // The one-dimensional estimates of the introduction, for comparison.
      const double E = 70e9, rho = 2700., sigma = 7e6, volume = 0.2 * 0.25;
      const double c = std::sqrt(E / rho);
      pcout << std::setprecision(4) << "step-3: 1D theory: the wave (c = " << c
            << " m/s) crosses the PD band between t = " << 0.4 / c << " and "
            << 0.6 / c << " s; behind it the band holds "
            << sigma * sigma / (2. * E) * volume
            << " J of kinetic energy; the wave reflected at the held end "
            << "crosses it between " << 1.4 / c << " and " << 1.6 / c
            << " s and leaves it at rest\n"
            << "  history.csv: kinetic_energy_pd, kinetic_energy_fe in "
               "output-step-3/"
            << std::endl;
      return status;
    }
  catch (const pdfem::InputError &e)
    {
      pcout << "step-3: error: " << e.what() << std::endl;
      return 2;
    }
}
