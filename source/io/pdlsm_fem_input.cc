// SPDX-License-Identifier: LGPL-2.1-or-later
// Reader for the input files of the peer code PDLSM-FEM (specs/004 §4): the
// command file (.in) and the mesh file (.lis) it names.
#include <pdfem/base/exceptions.h>
#include <pdfem/io/pdlsm_fem_input.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

namespace pdfem
{
  namespace IO
  {
    namespace
    {
      namespace fs = std::filesystem;
      using Model  = PDLSMFEMModel;

      const char *const allowed_keywords =
        "MSHFILE, SOLVER, SETSOLVING, NEWMARK, LUMPMASS, EBC, VEBC, NBC, "
        "VNBC, FC, TOPK, RF, VTKFORMAT, FENSF";

      std::string
      at_line(const unsigned int line)
      {
        return "line " + std::to_string(line);
      }

      /// A token as it appears in a message (long separator lines shortened).
      std::string
      in_quotes(const std::string_view token)
      {
        if (token.empty())
          return "nothing";
        if (token.size() > 40)
          return "'" + std::string(token.substr(0, 37)) + "...'";
        return "'" + std::string(token) + "'";
      }

      bool
      is_blank(const char c)
      {
        return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
      }

      /// Drop a leading '+' (std::from_chars does not accept it).
      std::string_view
      without_plus(std::string_view token)
      {
        if (token.size() > 1 && token[0] == '+' && token[1] != '-' &&
            token[1] != '+')
          token.remove_prefix(1);
        return token;
      }

      /// @p token as a finite number, or false.
      bool
      to_double(const std::string_view token, double &value)
      {
        const std::string_view t   = without_plus(token);
        const char            *end = t.data() + t.size();
        const auto [p, ec]         = std::from_chars(t.data(), end, value);
        return !t.empty() && ec == std::errc() && p == end &&
               std::isfinite(value);
      }

      /// @p token as a whole number, or false.
      bool
      to_integer(const std::string_view token, long long &value)
      {
        const std::string_view t   = without_plus(token);
        const char            *end = t.data() + t.size();
        const auto [p, ec]         = std::from_chars(t.data(), end, value);
        return !t.empty() && ec == std::errc() && p == end;
      }

      /// The whole of @p file, or false if it is not a readable file.
      bool
      read_text(const std::string &file, std::string &text)
      {
        std::error_code error;
        if (!fs::is_regular_file(file, error))
          return false;
        std::ifstream in(file, std::ios::binary);
        if (!in)
          return false;
        in.seekg(0, std::ios::end);
        const std::streamoff size = in.tellg();
        if (size < 0)
          return false;
        text.resize(static_cast<std::size_t>(size));
        in.seekg(0);
        in.read(text.data(), size);
        return static_cast<bool>(in);
      }

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

      /// One command of the command file: its line and its tokens.
      class Command
      {
      public:
        Command(const std::string                   &file,
                const unsigned int                   line,
                const std::vector<std::string_view> &tokens)
          : file(file)
          , line(line)
          , tokens(tokens)
          , keyword(tokens[0])
        {}

        [[noreturn]] void
        fail(const std::string &problem, const std::string &allowed = "") const
        {
          throw InputError(file, at_line(line), problem, allowed);
        }

        /// The number of arguments.
        std::size_t
        size() const
        {
          return tokens.size() - 1;
        }

        /// At least @p n arguments, for @p syntax.
        void
        require(const std::size_t n, const std::string &syntax) const
        {
          if (size() < n)
            fail(keyword + " needs " + std::to_string(n) + " value" +
                   (n == 1 ? "" : "s") + ", found " + std::to_string(size()),
                 keyword + " " + syntax);
        }

        std::string_view
        word(const std::size_t i) const
        {
          return tokens[i];
        }

        /// One of @p choices.
        std::string_view
        choice(const std::size_t                    i,
               const std::vector<std::string_view> &choices) const
        {
          std::string list;
          for (const auto &c : choices)
            list += (list.empty() ? "" : ", ") + std::string(c);
          require(i, list);
          for (const auto &c : choices)
            if (tokens[i] == c)
              return c;
          fail(keyword + ": unknown value " + in_quotes(tokens[i]), list);
        }

        double
        real(const std::size_t i, const std::string &what) const
        {
          double value = 0;
          if (!to_double(tokens[i], value))
            fail(keyword + ": " + what + " must be a number, found " +
                 in_quotes(tokens[i]));
          return value;
        }

        double
        positive(const std::size_t i, const std::string &what) const
        {
          const double value = real(i, what);
          if (!(value > 0))
            fail(keyword + ": " + what + " = " + std::string(tokens[i]) +
                   " is out of range",
                 what + " > 0");
          return value;
        }

        unsigned int
        natural(const std::size_t  i,
                const std::string &what,
                const unsigned int minimum = 0) const
        {
          long long value = 0;
          if (!to_integer(tokens[i], value))
            fail(keyword + ": " + what + " must be a whole number, found " +
                 in_quotes(tokens[i]));
          if (value < minimum || value > 2000000000)
            fail(keyword + ": " + what + " = " + std::string(tokens[i]) +
                   " is out of range",
                 std::to_string(minimum) + ".." + std::to_string(2000000000));
          return static_cast<unsigned int>(value);
        }

        /// A set id below @p n_sets.
        unsigned int
        set_id(const std::size_t  i,
               const std::size_t  n_sets,
               const std::string &kind) const
        {
          const unsigned int id = natural(i, "the set id");
          if (id >= n_sets)
            fail(keyword + ": the mesh file has no " + kind + " set " +
                   std::to_string(id),
                 n_sets == 0 ?
                   std::string("none: the mesh file has no ") + kind + " sets" :
                   "0.." + std::to_string(n_sets - 1));
          return id;
        }

        const std::string                   &file;
        const unsigned int                   line;
        const std::vector<std::string_view> &tokens;
        const std::string                    keyword;
      };

      void
      apply_command(const Command &c, Model &model)
      {
        const std::string &k = c.keyword;
        if (k == "SOLVER")
          {
            const auto s = c.choice(1, {"STATIC", "QUASI-STATIC", "DYNAMIC"});
            model.solver = s == "STATIC"       ? Model::Solver::static_solver :
                           s == "QUASI-STATIC" ? Model::Solver::quasi_static :
                                                 Model::Solver::dynamic;
            model.solver_given = true;
          }
        else if (k == "SETSOLVING")
          {
            c.require(5, "dt Nsteps writeFreq m a [m_e]");
            model.dt              = c.positive(1, "dt");
            model.n_steps         = c.natural(2, "Nsteps");
            model.write_frequency = c.natural(3, "writeFreq", 1);
            model.horizon_factor  = c.positive(4, "m");
            model.weight_factor   = c.real(5, "a");
            if (c.size() >= 6)
              {
                model.adaptive_factor = c.real(6, "m_e");
                if (model.adaptive_factor < 0)
                  c.fail(k + ": m_e = " + std::string(c.word(6)) +
                           " is out of range",
                         "m_e >= 0 (0 = off)");
              }
            model.setsolving_given = true;
          }
        else if (k == "NEWMARK")
          {
            model.newmark = c.choice(1, {"ON", "OFF"}) == "ON";
            // as the peer: gamma and beta only if both are given
            if (model.newmark && c.size() >= 3)
              {
                model.newmark_gamma = c.real(2, "gamma");
                model.newmark_beta  = c.real(3, "beta");
              }
          }
        else if (k == "LUMPMASS")
          model.lumped_mass = c.choice(1, {"ON", "OFF"}) == "ON";
        else if (k == "FENSF")
          model.fe_nodes_in_families = c.choice(1, {"ON", "OFF"}) == "ON";
        else if (k == "VTKFORMAT")
          model.vtk_ascii = c.choice(1, {"ASCII", "BINARY"}) == "ASCII";
        else if (k == "EBC" || k == "VEBC" || k == "NBC" || k == "VNBC")
          {
            c.require(2, "id value");
            const bool         essential = k == "EBC" || k == "VEBC";
            const unsigned int id =
              c.set_id(1,
                       essential ? model.essential.size() :
                                   model.natural.size(),
                       essential ? "essential BC" : "natural BC");
            const double value                = c.real(2, "the value");
            (k == "EBC"  ? model.ebc_value :
             k == "VEBC" ? model.ebc_rate :
             k == "NBC"  ? model.nbc_value :
                           model.nbc_rate)[id] = value;
          }
        else if (k == "FC")
          {
            c.require(1, "0 | 1 [m_r d_cf] | 2 [TopK]");
            long long flag = -1;
            if (!to_integer(c.word(1), flag) || flag < 0 || flag > 2)
              c.fail(k + ": unknown failure criterion " + in_quotes(c.word(1)),
                     "0 (none), 1 [m_r d_cf], 2 [TopK]");
            model.failure_criterion = static_cast<int>(flag);
            // as the peer: m_r and d_cf only if both are given
            if (flag == 1 && c.size() >= 3)
              {
                model.fc1_contour_factor = c.positive(2, "m_r");
                model.fc1_growth_factor  = c.positive(3, "d_cf");
              }
            if (flag == 2 && c.size() >= 2)
              model.top_k = c.natural(2, "TopK");
          }
        else if (k == "TOPK")
          {
            c.require(1, "k");
            model.top_k = c.natural(1, "k");
          }
        else if (k == "RF")
          {
            c.require(1, "id [id ...]");
            model.reaction_sets.clear();
            for (std::size_t i = 1; i <= c.size(); ++i)
              model.reaction_sets.push_back(
                c.set_id(i, model.essential.size(), "essential BC"));
          }
        else
          c.fail("unknown keyword " + in_quotes(k), allowed_keywords);
      }
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



    void
    apply_pdlsm_fem_overrides(PDLSMFEMModel &model)
    {
      const auto check = [&](const std::map<unsigned int, double> &values,
                             const char                           *keyword,
                             const std::size_t                     n_sets) {
        for (const auto &[id, value] : values)
          if (id >= n_sets)
            throw InputError(model.command_file,
                             std::string(keyword) + " " + std::to_string(id),
                             "the mesh file " + model.mesh_file +
                               " has no set " + std::to_string(id),
                             n_sets == 0 ? std::string("none") :
                                           "0.." + std::to_string(n_sets - 1));
      };
      check(model.ebc_value, "EBC", model.essential.size());
      check(model.ebc_rate, "VEBC", model.essential.size());
      check(model.nbc_value, "NBC", model.natural.size());
      check(model.nbc_rate, "VNBC", model.natural.size());
      for (const auto &[id, value] : model.ebc_value)
        model.essential[id].value = value;
      for (const auto &[id, value] : model.ebc_rate)
        model.essential[id].rate = value;
      for (const auto &[id, value] : model.nbc_value)
        model.natural[id].traction = value;
      for (const auto &[id, value] : model.nbc_rate)
        model.natural[id].rate = value;
    }



    PDLSMFEMModel
    read_pdlsm_fem(const std::string &command_file)
    {
      std::string text;
      if (!read_text(command_file, text))
        throw InputError(command_file,
                         "",
                         "cannot read the command file",
                         "an existing, readable file");

      Model                         model;
      bool                          mesh_read = false;
      std::vector<std::string_view> tokens;
      std::size_t                   pos  = 0;
      unsigned int                  line = 0;
      while (pos < text.size())
        {
          // one line; a token starting with '#' ends it
          ++line;
          std::size_t end = text.find('\n', pos);
          if (end == std::string::npos)
            end = text.size();
          tokens.clear();
          for (std::size_t i = pos; i < end;)
            {
              if (is_blank(text[i]))
                {
                  ++i;
                  continue;
                }
              const std::size_t start = i;
              while (i < end && !is_blank(text[i]))
                ++i;
              if (text[start] == '#')
                break;
              tokens.push_back(std::string_view(text).substr(start, i - start));
            }
          pos = end + 1;
          if (tokens.empty())
            continue;

          const Command command(command_file, line, tokens);
          if (command.keyword == "MSHFILE")
            {
              if (mesh_read)
                command.fail("MSHFILE given a second time",
                             "one MSHFILE, the first command");
              command.require(1, "mesh_file");
              const fs::path    given(tokens[1]);
              const fs::path    folder = fs::path(command_file).parent_path();
              const std::string mesh_file =
                (given.is_absolute() || folder.empty() ? given : folder / given)
                  .string();
              std::error_code error;
              if (!fs::is_regular_file(mesh_file, error))
                command.fail("the mesh file " + mesh_file + " does not exist",
                             "a .lis file, relative to the folder of the "
                             "command file");
              model           = read_pdlsm_fem_mesh(mesh_file);
              model.mesh_file = mesh_file;
              mesh_read       = true;
            }
          else if (!mesh_read)
            command.fail("expected MSHFILE as the first command, found " +
                           in_quotes(command.keyword),
                         "MSHFILE mesh_file as the first command");
          else
            apply_command(command, model);
        }

      model.command_file = command_file;
      if (!mesh_read)
        throw InputError(command_file,
                         "MSHFILE",
                         "missing: the command file names no mesh file",
                         "MSHFILE mesh_file as the first command");
      if (!model.solver_given)
        throw InputError(command_file,
                         "SOLVER",
                         "missing (required)",
                         "SOLVER STATIC | QUASI-STATIC | DYNAMIC");
      apply_pdlsm_fem_overrides(model);
      return model;
    }
  } // namespace IO
} // namespace pdfem
