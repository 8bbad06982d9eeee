// SPDX-License-Identifier: LGPL-2.1-or-later
//
// step-1: a coupled PD-FE static solve, written as a program
// ==========================================================
//
// Introduction
// ------------
//
// The `pdfem` command reads a scene file (`.prm`), builds a run from it and
// runs it. This tutorial does the same by hand, in a `main()` with no
// parameter file at all, to show what a run is made of and how a program
// reads the results back. Everything the scene file would say is a line of
// C++ here: the mesh, which cells are peridynamic, the material, the
// boundary conditions and the driver.
//
// The problem is the classic one of a small circular hole in a plate under
// uniaxial tension sigma. Kirsch (1898) found that in an infinite plate the
// hoop stress on the hole edge peaks at the two points on the diameter
// normal to the load, at three times the remote stress:
//
//   sigma_xx(0, +-r) = 3 sigma        (Kirsch; e.g. Timoshenko & Goodier,
//                                      Theory of Elasticity, §35)
//
// A finite strip of width W concentrates the stress a little more. Heywood's
// finite-width formula (Heywood 1952; Peterson's chart 4.1) gives, on the net
// section W - d,
//
//   K_tn = 2 + (1 - d/W)^3,   sigma_max = K_tn sigma W / (W - d),
//
// which for the hole of this program, d/W = 0.1, is K_t = sigma_max / sigma
// = 2.729 / 0.9 = 3.032: within 1.1 % of Kirsch's 3.
//
// The method: the plate is one mesh. Finite elements (Q1) cover it, except
// near the hole, where the cells are peridynamic (the PDLSM model:
// peridynamic least squares minimisation, Liu & Xin, EFM 2021). PD and FE
// share the nodes of their interface, and one coupled system holds the FE
// cell terms, the PD family terms and the PD boundary terms (see
// doc/theory.md and Coupling::CoupledSystem). The PD region is where cracks
// would grow in a fracture run; here it is simply the region of the peak
// stress, so that the peak is a PD result.
//
// What the program does, in the order of the code below:
//
//   1. meshes `plate_with_hole.geo` with gmsh (Mesh::prepare_msh_file),
//      reads it into a parallel::shared::Triangulation and looks up the
//      boundary names (Mesh::read_physical_names);
//   2. marks the cells near the hole as PD (RunSetup::cell_is_pd);
//   3. sets the material, the PD discretisation and the boundary conditions
//      (Coupling::Settings, Coupling::BoundaryCondition);
//   4. chooses the driver by its name, "static", as a scene file's
//      `Driver/Type` would;
//   5. runs a pdfem::Simulator, which writes the usual outputs
//      (history.csv, summary.json, solution.pvd), and then reads the nodal
//      stresses back through the Simulator to compare the peak with the
//      formulas above.
//
// The same run as a scene file is applications/examples/plate_with_hole
// (a longer strip with a larger hole); source/scene/scene.cc shows how the
// `pdfem` command turns a `.prm` into the same RunSetup this program fills.

// The includes. `simulator.h` brings RunSetup and Simulator (and with them
// the coupled system's settings); `gmsh_input.h` the mesh functions;
// `mpi_startup.h` a start-up helper for runs without mpirun.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/mpi_startup.h>
#include <pdfem/mesh/gmsh_input.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/shared_tria.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

namespace Step1
{
  using namespace dealii;

  // The problem's data, in SI units. The geometry must match the `.geo`
  // script: a strip x in [-1, 1], y in [-0.5, 0.5] with a hole of radius
  // 0.05 at the origin.
  constexpr double half_length    = 1.;
  constexpr double width          = 1.;
  constexpr double hole_radius    = 0.05;
  constexpr double youngs_modulus = 70e9; // aluminium
  constexpr double poissons_ratio = 0.33;
  constexpr double tension        = 7e6; // sigma [Pa] on the right end
  // The PD region: the cells whose centre lies within this distance of the
  // hole centre (three hole radii: the peak and its gradient are inside,
  // and so is more than a horizon of material around the hole edge).
  constexpr double pd_radius = 3. * hole_radius;


  // Step 1: the mesh
  // ----------------
  //
  // gmsh meshes the `.geo` script into a `.msh` file in the output folder.
  // Only rank 0 calls gmsh; the others wait for the file and read it too,
  // because a parallel::shared::Triangulation keeps every cell on every rank
  // (each rank then owns a METIS partition of them, as the `pdfem` command
  // does). The boundary ids of the mesh are the tags of its physical curves,
  // whose names read_physical_names() returns.
  std::unique_ptr<parallel::shared::Triangulation<2>>
  make_mesh(const std::string          &geo_file,
            const std::string          &out_dir,
            MPI_Comm                    comm,
            pdfem::Mesh::PhysicalNames &names)
  {
    std::string msh, error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // dimension 2, mesh size factor 1 (gmsh's -clscale): the sizes
          // of the script as they are.
          msh = pdfem::Mesh::prepare_msh_file(
            geo_file, 2, 1., out_dir, "step-1", "mesh");
        }
      catch (const pdfem::InputError &e)
        {
          error = e.what();
        }
    // Every rank learns whether gmsh succeeded, and where the mesh is.
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw pdfem::InputError("", "", error);
    msh = Utilities::MPI::broadcast(comm, msh, 0);

    names     = pdfem::Mesh::read_physical_names(msh, 2);
    auto tria = std::make_unique<parallel::shared::Triangulation<2>>(
      comm,
      Triangulation<2>::none,
      false,
      parallel::shared::Triangulation<2>::partition_metis);
    pdfem::Mesh::read_msh<2>(msh, *tria);
    return tria;
  }


  // Step 2: the PD region
  // ---------------------
  //
  // RunSetup::cell_is_pd has one flag per active cell, indexed by
  // `cell->active_cell_index()`. A scene file names mesh regions instead
  // (`Mesh/PD regions`); a program may use any rule. Here: the cells whose
  // centre is within pd_radius of the hole centre.
  std::vector<bool>
  mark_pd_cells(const Triangulation<2> &tria)
  {
    std::vector<bool> cell_is_pd(tria.n_active_cells(), false);
    for (const auto &cell : tria.active_cell_iterators())
      cell_is_pd[cell->active_cell_index()] = cell->center().norm() < pd_radius;
    return cell_is_pd;
  }


  // Step 3: material, peridynamics, boundary conditions
  // ---------------------------------------------------
  //
  // A boundary condition names a set of the mesh and one displacement
  // component (0 = x, 1 = y; for tractions also dim = the outward normal)
  // with a muparser expression of x, y, z and the load factor t. Its set is
  // either boundary ids (here looked up by the names of the `.geo`), or one
  // node at a point.
  //
  // The supports are those of a strip in uniform tension: rollers on the
  // left end (u_x = 0) and the node at its mid-point (-1, 0) pinned in y.
  // That removes the rigid-body motions without holding the Poisson
  // contraction, so both ends carry exactly uniform stress. The right end
  // is pulled by the normal traction sigma; the hole edge and the long
  // sides are free.
  pdfem::Coupling::Settings<2>
  make_settings(const pdfem::Mesh::PhysicalNames &names)
  {
    pdfem::Coupling::Settings<2> settings;
    settings.source_file = "step-1"; // named in error messages

    // Isotropic elasticity in plane stress, for a plate 1 m thick (reactions
    // and energies are reported for this thickness).
    settings.material.youngs_modulus = youngs_modulus;
    settings.material.poissons_ratio = poissons_ratio;
    settings.material.plane_stress   = true;
    settings.material.thickness      = 1.;

    // PDLSM: the horizon of node k is delta_k = m * Delta_k, with Delta_k
    // the square root of its nodal area, so that the horizon follows the
    // local mesh size (about 0.015 m at the hole edge); m = 3 is the value
    // of the scenes. The weight factor is that of the Gaussian influence
    // function (the defaults, written out).
    settings.horizon_factor = 3.;
    settings.weight_factor  = 0.33;

    pdfem::Coupling::BoundaryCondition<2> rollers;
    rollers.name         = "left";
    rollers.boundary_ids = {names.boundaries.at("left")};
    rollers.component    = 0;
    rollers.expression   = "0";
    settings.dirichlet.push_back(rollers);

    pdfem::Coupling::BoundaryCondition<2> pin;
    pin.name       = "(-1, 0)";
    pin.at_point   = true;
    pin.point      = Point<2>(-half_length, 0.);
    pin.component  = 1;
    pin.expression = "0";
    settings.dirichlet.push_back(pin);

    pdfem::Coupling::BoundaryCondition<2> pull;
    pull.name         = "right";
    pull.boundary_ids = {names.boundaries.at("right")};
    // Component dim = 2: the normal one. The expression is sigma, "7e+06".
    pull.component  = 2;
    pull.expression = pdfem::number(tension);
    settings.traction.push_back(pull);

    // The linear solver: the default, a direct solve by MUMPS (the coupled
    // matrix is not symmetric). It is the right choice for a few thousand
    // unknowns.
    settings.linear_solver.type = "direct";
    return settings;
  }
} // namespace Step1


// Step 4 and 5: the run and its result
// ------------------------------------
int
main(int argc, char **argv)
{
  using namespace dealii;
  using namespace Step1;

  // Without mpirun, Open MPI spends a third of a second starting itself;
  // this helper (what the `pdfem` command calls) makes a single process start
  // at once, and changes nothing under mpirun.
  pdfem::prepare_mpi_singleton_startup();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  ConditionalOStream               pcout(std::cout,
                           Utilities::MPI::this_mpi_process(comm) == 0);

  // The mesh script: the argument, or the one next to this source file
  // (CMakeLists.txt passes its folder as STEP_1_SOURCE_DIR).
  const std::string geo_file =
    argc > 1 ? argv[1] : STEP_1_SOURCE_DIR "/plate_with_hole.geo";

  try
    {
      // What one run is made of: a RunSetup. Its parts are filled by the
      // functions above; the rest are its outputs.
      pdfem::RunSetup<2> setup;
      setup.file    = "step-1"; // for messages and summary.json
      setup.name    = "step-1";
      setup.out_dir = "output-step-1";

      pdfem::Mesh::PhysicalNames names;
      setup.tria       = make_mesh(geo_file, setup.out_dir, comm, names);
      setup.cell_is_pd = mark_pd_cells(*setup.tria);
      setup.settings   = make_settings(names);

      // Step 4: the driver, chosen by its name as in a scene file
      // (`Driver/Type = static`): one linear solve at load factor t = 1.
      // The Simulator creates it from Drivers::registry(), where every driver
      // registered itself (`pdfem --list-plugins` lists them).
      setup.driver.type               = "static";
      setup.driver.load_steps         = 1;
      setup.driver.residual_tolerance = 1e-9;
      setup.write_vtu                 = true; // solution.pvd for ParaView

      // Step 5: the run. The Simulator takes the set-up, creates the driver
      // and checks that everything fits together (bad input throws
      // InputError here, before any work). run() builds the coupled system,
      // lets the driver solve it and writes history.csv, summary.json and
      // the fields (printing a line per step); it returns 0 when the run
      // completed.
      pdfem::Simulator<2> simulator(std::move(setup), comm);
      const int           status = simulator.run();
      if (status != 0)
        return status;

      // The result, read back through the Simulator: the displacement,
      // stress and damage of every node (replicated on every rank; the
      // stress of a PD node is the PDLSM nonlocal stress, that of an FE node
      // the extrapolated Gauss-point stress).
      const pdfem::Coupling::NodalResults<2> &results =
        simulator.get_nodal_results();
      const pdfem::Coupling::ProblemSize size = simulator.get_system().size();
      unsigned int                       peak = 0;
      for (unsigned int k = 0; k < results.stress.size(); ++k)
        if (results.stress[k][0][0] > results.stress[peak][0][0])
          peak = k;
      const double sigma_max = results.stress[peak][0][0];
      const double d_over_w  = 2. * hole_radius / width;
      const double heywood =
        (2. + std::pow(1. - d_over_w, 3)) / (1. - d_over_w);

      pcout << "step-1: plate with a hole, " << size.n_cells << " cells ("
            << size.n_pd_cells << " PD), " << size.n_nodes << " nodes ("
            << size.n_pd_nodes << " PD), " << size.n_dofs << " DoFs\n"
            << "  peak sigma_xx = " << std::setprecision(5) << sigma_max
            << " Pa at (" << results.position[peak] << "), a "
            << (results.kind[peak] == 2 ? "FE" : "PD") << " node\n"
            << "  stress concentration factor K_t = sigma_max / sigma = "
            << std::setprecision(4) << sigma_max / tension << "\n"
            << "  Kirsch (infinite plate): 3;  Heywood (d/W = " << d_over_w
            << "): " << heywood << "  (" << std::showpos << std::setprecision(2)
            << 100. * (sigma_max / tension / heywood - 1.) << std::noshowpos
            << " %)\n"
            << "  results in output-step-1/" << std::endl;
      return 0;
    }
  catch (const pdfem::InputError &e)
    {
      pcout << "step-1: error: " << e.what() << std::endl;
      return 2;
    }
}
