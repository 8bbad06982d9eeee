// SPDX-License-Identifier: LGPL-2.1-or-later
// Reader of the mesh file (.lis) of the peer code PDLSM-FEM (specs/004 §4.2).
#include <pdfem/base/exceptions.h>
#include <pdfem/io/pdlsm_fem_input.h>

#include <string_view>

#include "pdlsm_fem_input_internal.h"

namespace pdfem
{
  namespace IO
  {
    namespace
    {
      using namespace internal;
      using Model = PDLSMFEMModel;

      /**
       * A text held in memory, read token by token or line by line, that
       * always knows the line it is on (1-based). Tokens are separated by
       * blanks; '\r' counts as a blank, so CRLF files read as LF files.
       */
      class Text
      {
      public:
        Text(const std::string &file, std::string &&contents)
          : file(file)
          , text(std::move(contents))
        {
          last_line = 1;
          for (const char c : text)
            if (c == '\n')
              ++last_line;
          if (!text.empty() && text.back() == '\n')
            --last_line;
        }

        [[noreturn]] void
        fail(const unsigned int line,
             const std::string &problem,
             const std::string &allowed = "") const
        {
          throw InputError(file, at_line(line), problem, allowed);
        }

        [[noreturn]] void
        fail_end_of_file(const std::string &expected) const
        {
          fail(last_line, "unexpected end of file, expected " + expected);
        }

        /// The next token, across line ends; empty at the end of the file.
        std::string_view
        token(unsigned int &line_of_token)
        {
          while (pos < text.size() &&
                 (is_blank(text[pos]) || text[pos] == '\n'))
            if (text[pos++] == '\n')
              ++line;
          line_of_token = line;
          if (pos == text.size())
            {
              line_of_token = last_line;
              return {};
            }
          const std::size_t start = pos;
          while (pos < text.size() && !is_blank(text[pos]) && text[pos] != '\n')
            ++pos;
          mid_line = true;
          return std::string_view(text).substr(start, pos - start);
        }

        /**
         * The tokens of the next line that is not blank (none at the end of
         * the file) and its number. The line of the last token() is finished
         * first (see finish_line()).
         */
        unsigned int
        record(std::vector<std::string_view> &tokens)
        {
          finish_line("the previous value");
          tokens.clear();
          while (true)
            {
              while (pos < text.size() && is_blank(text[pos]))
                ++pos;
              if (pos < text.size() && text[pos] == '\n')
                {
                  ++pos;
                  ++line;
                  continue;
                }
              break;
            }
          if (pos == text.size())
            return last_line;
          const unsigned int this_line = line;
          while (pos < text.size() && text[pos] != '\n')
            if (is_blank(text[pos]))
              ++pos;
            else
              {
                const std::size_t start = pos;
                while (pos < text.size() && !is_blank(text[pos]) &&
                       text[pos] != '\n')
                  ++pos;
                tokens.push_back(
                  std::string_view(text).substr(start, pos - start));
              }
          next_line();
          return this_line;
        }

        /// The rest of the current line, as it is (the line is then done).
        std::string_view
        rest_of_line()
        {
          const std::size_t start = pos;
          while (pos < text.size() && text[pos] != '\n')
            ++pos;
          std::string_view rest =
            std::string_view(text).substr(start, pos - start);
          next_line();
          return rest;
        }

        /**
         * Nothing but blanks may follow the last token() on its line;
         * @p after says what that token ended, for the message.
         */
        void
        finish_line(const std::string &after)
        {
          if (!mid_line)
            return;
          while (pos < text.size() && is_blank(text[pos]))
            ++pos;
          if (pos < text.size() && text[pos] != '\n')
            {
              const std::size_t start = pos;
              while (pos < text.size() && !is_blank(text[pos]) &&
                     text[pos] != '\n')
                ++pos;
              fail(line,
                   "unexpected " +
                     in_quotes(
                       std::string_view(text).substr(start, pos - start)) +
                     " after " + after);
            }
          next_line();
        }

        /// Skip exactly one line: the separator before @p section.
        void
        skip_separator(const std::string &after, const std::string &section)
        {
          finish_line(after);
          if (pos == text.size())
            fail_end_of_file("the separator line before the " + section +
                             " section");
          rest_of_line();
        }

        bool
        at_end() const
        {
          return pos == text.size();
        }

        const std::string file;

      private:
        void
        next_line()
        {
          if (pos < text.size())
            {
              ++pos;
              ++line;
            }
          mid_line = false;
        }

        std::string  text;
        std::size_t  pos       = 0;
        unsigned int line      = 1;
        unsigned int last_line = 1;
        bool         mid_line  = false;
      };

      /// Reads the .lis layout of specs/004 §4.2 into a Model.
      class MeshReader
      {
      public:
        MeshReader(const std::string &file,
                   std::string      &&contents,
                   Model             &model)
          : in(file, std::move(contents))
          , model(model)
        {}

        void
        read()
        {
          read_header();
          read_nodes();
          read_elements();
          in.skip_separator("element " + std::to_string(model.elements.size()),
                            "essential BC");
          read_essential();
          in.skip_separator(
            model.essential.empty() ?
              std::string("the number of essential BC sets") :
              "the " + std::to_string(model.essential.back().nodes.size()) +
                " node ids of essential set " +
                std::to_string(model.essential.size() - 1),
            "natural BC");
          read_natural();
          in.skip_separator("the natural BC faces", "NO FAIL region");
          read_no_fail();
          in.skip_separator("the node ids of the NO FAIL region",
                            "pre-exist crack");
          read_cracks();
          in.finish_line("the last crack");
          unsigned int           line  = 0;
          const std::string_view extra = in.token(line);
          if (!extra.empty())
            in.fail(line,
                    "unexpected " + in_quotes(extra) + " after the " +
                      std::to_string(model.cracks.size()) +
                      " announced pre-existing cracks (end of the file "
                      "expected)");
        }

      private:
        // ------------------------------------------------------------ values
        double
        real(const std::string_view token,
             const unsigned int     line,
             const std::string     &what) const
        {
          double value = 0;
          if (!to_double(token, value))
            in.fail(line, "expected " + what + ", found " + in_quotes(token));
          return value;
        }

        long long
        integer(const std::string_view token,
                const unsigned int     line,
                const std::string     &what) const
        {
          long long value = 0;
          if (!to_integer(token, value))
            in.fail(line, "expected " + what + ", found " + in_quotes(token));
          return value;
        }

        unsigned int
        count(const std::string_view token,
              const unsigned int     line,
              const std::string     &what) const
        {
          const long long value = integer(token, line, what);
          if (value < 0 || value > 100000000)
            in.fail(line,
                    what + " " + std::string(token) + " is out of range",
                    "0..100000000");
          return static_cast<unsigned int>(value);
        }

        /// A 1-based node id of the file -> 0-based index.
        unsigned int
        node(const std::string_view token,
             const unsigned int     line,
             const std::string     &what) const
        {
          const long long id = integer(token, line, "a node id " + what);
          if (id < 1 || id > static_cast<long long>(model.nodes.size()))
            in.fail(line,
                    "node " + std::string(token) + " " + what +
                      " does not exist",
                    "node ids 1.." + std::to_string(model.nodes.size()));
          return static_cast<unsigned int>(id - 1);
        }

        /// A line on its own holding one count.
        unsigned int
        count_record(const std::string &what)
        {
          const unsigned int line = in.record(tokens);
          if (tokens.empty())
            in.fail_end_of_file(what);
          if (tokens.size() != 1)
            in.fail(line,
                    "expected " + what + " alone on its line, found " +
                      std::to_string(tokens.size()) +
                      " values (one separator line precedes each section)");
          return count(tokens[0], line, what);
        }

        /**
         * The next record, for item @p what: the end of the file and a first
         * token that is not a number (e.g. the next separator: fewer records
         * than announced) are errors.
         */
        unsigned int
        numeric_record(const std::string &what)
        {
          const unsigned int line = in.record(tokens);
          if (tokens.empty())
            in.fail_end_of_file(what);
          double value = 0;
          if (!to_double(tokens[0], value))
            in.fail(line,
                    "expected " + what + ", found " + in_quotes(tokens[0]));
          return line;
        }

        static std::string
        of(const unsigned int i, const unsigned int n)
        {
          return std::to_string(i) + " of " + std::to_string(n);
        }

        // ------------------------------------------------------------ sections
        void
        read_header()
        {
          unsigned int           line  = 0;
          const std::string_view title = in.token(line);
          if (title.empty())
            in.fail_end_of_file("the title (line 1)");
          model.title = std::string(title);
          in.rest_of_line();
          if (in.at_end())
            in.fail_end_of_file("a description line after the title");
          std::string_view label = in.rest_of_line();
          while (!label.empty() && is_blank(label.back()))
            label.remove_suffix(1);
          while (!label.empty() && is_blank(label.front()))
            label.remove_prefix(1);
          model.label = std::string(label);

          line = in.record(tokens);
          if (tokens.empty())
            in.fail_end_of_file("'2D|3D problem_type'");
          if (tokens[0] == "2D")
            model.dim = 2;
          else if (tokens[0] == "3D")
            model.dim = 3;
          else
            in.fail(line,
                    "expected the dimension, found " + in_quotes(tokens[0]),
                    "2D, 3D");
          if (tokens.size() != 2)
            in.fail(line,
                    "expected '" + std::string(tokens[0]) +
                      " problem_type', found " + std::to_string(tokens.size()) +
                      " values");
          const long long type = integer(tokens[1], line, "the problem type");
          if (model.dim == 2 && type != 1 && type != 2)
            in.fail(line,
                    "problem type " + std::string(tokens[1]) +
                      " is not a 2D problem type",
                    "1 (plane stress), 2 (plane strain)");
          model.problem_type = static_cast<int>(type);

          const char *const names[5] = {"Young's modulus",
                                        "Poisson's ratio",
                                        "density",
                                        "fracture toughness",
                                        "tensile strength"};
          line = numeric_record("'E nu rho K_Ic sigma_ult'");
          if (tokens.size() != 5)
            in.fail(line,
                    "expected 5 material values 'E nu rho K_Ic sigma_ult', "
                    "found " +
                      std::to_string(tokens.size()));
          double *const values[5] = {&model.youngs_modulus,
                                     &model.poissons_ratio,
                                     &model.density,
                                     &model.fracture_toughness,
                                     &model.tensile_strength};
          for (unsigned int i = 0; i < 5; ++i)
            *values[i] = real(tokens[i], line, names[i]);

          line = numeric_record("'number_of_nodes number_of_elements'");
          if (tokens.size() != 2)
            in.fail(line,
                    "expected 'number_of_nodes number_of_elements', found " +
                      std::to_string(tokens.size()) + " values");
          n_nodes    = count(tokens[0], line, "the number of nodes");
          n_elements = count(tokens[1], line, "the number of elements");
          if (n_nodes == 0 || n_elements == 0)
            in.fail(line,
                    "the mesh has no " +
                      std::string(n_nodes == 0 ? "nodes" : "elements"),
                    "at least 1");
        }

        void
        read_nodes()
        {
          model.nodes.resize(n_nodes);
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              const unsigned int line =
                numeric_record("node " + of(k + 1, n_nodes));
              if (tokens.size() != 4)
                in.fail(line,
                        "expected 'id x y z' for node " + of(k + 1, n_nodes) +
                          ", found " + std::to_string(tokens.size()) +
                          " values");
              check_id(tokens[0], line, "node", k + 1);
              for (unsigned int d = 0; d < 3; ++d)
                model.nodes[k][d] = real(tokens[d + 1],
                                         line,
                                         std::string(1, "xyz"[d]) +
                                           " of node " + std::to_string(k + 1));
            }
        }

        void
        check_id(const std::string_view token,
                 const unsigned int     line,
                 const std::string     &kind,
                 const unsigned int     expected) const
        {
          const long long id = integer(token, line, kind + " id");
          if (id != expected)
            in.fail(line,
                    "expected " + kind + " id " + std::to_string(expected) +
                      ", found " + in_quotes(token) + " (" + kind +
                      " ids must be consecutive from 1)");
        }

        void
        read_elements()
        {
          const unsigned int n_ids = model.dim == 2 ? 4 : 8;
          model.elements.resize(n_elements);
          std::vector<unsigned int> ids(n_ids);
          for (unsigned int k = 0; k < n_elements; ++k)
            {
              const std::string  name = "element " + std::to_string(k + 1);
              const unsigned int line =
                numeric_record("element " + of(k + 1, n_elements));
              if (tokens.size() < 2)
                in.fail(line,
                        "expected 'id type' and " + std::to_string(n_ids) +
                          " node ids for " + name + ", found " +
                          std::to_string(tokens.size()) + " value");
              if (tokens.size() != n_ids + 2)
                in.fail(line,
                        "expected " + std::to_string(n_ids) + " node ids for " +
                          name + ", found " +
                          std::to_string(tokens.size() - 2));
              check_id(tokens[0], line, "element", k + 1);
              const long long type =
                integer(tokens[1], line, "the type of " + name);
              if (type != 1 && type != 2)
                in.fail(line,
                        "element type " + std::string(tokens[1]) + " of " +
                          name + " is unknown",
                        "1 (PD), 2 (FE)");
              for (unsigned int i = 0; i < n_ids; ++i)
                ids[i] = node(tokens[i + 2], line, "of " + name);

              Model::Element &element = model.elements[k];
              element.type            = static_cast<unsigned int>(type);
              element.vertices        = model.dim == 2 ?
                                          quad_or_triangle(ids, line, name) :
                                          hex_or_tet(ids, line, name);
            }
        }

        static bool
        distinct(const std::vector<unsigned int> &ids)
        {
          for (std::size_t i = 0; i < ids.size(); ++i)
            for (std::size_t j = i + 1; j < ids.size(); ++j)
              if (ids[i] == ids[j])
                return false;
          return true;
        }

        std::string
        as_written(const std::vector<unsigned int> &ids) const
        {
          std::string s;
          for (const unsigned int i : ids)
            s += (s.empty() ? "" : " ") + std::to_string(i + 1);
          return s;
        }

        /// I J K L -> quadrilateral; I J K K -> triangle I J K (specs/004
        /// §1.4).
        std::vector<unsigned int>
        quad_or_triangle(const std::vector<unsigned int> &ids,
                         const unsigned int               line,
                         const std::string               &name) const
        {
          if (distinct(ids))
            return ids;
          const std::vector<unsigned int> triangle = {ids[0], ids[1], ids[2]};
          if (ids[2] == ids[3] && distinct(triangle))
            return triangle;
          in.fail(line,
                  name + ": node ids " + as_written(ids) +
                    " are neither a quadrilateral nor a triangle",
                  "I J K L (4 distinct), I J K K (triangle)");
        }

        /// I..P -> hexahedron; I J K K L L L L -> tetrahedron I J K L.
        std::vector<unsigned int>
        hex_or_tet(const std::vector<unsigned int> &ids,
                   const unsigned int               line,
                   const std::string               &name) const
        {
          if (distinct(ids))
            return ids;
          const std::vector<unsigned int> tet = {ids[0],
                                                 ids[1],
                                                 ids[2],
                                                 ids[4]};
          if (ids[2] == ids[3] && ids[4] == ids[5] && ids[4] == ids[6] &&
              ids[4] == ids[7] && distinct(tet))
            return tet;
          in.fail(line,
                  name + ": node ids " + as_written(ids) +
                    " are neither a hexahedron nor a tetrahedron",
                  "I J K L M N O P (8 distinct), I J K K L L L L "
                  "(tetrahedron); wedges and pyramids are not supported");
        }

        void
        read_essential()
        {
          const unsigned int n_sets =
            count_record("the number of essential BC sets");
          model.essential.resize(n_sets);
          std::vector<unsigned int> sizes(n_sets);
          for (unsigned int s = 0; s < n_sets; ++s)
            {
              const std::string  what = "essential set " + std::to_string(s);
              const unsigned int line =
                numeric_record("'number_of_nodes DOF value' of " + what);
              if (tokens.size() != 3)
                in.fail(line,
                        "expected 'number_of_nodes DOF value' for " + what +
                          ", found " + std::to_string(tokens.size()) +
                          " values");
              sizes[s] =
                count(tokens[0], line, "the number of nodes of " + what);
              Model::EssentialSet &set = model.essential[s];
              if (tokens[1] == "UX")
                set.component = 0;
              else if (tokens[1] == "UY")
                set.component = 1;
              else if (tokens[1] == "UZ" && model.dim == 3)
                set.component = 2;
              else
                in.fail(line,
                        "unknown DOF " + in_quotes(tokens[1]) + " for " + what +
                          (tokens[1] == "UZ" ? " in 2D" : ""),
                        model.dim == 2 ? "UX, UY" : "UX, UY, UZ");
              set.value = real(tokens[2], line, "the value of " + what);
            }

          // owner[3 * node + component] = 1 + the set that constrains it
          std::vector<unsigned int> owner(3 * model.nodes.size(), 0);
          const char *const         dof_names[3] = {"UX", "UY", "UZ"};
          for (unsigned int s = 0; s < n_sets; ++s)
            {
              Model::EssentialSet &set  = model.essential[s];
              const std::string    what = "essential set " + std::to_string(s);
              set.nodes.resize(sizes[s]);
              for (unsigned int i = 0; i < sizes[s]; ++i)
                {
                  unsigned int           line  = 0;
                  const std::string_view token = in.token(line);
                  const std::string      item =
                    "node id " + of(i + 1, sizes[s]) + " of " + what;
                  if (token.empty())
                    in.fail_end_of_file(item);
                  long long id = 0;
                  if (!to_integer(token, id))
                    in.fail(line,
                            "expected " + item + ", found " + in_quotes(token));
                  const unsigned int n = node(token, line, "in " + what);
                  unsigned int      &o = owner[3 * n + set.component];
                  if (o != 0)
                    in.fail(line,
                            "DOF " + std::string(dof_names[set.component]) +
                              " of node " + std::string(token) +
                              (o == s + 1 ? " is listed twice in " + what :
                                            " is constrained twice, by "
                                            "essential sets " +
                                              std::to_string(o - 1) + " and " +
                                              std::to_string(s)),
                            "each DOF of a node in one essential set, once");
                  o            = s + 1;
                  set.nodes[i] = n;
                }
            }
        }

        void
        read_natural()
        {
          const unsigned int n_sets =
            count_record("the number of natural BC sets");
          model.natural.resize(n_sets);
          std::vector<unsigned int> sizes(n_sets);
          for (unsigned int s = 0; s < n_sets; ++s)
            {
              const std::string  what = "natural set " + std::to_string(s);
              const unsigned int line =
                numeric_record("'number_of_faces traction' of " + what);
              if (tokens.size() != 2)
                in.fail(line,
                        "expected 'number_of_faces traction' for " + what +
                          ", found " + std::to_string(tokens.size()) +
                          " values");
              sizes[s] =
                count(tokens[0], line, "the number of faces of " + what);
              model.natural[s].traction =
                real(tokens[1], line, "the traction of " + what);
            }

          const unsigned int        n_ids = model.dim == 2 ? 2 : 4;
          std::vector<unsigned int> ids(n_ids);
          for (unsigned int s = 0; s < n_sets; ++s)
            {
              const std::string what  = "natural set " + std::to_string(s);
              auto             &faces = model.natural[s].faces;
              faces.resize(sizes[s]);
              for (unsigned int f = 0; f < sizes[s]; ++f)
                {
                  const std::string face =
                    "face " + of(f + 1, sizes[s]) + " of " + what;
                  const unsigned int line = numeric_record(face);
                  if (tokens.size() != n_ids)
                    in.fail(line,
                            "expected " + std::to_string(n_ids) +
                              " node ids for " + face + ", found " +
                              std::to_string(tokens.size()));
                  for (unsigned int i = 0; i < n_ids; ++i)
                    ids[i] = node(tokens[i], line, "of " + face);
                  if (distinct(ids))
                    faces[f] = ids;
                  else if (n_ids == 4 && ids[2] == ids[3] &&
                           distinct({ids[0], ids[1], ids[2]}))
                    faces[f] = {ids[0], ids[1], ids[2]};
                  else
                    in.fail(line,
                            face + ": node ids " + as_written(ids) +
                              " are not a " +
                              (n_ids == 2 ? "boundary edge" : "boundary face"),
                            n_ids == 2 ? "2 distinct node ids" :
                                         "p q r s (4 distinct), p q r r "
                                         "(triangle)");
                }
            }
        }

        void
        read_no_fail()
        {
          const unsigned int n = count_record("the number of NO FAIL nodes");
          model.no_fail_nodes.resize(n);
          for (unsigned int i = 0; i < n; ++i)
            {
              unsigned int           line  = 0;
              const std::string_view token = in.token(line);
              const std::string      item =
                "node id " + of(i + 1, n) + " of the NO FAIL region";
              if (token.empty())
                in.fail_end_of_file(item);
              long long id = 0;
              if (!to_integer(token, id))
                in.fail(line,
                        "expected " + item + ", found " + in_quotes(token));
              model.no_fail_nodes[i] =
                node(token, line, "in the NO FAIL region");
            }
        }

        void
        read_cracks()
        {
          const unsigned int n =
            count_record("the number of pre-existing cracks");
          const unsigned int n_points = model.dim == 2 ? 2 : 3;
          model.cracks.resize(n);
          for (unsigned int c = 0; c < n; ++c)
            {
              const std::string  what = "crack " + of(c + 1, n);
              const unsigned int line = numeric_record(what);
              if (tokens.size() != 3 * n_points)
                in.fail(line,
                        "expected " + std::to_string(n_points) + " points (" +
                          std::to_string(3 * n_points) + " coordinates) for " +
                          what + " in " + std::to_string(model.dim) +
                          "D, found " + std::to_string(tokens.size()) +
                          " coordinates",
                        model.dim == 2 ? "x1 y1 z1 x2 y2 z2 (point 2 = tip)" :
                                         "x1 y1 z1 x2 y2 z2 x3 y3 z3");
              model.cracks[c].resize(n_points);
              for (unsigned int p = 0; p < n_points; ++p)
                for (unsigned int d = 0; d < 3; ++d)
                  model.cracks[c][p][d] =
                    real(tokens[3 * p + d], line, "a coordinate of " + what);
            }
        }

        Text                          in;
        Model                        &model;
        std::vector<std::string_view> tokens;
        unsigned int                  n_nodes    = 0;
        unsigned int                  n_elements = 0;
      };
    } // namespace



    PDLSMFEMModel
    read_pdlsm_fem_mesh(const std::string &mesh_file)
    {
      std::string text;
      if (!read_text(mesh_file, text))
        throw InputError(mesh_file,
                         "",
                         "cannot read the mesh file",
                         "an existing, readable .lis file");
      Model model;
      model.mesh_file = mesh_file;
      MeshReader(mesh_file, std::move(text), model).read();
      return model;
    }
  } // namespace IO
} // namespace pdfem
