// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-convert: a PDLSM-FEM command file as a native pdfem scene.
//   pdfem-convert model.in [--output DIR]
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/mpi_startup.h>
#include <pdfem/scene/convert.h>
#include <pdfem/scene/scene.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

namespace
{
  void
  print_help(std::ostream &out)
  {
    out << "pdfem-convert " << PDFEM_VERSION
        << ": a PDLSM-FEM command file as a native pdfem scene\n\n"
           "Usage:\n"
           "  pdfem-convert MODEL.in [--output DIR]\n"
           "  pdfem-convert --help | --version\n\n"
           "Reads MODEL.in and the .lis mesh file it names (as `pdfem "
           "MODEL.in` does) and\n"
           "writes DIR/MODEL.prm and DIR/MODEL.msh (gmsh 2.2 ASCII), so that "
           "`pdfem MODEL.prm`\n"
           "runs what `pdfem MODEL.in` runs: the same history.csv and "
           "summary.json.\n\n"
           "Options:\n"
           "  --output DIR   write into DIR (created if missing; default: the "
           "working\n"
           "                 directory). Existing files are overwritten.\n\n"
           "The mesh keeps the .lis numbering: element types 1/2 become the "
           "regions 'pd'/'fe',\n"
           "essential set i the node set 'ebc<i>', natural set i the boundary "
           "'nbc<i>',\n"
           "the NO FAIL region the node set 'nofail'. The .prm sets every "
           "parameter the run\n"
           "uses (solver, tolerances, growth length, crack tips, RF group); "
           "see the user\n"
           "guide, section 2b.\n\n"
           "Exit status: 0 written; 2 bad input or a model that a .prm cannot "
           "express (one\n"
           "line 'pdfem-convert: error: ...' on stderr, nothing written).\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  pdfem::prepare_mpi_singleton_startup();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::string input, output = ".";
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
            std::cout << "pdfem-convert " << PDFEM_VERSION << std::endl;
          return 0;
        }
      if (arg == "--output" || arg == "-o")
        {
          if (i + 1 >= argc)
            {
              if (root)
                std::cerr << "pdfem-convert: error: --output needs a folder\n";
              return pdfem::Scene::ExitCode::input_error;
            }
          output = argv[++i];
        }
      else if (!arg.empty() && arg[0] == '-')
        {
          if (root)
            std::cerr << "pdfem-convert: error: unknown option '" << arg
                      << "' (allowed: --output DIR, --help, --version)\n";
          return pdfem::Scene::ExitCode::input_error;
        }
      else if (input.empty())
        input = arg;
      else
        {
          if (root)
            std::cerr << "pdfem-convert: error: more than one input file "
                         "given ('"
                      << input << "', '" << arg << "')\n";
          return pdfem::Scene::ExitCode::input_error;
        }
    }
  if (input.empty())
    {
      if (root)
        print_help(std::cerr);
      return pdfem::Scene::ExitCode::input_error;
    }
  if (input.size() < 3 || input.substr(input.size() - 3) != ".in")
    {
      if (root)
        std::cerr << "pdfem-convert: error: " << input
                  << ": not a PDLSM-FEM command file (allowed: a .in file)\n";
      return pdfem::Scene::ExitCode::input_error;
    }

  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    {
      if (root)
        std::cerr << "pdfem-convert: error: runs on one process (allowed: "
                     "pdfem-convert without mpirun)\n";
      return pdfem::Scene::ExitCode::input_error;
    }
  try
    {
      const pdfem::Scene::Conversion c =
        pdfem::Scene::convert_pdlsm_fem(input, output, MPI_COMM_WORLD);
      if (root)
        {
          for (const auto &note : c.notes)
            std::cerr << "pdfem-convert: note: " << note << "\n";
          std::cout << "pdfem-convert: wrote " << c.prm_file << " and "
                    << c.msh_file << std::endl;
        }
      return 0;
    }
  catch (const pdfem::InputError &e)
    {
      if (root)
        std::cerr << "pdfem-convert: error: " << e.what() << std::endl;
      return pdfem::Scene::ExitCode::input_error;
    }
}
