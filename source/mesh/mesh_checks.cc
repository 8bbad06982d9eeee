// SPDX-License-Identifier: LGPL-2.1-or-later
// Mesh checks before any work (issue 19): the structure of a gmsh .msh file
// before deal.II reads it, and the shape of every cell after.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/mesh/mesh_checks.h>

#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unordered_set>
#include <vector>

namespace pdfem
{
  namespace Mesh
  {
    namespace
    {
      /// The number of nodes of gmsh element type @p type (0: unknown).
      unsigned int
      nodes_of_element_type(const unsigned long type)
      {
        static const unsigned int n[] = {0,  2,  3,  4,  4,  8,  6,  5,
                                         3,  6,  9,  10, 27, 18, 14, 1,
                                         8,  20, 15, 13, 9,  10, 12, 15,
                                         15, 21, 4,  5,  6,  20, 35, 56};
        return type < sizeof(n) / sizeof(n[0]) ? n[type] : 0;
      }

      /// A forward reader of a .msh file that knows its line number and
      /// names it in every error.
      class MshLines
      {
      public:
        explicit MshLines(const std::string &file)
          : file(file)
          , in(file)
        {
          if (!in)
            fail("the file cannot be opened");
        }

        /// The next line, without a trailing '\r'; false at the end.
        bool
        next(std::string &line)
        {
          if (!std::getline(in, line))
            return false;
          ++number;
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          return true;
        }

        /// The whitespace-separated fields of the next line of section
        /// @p section, which must exist.
        const std::vector<std::string> &
        fields(const std::string &section)
        {
          std::string line;
          if (!next(line))
            fail("the file ends inside " + section);
          tokens.clear();
          std::size_t i = 0;
          while (i < line.size())
            {
              while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
                ++i;
              const std::size_t start = i;
              while (i < line.size() && line[i] != ' ' && line[i] != '\t')
                ++i;
              if (i > start)
                tokens.push_back(line.substr(start, i - start));
            }
          return tokens;
        }

        /// fields() of a line that must hold exactly @p n of them.
        const std::vector<std::string> &
        fields(const std::string &section,
               const std::size_t  n,
               const std::string &what)
        {
          fields(section);
          if (tokens.size() != n)
            fail(section + ": expected " + what + " (" + std::to_string(n) +
                 " fields), found " + std::to_string(tokens.size()) +
                 " fields");
          return tokens;
        }

        /// A non-negative integer.
        unsigned long
        integer(const std::string &token, const std::string &what)
        {
          char *end             = nullptr;
          errno                 = 0;
          const unsigned long v = token.empty() || token[0] == '-' ?
                                    0 :
                                    std::strtoul(token.c_str(), &end, 10);
          if (end == nullptr || *end != '\0' || errno != 0)
            fail(what + " '" + token + "' is not a non-negative integer");
          return v;
        }

        /// A finite real number.
        double
        real(const std::string &token, const std::string &what)
        {
          char        *end = nullptr;
          const double v   = std::strtod(token.c_str(), &end);
          if (end == token.c_str() || *end != '\0' || !std::isfinite(v))
            fail(what + " '" + token + "' is not a finite number");
          return v;
        }

        /// The next line must be @p marker (a section's end).
        void
        expect(const std::string &marker, const std::string &why)
        {
          std::string line;
          if (!next(line))
            fail("the file ends before " + marker);
          if (line != marker)
            fail("expected " + marker + " (" + why + "), found '" +
                 line.substr(0, 40) + "'");
        }

        [[noreturn]] void
        fail(const std::string &problem) const
        {
          throw InputError(file,
                           "line " + std::to_string(number),
                           problem,
                           "an ASCII gmsh mesh, format 2.2 or 4.1, as gmsh "
                           "writes it");
        }

      private:
        const std::string        file;
        std::ifstream            in;
        unsigned long            number = 0;
        std::vector<std::string> tokens;
      };

      /// The node lines of one element (@p nodes fields from @p first):
      /// every node in @p node_tags, none twice.
      void
      check_element_nodes(MshLines                                &lines,
                          const std::vector<std::string>          &t,
                          const std::size_t                        first,
                          const std::unordered_set<unsigned long> &node_tags)
      {
        const std::string element = "element " + t[0];
        for (std::size_t i = first; i < t.size(); ++i)
          {
            const unsigned long node = lines.integer(t[i], element + ": node");
            if (node_tags.count(node) == 0)
              lines.fail(element + ": node " + t[i] + " is not in $Nodes");
            for (std::size_t j = first; j < i; ++j)
              if (t[j] == t[i])
                lines.fail(element + " repeats node " + t[i]);
          }
      }

      /// The header of a 4.1 section of blocks ($Nodes, $Elements): its
      /// counts and tag range, checked against the blocks as they come.
      struct BlockedSection
      {
        BlockedSection(MshLines          &lines,
                       const std::string &section,
                       const std::string &item)
          : lines(lines)
          , section(section)
          , item(item)
        {
          const std::string Item(1, char(std::toupper(item[0])));
          const auto       &h =
            lines.fields(section,
                         4,
                         "numEntityBlocks num" + Item + item.substr(1) +
                           "s min" + Item + item.substr(1) + "Tag max" + Item +
                           item.substr(1) + "Tag");
          blocks = lines.integer(h[0], "numEntityBlocks");
          n      = lines.integer(h[1], "the number of " + item + "s");
          lo     = lines.integer(h[2], "the smallest " + item + " tag");
          hi     = lines.integer(h[3], "the largest " + item + " tag");
        }

        /// A block of @p m more items.
        void
        add_block(const unsigned long m)
        {
          if (m > n - total)
            lines.fail("the " + item + " blocks hold more than the " +
                       std::to_string(n) + " " + item +
                       "s the header declares");
          total += m;
        }

        /// The tag @p t of an item.
        unsigned long
        tag(const std::string &t) const
        {
          const unsigned long v = lines.integer(t, item + " tag");
          if (v < lo || v > hi)
            lines.fail(item + " tag " + t + " outside the declared range " +
                       std::to_string(lo) + ".." + std::to_string(hi));
          return v;
        }

        /// After the last block: the counts agree, the section ends.
        void
        finish()
        {
          if (total != n)
            lines.fail("the " + item + " blocks hold " + std::to_string(total) +
                       " " + item + "s, the header declares " +
                       std::to_string(n));
          lines.expect("$End" + section.substr(1),
                       "after the counted " + item + " blocks");
        }

        MshLines         &lines;
        const std::string section, item;
        unsigned long     blocks = 0, n = 0, lo = 0, hi = 0, total = 0;
      };

      void
      check_nodes_41(MshLines &lines, std::unordered_set<unsigned long> &tags)
      {
        const std::string S = "$Nodes";
        BlockedSection    section(lines, S, "node");
        for (unsigned long b = 0; b < section.blocks; ++b)
          {
            const auto         &t   = lines.fields(S,
                                         4,
                                         "a node block header: entityDim "
                                                   "entityTag parametric "
                                                   "numNodesInBlock");
            const unsigned long dim = lines.integer(t[0], "entityDim");
            lines.integer(t[1], "entityTag");
            const unsigned long parametric = lines.integer(t[2], "parametric");
            const unsigned long m = lines.integer(t[3], "numNodesInBlock");
            if (dim > 3 || parametric > 1)
              lines.fail("a node block header with entityDim " + t[0] +
                         " and parametric " + t[2] +
                         " (allowed: 0..3 and 0 or 1)");
            section.add_block(m);
            for (unsigned long i = 0; i < m; ++i)
              {
                const std::string t = lines.fields(S, 1, "a node tag")[0];
                if (!tags.insert(section.tag(t)).second)
                  lines.fail("node tag " + t + " twice");
              }
            const std::size_t coordinates = 3 + (parametric ? dim : 0);
            for (unsigned long i = 0; i < m; ++i)
              for (const auto &x :
                   lines.fields(S, coordinates, "the node's coordinates"))
                lines.real(x, "coordinate");
          }
        section.finish();
      }

      void
      check_elements_41(MshLines                                &lines,
                        const std::unordered_set<unsigned long> &node_tags)
      {
        const std::string S = "$Elements";
        BlockedSection    section(lines, S, "element");
        for (unsigned long b = 0; b < section.blocks; ++b)
          {
            const auto &t = lines.fields(S,
                                         4,
                                         "an element block header: entityDim "
                                         "entityTag elementType "
                                         "numElementsInBlock");
            if (lines.integer(t[0], "entityDim") > 3)
              lines.fail("an element block header with entityDim " + t[0] +
                         " (allowed: 0..3)");
            lines.integer(t[1], "entityTag");
            const unsigned long type = lines.integer(t[2], "elementType");
            const unsigned long m = lines.integer(t[3], "numElementsInBlock");
            const unsigned int  k = nodes_of_element_type(type);
            if (k == 0)
              lines.fail("element type " + t[2] + " is not a gmsh type");
            section.add_block(m);
            for (unsigned long i = 0; i < m; ++i)
              {
                const auto &e = lines.fields(S,
                                             1 + k,
                                             "an element tag and its " +
                                               std::to_string(k) + " nodes");
                section.tag(e[0]);
                check_element_nodes(lines, e, 1, node_tags);
              }
          }
        section.finish();
      }

      void
      check_nodes_22(MshLines &lines, std::unordered_set<unsigned long> &tags)
      {
        const std::string   S = "$Nodes";
        const unsigned long n =
          lines.integer(lines.fields(S, 1, "the number of nodes")[0],
                        "number of nodes");
        for (unsigned long i = 0; i < n; ++i)
          {
            const auto &t = lines.fields(S, 4, "a node: tag x y z");
            if (!tags.insert(lines.integer(t[0], "node tag")).second)
              lines.fail("node tag " + t[0] + " twice");
            for (unsigned int d = 1; d < 4; ++d)
              lines.real(t[d], "coordinate");
          }
        lines.expect("$EndNodes", "after the counted nodes");
      }

      void
      check_elements_22(MshLines                                &lines,
                        const std::unordered_set<unsigned long> &node_tags)
      {
        const std::string   S = "$Elements";
        const unsigned long n =
          lines.integer(lines.fields(S, 1, "the number of elements")[0],
                        "number of elements");
        for (unsigned long i = 0; i < n; ++i)
          {
            const auto &t = lines.fields(S);
            if (t.size() < 3)
              lines.fail("$Elements: expected tag, type, number of tags");
            lines.integer(t[0], "element tag");
            const unsigned int k =
              nodes_of_element_type(lines.integer(t[1], "element type"));
            if (k == 0)
              lines.fail("element type " + t[1] + " is not a gmsh type");
            const unsigned long n_tags = lines.integer(t[2], "number of tags");
            if (t.size() != 3 + n_tags + k)
              lines.fail("element " + t[0] + ": expected " +
                         std::to_string(3 + n_tags + k) + " fields (" +
                         std::to_string(n_tags) + " tags, " +
                         std::to_string(k) + " nodes), found " +
                         std::to_string(t.size()));
            for (std::size_t i = 3; i < 3 + n_tags; ++i)
              lines.integer(t[i], "element " + t[0] + ": tag");
            check_element_nodes(lines, t, 3 + n_tags, node_tags);
          }
        lines.expect("$EndElements", "after the counted elements");
      }

      void
      check_physical_names(MshLines &lines)
      {
        const std::string   S = "$PhysicalNames";
        const unsigned long n =
          lines.integer(lines.fields(S, 1, "the number of names")[0],
                        "number of physical names");
        for (unsigned long i = 0; i < n; ++i)
          {
            const auto &t = lines.fields(S);
            if (t.size() < 3 || t[2][0] != '"' || t.back().back() != '"')
              lines.fail("$PhysicalNames: expected dimension, tag and a "
                         "quoted name");
            lines.integer(t[0], "dimension");
            lines.integer(t[1], "physical tag");
          }
        lines.expect("$EndPhysicalNames", "after the counted names");
      }

      void
      check_entities_41(MshLines &lines)
      {
        const std::string S = "$Entities";
        auto              h = lines.fields(S,
                              4,
                              "numPoints numCurves numSurfaces "
                                           "numVolumes");
        unsigned long     count[4];
        for (unsigned int d = 0; d < 4; ++d)
          count[d] = lines.integer(h[d], "number of entities");
        for (unsigned int d = 0; d < 4; ++d)
          for (unsigned long i = 0; i < count[d]; ++i)
            {
              const auto       &t             = lines.fields(S);
              const std::size_t n_physical_at = d == 0 ? 4 : 7;
              if (t.size() <= n_physical_at)
                lines.fail("$Entities: an entity line too short");
              const std::size_t end =
                n_physical_at + 1 +
                lines.integer(t[n_physical_at], "numPhysicalTags");
              const std::size_t expected =
                d == 0 ? end :
                         end + 1 +
                           (t.size() > end ?
                              lines.integer(t[end], "numBoundingEntities") :
                              0);
              if (t.size() != expected)
                lines.fail("$Entities: expected " + std::to_string(expected) +
                           " fields, found " + std::to_string(t.size()));
              // tag, bounding box (or point), physical tags, bounding
              // entities (signed: their orientation).
              lines.integer(t[0], "entity tag");
              for (std::size_t i = 1; i < n_physical_at; ++i)
                lines.real(t[i], "coordinate");
              for (std::size_t i = n_physical_at + 1; i < t.size(); ++i)
                lines.integer(t[i][0] == '-' ? t[i].substr(1) : t[i],
                              "entity tag");
            }
        lines.expect("$EndEntities", "after the counted entities");
      }
    } // namespace

    void
    check_msh_file(const std::string &msh_file)
    {
      MshLines                          lines(msh_file);
      std::unordered_set<unsigned long> node_tags;
      std::string                       line;
      bool v4 = false, format = false, nodes = false, elements = false;
      while (lines.next(line))
        {
          if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
          if (line == "$MeshFormat")
            {
              const auto &t =
                lines.fields(line, 3, "version file-type data-size");
              const double version = lines.real(t[0], "version");
              if (lines.integer(t[2], "data-size") != sizeof(double))
                lines.fail("data-size " + t[2] + " (gmsh writes 8)");
              if (lines.integer(t[1], "file-type") != 0)
                lines.fail("a binary .msh file; pdfem reads ASCII ones "
                           "(gmsh -format msh4 or msh22, without -bin)");
              if (version != 4.1 && !(version >= 2. && version < 3.))
                lines.fail("gmsh format " + t[0] + " (read: 2.2 and 4.1)");
              v4     = version >= 4.;
              format = true;
              lines.expect("$EndMeshFormat", "after the format line");
            }
          else if (!format)
            lines.fail("expected $MeshFormat first, found '" +
                       line.substr(0, 40) + "'");
          else if (line == "$PhysicalNames")
            check_physical_names(lines);
          else if (line == "$Entities" && v4)
            check_entities_41(lines);
          else if (line == "$Nodes" && !nodes)
            {
              v4 ? check_nodes_41(lines, node_tags) :
                   check_nodes_22(lines, node_tags);
              nodes = true;
            }
          else if (line == "$Elements" && nodes && !elements)
            {
              v4 ? check_elements_41(lines, node_tags) :
                   check_elements_22(lines, node_tags);
              elements = true;
            }
          else if (line == "$Nodes" || line == "$Elements")
            lines.fail(line + (nodes ? " a second time" : " before $Nodes"));
          else if (line[0] == '$' && line.rfind("$End", 0) != 0)
            {
              // A section pdfem does not read ($NodeData, $Periodic, ..).
              const std::string end = "$End" + line.substr(1);
              while (lines.next(line) && line != end)
                ;
              if (line != end)
                lines.fail("the file ends before " + end);
            }
          else
            lines.fail("unexpected text outside any section: '" +
                       line.substr(0, 40) + "'");
        }
      if (!format || !nodes || !elements)
        lines.fail(std::string("the file has no ") +
                   (!format ? "$MeshFormat" :
                    !nodes  ? "$Nodes" :
                              "$Elements") +
                   " section");
    }

    template <int dim>
    void
    check_cell_shapes(const dealii::Triangulation<dim, dim> &tria,
                      const std::string                     &file)
    {
      using namespace dealii;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int      n = cell->n_vertices();
          std::vector<Point<dim>> x(n);
          for (unsigned int v = 0; v < n; ++v)
            x[v] = cell->vertex(v);
          double longest = 0.;
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < a; ++b)
              longest = std::max(longest, x[a].distance(x[b]));
          // Corner Jacobians: at each vertex of a hypercube (deal.II's
          // lexicographic numbering: the neighbour along d is v ^ 2^d, and
          // the sign of the local axis 1 - 2 bit_d), once for a simplex.
          const bool simplex  = n == dim + 1;
          double     smallest = 1e300, largest = -1e300;
          for (unsigned int v = 0; v < (simplex ? 1 : n); ++v)
            {
              Tensor<2, dim> J;
              double         sign = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const unsigned int w = simplex ? d + 1 : v ^ (1u << d);
                  const unsigned int o = simplex ? 0 : v;
                  if (!simplex && ((v >> d) & 1u))
                    sign = -sign;
                  for (unsigned int i = 0; i < dim; ++i)
                    J[i][d] = x[w][i] - x[o][i];
                }
              const double det = sign * determinant(J);
              smallest         = std::min(smallest, det);
              largest          = std::max(largest, det);
            }
          const double tolerance = 1e-10 * std::pow(longest, dim);
          std::string  problem;
          if (smallest > tolerance)
            continue;
          if (largest > tolerance && smallest < -tolerance)
            problem = "is tangled (its corners turn both ways, e.g. a "
                      "bow-tie)";
          else if (largest < -tolerance)
            problem = "is inverted (negative measure)";
          else
            problem = "is degenerate (a corner of zero area or volume: a "
                      "repeated vertex, or one on its neighbours' line)";
          std::ostringstream where;
          where << "cell " << cell->active_cell_index() + 1 << " (vertices";
          for (const auto &p : x)
            where << " (" << p << ")";
          where << ")";
          throw InputError(file,
                           "elements",
                           where.str() + " " + problem,
                           "cells whose corners all turn the same way, with "
                           "a positive area or volume");
        }
    }

#define INSTANTIATE(dim)                \
  template void check_cell_shapes<dim>( \
    const dealii::Triangulation<dim, dim> &, const std::string &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Mesh
} // namespace pdfem
