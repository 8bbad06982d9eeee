// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem: run a scene file.  pdfem scene.prm [--output DIR] [--quiet]
#include <pdfem/base/config.h>
#include <pdfem/base/mpi_startup.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/fracture/criterion.h>
#include <pdfem/io/parameters.h>
#include <pdfem/scene/scene.h>
#include <pdfem/simulator/postprocess.h>

#include <deal.II/base/mpi.h>

#include <cstring>
#include <iostream>
#include <string>

namespace
{
  void
  print_help(std::ostream &out)
  {
    out
      << "pdfem " << PDFEM_VERSION
      << ": coupled peridynamics (PDLSM) and finite elements\n\n"
         "Usage:\n"
         "  pdfem SCENE.prm [--output DIR] [--quiet] [--restart DIR]\n"
         "  mpirun -np N pdfem SCENE.prm ...\n"
         "  pdfem [SCENE.prm [--set ...]] --print-parameters\n"
         "  pdfem --list-plugins\n"
         "  pdfem --help | --version\n\n"
         "Options:\n"
         "  --output DIR         write results into DIR (default: the "
         "scene's\n"
         "                       Output/Directory, or output-<scene name>)\n"
         "  --quiet              no progress output\n"
         "  --set PATH=VALUE     override a parameter, e.g. --set "
         "\"Mesh/Global refinements=2\"\n"
         "                       (repeatable)\n"
         "  --restart DIR        go on from the checkpoint in the output "
         "folder DIR\n"
         "                       (Output/Checkpoint steps, or a SIGINT/SIGTERM "
         "wrote it)\n"
         "  --print-parameters   every scene parameter with its default and "
         "documentation;\n"
         "                       with a scene: its parameters as the run "
         "would use them\n"
         "                       (every --set applied), nothing run\n"
         "  --list-plugins       every registered driver, crack criterion and "
         "postprocessor\n\n"
         "Outputs: history.csv (one row per step), summary.json (sizes, "
         "final values,\n"
         "timings, exit_state), solution-NNNNN.pvtu and solution.pvd "
         "(ParaView).\n"
         "Exit status: 0 completed, 2 bad input, 3 the run stopped (see "
         "summary.json).\n";
  }
  void
  list_plugins(std::ostream &out)
  {
    out << "Drivers (Driver/Type):\n";
    pdfem::Drivers::registry().list(out);
    out << "\nCrack criteria (Fracture/Criterion; also 'none'):\n";
    pdfem::Fracture::registry<2>().list(out);
    out << "\nPostprocessors (each takes part where it applies):\n";
    pdfem::Postprocess::registry<2>().list(out);
  }
} // namespace

int
main(int argc, char **argv)
{
  pdfem::prepare_mpi_singleton_startup();
  // Threads: the cores of this machine shared among its ranks (deal.II's
  // choice; DEAL_II_NUM_THREADS caps it).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  const bool root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  pdfem::Scene::RunOptions options;
  std::string              scene;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
        {
          if (root)
            print_help(std::cout);
          return 0;
        }
      if (arg == "--version")
        {
          if (root)
            std::cout << "pdfem " << PDFEM_VERSION << std::endl;
          return 0;
        }
      if (arg == "--print-parameters")
        options.print_parameters = true;
      else if (arg == "--list-plugins")
        {
          if (root)
            list_plugins(std::cout);
          return 0;
        }
      else if (arg == "--quiet" || arg == "-q")
        options.quiet = true;
      else if (arg == "--set")
        {
          const std::string assignment = i + 1 < argc ? argv[++i] : "";
          const auto        eq         = assignment.find('=');
          if (eq == std::string::npos || eq == 0)
            {
              if (root)
                std::cerr << "pdfem: error: --set needs PATH=VALUE, e.g. "
                             "--set \"Mesh/Global refinements=2\"\n";
              return 2;
            }
          options.overrides.emplace_back(assignment.substr(0, eq),
                                         assignment.substr(eq + 1));
        }
      else if (arg == "--restart")
        {
          if (i + 1 >= argc)
            {
              if (root)
                std::cerr << "pdfem: error: --restart needs the output folder "
                             "of the run to go on with\n";
              return 2;
            }
          options.restart = argv[++i];
        }
      else if (arg == "--output" || arg == "-o")
        {
          if (i + 1 >= argc)
            {
              if (root)
                std::cerr << "pdfem: error: --output needs a folder\n";
              return 2;
            }
          options.output_directory = argv[++i];
        }
      else if (!arg.empty() && arg[0] == '-')
        {
          if (root)
            std::cerr << "pdfem: error: unknown option '" << arg
                      << "' (allowed: --output DIR, --quiet, --set PATH=VALUE, "
                         "--restart DIR, --help, "
                         "--version, --print-parameters, --list-plugins)\n";
          return 2;
        }
      else if (scene.empty())
        scene = arg;
      else
        {
          if (root)
            std::cerr << "pdfem: error: more than one scene file given ('"
                      << scene << "', '" << arg << "')\n";
          return 2;
        }
    }
  if (scene.empty() && options.print_parameters)
    {
      if (root)
        pdfem::Parameters::print_all(std::cout);
      return 0;
    }
  if (scene.empty())
    {
      if (root)
        print_help(std::cerr);
      return 2;
    }
  return pdfem::Scene::run(scene, options, MPI_COMM_WORLD);
}
