// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/mesh/gmsh_input.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pdfem
{
  namespace Mesh
  {
    namespace fs = std::filesystem;

    std::string
    PhysicalNames::list(const std::map<std::string, unsigned int> &names)
    {
      std::string s;
      for (const auto &[name, tag] : names)
        s += (s.empty() ? "" : ", ") + name;
      return s.empty() ? "(none)" : s;
    }

    PhysicalNames
    read_physical_names(const std::string &msh_file, const int dim)
    {
      PhysicalNames names;
      std::ifstream in(msh_file);
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind("$PhysicalNames", 0) == 0)
          {
            unsigned int n = 0;
            in >> n;
            for (unsigned int i = 0; i < n; ++i)
              {
                int          group_dim = 0;
                unsigned int tag       = 0;
                in >> group_dim >> tag;
                std::getline(in, line);
                const auto a = line.find('"');
                const auto b = line.rfind('"');
                if (a == std::string::npos || b <= a)
                  continue;
                const std::string name = line.substr(a + 1, b - a - 1);
                if (group_dim == dim)
                  names.regions[name] = tag;
                else if (group_dim == dim - 1)
                  names.boundaries[name] = tag;
              }
            break;
          }
      return names;
    }

    std::string
    prepare_msh_file(const std::string &input,
                     const int          dim,
                     const double       size_factor,
                     const std::string &work_dir,
                     const std::string &prm_file,
                     const std::string &parameter)
    {
      if (!fs::exists(input))
        throw InputError(prm_file,
                         parameter,
                         "the mesh file '" + input + "' does not exist",
                         "an existing .msh or .geo file");
      const std::string extension = fs::path(input).extension().string();
      if (extension == ".msh")
        return input;
      if (extension != ".geo")
        throw InputError(prm_file,
                         parameter,
                         "'" + input + "' is neither a .msh nor a .geo file",
                         ".msh (gmsh 2.2 or 4.1) or .geo");

      fs::create_directories(work_dir);
      const std::string msh =
        (fs::path(work_dir) / (fs::path(input).stem().string() + ".msh"))
          .string();
      const std::string log = msh + ".log";
      const std::string command =
        "gmsh -" + std::to_string(dim) + " -format msh4 -v 2 -clscale " +
        number(size_factor) + " \"" + input + "\" -o \"" + msh + "\" > \"" +
        log + "\" 2>&1";
      if (std::system(command.c_str()) != 0 || !fs::exists(msh))
        {
          std::ifstream     l(log);
          std::stringstream s;
          s << l.rdbuf();
          throw InputError(prm_file,
                           parameter,
                           "gmsh could not mesh '" + input + "': " + s.str(),
                           "a .geo script that 'gmsh -" + std::to_string(dim) +
                             "' meshes (is gmsh installed?)");
        }
      return msh;
    }

    template <int dim>
    void
    read_msh(const std::string &msh_file, dealii::Triangulation<dim, dim> &tria)
    {
      dealii::GridIn<dim> grid_in(tria);
      std::ifstream       in(msh_file);
      grid_in.read_msh(in);
    }

#define INSTANTIATE(dim)                           \
  template void read_msh<dim>(const std::string &, \
                              dealii::Triangulation<dim, dim> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Mesh
} // namespace pdfem
