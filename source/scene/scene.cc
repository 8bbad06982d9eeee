// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/io/atomic_file.h>
#include <pdfem/io/field_output.h>
#include <pdfem/io/history.h>
#include <pdfem/io/json_writer.h>
#include <pdfem/io/parameters.h>
#include <pdfem/io/pdlsm_fem_input.h>
#include <pdfem/mesh/cracks.h>
#include <pdfem/mesh/gmsh_input.h>
#include <pdfem/mesh/mesh_checks.h>
#include <pdfem/scene/scene.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>

#include "scene_internal.h"
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace pdfem
{
  namespace Scene
  {
    using namespace dealii;
    namespace fs = std::filesystem;
    using Coupling::component_names;
    using Coupling::stress_component;
    using Coupling::stress_component_names;
    using internal::make_output_folder;
    using internal::seconds_since;
    using internal::Setup;

    namespace
    {
      using clock = std::chrono::steady_clock;

      std::string
      resolve(const std::string &path, const std::string &base)
      {
        const fs::path p(path);
        return p.is_absolute() ? path : (fs::path(base) / p).string();
      }

      /// A region or boundary given by name, or by a number (its tag).
      bool
      lookup(const std::map<std::string, unsigned int> &names,
             const std::string                         &name,
             unsigned int                              &tag)
      {
        const auto it = names.find(name);
        if (it != names.end())
          {
            tag = it->second;
            return true;
          }
        if (!name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
              return std::isdigit(static_cast<unsigned char>(c));
            }))
          {
            tag = std::stoul(name);
            return true;
          }
        return false;
      }

      template <int dim>
      std::vector<Coupling::BoundaryCondition<dim>>
      resolve_conditions(
        const std::vector<Parameters::BoundaryEntry> &entries,
        const Mesh::PhysicalNames                    &names,
        const std::set<unsigned int>                 &boundary_ids_in_mesh,
        const std::map<std::string, std::vector<unsigned int>> &node_sets,
        const std::string                                      &file,
        const std::string                                      &parameter,
        const bool                                              allow_points)
      {
        std::vector<Coupling::BoundaryCondition<dim>> result;
        for (const auto &e : entries)
          {
            Coupling::BoundaryCondition<dim> bc;
            bc.name       = e.boundary;
            bc.component  = e.component;
            bc.expression = e.expression;
            if (!e.boundary.empty() && e.boundary.front() == '(')
              {
                if (!allow_points)
                  throw InputError(file,
                                   parameter,
                                   "a point '" + e.boundary +
                                     "' cannot carry a traction",
                                   "the name of a boundary");
                std::string inner = e.boundary.substr(1);
                inner             = inner.substr(0, inner.find(')'));
                std::stringstream s(inner);
                std::string       part;
                unsigned int      d = 0;
                while (std::getline(s, part, ','))
                  {
                    if (d >= dim)
                      break;
                    try
                      {
                        bc.point[d++] = std::stod(part);
                      }
                    catch (...)
                      {
                        d = dim + 1;
                        break;
                      }
                  }
                if (d != dim)
                  throw InputError(file,
                                   parameter,
                                   "cannot read the point '" + e.boundary + "'",
                                   dim == 2 ? "(x, y)" : "(x, y, z)");
                bc.at_point = true;
              }
            else
              {
                unsigned int tag      = 0;
                const auto   node_set = node_sets.find(e.boundary);
                if (names.boundaries.count(e.boundary) == 0 &&
                    node_set != node_sets.end())
                  {
                    // A node set (gmsh physical points): any mesh nodes.
                    if (!allow_points)
                      throw InputError(file,
                                       parameter,
                                       "the node set '" + e.boundary +
                                         "' cannot carry a traction",
                                       "the name of a boundary");
                    bc.vertices = node_set->second;
                  }
                else if (!lookup(names.boundaries, e.boundary, tag) ||
                         boundary_ids_in_mesh.count(tag) == 0)
                  throw InputError(
                    file,
                    parameter,
                    "the mesh has no boundary named '" + e.boundary + "'",
                    "boundaries of the mesh: " +
                      Mesh::PhysicalNames::list(names.boundaries) +
                      (allow_points ?
                         "; node sets: " +
                           Mesh::PhysicalNames::list(names.node_sets) +
                           "; or a node given as (x, y[, z])" :
                         ""));
                else
                  bc.boundary_ids = {tag};
              }
            result.push_back(bc);
          }
        return result;
      }

      template <int dim>
      void
      setup_from_prm(const Parameters::Scene &prm,
                     const RunOptions        &options,
                     MPI_Comm                 comm,
                     Setup<dim>              &setup)
      {
        const bool root   = Utilities::MPI::this_mpi_process(comm) == 0;
        setup.file        = prm.file;
        setup.name        = prm.name;
        setup.driver      = prm.driver;
        setup.write_vtu   = prm.output.write_vtu;
        setup.write_every = prm.output.write_every;
        setup.fracture    = prm.fracture;

        setup.write_nodes_csv    = prm.output.write_nodes_csv;
        setup.print_timings      = prm.output.print_timings;
        setup.patch_test         = prm.output.patch_test;
        setup.checkpoint_steps   = prm.output.checkpoint_steps;
        setup.checkpoint_minutes = prm.output.checkpoint_minutes;
        setup.progress_interval  = prm.output.progress_interval;
        setup.restart_from       = options.restart;
        auto &timings            = setup.timings;

        // ---- output folder
        // A restart without a checkpoint stops here, before any work.
        const std::string restart_folder =
          options.restart.empty() ? "" :
                                    checkpoint_output_folder(options.restart);
        std::string out_dir = options.output_directory;
        if (out_dir.empty())
          out_dir = restart_folder;
        if (out_dir.empty())
          out_dir = prm.output.directory.empty() ?
                      "output-" + prm.name :
                      resolve(prm.output.directory, prm.base_dir);
        setup.out_dir = out_dir;
        make_output_folder(out_dir, prm.file, "Output/Directory", comm);

        // ---- mesh (gmsh runs on rank 0 only)
        auto              start = clock::now();
        const std::string input = resolve(prm.mesh.input_file, prm.base_dir);
        std::string       msh;
        std::string       mesh_error;
        if (root)
          try
            {
              msh = Mesh::prepare_msh_file(input,
                                           dim,
                                           prm.mesh.size_factor,
                                           out_dir,
                                           prm.file,
                                           "Mesh/Input file");
            }
          catch (const InputError &e)
            {
              mesh_error = e.what();
            }
        // The file's structure before deal.II's reader trusts it.
        if (mesh_error.empty() && Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              Mesh::check_msh_file(msh);
            }
          catch (const InputError &e)
            {
              mesh_error = e.what();
            }
        mesh_error = Utilities::MPI::broadcast(comm, mesh_error, 0);
        if (!mesh_error.empty())
          throw InputError("", "", mesh_error);
        msh = Utilities::MPI::broadcast(comm, msh, 0);

        const Mesh::PhysicalNames names = Mesh::read_physical_names(msh, dim);
        auto                     &tria  = setup.create_triangulation(comm);
        Mesh::read_msh<dim>(msh, tria);
        Mesh::check_cell_shapes(tria, msh);
        // Node sets (physical points) as vertex indices, which global
        // refinement keeps; read only when the scene uses them (so that a
        // mesh with unused physical points in another format still works).
        bool uses_node_sets = !prm.fracture.no_fail_nodes.empty();
        for (const auto &e : prm.boundary_conditions.dirichlet)
          uses_node_sets =
            uses_node_sets || (names.node_sets.count(e.boundary) > 0 &&
                               names.boundaries.count(e.boundary) == 0);
        const auto node_sets =
          uses_node_sets ? Mesh::read_node_sets<dim>(msh, tria) :
                           std::map<std::string, std::vector<unsigned int>>();
        if (prm.mesh.refinements > 0)
          tria.refine_global(prm.mesh.refinements);
        timings["mesh"] = seconds_since(start);
        start           = clock::now();

        // ---- regions
        std::set<unsigned int> material_ids, boundary_ids;
        for (const auto &cell : tria.active_cell_iterators())
          {
            material_ids.insert(cell->material_id());
            for (const unsigned int f : cell->face_indices())
              if (cell->at_boundary(f))
                boundary_ids.insert(cell->face(f)->boundary_id());
          }
        std::vector<bool> &cell_is_pd = setup.cell_is_pd;
        cell_is_pd.assign(tria.n_active_cells(), false);
        const auto &regions = prm.mesh.pd_regions;
        const bool  all_pd =
          std::find(regions.begin(), regions.end(), "all") != regions.end();
        const bool no_pd =
          regions.empty() ||
          std::find(regions.begin(), regions.end(), "none") != regions.end();
        std::set<unsigned int> pd_ids;
        if (!all_pd && !no_pd)
          for (const auto &r : regions)
            {
              unsigned int tag = 0;
              if (!lookup(names.regions, r, tag) || !material_ids.count(tag))
                throw InputError(prm.file,
                                 "Mesh/PD regions",
                                 "the mesh has no region named '" + r + "'",
                                 "regions of the mesh: " +
                                   Mesh::PhysicalNames::list(names.regions) +
                                   ", 'all' or 'none'");
              pd_ids.insert(tag);
            }
        unsigned int n_pd_cells = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            const bool pd =
              !no_pd && (all_pd || pd_ids.count(cell->material_id()));
            cell_is_pd[cell->active_cell_index()] = pd;
            n_pd_cells += pd;
          }
        if (!no_pd && n_pd_cells == 0)
          throw InputError(prm.file,
                           "Mesh/PD regions",
                           "the PD region is empty (no cell of the mesh "
                           "belongs to it)",
                           "regions with cells, or 'none' for pure FE");

        // ---- boundary conditions against the mesh
        Coupling::Settings<dim> &settings = setup.settings;
        settings.source_file              = prm.file;
        settings.material.youngs_modulus  = prm.material.youngs_modulus;
        settings.material.poissons_ratio  = prm.material.poissons_ratio;
        settings.material.density         = prm.material.density;
        settings.material.plane_stress =
          dim == 2 &&
          prm.material.plane == Parameters::PlaneModel::plane_stress;
        settings.material.thickness   = prm.material.thickness;
        settings.horizon_factor       = prm.peridynamics.horizon_factor;
        settings.fe_nodes_in_families = prm.peridynamics.fe_nodes_in_families;
        settings.free_crack_faces     = prm.peridynamics.free_crack_faces;
        settings.cracks = Mesh::make_cracks<dim>(prm.peridynamics.cracks);
        settings.dirichlet =
          resolve_conditions<dim>(prm.boundary_conditions.dirichlet,
                                  names,
                                  boundary_ids,
                                  node_sets,
                                  prm.file,
                                  "Boundary conditions/Dirichlet",
                                  true);
        settings.traction =
          resolve_conditions<dim>(prm.boundary_conditions.traction,
                                  names,
                                  boundary_ids,
                                  node_sets,
                                  prm.file,
                                  "Boundary conditions/Traction",
                                  false);
        settings.body_force    = prm.boundary_conditions.body_force;
        settings.linear_solver = prm.linear_solver;

        // ---- reaction group: indices of the Dirichlet sets (distinct
        // target names, in order of first appearance)
        std::vector<std::string> set_names;
        for (const auto &bc : settings.dirichlet)
          if (std::find(set_names.begin(), set_names.end(), bc.name) ==
              set_names.end())
            set_names.push_back(bc.name);
        for (const auto &name : prm.boundary_conditions.reaction_group)
          setup.reaction_group.push_back(
            std::find(set_names.begin(), set_names.end(), name) -
            set_names.begin());

        // ---- no-fail nodes and crack tips
        for (const auto &name : prm.fracture.no_fail_nodes)
          {
            const auto it = node_sets.find(name);
            if (it == node_sets.end())
              throw InputError(prm.file,
                               "Fracture/No-fail nodes",
                               "the mesh has no node set named '" + name + "'",
                               "node sets (physical points) of the mesh: " +
                                 Mesh::PhysicalNames::list(names.node_sets));
            settings.no_fail_vertices.insert(settings.no_fail_vertices.end(),
                                             it->second.begin(),
                                             it->second.end());
          }
        if (prm.fracture.tip_at_second_point) // 3D cracks have no tips
          setup.tip_at_end.assign(settings.cracks.size(), true);

        setup.setup_start = start;
      }
    } // namespace

    namespace internal
    {
      void
      make_output_folder(const std::string &out_dir,
                         const std::string &file,
                         const std::string &parameter,
                         MPI_Comm           comm)
      {
        // Checked on rank 0, the verdict shared: every rank stops alike.
        std::string problem;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::error_code ec;
            fs::create_directories(out_dir, ec);
            if (ec || !fs::is_directory(out_dir))
              problem = "cannot create the output folder '" + out_dir +
                        "': " + (ec ? ec.message() : "not a folder");
            else
              {
                // An existing folder may be read-only (checked by writing,
                // which also covers ACLs and read-only mounts).
                const std::string probe = out_dir + "/.pdfem-write-test";
                const int         fd =
                  ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
                if (fd < 0)
                  problem = "cannot write into the output folder '" + out_dir +
                            "': " + std::strerror(errno);
                else
                  {
                    ::close(fd);
                    ::unlink(probe.c_str());
                  }
              }
          }
        problem = Utilities::MPI::broadcast(comm, problem, 0);
        if (!problem.empty())
          throw InputError(file, parameter, problem, "a writable folder");
      }

    } // namespace internal

    namespace
    {
      /// A PDLSM-FEM command file (and the .lis mesh it names).
      template <int dim>
      int
      run_pdlsm_fem(const IO::PDLSMFEMModel &model,
                    const RunOptions        &options,
                    MPI_Comm                 comm,
                    const clock::time_point  start)
      {
        Setup<dim> setup;
        setup.total_start = start;
        internal::setup_from_pdlsm_fem<dim>(model, options, comm, setup);
        auto           plugins = make_plugins<dim>(setup.file,
                                         setup.driver,
                                         setup.fracture,
                                         ModelChoice{"pdlsm"},
                                         nullptr,
                                         setup.settings.material.density,
                                         setup.settings.linear_solver);
        Simulator<dim> simulator(std::move(setup), comm, std::move(plugins));
        simulator.set_quiet(options.quiet);
        return simulator.run();
      }

      /// The parameters as read, every --set applied, the mesh file made
      /// absolute, so that they repeat the run from any folder.
      void
      print_resolved(const Parameters::Scene &prm, std::ostream &out)
      {
        ParameterHandler &handler = *prm.handler;
        handler.enter_subsection("Mesh");
        handler.set("Input file",
                    fs::absolute(resolve(prm.mesh.input_file, prm.base_dir))
                      .lexically_normal()
                      .string());
        handler.leave_subsection();
        handler.print_parameters(out, ParameterHandler::ShortPRM);
      }

      /// parameters.prm in @p out_dir (rank 0): print_resolved(), so that
      /// `pdfem out_dir/parameters.prm` repeats the run.
      void
      save_parameters(const Parameters::Scene &prm,
                      const std::string       &out_dir,
                      MPI_Comm                 comm)
      {
        std::string error;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          error = IO::write_atomically(out_dir + "/parameters.prm",
                                       [&](std::ostream &out) {
                                         print_resolved(prm, out);
                                       });
        error = Utilities::MPI::broadcast(comm, error, 0);
        if (!error.empty())
          throw InputError(prm.file,
                           "Output/Directory",
                           error,
                           "a writable folder with free space");
      }

      /// A .prm scene.
      template <int dim>
      int
      run_prm(const Parameters::Scene &prm,
              const RunOptions        &options,
              MPI_Comm                 comm,
              const clock::time_point  start)
      {
        auto       plugins = plugins_of<dim>(prm);
        Setup<dim> setup;
        setup.total_start = start;
        setup_from_prm<dim>(prm, options, comm, setup);
        save_parameters(prm, setup.out_dir, comm);
        Simulator<dim> simulator(std::move(setup), comm, std::move(plugins));
        simulator.set_quiet(options.quiet);
        return simulator.run();
      }
    } // namespace

    template <int dim>
    RunPlugins<dim>
    plugins_of(const Parameters::Scene &prm)
    {
      return make_plugins<dim>(prm.file,
                               prm.driver,
                               prm.fracture,
                               ModelChoice{prm.peridynamics.model,
                                           !prm.peridynamics.cracks.empty(),
                                           prm.peridynamics.free_crack_faces},
                               prm.handler.get(),
                               prm.material.density,
                               prm.linear_solver);
    }

    int
    run(const std::string &file, const RunOptions &options, MPI_Comm comm)
    {
      const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
      try
        {
          const auto start = clock::now();
          if (fs::path(file).extension() == ".in" && options.print_parameters)
            throw InputError(file,
                             "--print-parameters",
                             "a PDLSM-FEM command file has no scene "
                             "parameters to print",
                             "a .prm scene (pdfem-convert makes one from "
                             "the command file)");
          if (fs::path(file).extension() == ".in")
            {
              const IO::PDLSMFEMModel model = IO::read_pdlsm_fem(file);
              if (model.dim == 2)
                return run_pdlsm_fem<2>(model, options, comm, start);
#if PDFEM_WITH_3D
              return run_pdlsm_fem<3>(model, options, comm, start);
#endif
            }
          Parameters::Scene prm;
          prm.read(file, options.overrides);
          if (options.print_parameters)
            {
              // The plugins named are checked too (their own parameters).
              if (prm.dim == 2)
                plugins_of<2>(prm);
#if PDFEM_WITH_3D
              else
                plugins_of<3>(prm);
#endif
              if (root)
                print_resolved(prm, std::cout);
              return ExitCode::completed;
            }
          if (prm.dim == 2)
            return run_prm<2>(prm, options, comm, start);
#if PDFEM_WITH_3D
          return run_prm<3>(prm, options, comm, start);
#else
          throw InputError(file,
                           "Dimension",
                           "this pdfem was built without 3D",
                           "2 (rebuild with PDFEM_WITH_3D=ON for 3)");
#endif
        }
      catch (const InputError &e)
        {
          if (root)
            std::cerr << "pdfem: error: " << e.what() << std::endl;
          return ExitCode::input_error;
        }
    }

#define INSTANTIATE(dim) \
  template RunPlugins<dim> plugins_of<dim>(const Parameters::Scene &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Scene
} // namespace pdfem
