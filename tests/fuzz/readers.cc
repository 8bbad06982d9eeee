// SPDX-License-Identifier: LGPL-2.1-or-later
#include "readers.h"

#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/io/parameters.h>
#include <pdfem/io/pdlsm_fem_input.h>
#include <pdfem/mesh/gmsh_input.h>
#include <pdfem/mesh/mesh_checks.h>
#include <pdfem/scene/scene.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/grid/tria.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string_view>

#include <unistd.h>

namespace pdfem
{
  namespace Fuzz
  {
    namespace
    {
      namespace fs = std::filesystem;

      [[noreturn]] void
      fail(const std::string &what)
      {
        std::fprintf(stderr, "pdfem fuzz: %s\n", what.c_str());
        std::abort();
      }

      /// This process's scratch folder (one per process: fuzzers run
      /// several jobs side by side), removed when the process exits
      /// normally (a crash leaves its inputs there).
      const fs::path &
      scratch()
      {
        static const fs::path folder = [] {
          const fs::path f = fs::temp_directory_path() /
                             ("pdfem-fuzz-" + std::to_string(::getpid()));
          fs::create_directories(f);
          return f;
        }();
        // Registered after the folder is made, so run before it is gone.
        static const bool removed_at_exit =
          std::atexit([] {
            std::error_code ignored;
            fs::remove_all(scratch(), ignored);
          }) == 0;
        (void)removed_at_exit;
        return folder;
      }

      void
      write_file(const std::string &path, const std::string_view contents)
      {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), contents.size());
        if (!out)
          fail("cannot write " + path);
      }

      /// Write @p contents to the scratch file @p name. With
      /// PDFEM_FUZZ_KEEP=N, the last N inputs are also kept, as
      /// `<name>.0` ... `<name>.N-1` in the scratch folder: a fault that
      /// shows only later (memory an uninstrumented library overwrote) can
      /// then be traced by replaying them under valgrind.
      std::string
      write(const std::string &name, const std::string_view contents)
      {
        const std::string path = (scratch() / name).string();
        write_file(path, contents);
        static const unsigned long keep = [] {
          const char *n = std::getenv("PDFEM_FUZZ_KEEP");
          return n != nullptr ? std::strtoul(n, nullptr, 10) : 0ul;
        }();
        static unsigned long count = 0;
        if (keep > 0)
          write_file(path + "." + std::to_string(count++ % keep), contents);
        return path;
      }

      /// Run @p read; an InputError is a refusal and must be one line.
      template <typename Read>
      Outcome
      judge(Read &&read)
      {
        try
          {
            read();
            return Outcome::accepted;
          }
        catch (const InputError &e)
          {
            const std::string message = e.what();
            if (message.empty())
              fail("an InputError without a message");
            if (message.find('\n') != std::string::npos)
              fail("an InputError message of more than one line:\n" + message);
            return Outcome::refused;
          }
        catch (const std::exception &e)
          {
            fail(std::string("not an InputError: ") + e.what());
          }
        catch (...)
          {
            fail("an exception of unknown type");
          }
      }

      template <int dim>
      void
      read_mesh_as(const std::string &msh)
      {
        Mesh::read_physical_names(msh, dim);
        dealii::Triangulation<dim> tria;
        Mesh::read_msh<dim>(msh, tria);
        Mesh::check_cell_shapes(tria, msh);
        Mesh::read_node_sets<dim>(msh, tria);
      }

    } // namespace

    Outcome
    read_prm(const std::uint8_t *data, const std::size_t size)
    {
      const std::string file =
        write("fuzz.prm", {reinterpret_cast<const char *>(data), size});
      return judge([&] {
        Parameters::Scene prm;
        prm.read(file);
        if (prm.dim == 2)
          Scene::plugins_of<2>(prm);
#if PDFEM_WITH_3D
        else
          Scene::plugins_of<3>(prm);
#endif
      });
    }

    Outcome
    read_msh(const std::uint8_t *data, const std::size_t size)
    {
      const std::string file =
        write("fuzz.msh", {reinterpret_cast<const char *>(data), size});
      Outcome outcome = judge([&] { Mesh::check_msh_file(file); });
      if (outcome == Outcome::refused)
        return outcome;
      // A checked file of either dimension: the wrong one is refused.
      outcome = judge([&] { read_mesh_as<2>(file); });
#if PDFEM_WITH_3D
      if (judge([&] { read_mesh_as<3>(file); }) == Outcome::accepted)
        outcome = Outcome::accepted;
#endif
      return outcome;
    }

    Outcome
    read_pdlsm_fem(const std::uint8_t *data, const std::size_t size)
    {
      const std::string_view all(reinterpret_cast<const char *>(data), size);
      const std::string_view separator = "\n#@ mesh\n";
      const std::size_t      split     = all.find(separator);
      fs::remove(scratch() / "mesh.lis");
      if (split != std::string_view::npos)
        write("mesh.lis", all.substr(split + separator.size()));
      const std::string file = write("fuzz.in", all.substr(0, split));
      return judge([&] {
        const IO::PDLSMFEMModel model = IO::read_pdlsm_fem(file);
        if (model.dim == 2)
          {
            dealii::Triangulation<2> tria;
            IO::create_triangulation(model, tria);
          }
#if PDFEM_WITH_3D
        else
          {
            dealii::Triangulation<3> tria;
            IO::create_triangulation(model, tria);
          }
#endif
      });
    }

    Reader
    reader(const std::string &name)
    {
      if (name == "prm")
        return read_prm;
      if (name == "msh")
        return read_msh;
      if (name == "pdlsm_fem")
        return read_pdlsm_fem;
      return nullptr;
    }
  } // namespace Fuzz
} // namespace pdfem
