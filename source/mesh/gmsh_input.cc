// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/mesh/gmsh_input.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <array>
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
                else if (group_dim == 0)
                  names.node_sets[name] = tag;
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
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          throw InputError(msh_file,
                           "",
                           "deal.II cannot read the mesh: " +
                             ParameterTools::clean_dealii_message(e.what()),
                           "a gmsh ASCII mesh (format 2.2 or 4.1) of "
                           "dimension " +
                             std::to_string(dim));
        }
    }

    template <int dim>
    std::map<std::string, std::vector<unsigned int>>
    read_node_sets(const std::string                     &msh_file,
                   const dealii::Triangulation<dim, dim> &tria)
    {
      std::map<std::string, std::vector<unsigned int>> sets;
      const PhysicalNames names = read_physical_names(msh_file, dim);
      if (names.node_sets.empty())
        return sets;
      std::map<unsigned int, std::string> name_of_tag;
      for (const auto &[name, tag] : names.node_sets)
        name_of_tag[tag] = name;

      const auto fail = [&](const std::string &problem) {
        throw InputError(msh_file,
                         "node sets (physical points)",
                         problem,
                         "ASCII gmsh format 2.2 or 4.1 with point elements "
                         "(type 15) on mesh vertices");
      };
      std::ifstream                                   in(msh_file);
      std::string                                     line;
      std::map<unsigned long, std::array<double, 3>>  nodes;
      std::map<std::string, std::vector<std::size_t>> set_nodes;
      bool                                            v4 = false;
      // 4.1: the physical tags of each point entity ($Entities)
      std::map<unsigned long, std::vector<unsigned long>> point_physicals;
      while (std::getline(in, line))
        if (line.rfind("$MeshFormat", 0) == 0)
          {
            double version = 0;
            int    binary  = 0;
            in >> version >> binary;
            v4 = version >= 4.;
            if ((version >= 3. && version != 4.1) || binary != 0)
              fail("the file is gmsh format " + number(version) +
                   (binary ? " (binary)" : ""));
          }
        else if (v4 && line.rfind("$Entities", 0) == 0)
          {
            std::size_t n_points = 0, n_other = 0;
            in >> n_points >> n_other >> n_other >> n_other;
            for (std::size_t i = 0; i < n_points; ++i)
              {
                unsigned long tag = 0, n_physicals = 0;
                double        x = 0;
                in >> tag >> x >> x >> x >> n_physicals;
                auto &physicals = point_physicals[tag];
                physicals.resize(n_physicals);
                for (auto &p : physicals)
                  in >> p;
              }
          }
        else if (v4 && line.rfind("$Nodes", 0) == 0)
          {
            std::size_t n_blocks = 0, n = 0, lo = 0, hi = 0;
            in >> n_blocks >> n >> lo >> hi;
            for (std::size_t b = 0; b < n_blocks; ++b)
              {
                int                        entity_dim = 0, parametric = 0;
                std::size_t                tag = 0, n_in_block = 0;
                std::vector<unsigned long> ids;
                in >> entity_dim >> tag >> parametric >> n_in_block;
                ids.resize(n_in_block);
                for (auto &id : ids)
                  in >> id;
                for (const auto id : ids)
                  {
                    std::array<double, 3> x{};
                    in >> x[0] >> x[1] >> x[2];
                    double u = 0;
                    for (int k = 0; parametric && k < entity_dim; ++k)
                      in >> u;
                    nodes[id] = x;
                  }
              }
          }
        else if (v4 && line.rfind("$Elements", 0) == 0)
          {
            std::size_t n_blocks = 0, n = 0, lo = 0, hi = 0;
            in >> n_blocks >> n >> lo >> hi;
            for (std::size_t b = 0; b < n_blocks; ++b)
              {
                int           entity_dim = 0, type = 0;
                unsigned long tag = 0, n_in_block = 0;
                in >> entity_dim >> tag >> type >> n_in_block;
                std::getline(in, line);
                for (unsigned long i = 0; i < n_in_block; ++i)
                  {
                    std::getline(in, line);
                    if (type != 15 || entity_dim != 0)
                      continue;
                    std::istringstream s(line);
                    unsigned long      id = 0, node = 0;
                    s >> id >> node;
                    for (const auto physical : point_physicals[tag])
                      {
                        const auto it = name_of_tag.find(physical);
                        if (it != name_of_tag.end())
                          set_nodes[it->second].push_back(node);
                      }
                  }
              }
          }
        else if (line.rfind("$Nodes", 0) == 0)
          {
            std::size_t n = 0;
            in >> n;
            for (std::size_t i = 0; i < n; ++i)
              {
                unsigned long         id = 0;
                std::array<double, 3> x{};
                in >> id >> x[0] >> x[1] >> x[2];
                nodes[id] = x;
              }
          }
        else if (line.rfind("$Elements", 0) == 0)
          {
            std::size_t n = 0;
            in >> n;
            std::getline(in, line);
            for (std::size_t i = 0; i < n && std::getline(in, line); ++i)
              {
                std::istringstream s(line);
                unsigned long      id = 0, type = 0, n_tags = 0, node = 0;
                s >> id >> type >> n_tags;
                if (type != 15 || n_tags == 0)
                  continue;
                unsigned long physical = 0, tag = 0;
                s >> physical;
                for (unsigned long t = 1; t < n_tags; ++t)
                  s >> tag;
                s >> node;
                const auto it = name_of_tag.find(physical);
                if (it != name_of_tag.end())
                  set_nodes[it->second].push_back(node);
              }
          }
      if (!in.eof() && in.fail())
        fail("cannot read the file");

      // Vertices by their coordinates (read by the same operator>>, so
      // equal bit for bit).
      // Two vertices at one place (a seam) would make the match ambiguous:
      // numbers::invalid_unsigned_int marks such places.
      const unsigned int                              twice = -1;
      std::map<std::array<double, dim>, unsigned int> vertex_at;
      const auto &vertices = tria.get_vertices();
      const auto &used     = tria.get_used_vertices();
      for (unsigned int v = 0; v < vertices.size(); ++v)
        if (used[v])
          {
            std::array<double, dim> key;
            for (unsigned int d = 0; d < dim; ++d)
              key[d] = vertices[v][d];
            const auto [it, inserted] = vertex_at.emplace(key, v);
            if (!inserted)
              it->second = twice;
          }
      for (const auto &[name, ids] : set_nodes)
        {
          auto &set = sets[name];
          for (const auto id : ids)
            {
              const auto n = nodes.find(id);
              if (n == nodes.end())
                fail("node set '" + name + "': node " + std::to_string(id) +
                     " is not in $Nodes");
              std::array<double, dim> key;
              for (unsigned int d = 0; d < dim; ++d)
                key[d] = n->second[d];
              const auto v = vertex_at.find(key);
              if (v == vertex_at.end())
                fail("node set '" + name + "': node " + std::to_string(id) +
                     " belongs to no cell");
              if (v->second == twice)
                fail("node set '" + name + "': node " + std::to_string(id) +
                     " shares its coordinates with another vertex (node "
                     "sets are matched to the mesh by coordinates)");
              set.push_back(v->second);
            }
        }
      for (const auto &[name, tag] : names.node_sets)
        sets[name]; // an empty group is still a set
      return sets;
    }

#define INSTANTIATE(dim)                                          \
  template void read_msh<dim>(const std::string &,                \
                              dealii::Triangulation<dim, dim> &); \
  template std::map<std::string, std::vector<unsigned int>>       \
  read_node_sets<dim>(const std::string &,                        \
                      const dealii::Triangulation<dim, dim> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Mesh
} // namespace pdfem
