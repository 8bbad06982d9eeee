// SPDX-License-Identifier: LGPL-2.1-or-later
// A run from a PDLSM-FEM command file and its .lis mesh (specs/004 §4): the
// model's elements become cells, its node sets Dirichlet sets, its face sets
// traction boundaries.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/io/pdlsm_fem_input.h>
#include <pdfem/mesh/cracks.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "scene_internal.h"

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      using namespace dealii;

      namespace
      {
        std::string
        exact(const double v)
        {
          std::ostringstream s;
          s << std::setprecision(17) << v;
          return s.str();
        }

        /// Boundary ids given to the natural (traction) sets: 10, 11, ...
        constexpr unsigned int first_traction_id = 10;
      } // namespace

      template <int dim>
      void
      setup_from_pdlsm_fem(const IO::PDLSMFEMModel &model,
                           const RunOptions        &options,
                           MPI_Comm                 comm,
                           Setup<dim>              &setup)
      {
        using Solver    = IO::PDLSMFEMModel::Solver;
        const auto &cmd = model.command_file;
        setup.file      = cmd;
        setup.name      = std::filesystem::path(cmd).stem().string();
        setup.driver    = Parameters::Driver();

        // ---- command-line overrides: the output ones, and for SOLVER
        // DYNAMIC a few driver ones (benchmarks: step sweeps, reuse).
        std::vector<std::pair<std::string, std::string>> driver_overrides;
        for (const auto &[path, value] : options.overrides)
          {
            if (path.rfind("Driver/", 0) == 0)
              {
                driver_overrides.emplace_back(path, value);
                continue;
              }
            const bool on = value == "true";
            if (!on && value != "false")
              throw InputError("--set",
                               path,
                               "'" + value + "' is not a boolean",
                               "true or false");
            if (path == "Output/Write vtu")
              setup.write_vtu = on;
            else if (path == "Output/Write nodes csv")
              setup.write_nodes_csv = on;
            else if (path == "Output/Print timings")
              setup.print_timings = on;
            else
              throw InputError("--set",
                               path,
                               "cannot be set for a PDLSM-FEM command file",
                               "Output/Write vtu, Output/Write nodes csv, "
                               "Output/Print timings; with SOLVER DYNAMIC "
                               "also Driver/Time step, Driver/Time step "
                               "safety factor, Driver/End time, "
                               "Driver/Reuse factorization, Driver/History "
                               "interval");
          }

        // ---- what is not there yet: say so before any work
        if ((model.failure_criterion == 1 || model.adaptive_factor > 0.) &&
            dim != 2)
          throw InputError(cmd,
                           model.failure_criterion == 1 ? "FC 1" :
                                                          "SETSOLVING m_e",
                           "stress-intensity factors and the adaptive PD "
                           "region are 2D only",
                           "FC 0 or FC 2 in 3D");

        // ---- crack criterion (specs/004 §3): FC 1 = mcts, FC 2 = max
        // principal stress; a static run only evaluates and reports it
        Parameters::Fracture &fracture = setup.fracture;
        if (model.failure_criterion == 1)
          {
            fracture.criterion = "mcts";
            fracture.toughness = model.fracture_toughness;
            // The domain: from one horizon (m element sizes: inside it the
            // nonlocal fields are smeared) to m_r element sizes beyond it
            // (the peer's line contour lies at m_r, inside the horizon's
            // reach when m_r < 2m). On plateCrack this gives the K_I of a
            // fine-mesh FE model with a real slit to 0.1 %.
            fracture.domain_inner_radius = model.horizon_factor;
            fracture.domain_outer_radius =
              model.horizon_factor + model.fc1_contour_factor;
            if (!(fracture.toughness > 0.))
              throw InputError(model.mesh_file,
                               "line 4 (fracture toughness)",
                               "K_Ic = " + number(fracture.toughness) +
                                 " is not positive (FC 1 needs it)",
                               "K_Ic > 0");
          }
        else if (model.failure_criterion == 2)
          {
            fracture.criterion        = "max principal stress";
            fracture.tensile_strength = model.tensile_strength;
            fracture.top_k            = model.top_k;
            if (!(fracture.tensile_strength > 0.))
              throw InputError(model.mesh_file,
                               "line 4 (ultimate tensile stress)",
                               "sigma_ult = " +
                                 number(fracture.tensile_strength) +
                                 " is not positive (FC 2 needs it)",
                               "sigma_ult > 0");
          }
        fracture.adaptive_margin = model.adaptive_factor;
        // Each crack is [start, tip] (specs/004 §3.1).
        setup.tip_at_end.assign(model.cracks.size(), true);

        // ---- load stepping: VEBC/VNBC are increments per step of t
        const bool quasi_static = model.solver == Solver::quasi_static;
        if (quasi_static)
          {
            setup.driver.type                  = "quasi-static";
            setup.driver.load_steps            = model.n_steps;
            setup.driver.load_increment        = 1.;
            setup.driver.initial_load          = 0.;
            setup.driver.jump_to_critical_load = true;
            setup.write_every                  = model.write_frequency;
          }
        const bool dynamic = model.solver == Solver::dynamic;
        if (dynamic)
          {
            // SOLVER DYNAMIC: explicit central difference (NEWMARK OFF) or
            // Newmark (specs/004 §2.3-2.4); SETSOLVING dt N writeFreq.
            auto &driver = setup.driver;
            driver.type  = model.newmark ? "newmark" : "explicit";
            if (!(model.dt > 0.))
              throw InputError(cmd,
                               "SETSOLVING",
                               "the time step dt = " + number(model.dt) +
                                 " is not positive",
                               "dt > 0 [s]");
            if (!(model.density > 0.))
              throw InputError(model.mesh_file,
                               "line 4",
                               "density rho = " + number(model.density) +
                                 " for SOLVER DYNAMIC",
                               "rho > 0");
            driver.time_step     = model.dt;
            driver.end_time      = model.dt * model.n_steps;
            driver.newmark_beta  = model.newmark_beta;
            driver.newmark_gamma = model.newmark_gamma;
            if (model.newmark)
              {
                const double g = model.newmark_gamma, b = model.newmark_beta;
                const double b_min = (2. * g + 1.) * (2. * g + 1.) / 16.;
                if (!(g >= 0.5) || !(b >= b_min - 1e-14) || !(b <= 1.))
                  throw InputError(cmd,
                                   "NEWMARK ON gamma beta",
                                   "gamma = " + number(g) +
                                     ", beta = " + number(b) +
                                     " are outside the unconditionally "
                                     "stable range",
                                   "gamma >= 0.5, (2 gamma + 1)^2 / 16 <= "
                                   "beta <= 1");
                // The peer's Newmark: consistent FE mass + PD lumped mass.
                driver.mass = "consistent";
              }
            else
              {
                driver.mass = "lumped";
                if (!model.lumped_mass)
                  setup.notes.push_back(
                    cmd + ": LUMPMASS OFF: the explicit driver uses the lumped "
                          "mass (a consistent one would need a solve per "
                          "step)");
              }
            for (const auto &[path, value] : driver_overrides)
              {
                const std::string entry = path.substr(7);
                try
                  {
                    if (entry == "Time step")
                      driver.time_step =
                        value == "auto" ? 0. : std::stod(value);
                    else if (entry == "Time step safety factor")
                      driver.safety_factor = std::stod(value);
                    else if (entry == "End time")
                      driver.end_time = std::stod(value);
                    else if (entry == "History interval")
                      driver.history_interval = std::stoul(value);
                    else if (entry == "Reuse factorization" &&
                             (value == "true" || value == "false"))
                      driver.reuse_factorization = value == "true";
                    else
                      throw std::invalid_argument(entry);
                  }
                catch (const std::exception &)
                  {
                    throw InputError("--set",
                                     path,
                                     "cannot be set to '" + value +
                                       "' for a PDLSM-FEM command file",
                                     "Driver/Time step (> 0 or auto), Time "
                                     "step safety factor (> 0), End time "
                                     "(> 0), History interval (>= 1), Reuse "
                                     "factorization (true|false)");
                  }
              }
            if ((driver.time_step == 0. && model.newmark) ||
                driver.time_step < 0. || !(driver.safety_factor > 0.) ||
                !(driver.end_time > 0.) || driver.history_interval == 0)
              throw InputError("--set",
                               "Driver",
                               "an override is out of range",
                               "Time step > 0 (auto: explicit only), safety "
                               "factor > 0, End time > 0, History interval "
                               ">= 1");
            if (model.failure_criterion == 1)
              setup.notes.push_back(
                cmd + ": FC 1 in a DYNAMIC run: stress-intensity factors "
                      "and MCTS growth are quasi-static; every bond stays "
                      "intact (the peer's code moves the tips and breaks "
                      "nothing either). FC 2 breaks bonds in dynamic runs");
          }
        if (!dynamic && !driver_overrides.empty())
          throw InputError("--set",
                           driver_overrides.front().first,
                           "cannot be set for a PDLSM-FEM command file with "
                           "SOLVER STATIC or QUASI-STATIC",
                           "Output/Write vtu, Output/Write nodes csv, "
                           "Output/Print timings");

        // ---- material (mesh file line 4)
        const double E = model.youngs_modulus, nu = model.poissons_ratio;
        const bool   plane_stress = dim == 2 && model.problem_type != 2;
        if (!(E > 0.))
          throw InputError(model.mesh_file,
                           "line 4",
                           "Young's modulus E = " + number(E) +
                             " is not positive",
                           "E > 0");
        if (!(nu > -1. && (plane_stress ? nu <= 0.5 : nu < 0.5)))
          throw InputError(model.mesh_file,
                           "line 4",
                           "Poisson's ratio nu = " + number(nu) +
                             " is out of range",
                           plane_stress ? "-1 < nu <= 0.5" : "-1 < nu < 0.5");

        // ---- output folder
        const std::string restart_folder =
          options.restart.empty() ? "" :
                                    checkpoint_output_folder(options.restart);
        setup.out_dir      = !options.output_directory.empty() ?
                               options.output_directory :
                             !restart_folder.empty() ? restart_folder :
                                                       "output-" + setup.name;
        setup.restart_from = options.restart;
        make_output_folder(setup.out_dir, cmd, "output folder", comm);

        // ---- cells: vertex index = node id - 1, material id = element type
        auto start = std::chrono::steady_clock::now();
        setup.create_triangulation(comm);
        auto &tria = *setup.tria;
        IO::create_triangulation(model, tria);
        setup.cell_is_pd.assign(tria.n_active_cells(), false);
        for (const auto &cell : tria.active_cell_iterators())
          setup.cell_is_pd[cell->active_cell_index()] =
            cell->material_id() == 1;

        // ---- natural sets: their faces get boundary ids 10, 11, ...
        std::map<std::vector<unsigned int>,
                 std::pair<typename Triangulation<dim>::active_cell_iterator,
                           unsigned int>>
          boundary_faces;
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                std::vector<unsigned int> key;
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  key.push_back(cell->face(f)->vertex_index(v));
                std::sort(key.begin(), key.end());
                boundary_faces[key] = {cell, f};
              }
        Coupling::Settings<dim> &settings = setup.settings;
        for (std::size_t s = 0; s < model.natural.size(); ++s)
          {
            for (const auto &face : model.natural[s].faces)
              {
                std::vector<unsigned int> key(face);
                std::sort(key.begin(), key.end());
                const auto it = boundary_faces.find(key);
                if (it == boundary_faces.end())
                  {
                    std::string ids;
                    for (const unsigned int v : face)
                      ids += (ids.empty() ? "" : " ") + std::to_string(v + 1);
                    throw InputError(model.mesh_file,
                                     "natural set " + std::to_string(s),
                                     "the face (" + ids +
                                       ") is not a boundary face of the mesh",
                                     "faces on the boundary of the elements");
                  }
                it->second.first->face(it->second.second)
                  ->set_boundary_id(first_traction_id + s);
              }
            Coupling::BoundaryCondition<dim> bc;
            bc.name         = "nbc" + std::to_string(s);
            bc.boundary_ids = {
              static_cast<unsigned int>(first_traction_id + s)};
            bc.component  = dim; // normal: positive = tension, as the peer
            bc.expression = exact(model.natural[s].traction);
            if ((quasi_static || dynamic) && model.natural[s].rate != 0.)
              bc.expression += " + (" + exact(model.natural[s].rate) + ") * t";
            settings.traction.push_back(bc);
          }
        setup.timings["mesh"] = std::chrono::duration<double>(
                                  std::chrono::steady_clock::now() - start)
                                  .count();
        setup.setup_start = std::chrono::steady_clock::now();

        // ---- essential sets: node lists with one component each
        for (std::size_t s = 0; s < model.essential.size(); ++s)
          {
            const auto                      &set = model.essential[s];
            Coupling::BoundaryCondition<dim> bc;
            bc.name       = "ebc" + std::to_string(s);
            bc.vertices   = set.nodes;
            bc.component  = set.component;
            bc.expression = exact(set.value); // static: VEBC rates unused
            // VEBC: a displacement increment per step (quasi-static) or a
            // prescribed velocity (dynamic).
            if ((quasi_static || dynamic) && set.rate != 0.)
              bc.expression += " + (" + exact(set.rate) + ") * t";
            settings.dirichlet.push_back(bc);
          }
        for (const unsigned int s : model.reaction_sets)
          setup.reaction_group.push_back(s);

        // ---- the rest of the model
        settings.source_file             = cmd;
        settings.material.youngs_modulus = E;
        settings.material.poissons_ratio = nu;
        settings.material.density        = model.density;
        settings.material.plane_stress   = plane_stress;
        settings.material.thickness      = 1.; // PDLSM-FEM: unit thickness
        settings.horizon_factor          = model.horizon_factor;
        settings.weight_factor           = model.weight_factor;
        settings.fe_nodes_in_families    = model.fe_nodes_in_families;
        std::vector<std::vector<std::array<double, 3>>> cracks(
          model.cracks.begin(), model.cracks.end());
        settings.cracks           = Mesh::make_cracks<dim>(cracks);
        settings.no_fail_vertices = model.no_fail_nodes; // vertex = node - 1
        // The peer's growth length and virtual crack: d_cf x Delta_min, the
        // square root of the smallest element area (specs/004 §3.1 item 7).
        double smallest = std::numeric_limits<double>::max();
        for (const auto &cell : tria.active_cell_iterators())
          smallest = std::min(smallest, cell->measure());
        fracture.growth_length_absolute =
          model.fc1_growth_factor * std::pow(smallest, 1. / dim);
        if (!(settings.horizon_factor >= 1.))
          throw InputError(cmd,
                           "SETSOLVING",
                           "the horizon factor m = " +
                             number(settings.horizon_factor) +
                             " is smaller than 1",
                           "m >= 1");
        // The solver chosen by cost (Type = auto): matrix-free GMRES first,
        // tight enough for 1e-10 on exact solutions: on the peer's static
        // inputs it gives MUMPS's answer to 1e-11, 5x faster in 2D
        // (plateHole 0.38 -> 0.07 s) and in 3D the only way to stay under
        // 1 GB; a kept factorisation where solves reuse one matrix.
        settings.linear_solver.type           = "auto";
        settings.linear_solver.preconditioner = "amg fe";
        settings.linear_solver.tolerance      = 1e-12;
        setup.driver.residual_tolerance       = 1e-11;
        if (quasi_static)
          {
            // Crack growth needs the load-displacement curve to plotting
            // accuracy, not to round-off: 1e-9 moves the peak reaction of
            // plateCrack FC1 by 3e-11 relative and saves a quarter of the
            // GMRES iterations.
            settings.linear_solver.tolerance = 1e-10;
            setup.driver.residual_tolerance  = 1e-9;
          }
        if (model.solver == Solver::dynamic && model.newmark)
          {
            // K_N is factorised once and reused: a direct solver (on
            // plateCrack a MUMPS solve takes 14 ms, KLU's 12 ms with a 5x
            // slower factorisation, GMRES + ILU 5 iterations 30 ms).
            settings.linear_solver.type          = "direct";
            settings.linear_solver.direct_solver = "mumps";
          }
      }

#define INSTANTIATE(dim)                                             \
  template void setup_from_pdlsm_fem<dim>(const IO::PDLSMFEMModel &, \
                                          const RunOptions &,        \
                                          MPI_Comm,                  \
                                          Setup<dim> &);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
