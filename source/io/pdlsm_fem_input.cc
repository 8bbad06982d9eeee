// SPDX-License-Identifier: LGPL-2.1-or-later
// Reader for the input files of the peer code PDLSM-FEM (specs/004 §4): the
// command file (.in), and the token helpers shared with the reader of the
// mesh file (.lis) it names (pdlsm_fem_mesh_input.cc).
#include <pdfem/base/exceptions.h>
#include <pdfem/io/pdlsm_fem_input.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>

#include "pdlsm_fem_input_internal.h"

namespace pdfem
{
  namespace IO
  {
    namespace
    {
      namespace fs = std::filesystem;
    } // namespace

    namespace internal
    {
      namespace
      {
        /// Drop a leading '+' (std::from_chars does not accept it).
        std::string_view
        without_plus(std::string_view token)
        {
          if (token.size() > 1 && token[0] == '+' && token[1] != '-' &&
              token[1] != '+')
            token.remove_prefix(1);
          return token;
        }
      } // namespace

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
    } // namespace internal

    namespace
    {
      using namespace internal;
      using Model = PDLSMFEMModel;

      const char *const allowed_keywords =
        "MSHFILE, SOLVER, SETSOLVING, NEWMARK, LUMPMASS, EBC, VEBC, NBC, "
        "VNBC, FC, TOPK, RF, VTKFORMAT, FENSF";

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
