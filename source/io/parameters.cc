// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/base/plugins.h>
#include <pdfem/io/parameters.h>
#include <pdfem/pd_models/interface.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace pdfem
{
  namespace Parameters
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    using namespace ParameterTools;

    namespace
    {
      /// Every declared entry as "Subsection/.../Name" (read from the
      /// handler's own listing).
      std::vector<std::string>
      declared_entries(const ParameterHandler &prm)
      {
        std::ostringstream listing;
        prm.print_parameters(listing, ParameterHandler::ShortPRM);
        std::istringstream       in(listing.str());
        std::vector<std::string> path, entries;
        for (std::string line; std::getline(in, line);)
          {
            line = trim(line);
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(trim(line.substr(11)));
            else if (line == "end" && !path.empty())
              path.pop_back();
            else if (line.rfind("set ", 0) == 0)
              {
                std::string entry;
                for (const auto &p : path)
                  entry += p + "/";
                entries.push_back(entry +
                                  trim(line.substr(4, line.find('=') - 4)));
              }
          }
        return entries;
      }

      /// " (did you mean 'Driver/Load steps'?)" for an unknown entry
      /// @p name (a path or a bare name); empty when nothing is close.
      std::string
      suggestion(const ParameterHandler &prm, const std::string &name)
      {
        if (name.empty())
          return "";
        const std::vector<std::string> entries = declared_entries(prm);
        const std::string              leaf = name.substr(name.rfind('/') + 1);
        std::vector<std::string>       leaves;
        for (const auto &e : entries)
          leaves.push_back(e.substr(e.rfind('/') + 1));
        // The same name in another subsection first, else the nearest.
        std::string near = Plugins::nearest_name(name, entries);
        if (near.empty())
          {
            const std::string near_leaf = Plugins::nearest_name(leaf, leaves);
            for (std::size_t i = 0; i < entries.size() && near.empty(); ++i)
              if (!near_leaf.empty() && leaves[i] == near_leaf)
                near = entries[i];
          }
        return near.empty() ? "" : " (did you mean '" + near + "'?)";
      }

      /// The entry deal.II's message @p what says is unknown: "name
      /// <X>" or "entry <X>".
      std::string
      unknown_entry(const std::string &what)
      {
        for (const std::string key : {"with name <", "for entry <"})
          {
            const auto at = what.find(key);
            if (at != std::string::npos)
              return what.substr(at + key.size(),
                                 what.find('>', at) - at - key.size());
          }
        return "";
      }

      std::vector<BoundaryEntry>
      parse_boundary_entries(const std::string &text,
                             const std::string &file,
                             const std::string &parameter,
                             const int          dim,
                             const bool         allow_normal)
      {
        const std::string allowed_components =
          std::string(dim == 2 ? "x, y" : "x, y, z") +
          (allow_normal ? ", normal" : "");
        const std::string form =
          "'boundary name: component = expression', separated by ';', "
          "component one of " +
          allowed_components;
        std::vector<BoundaryEntry> entries;
        for (const std::string &item : split(text, ';'))
          {
            const auto colon = item.find(':');
            const auto equal = item.find('=');
            if (colon == std::string::npos || equal == std::string::npos ||
                equal < colon)
              throw InputError(file,
                               parameter,
                               "cannot read '" + item + "'",
                               form);
            BoundaryEntry entry;
            entry.boundary = trim(item.substr(0, colon));
            const std::string comp =
              trim(item.substr(colon + 1, equal - colon - 1));
            entry.expression = trim(item.substr(equal + 1));
            if (comp == "x")
              entry.component = 0;
            else if (comp == "y")
              entry.component = 1;
            else if (comp == "z" && dim == 3)
              entry.component = 2;
            else if (comp == "normal" && allow_normal)
              entry.component = dim;
            else
              throw InputError(file,
                               parameter,
                               "unknown component '" + comp + "' in '" + item +
                                 "'",
                               allowed_components);
            if (entry.boundary.empty() || entry.expression.empty())
              throw InputError(file,
                               parameter,
                               "cannot read '" + item + "'",
                               form);
            check_expression(entry.expression, file, parameter);
            entries.push_back(entry);
          }
        return entries;
      }

    } // namespace

    // ------------------------------------------------------------------ Mesh
    void
    Mesh::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.declare_entry("Input file",
                        "",
                        Anything(),
                        "A gmsh mesh (.msh, format 2.2 or 4.1) or a gmsh "
                        "script (.geo, meshed by the gmsh executable at run "
                        "time). Relative to the parameter file's folder. "
                        "Physical surfaces (2D) or volumes (3D) name the "
                        "regions; physical curves (2D) or surfaces (3D) name "
                        "the boundaries.");
      prm.declare_entry("Global refinements",
                        "0",
                        Integer(0, 10),
                        "Number of global refinements after reading.");
      prm.declare_entry("Mesh size factor",
                        "1",
                        Double(),
                        "For a .geo input: every element size is multiplied "
                        "by this factor (gmsh -clscale), so 0.5 halves the "
                        "element size. Unlike global refinement, gmsh then "
                        "follows curved boundaries. > 0.");
      prm.declare_entry("PD regions",
                        "pd",
                        Anything(),
                        "Comma-separated physical names of the cells "
                        "discretised by peridynamics; 'all' (every cell) or "
                        "'none' (pure finite elements).");
      prm.leave_subsection();
    }

    void
    Mesh::parse(ParameterHandler &prm, const std::string &file)
    {
      prm.enter_subsection("Mesh");
      input_file  = trim(prm.get("Input file"));
      refinements = prm.get_integer("Global refinements");
      size_factor = prm.get_double("Mesh size factor");
      pd_regions  = split(prm.get("PD regions"), ',');
      prm.leave_subsection();
      if (!(size_factor > 0.))
        throw InputError(file,
                         "Mesh/Mesh size factor",
                         number(size_factor) + " is not positive",
                         "a factor > 0");
      if (input_file.empty())
        throw InputError(file,
                         "Mesh/Input file",
                         "no mesh file given",
                         "a .msh or .geo file");
    }

    // -------------------------------------------------------------- Material
    void
    Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Young's modulus", "0", Double(), "E [Pa], > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0",
                        Double(),
                        "nu [-]: -1 < nu < 0.5 (3D and plane strain), "
                        "-1 < nu <= 0.5 (plane stress).");
      prm.declare_entry("Density",
                        "0",
                        Double(),
                        "rho [kg/m^3], >= 0 (> 0 for dynamic runs).");
      prm.declare_entry("Plane model",
                        "plane stress",
                        Selection("plane stress|plane strain"),
                        "2D only: plane stress or plane strain.");
      prm.declare_entry("Thickness",
                        "1",
                        Double(),
                        "2D only: thickness [m] (> 0); forces and reactions "
                        "are for this thickness.");
      prm.leave_subsection();
    }

    void
    Material::parse(ParameterHandler &prm, const std::string &file, int dim)
    {
      prm.enter_subsection("Material");
      youngs_modulus = prm.get_double("Young's modulus");
      poissons_ratio = prm.get_double("Poisson's ratio");
      density        = prm.get_double("Density");
      plane          = prm.get("Plane model") == "plane strain" ?
                         PlaneModel::plane_strain :
                         PlaneModel::plane_stress;
      thickness      = prm.get_double("Thickness");
      prm.leave_subsection();

      if (!(youngs_modulus > 0.))
        throw InputError(file,
                         "Material/Young's modulus",
                         "E = " + number(youngs_modulus) + " is not positive",
                         "E > 0");
      const bool plane_stress = dim == 2 && plane == PlaneModel::plane_stress;
      const bool nu_ok =
        poissons_ratio > -1. &&
        (plane_stress ? poissons_ratio <= 0.5 : poissons_ratio < 0.5);
      if (!nu_ok)
        throw InputError(file,
                         "Material/Poisson's ratio",
                         "nu = " + number(poissons_ratio) +
                           " is out of range for " +
                           (dim == 3     ? std::string("3D") :
                            plane_stress ? "plane stress" :
                                           "plane strain"),
                         plane_stress ? "-1 < nu <= 0.5" : "-1 < nu < 0.5");
      if (density < 0.)
        throw InputError(file,
                         "Material/Density",
                         "rho = " + number(density) + " is negative",
                         "rho >= 0");
      if (!(thickness > 0.))
        throw InputError(file,
                         "Material/Thickness",
                         "thickness = " + number(thickness) +
                           " is not positive",
                         "thickness > 0");
    }

    // ---------------------------------------------------------- Peridynamics
    void
    Peridynamics::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Peridynamics");
      const auto &models = PDModels::registry<2>();
      prm.declare_entry("Model",
                        "auto",
                        Selection("auto|" + models.selection()),
                        "PD model of the PD cells (pdfem --list-plugins). "
                        "auto: 'pdlsm energy' for the dynamic drivers "
                        "(explicit, newmark), whose collocated counterpart "
                        "has growing modes, and for scenes with cracks "
                        "(Pre-existing cracks or a Fracture/Criterion), "
                        "whose supports it leaves unloaded; 'pdlsm' "
                        "otherwise, and for static scenes with Crack faces "
                        "= free surface. " +
                          models.summary() +
                          "rnp scenes run every cell as PD (subsection "
                          "RNP).");
      prm.declare_entry("Horizon factor",
                        "3",
                        Double(),
                        "m in delta_i = m * Delta_i, Delta_i = V_i^(1/dim) "
                        "(V_i: nodal volume); m >= 1.");
      prm.declare_entry("Family members",
                        "all nodes",
                        Selection("all nodes|pd nodes"),
                        "Which nodes may belong to a PD family: every mesh "
                        "node within the horizon, or PD nodes only.");
      prm.declare_entry(
        "Crack faces",
        "cut bonds",
        Selection("cut bonds|free surface"),
        "How a crack (pre-existing or grown by mcts) enters the collocated "
        "pdlsm model (pdlsm energy refits cut families itself and refuses "
        "'free surface'). "
        "'cut bonds': the bonds crossing it are removed and every family "
        "keeps the fit of its whole initial family (PDLSM-FEM). 'free "
        "surface': in addition, families that lost bonds to a crack are "
        "refitted over their intact bonds, and the crack faces get the "
        "PDLSM boundary term s_k of an outer boundary, so that they are "
        "traction free (2D only; doc/theory.md §9).");
      prm.declare_entry("Pre-existing cracks",
                        "",
                        Anything(),
                        "Cracks present at the start; bonds crossing them are "
                        "cut. 2D: segments '(x1, y1) -- (x2, y2)'; 3D: "
                        "triangles '(x,y,z) -- (x,y,z) -- (x,y,z)'. Several "
                        "separated by ';'.");
      // Each PD model's own parameters.
      models.declare_parameters(prm);
      prm.leave_subsection();
    }

    void
    Peridynamics::parse(ParameterHandler &prm, const std::string &file, int dim)
    {
      prm.enter_subsection("Peridynamics");
      model                        = prm.get("Model");
      horizon_factor               = prm.get_double("Horizon factor");
      fe_nodes_in_families         = prm.get("Family members") == "all nodes";
      free_crack_faces             = prm.get("Crack faces") == "free surface";
      const std::string crack_text = prm.get("Pre-existing cracks");
      prm.leave_subsection();

      if (free_crack_faces && dim != 2)
        throw InputError(file,
                         "Peridynamics/Crack faces",
                         "'free surface' is implemented in 2D only",
                         "'cut bonds' in 3D");
      if (!(horizon_factor >= 1.))
        throw InputError(file,
                         "Peridynamics/Horizon factor",
                         "m = " + number(horizon_factor) +
                           " is smaller than 1 (the horizon would be smaller "
                           "than the node spacing)",
                         "m >= 1");
      cracks.clear();
      const std::string parameter = "Peridynamics/Pre-existing cracks";
      for (const std::string &crack : split(crack_text, ';'))
        {
          std::vector<std::array<double, 3>> points;
          std::string                        rest = crack;
          std::size_t                        pos;
          while ((pos = rest.find("--")) != std::string::npos)
            {
              points.push_back(
                parse_point(rest.substr(0, pos), file, parameter, dim));
              rest = rest.substr(pos + 2);
            }
          points.push_back(parse_point(rest, file, parameter, dim));
          if (static_cast<int>(points.size()) != dim)
            throw InputError(file,
                             parameter,
                             "'" + crack + "' has " +
                               std::to_string(points.size()) + " points",
                             dim == 2 ? "2 points per crack in 2D" :
                                        "3 points per crack in 3D");
          cracks.push_back(points);
        }
    }

    // --------------------------------------------------- Boundary conditions
    void
    BoundaryConditions::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Dirichlet",
                        "",
                        Anything(),
                        "Prescribed displacements: 'boundary: component = "
                        "expression; ...', component x, y or z, expression "
                        "a function of x, y, z and t (t = load factor in "
                        "static runs). Example: 'left: x = 0; right: x = "
                        "1e-4*x'. The target is a boundary name, a node "
                        "set (a gmsh physical point group: any nodes of the "
                        "mesh, e.g. interior ones; ASCII .msh 2.2 or 4.1) "
                        "or a node '(x, y[, z])'. Where two entries fix the "
                        "same DoF, the first one counts.");
      prm.declare_entry("Traction",
                        "",
                        Anything(),
                        "Applied tractions [Pa]: 'boundary: component = "
                        "expression; ...', component x, y, z or normal "
                        "(positive along the outward normal = tension).");
      prm.declare_entry("Body force",
                        "",
                        Anything(),
                        "Body force per unit volume [N/m^3]: dim expressions "
                        "of x, y, z, t separated by ';' (empty: none).");
      prm.declare_entry("Reaction group",
                        "",
                        Anything(),
                        "Comma-separated Dirichlet targets (boundary or node "
                        "set names) whose reactions are also summed: "
                        "history.csv columns reaction_RF_<x,y,z> and "
                        "summary.json final.reaction_RF (PDLSM-FEM's RF). "
                        "Empty: no sum. Not with Peridynamics/Model = rnp.");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse(ParameterHandler  &prm,
                              const std::string &file,
                              int                dim)
    {
      prm.enter_subsection("Boundary conditions");
      dirichlet = parse_boundary_entries(prm.get("Dirichlet"),
                                         file,
                                         "Boundary conditions/Dirichlet",
                                         dim,
                                         false);
      traction  = parse_boundary_entries(
        prm.get("Traction"), file, "Boundary conditions/Traction", dim, true);
      body_force     = split(prm.get("Body force"), ';');
      reaction_group = split(prm.get("Reaction group"), ',');
      prm.leave_subsection();
      for (const std::string &name : reaction_group)
        if (std::none_of(dirichlet.begin(),
                         dirichlet.end(),
                         [&](const BoundaryEntry &e) {
                           return e.boundary == name;
                         }))
          throw InputError(file,
                           "Boundary conditions/Reaction group",
                           "'" + name +
                             "' is not a target of the Dirichlet "
                             "conditions",
                           "targets named in Boundary conditions/Dirichlet");
      if (!body_force.empty() && static_cast<int>(body_force.size()) != dim)
        throw InputError(file,
                         "Boundary conditions/Body force",
                         "needs " + std::to_string(dim) + " expressions, got " +
                           std::to_string(body_force.size()),
                         "empty, or dim expressions separated by ';'");
      for (const auto &e : body_force)
        check_expression(e, file, "Boundary conditions/Body force");
    }

    // ------------------------------------------------------------------- RNP
    void
    RNP::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Peridynamics");
      prm.enter_subsection("RNP");
      calibration      = prm.get("Calibration");
      C                = prm.get_double("C");
      beta             = prm.get_double("beta");
      fracture_energy  = prm.get_double("Fracture energy");
      influence        = prm.get("Influence function");
      force_scaling    = prm.get("Force scaling");
      nodal_volumes    = prm.get("Nodal volumes");
      dirichlet_layer  = prm.get_double("Dirichlet layer");
      tangent          = prm.get("Tangent");
      interface_energy = prm.get("Interface energy");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    // ---------------------------------------------------------------- Output
    void
    Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "",
                        Anything(),
                        "Output folder (created if missing). Empty: "
                        "'output-<scene name>' in the working directory. "
                        "The command-line option --output overrides it.");
      prm.declare_entry("Write vtu",
                        "true",
                        Bool(),
                        "Write solution-NNNNN.vtu/.pvtu and solution.pvd.");
      prm.declare_entry("Write every",
                        "0",
                        Integer(0),
                        "Field output every this many steps and at the last "
                        "one; 0: at the last step only.");
      prm.declare_entry("Write nodes csv",
                        "false",
                        Bool(),
                        "Write nodes.csv: every node's coordinates, "
                        "displacement and stress, sorted by coordinates "
                        "(independent of the number of ranks).");
      prm.declare_entry(
        "Patch test",
        "auto",
        Selection("auto|true|false"),
        "The patch test of the PD-FE coupling before the run (summary.json "
        "patch_test: unit strains on the boundary, the rest solved): auto "
        "runs it for pairwise PD models (rnp) with FE cells, whose coupling "
        "by shared nodes is not exact.");
      prm.declare_entry("Print timings",
                        "false",
                        Bool(),
                        "Print a table of wall times per phase at the end "
                        "(the set-up with its parts, as summary.json's "
                        "timings.setup_phases).");
      prm.declare_entry(
        "Checkpoint steps",
        "0",
        Integer(0),
        "Write a checkpoint (the folder 'checkpoint' in the output folder) "
        "every this many steps; 0: not by count. SIGINT and SIGTERM write one "
        "too. 'pdfem scene.prm --restart <output folder>' goes on from it. "
        "Every driver of pdfem.");
      prm.declare_entry("Checkpoint minutes",
                        "0",
                        Double(0.),
                        "Write a checkpoint when this many minutes of wall "
                        "time passed since the last one; 0: not by time.");
      prm.declare_entry("Progress interval",
                        "5",
                        Double(0.),
                        "Inside a long step (Newton iterations, a snap-back "
                        "path, relaxation iterations) and between the lines "
                        "of a dynamic run: a progress line at least every "
                        "this many seconds [s] (0: at every iteration).");
      prm.leave_subsection();
    }

    void
    Output::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Output");
      directory          = trim(prm.get("Directory"));
      write_vtu          = prm.get_bool("Write vtu");
      write_every        = prm.get_integer("Write every");
      write_nodes_csv    = prm.get_bool("Write nodes csv");
      print_timings      = prm.get_bool("Print timings");
      patch_test         = prm.get("Patch test");
      checkpoint_steps   = prm.get_integer("Checkpoint steps");
      checkpoint_minutes = prm.get_double("Checkpoint minutes");
      progress_interval  = prm.get_double("Progress interval");
      prm.leave_subsection();
    }

    // ----------------------------------------------------------------- Scene
    void
    Scene::declare(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Integer(2, 3),
                        "Space dimension of the scene: 2 or 3.");
      Mesh::declare(prm);
      Material::declare(prm);
      Peridynamics::declare(prm);
      BoundaryConditions::declare(prm);
      LinearSolver::declare(prm);
      Driver::declare(prm);
      Fracture::declare(prm);
      Output::declare(prm);
    }

    void
    Scene::read(
      const std::string                                      &parameter_file,
      const std::vector<std::pair<std::string, std::string>> &overrides)
    {
      namespace fs = std::filesystem;
      file         = parameter_file;
      if (!fs::exists(file))
        throw InputError(file, "", "the parameter file does not exist");
      base_dir = fs::absolute(fs::path(file)).parent_path().string();
      name     = fs::path(file).stem().string();

      handler               = std::make_shared<ParameterHandler>();
      ParameterHandler &prm = *handler;
      declare(prm);
      try
        {
          prm.parse_input(file, "", false, true);
        }
      catch (const dealii::ExceptionBase &e)
        {
          // deal.II wraps its message at a width, so a name may be split
          // across lines (where depends on the file name's length): read
          // the unknown entry from the joined one-line message.
          const std::string message = clean_dealii_message(e.what());
          throw InputError(file,
                           "",
                           message + suggestion(prm, unknown_entry(message)),
                           "see 'pdfem --print-parameters'");
        }
      for (const auto &[path, value] : overrides)
        {
          const auto   parts = split(path, '/');
          unsigned int depth = 0;
          try
            {
              for (; depth + 1 < parts.size(); ++depth)
                prm.enter_subsection(parts[depth]);
              prm.set(parts.back(), value);
            }
          catch (const dealii::ExceptionBase &e)
            {
              throw InputError(
                "--set",
                path,
                "cannot set it to '" + value +
                  "': " + clean_dealii_message(e.what()) +
                  (unknown_entry(clean_dealii_message(e.what())).empty() ?
                     "" :
                     suggestion(prm, path)),
                "see 'pdfem --print-parameters'");
            }
          for (; depth > 0; --depth)
            prm.leave_subsection();
        }
      // A value that matches its pattern can still fail to convert (a
      // subnormal number such as 1e-320 in a Double entry): one line too.
      try
        {
          dim = prm.get_integer("Dimension");
          mesh.parse(prm, file);
          material.parse(prm, file, dim);
          peridynamics.parse(prm, file, dim);
          rnp.parse(prm, file);
          boundary_conditions.parse(prm, file, dim);
          linear_solver.parse(prm, file);
          driver.parse(prm, file, dim);
          fracture.parse(prm, file);
          output.parse(prm, file);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(file,
                           "",
                           clean_dealii_message(e.what()),
                           "see 'pdfem --print-parameters'");
        }
      // Which driver and criterion fit the model is checked by the plugins
      // themselves (pdfem::check_plugins()).
    }

    int
    read_dimension(const std::string &file)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError(file, "", "cannot open the parameter file");
      const std::regex pattern(R"(^\s*set\s+Dimension\s*=\s*(\S+))");
      std::string      line;
      while (std::getline(in, line))
        {
          std::smatch m;
          if (std::regex_search(line, m, pattern))
            {
              const std::string value = m[1];
              if (value == "2" || value == "3")
                return std::stoi(value);
              throw InputError(file,
                               "Dimension",
                               "'" + value + "' is not a dimension",
                               "2 or 3");
            }
        }
      return 2;
    }

    void
    print_all(std::ostream &out)
    {
      ParameterHandler prm;
      Scene::declare(prm);
      prm.print_parameters(out, ParameterHandler::PRM);
    }
  } // namespace Parameters
} // namespace pdfem
