// SPDX-License-Identifier: LGPL-2.1-or-later
// custom_program: the smallest program written against the pdfem library.
// It runs a scene file once per value of a parameter, here the horizon factor
// m, and prints one value of each run's summary. Programs like this make
// parameter studies without touching the scene file.
//
//   custom_program SCENE.prm [m ...]
#include <pdfem/scene/scene.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::cerr << "usage: custom_program SCENE.prm [horizon factor ...]\n";
      return 2;
    }
  const std::string scene  = argv[1];
  int               status = 0;
  for (int i = 2; i < argc || i == 2; ++i)
    {
      pdfem::Scene::RunOptions options;
      options.quiet            = true;
      options.output_directory = "custom-output-" + std::to_string(i);
      if (i < argc)
        options.overrides.emplace_back("Peridynamics/Horizon factor", argv[i]);
      status = pdfem::Scene::run(scene, options, MPI_COMM_WORLD);
      if (status != pdfem::Scene::completed)
        return status;

      // summary.json is written by rank 0; print its exit state line.
      std::ifstream in(options.output_directory + "/summary.json");
      std::string   line;
      while (std::getline(in, line))
        if (line.find("\"exit_state\"") != std::string::npos)
          std::cout << "m = " << (i < argc ? argv[i] : "(file)") << ": "
                    << line.substr(line.find(':') + 2) << std::endl;
    }
  return status;
}
