// SPDX-License-Identifier: LGPL-2.1-or-later
// Mesh checks before any work (issue 19): the structure of a gmsh .msh file
// before deal.II reads it, and the shape of every cell after.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/mesh/mesh_checks.h>

#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unordered_map>
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
          // A NUL ended a number for strtod but not for deal.II's reader,
          // which then read the line otherwise than the check (and wrote
          // past a vector: a fuzzer's find).
          for (const char c : line)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
              fail("a control character (byte " +
                   std::to_string(static_cast<unsigned char>(c)) +
                   ") in the text");
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
          if (end != token.c_str() + token.size() || errno != 0)
            fail(what + " '" + token + "' is not a non-negative integer");
          return v;
        }

        /// A finite real number.
        double
        real(const std::string &token, const std::string &what)
        {
          char        *end = nullptr;
          const double v   = std::strtod(token.c_str(), &end);
          if (token.empty() || end != token.c_str() + token.size() ||
              !std::isfinite(v))
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
          fail_at(number, problem);
        }

        /// fail() naming line @p line_number instead of the current one.
        [[noreturn]] void
        fail_at(const unsigned long line_number,
                const std::string  &problem) const
        {
          throw InputError(file,
                           "line " + std::to_string(line_number),
                           problem,
                           "an ASCII gmsh mesh, format 2.2 or 4.1, as gmsh "
                           "writes it");
        }

        /// The number of the line read last (from 1).
        unsigned long
        line_number() const
        {
          return number;
        }

      private:
        const std::string        file;
        std::ifstream            in;
        unsigned long            number = 0;
        std::vector<std::string> tokens;
      };

      /// The nodes of the file: tag -> coordinates.
      using Nodes = std::unordered_map<unsigned long, std::array<double, 3>>;

      /// A linear cell of the file (triangle, quadrilateral, tetrahedron,
      /// hexahedron) for the shape check: its gmsh type, tag, nodes in the
      /// file's order, and line.
      struct FileCell
      {
        unsigned long              type;
        std::string                tag;
        std::vector<unsigned long> nodes;
        unsigned long              line;
      };

      /// The node fields of one element (from @p first) of gmsh type
      /// @p type: every node in @p nodes, none twice. Linear cells are
      /// added to @p cells.
      void
      check_element_nodes(MshLines                       &lines,
                          const std::vector<std::string> &t,
                          const std::size_t               first,
                          const unsigned long             type,
                          const Nodes                    &nodes,
                          std::vector<FileCell>          &cells)
      {
        const std::string element = "element " + t[0];
        FileCell          cell{type, t[0], {}, lines.line_number()};
        for (std::size_t i = first; i < t.size(); ++i)
          {
            const unsigned long node = lines.integer(t[i], element + ": node");
            if (nodes.count(node) == 0)
              lines.fail(element + ": node " + t[i] + " is not in $Nodes");
            for (std::size_t j = first; j < i; ++j)
              if (t[j] == t[i])
                lines.fail(element + " repeats node " + t[i]);
            cell.nodes.push_back(node);
          }
        if (type >= 2 && type <= 5)
          cells.push_back(std::move(cell));
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
      check_nodes_41(MshLines &lines, Nodes &nodes)
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
            std::vector<unsigned long> tags;
            for (unsigned long i = 0; i < m; ++i)
              {
                const std::string t = lines.fields(S, 1, "a node tag")[0];
                tags.push_back(section.tag(t));
                if (!nodes.emplace(tags.back(), std::array<double, 3>()).second)
                  lines.fail("node tag " + t + " twice");
              }
            const std::size_t coordinates = 3 + (parametric ? dim : 0);
            for (unsigned long i = 0; i < m; ++i)
              {
                const auto &x =
                  lines.fields(S, coordinates, "the node's coordinates");
                for (unsigned int d = 0; d < coordinates; ++d)
                  {
                    const double v = lines.real(x[d], "coordinate");
                    if (d < 3)
                      nodes[tags[i]][d] = v;
                  }
              }
          }
        section.finish();
      }

      void
      check_elements_41(MshLines              &lines,
                        const Nodes           &nodes,
                        std::vector<FileCell> &cells)
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
                check_element_nodes(lines, e, 1, type, nodes, cells);
              }
          }
        section.finish();
      }

      void
      check_nodes_22(MshLines &lines, Nodes &nodes)
      {
        const std::string   S = "$Nodes";
        const unsigned long n =
          lines.integer(lines.fields(S, 1, "the number of nodes")[0],
                        "number of nodes");
        for (unsigned long i = 0; i < n; ++i)
          {
            const auto           &t = lines.fields(S, 4, "a node: tag x y z");
            std::array<double, 3> x;
            for (unsigned int d = 0; d < 3; ++d)
              x[d] = lines.real(t[d + 1], "coordinate");
            if (!nodes.emplace(lines.integer(t[0], "node tag"), x).second)
              lines.fail("node tag " + t[0] + " twice");
          }
        lines.expect("$EndNodes", "after the counted nodes");
      }

      void
      check_elements_22(MshLines              &lines,
                        const Nodes           &nodes,
                        std::vector<FileCell> &cells)
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
            const unsigned long type = lines.integer(t[1], "element type");
            const unsigned int  k    = nodes_of_element_type(type);
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
            check_element_nodes(lines, t, 3 + n_tags, type, nodes, cells);
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

      /// What is wrong with the cell of corners @p x (deal.II's vertex
      /// order); empty if nothing, or if it is only inverted and
      /// @p inverted_allowed.
      template <int dim>
      std::string
      shape_problem(const std::vector<dealii::Point<dim>> &x,
                    const bool inverted_allowed = false)
      {
        using namespace dealii;
        const unsigned int n       = x.size();
        double             longest = 0.;
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
        if (smallest > tolerance)
          return "";
        if (largest > tolerance && smallest < -tolerance)
          return "is tangled (its corners turn both ways, e.g. a bow-tie)";
        if (largest < -tolerance)
          return inverted_allowed ? "" : "is inverted (negative measure)";
        return "is degenerate (a corner of zero area or volume: a repeated "
               "vertex, or one on its neighbours' line)";
      }

      /// Throw if cell number @p index (from 0) of corners @p x is bad.
      template <int dim>
      void
      check_shape(const std::vector<dealii::Point<dim>> &x,
                  const std::size_t                      index,
                  const std::string                     &file)
      {
        const std::string problem = shape_problem(x);
        if (problem.empty())
          return;
        std::ostringstream where;
        where << "cell " << index + 1 << " (vertices";
        for (const auto &p : x)
          where << " (" << p << ")";
        where << ")";
        throw InputError(file,
                         "elements",
                         where.str() + " " + problem,
                         "cells whose corners all turn the same way, with "
                         "a positive area or volume");
      }

      /// The shapes of the cells of the mesh's dimension (the highest of
      /// its linear cells; other cells are faces): tangled or degenerate
      /// cells are refused, inverted ones left to deal.II's reader, which
      /// turns them round. deal.II 9.4's GridIn orders the cells with
      /// GridTools::consistently_order_cells(), which loops forever on some
      /// tangled quadrilaterals (the .msh fuzz target's find).
      /// shape_problem() of a cell of the file, as a cell of dimension
      /// @p dim; an inverted cell is no problem (the reader turns it).
      template <int dim>
      std::string
      file_cell_problem(const FileCell &cell, const Nodes &nodes)
      {
        const auto order = lexicographic_vertex_order(cell.nodes, dim);
        std::vector<dealii::Point<dim>> x(order.size());
        for (std::size_t k = 0; k < order.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            x[k][d] = nodes.at(order[k])[d];
        return shape_problem(x, true);
      }

      void
      check_file_cell_shapes(const MshLines              &lines,
                             const std::vector<FileCell> &cells,
                             const Nodes                 &nodes)
      {
        const bool three_d =
          std::any_of(cells.begin(), cells.end(), [](const FileCell &c) {
            return c.type == 4 || c.type == 5;
          });
        for (const FileCell &cell : cells)
          {
            if (three_d != (cell.type == 4 || cell.type == 5))
              continue;
            const std::string problem = three_d ?
                                          file_cell_problem<3>(cell, nodes) :
                                          file_cell_problem<2>(cell, nodes);
            if (!problem.empty())
              lines.fail_at(cell.line, "element " + cell.tag + " " + problem);
          }
      }
    } // namespace

    void
    check_msh_file(const std::string &msh_file)
    {
      MshLines              lines(msh_file);
      Nodes                 coordinates;
      std::vector<FileCell> cells;
      std::string           line;
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
              v4 ? check_nodes_41(lines, coordinates) :
                   check_nodes_22(lines, coordinates);
              nodes = true;
            }
          else if (line == "$Elements" && nodes && !elements)
            {
              v4 ? check_elements_41(lines, coordinates, cells) :
                   check_elements_22(lines, coordinates, cells);
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
      check_file_cell_shapes(lines, cells, coordinates);
    }


    template <int dim>
    void
    check_cell_shapes(const dealii::Triangulation<dim, dim> &tria,
                      const std::string                     &file)
    {
      for (const auto &cell : tria.active_cell_iterators())
        {
          std::vector<dealii::Point<dim>> x(cell->n_vertices());
          for (unsigned int v = 0; v < x.size(); ++v)
            x[v] = cell->vertex(v);
          check_shape(x, cell->active_cell_index(), file);
        }
    }

    template <int dim>
    void
    check_cell_shapes(const std::vector<dealii::Point<dim, double>> &vertices,
                      const std::vector<dealii::CellData<dim>>      &cells,
                      const std::string                             &file)
    {
      for (std::size_t c = 0; c < cells.size(); ++c)
        {
          std::vector<dealii::Point<dim>> x;
          for (const unsigned int v : cells[c].vertices)
            x.push_back(vertices.at(v));
          check_shape(x, c, file);
        }
    }

#define INSTANTIATE(dim)                                           \
  template void check_cell_shapes<dim>(                            \
    const dealii::Triangulation<dim, dim> &, const std::string &); \
  template void check_cell_shapes<dim>(                            \
    const std::vector<dealii::Point<dim, double>> &,               \
    const std::vector<dealii::CellData<dim>> &,                    \
    const std::string &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Mesh
} // namespace pdfem
