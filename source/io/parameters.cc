// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/io/parameters.h>

#include <deal.II/base/function_parser.h>
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

    namespace
    {
      std::string
      trim(const std::string &s)
      {
        const auto b = s.find_first_not_of(" \t\r\n");
        if (b == std::string::npos)
          return "";
        const auto e = s.find_last_not_of(" \t\r\n");
        return s.substr(b, e - b + 1);
      }

      std::vector<std::string>
      split(const std::string &s, const char delimiter)
      {
        std::vector<std::string> parts;
        std::stringstream        in(s);
        std::string              part;
        while (std::getline(in, part, delimiter))
          if (!trim(part).empty())
            parts.push_back(trim(part));
        return parts;
      }

      /// Check that a muparser expression of x, y, z, t parses.
      void
      check_expression(const std::string &expression,
                       const std::string &file,
                       const std::string &parameter)
      {
        try
          {
            dealii::FunctionParser<3> f(1);
            f.initialize("x,y,z,t",
                         expression,
                         std::map<std::string, double>(),
                         true);
            (void)f.value(dealii::Point<3>());
          }
        catch (...)
          {
            throw InputError(file,
                             parameter,
                             "cannot parse the expression '" + expression + "'",
                             "a muparser expression of x, y, z and t");
          }
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

      std::array<double, 3>
      parse_point(const std::string &text,
                  const std::string &file,
                  const std::string &parameter,
                  const int          dim)
      {
        std::string s = trim(text);
        if (s.size() < 2 || s.front() != '(' || s.back() != ')')
          throw InputError(file,
                           parameter,
                           "cannot read the point '" + text + "'",
                           "(x, y) in 2D, (x, y, z) in 3D");
        const auto            parts = split(s.substr(1, s.size() - 2), ',');
        std::array<double, 3> p{{0., 0., 0.}};
        if (static_cast<int>(parts.size()) != dim)
          throw InputError(file,
                           parameter,
                           "the point '" + text + "' does not have " +
                             std::to_string(dim) + " coordinates",
                           "(x, y) in 2D, (x, y, z) in 3D");
        for (int d = 0; d < dim; ++d)
          try
            {
              std::size_t used = 0;
              p[d]             = std::stod(parts[d], &used);
              if (used != parts[d].size())
                throw std::invalid_argument("trailing");
            }
          catch (...)
            {
              throw InputError(file,
                               parameter,
                               "'" + parts[d] + "' is not a number",
                               "(x, y) in 2D, (x, y, z) in 3D");
            }
        return p;
      }

      /// Turn a deal.II parameter-parsing exception into one clear line.
      std::string
      clean_dealii_message(const std::string &what)
      {
        const std::string key = "Additional information:";
        auto              pos = what.find(key);
        std::string       msg =
          pos == std::string::npos ? what : what.substr(pos + key.size());
        msg = std::regex_replace(msg, std::regex("-{5,}"), "");
        msg = std::regex_replace(msg, std::regex("\\s+"), " ");
        return trim(msg);
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
      prm.declare_entry("Model",
                        "pdlsm",
                        Selection("pdlsm|rnp"),
                        "PD model of the PD cells: 'pdlsm' (peridynamic "
                        "least squares minimisation, second-order Taylor "
                        "basis; Madenci et al. 2019, Liu & Xin 2021), or "
                        "'rnp' (regularized nonlinear pairwise cohesive "
                        "bonds, Diehl & Lipton 2022; every cell PD, see "
                        "subsection RNP).");
      prm.declare_entry("Horizon factor",
                        "3",
                        Double(),
                        "m in delta_i = m * Delta_i, Delta_i = V_i^(1/dim) "
                        "(V_i: nodal volume); m >= 1.");
      prm.declare_entry("Weight factor",
                        "0.33",
                        Double(),
                        "a in the weight omega = exp(-(|xi|/(a delta))^2); "
                        "a > 0 (typical: 1/3 for quads, 1/4 for triangles).");
      prm.declare_entry("Family members",
                        "all nodes",
                        Selection("all nodes|pd nodes"),
                        "Which nodes may belong to a PD family: every mesh "
                        "node within the horizon, or PD nodes only.");
      prm.declare_entry(
        "Crack faces",
        "cut bonds",
        Selection("cut bonds|free surface"),
        "How a crack (pre-existing or grown by mcts) enters the PDLSM model. "
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
      prm.leave_subsection();
    }

    void
    Peridynamics::parse(ParameterHandler &prm, const std::string &file, int dim)
    {
      prm.enter_subsection("Peridynamics");
      model                        = prm.get("Model");
      horizon_factor               = prm.get_double("Horizon factor");
      weight_factor                = prm.get_double("Weight factor");
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
      if (!(weight_factor > 0.))
        throw InputError(file,
                         "Peridynamics/Weight factor",
                         "a = " + number(weight_factor) + " is not positive",
                         "a > 0");
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

    // --------------------------------------------------------- Linear solver
    void
    LinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "direct",
                        Selection("direct|gmres"),
                        "direct (sparse LU) or gmres (preconditioned, "
                        "restarted GMRES). The coupled matrix is not "
                        "symmetric, so CG is not offered.");
      prm.declare_entry("Direct solver",
                        "mumps",
                        Selection("mumps|klu"),
                        "Amesos package for 'direct': mumps (parallel) or "
                        "klu (serial, gathers on rank 0).");
      prm.declare_entry("Preconditioner",
                        "amg fe",
                        Selection("amg fe|amg|ilu"),
                        "For gmres: 'amg fe' (matrix-free coupled operator; "
                        "Trilinos ML algebraic multigrid built from the local "
                        "Q1/P1 stiffness of every cell, PD cells included, "
                        "followed by one block-Jacobi correction with the "
                        "coupled operator), 'amg' (ML built from the "
                        "assembled coupled matrix, kept while bonds break "
                        "until GMRES needs twice its first iteration count) "
                        "or 'ilu' (Ifpack ILU(1) of it).");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Double(0.),
                        "gmres: relative residual reduction.");
      prm.declare_entry("Max iterations",
                        "2000",
                        Integer(1),
                        "gmres: iteration limit.");
      prm.declare_entry("GMRES restart",
                        "150",
                        Integer(5, 2000),
                        "gmres: Krylov vectors kept before a restart. A "
                        "restart forgets the search space: on the 3D box, "
                        "30 takes 319 iterations, 150 takes 109 (= no "
                        "restart). Memory: 8 bytes x DoFs x this number.");
      prm.leave_subsection();
    }

    void
    LinearSolver::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Linear solver");
      type           = prm.get("Type");
      direct_solver  = prm.get("Direct solver");
      preconditioner = prm.get("Preconditioner");
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Max iterations");
      restart        = prm.get_integer("GMRES restart");
      prm.leave_subsection();
    }

    // ---------------------------------------------------------------- Driver
    void
    Driver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Driver");
      prm.declare_entry(
        "Type",
        "static",
        Selection("static|quasi-static|newton|arc length|explicit|newmark"),
        "static: equilibrium under the full load, reached in 'Load steps' "
        "equal increments of the load factor t. quasi-static: crack growth "
        "under a slowly increasing load: after each equilibrium the "
        "Fracture criterion is checked; where cracks grew the load is held "
        "and equilibrium found again, otherwise t grows by 'Load "
        "increment'. 'Load steps' is then the number of steps in all. "
        "newton: the static stepping with a line search, load step cutting "
        "and a stability check of every converged step (nonlinear models: "
        "rnp); a step that cannot be completed stops the run with exit "
        "state 'unstable'. arc length: the load factor becomes an unknown "
        "(Crisfield's arc-length continuation), so the path is followed "
        "through limit points and snap-backs; loads linear in t only: "
        "forces t q, prescribed values u_p(0) + t w, or both (rnp). "
        "explicit: central difference with lumped mass in physical time t "
        "(specs/004 §2.3), automatic stable time step. newmark: implicit "
        "Newmark (beta, gamma) in physical time t (specs/004 §2.4), the "
        "factorisation of M + beta dt^2 K reused while no bond breaks. In "
        "dynamic runs, t in the boundary expressions is physical time.");
      prm.declare_entry("Load steps",
                        "1",
                        Integer(1),
                        "Number of load increments (static: t = k / Load "
                        "steps), or of steps in all (quasi-static).");
      prm.declare_entry("Load increment",
                        "0",
                        Double(0.),
                        "quasi-static: the nominal increment of t (0: 1 / "
                        "Load steps). Prescribed displacements and loads are "
                        "expressions of t.");
      prm.declare_entry("Initial load",
                        "-1",
                        Double(),
                        "quasi-static: the load factor t of the first "
                        "solve; < 0: one Load increment (PDLSM-FEM: 0, an "
                        "unloaded first step).");
      prm.declare_entry("Jump to critical load",
                        "true",
                        Bool(),
                        "quasi-static: when the load at which the criterion "
                        "would be met, extrapolated linearly from the last "
                        "step (loads proportional to t), is nearer than one "
                        "increment, go there directly (PDLSM-FEM's rule).");
      prm.declare_entry("Hold load while cracks grow",
                        "true",
                        Bool(),
                        "quasi-static: keep t where it is while the "
                        "criterion breaks bonds, until the cracks arrest "
                        "(PDLSM-FEM). false: t follows its increments "
                        "whatever breaks, for load histories (loading, "
                        "unloading, reloading).");
      prm.declare_entry("Residual tolerance",
                        "1e-9",
                        Double(0.),
                        "Equilibrium iterations stop when |r| <= tol * "
                        "max(|r_0|, |f_ext|, |f_int|); |f_int| includes the "
                        "reactions, the force scale of displacement-driven "
                        "runs.");
      prm.declare_entry("Max iterations",
                        "10",
                        Integer(1),
                        "Equilibrium iterations per load step before the run "
                        "stops with exit state 'diverged' (newton: before the "
                        "step is cut).");
      prm.declare_entry("Max step cuts",
                        "4",
                        Integer(0),
                        "newton: cuts of the load increment in a row (two "
                        "converged steps undo one) before the run stops with "
                        "exit state 'unstable'.");
      prm.declare_entry("Step cut factor",
                        "0.25",
                        Double(0., 1.),
                        "newton: a cut multiplies the load increment by this "
                        "(0 < factor < 1).");
      prm.declare_entry("Arc length steps",
                        "50",
                        Integer(1),
                        "arc length: steps along the path (the run also ends "
                        "when the load factor reaches 1). The first step is "
                        "load-controlled, 1 / Load steps; its displacement "
                        "increment sets the arc length.");
      prm.declare_entry("Line search",
                        "true",
                        Bool(),
                        "newton: backtracking on the residual norm.");
      prm.declare_entry("Stability check",
                        "true",
                        Bool(),
                        "newton: test every converged state for stability "
                        "(reduced tangent positive definite); an unstable "
                        "state is rejected like a diverged step.");
      prm.declare_entry("Time step",
                        "auto",
                        Anything(),
                        "Dynamic runs: the time step [s], > 0, or 'auto' "
                        "(explicit only): 'Time step safety factor' times "
                        "the critical step 2/omega_max, omega_max^2 the "
                        "largest eigenvalue of M^-1 K by power iteration.");
      prm.declare_entry("End time",
                        "0",
                        Double(),
                        "Dynamic runs: the end time [s], > 0.");
      prm.declare_entry("Time step safety factor",
                        "0.9",
                        Double(),
                        "Explicit, automatic step: dt = factor * 2/omega_max, "
                        "0 < factor; above 1 the run is unstable (a note "
                        "says so).");
      prm.declare_entry("Eigenvalue iterations",
                        "50",
                        Integer(1),
                        "Power iterations for omega_max^2, the largest "
                        "eigenvalue of M^-1 K.");
      prm.declare_entry("Newmark beta",
                        "0.25",
                        Double(),
                        "Newmark beta: unconditionally stable for "
                        "beta >= (2 gamma + 1)^2 / 16 (0.25 with gamma = "
                        "0.5: average acceleration).");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Double(),
                        "Newmark gamma >= 0.5 (0.5: no numerical damping; "
                        "larger values damp high frequencies).");
      prm.declare_entry("HHT alpha",
                        "0",
                        Double(),
                        "Newmark: HHT-alpha numerical damping of high "
                        "frequencies, -1/3 <= alpha <= 0 (0: none). If not 0, "
                        "beta = (1 - alpha)^2 / 4 and gamma = 1/2 - alpha "
                        "replace 'Newmark beta' and 'Newmark gamma'.");
      prm.declare_entry("Mass",
                        "lumped",
                        Selection("lumped|consistent"),
                        "lumped: FE row-sum lumping over the FE cells plus "
                        "rho V^pd over the PD cells, one value per node. "
                        "consistent (newmark only): the consistent FE mass "
                        "plus the PD lumped mass.");
      prm.declare_entry("Reuse factorization",
                        "true",
                        Bool(),
                        "Newmark: factorise M + beta dt^2 K once and reuse it "
                        "while no bond breaks (false: every step, as the "
                        "peer code does; for benchmarks).");
      prm.declare_entry("Initial velocity",
                        "",
                        Anything(),
                        "Dynamic runs: dim expressions of x, y, z separated "
                        "by ';' (empty: at rest) [m/s].");
      prm.declare_entry("Energy tolerance",
                        "0.5",
                        Double(),
                        "Dynamic runs stop with exit state 'time step too "
                        "large' when kinetic + strain + dissipated energy "
                        "exceeds the initial energy plus the external work "
                        "by more than this fraction of the largest energy "
                        "supplied so far (> 0).");
      prm.declare_entry("History interval",
                        "1",
                        Integer(1),
                        "Dynamic runs: a history.csv row every this many "
                        "steps (and at the last step).");
      prm.declare_entry("Monitor points",
                        "",
                        Anything(),
                        "Dynamic runs: 'name: (x, y[, z])' separated by ';'; "
                        "the displacement of the node nearest to each point "
                        "goes into history.csv as u_<name>_<component>.");
      prm.leave_subsection();
    }

    void
    Driver::parse(ParameterHandler &prm, const std::string &file, int dim)
    {
      prm.enter_subsection("Driver");
      type                        = prm.get("Type");
      load_steps                  = prm.get_integer("Load steps");
      load_increment              = prm.get_double("Load increment");
      initial_load                = prm.get_double("Initial load");
      jump_to_critical_load       = prm.get_bool("Jump to critical load");
      hold_load_while_growing     = prm.get_bool("Hold load while cracks grow");
      max_step_cuts               = prm.get_integer("Max step cuts");
      step_cut_factor             = prm.get_double("Step cut factor");
      line_search                 = prm.get_bool("Line search");
      arc_length_steps            = prm.get_integer("Arc length steps");
      stability_check             = prm.get_bool("Stability check");
      residual_tolerance          = prm.get_double("Residual tolerance");
      max_iterations              = prm.get_integer("Max iterations");
      const std::string step_text = trim(prm.get("Time step"));
      end_time                    = prm.get_double("End time");
      safety_factor               = prm.get_double("Time step safety factor");
      eigenvalue_iterations       = prm.get_integer("Eigenvalue iterations");
      newmark_beta                = prm.get_double("Newmark beta");
      newmark_gamma               = prm.get_double("Newmark gamma");
      hht_alpha                   = prm.get_double("HHT alpha");
      mass                        = prm.get("Mass");
      reuse_factorization         = prm.get_bool("Reuse factorization");
      initial_velocity            = split(prm.get("Initial velocity"), ';');
      energy_tolerance            = prm.get_double("Energy tolerance");
      history_interval            = prm.get_integer("History interval");
      const std::string monitors  = prm.get("Monitor points");
      prm.leave_subsection();
      if (!(step_cut_factor > 0. && step_cut_factor < 1.))
        throw InputError(file,
                         "Driver/Step cut factor",
                         number(step_cut_factor) + " is not between 0 and 1",
                         "0 < factor < 1");

      if (!dynamic())
        return;
      const std::string p = "Driver/";
      if (step_text == "auto")
        time_step = 0.;
      else
        {
          std::size_t end = 0;
          try
            {
              time_step = std::stod(step_text, &end);
            }
          catch (...)
            {
              end = 0;
            }
          if (end != step_text.size() || !(time_step > 0.))
            throw InputError(file,
                             p + "Time step",
                             "'" + step_text + "' is not a positive time step",
                             type == "explicit" ? "dt > 0 [s], or 'auto'" :
                                                  "dt > 0 [s]");
        }
      if (type == "newmark" && time_step == 0.)
        throw InputError(file,
                         p + "Time step",
                         "'auto' is for the explicit driver only (Newmark is "
                         "unconditionally stable: the step is an accuracy "
                         "choice)",
                         "dt > 0 [s]");
      if (!(end_time > 0.))
        throw InputError(file,
                         p + "End time",
                         "end time = " + number(end_time) + " is not positive",
                         "end time > 0 [s]");
      if (!(safety_factor > 0.))
        throw InputError(file,
                         p + "Time step safety factor",
                         number(safety_factor) + " is not positive",
                         "factor > 0 (0.9 by default; above 1 is unstable)");
      if (!(hht_alpha >= -1. / 3. - 1e-14 && hht_alpha <= 0.))
        throw InputError(file,
                         p + "HHT alpha",
                         "alpha = " + number(hht_alpha) +
                           " is outside the range of the HHT method",
                         "-1/3 <= alpha <= 0");
      if (type == "newmark" && hht_alpha == 0.)
        {
          if (!(newmark_gamma >= 0.5))
            throw InputError(
              file,
              p + "Newmark gamma",
              "gamma = " + number(newmark_gamma) +
                " is outside the stable range (gamma < 1/2 amplifies "
                "every mode)",
              "gamma >= 0.5 with beta >= (2 gamma + 1)^2 / 16");
          const double beta_min =
            (2. * newmark_gamma + 1.) * (2. * newmark_gamma + 1.) / 16.;
          if (!(newmark_beta >= beta_min - 1e-14) || !(newmark_beta <= 1.))
            throw InputError(
              file,
              p + "Newmark beta",
              "beta = " + number(newmark_beta) +
                " is outside the unconditionally stable range for gamma = " +
                number(newmark_gamma),
              number(beta_min) + " = (2 gamma + 1)^2 / 16 <= beta <= 1");
        }
      if (type == "explicit" && mass == "consistent")
        throw InputError(file,
                         p + "Mass",
                         "the explicit driver needs a lumped mass (a "
                         "consistent mass would need a solve per step)",
                         "lumped (or Type = newmark for a consistent mass)");
      if (!initial_velocity.empty() &&
          static_cast<int>(initial_velocity.size()) != dim)
        throw InputError(file,
                         p + "Initial velocity",
                         "needs " + std::to_string(dim) + " expressions, got " +
                           std::to_string(initial_velocity.size()),
                         "empty, or dim expressions separated by ';'");
      for (const auto &e : initial_velocity)
        check_expression(e, file, p + "Initial velocity");
      if (!(energy_tolerance > 0.))
        throw InputError(file,
                         p + "Energy tolerance",
                         number(energy_tolerance) + " is not positive",
                         "tolerance > 0");
      for (const std::string &item : split(monitors, ';'))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError(file,
                             p + "Monitor points",
                             "cannot read '" + item + "'",
                             "'name: (x, y[, z])' separated by ';'");
          MonitorPoint m;
          m.name  = trim(item.substr(0, colon));
          m.point = parse_point(trim(item.substr(colon + 1)),
                                file,
                                p + "Monitor points",
                                dim);
          monitor_points.push_back(m);
        }
    }

    // ------------------------------------------------------------------- RNP
    void
    RNP::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Peridynamics");
      prm.enter_subsection("RNP");
      prm.declare_entry("Calibration",
                        "moduli",
                        Selection("moduli|constants"),
                        "moduli: C beta from Material/Young's modulus and C "
                        "from the fracture energy (doc/theory.md, RNP "
                        "calibration); the Poisson's ratio must be the "
                        "model's (1/3 plane stress, 1/4 plane strain and 3D). "
                        "constants: C and beta as given.");
      prm.declare_entry("C",
                        "0",
                        Double(0.),
                        "C in g(r) = C (1 - exp(-beta r^2)) (constants).");
      prm.declare_entry("beta",
                        "0",
                        Double(0.),
                        "beta in g(r) = C (1 - exp(-beta r^2)) (constants).");
      prm.declare_entry("Fracture energy",
                        "0",
                        Double(0.),
                        "G_c [J/m^2] (moduli): C = G_c omega_d / (2 "
                        "omega_(d-1) M_d).");
      prm.declare_entry("Influence function",
                        "constant",
                        Selection("constant|linear"),
                        "J(|xi|/horizon): constant 1 or linear 1 - |xi|/eps.");
      prm.declare_entry("Force scaling",
                        "paper",
                        Selection("paper|prototype"),
                        "paper: g'(sqrt|xi| S)/sqrt|xi| (eq. 27, the one the "
                        "calibration holds for); prototype: g'/|xi| (the "
                        "Python prototype, for regression only).");
      prm.declare_entry("Nodal volumes",
                        "cells",
                        Selection("cells|uniform"),
                        "cells: sum of V_cell / n_vertices; uniform: h^dim "
                        "for every node (the paper's lattice), h the largest "
                        "cell size.");
      prm.declare_entry("Dirichlet layer",
                        "1",
                        Double(0.),
                        "Prescribed displacements act on every node within "
                        "this many horizons of the named boundary (the "
                        "nonlocal boundary layer); 0: the boundary's nodes "
                        "only.");
      prm.declare_entry("Tangent",
                        "analytic",
                        Selection("analytic|finite difference"),
                        "analytic (eq. 33-34 corrected) or central finite "
                        "differences of the nodal forces (for comparison).");
      prm.declare_entry(
        "Interface energy",
        "full bonds",
        Selection("full bonds|partition"),
        "With FE cells around the RNP region and Family members = all "
        "nodes: full bonds: every bond counts fully (the FE cells next to "
        "the interface are stiffened by the bonds reaching into them); "
        "partition: each bond is weighted by the mean PD share of its two "
        "nodes' volumes, so that bonds and FE cells split the energy "
        "(doc/theory.md, RNP coupling; smaller ghost forces).");
      prm.leave_subsection();
      prm.leave_subsection();
    }

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

    // -------------------------------------------------------------- Fracture
    void
    Fracture::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Fracture");
      prm.declare_entry(
        "Criterion",
        "none",
        Selection("none|mcts|max principal stress|critical stretch"),
        "none: cracks never grow. mcts: stress-intensity factors K_I, K_II "
        "and J at every crack tip by the domain interaction integral; a tip "
        "grows by 'Growth length' in the direction of the maximum "
        "circumferential tensile stress when K_eq > 'Fracture toughness' "
        "(2D; PDLSM-FEM FC 1). max principal stress: bonds whose averaged "
        "nodal stress has a principal value above 'Tensile strength' get a "
        "virtual crack normal to that direction (PDLSM-FEM FC 2; 2D and "
        "3D). critical stretch: a bond breaks when its stretch "
        "(|xi + eta| - |xi|) / |xi| exceeds 'Critical stretch' (2D and 3D; "
        "quasi-static and dynamic). In static runs the criterion is only "
        "evaluated and reported.");
      prm.declare_entry("Fracture toughness",
                        "0",
                        Double(0.),
                        "K_Ic [Pa sqrt(m)] (mcts).");
      prm.declare_entry("Tensile strength",
                        "0",
                        Double(0.),
                        "sigma_ult [Pa] (max principal stress).");
      prm.declare_entry("Domain inner radius",
                        "4",
                        Double(0.),
                        "Interaction integral: the weight q is 1 inside this "
                        "radius, in element sizes of the cell nearest the "
                        "tip; the fields there do not enter. Keep it at least "
                        "the Horizon factor: inside a horizon of the tip the "
                        "nonlocal fields are smeared.");
      prm.declare_entry("Domain outer radius",
                        "10",
                        Double(0.),
                        "Interaction integral: q falls smoothly to 0 at this "
                        "radius, in element sizes.");
      prm.declare_entry("Front points",
                        "5",
                        Integer(1),
                        "3D, mcts: the points of each straight crack front "
                        "where K_I, K_II, K_III and J are computed, evenly "
                        "spaced, both ends included (1: the middle).");
      prm.declare_entry("Front half-width",
                        "2",
                        Double(0.),
                        "3D, mcts: the half-width w of the weight along the "
                        "front, q_s = cos^2(pi d / 2w) for |d| < w, in "
                        "element sizes at the front point.");
      prm.declare_entry("Growth length",
                        "1",
                        Double(0.),
                        "mcts: the advance d_c of a tip per growth step; max "
                        "principal stress: the length of a virtual crack; in "
                        "element sizes at the tip or bond.");
      prm.declare_entry("Absolute growth length",
                        "0",
                        Double(0.),
                        "> 0: replaces 'Growth length' by this length [m] "
                        "everywhere (PDLSM-FEM: d_cf times the square root "
                        "of the smallest element area); 0: Growth length "
                        "counts.");
      prm.declare_entry("Top K",
                        "0",
                        Integer(0),
                        "max principal stress: at most this many bonds (the "
                        "most stressed) get a virtual crack per step; 0: all.");
      prm.declare_entry("Critical stretch",
                        "0",
                        Double(0.),
                        "critical stretch: s_c; 0: from 'Fracture energy' by "
                        "the bond-based relation, s_c = sqrt(4 pi G_c / (9 E "
                        "delta)) in 2D, sqrt(5 G_c / (9 K delta)) in 3D (K "
                        "the bulk modulus, delta the owner's horizon).");
      prm.declare_entry("Fracture energy",
                        "0",
                        Double(0.),
                        "G_c [J/m^2] for the critical stretch.");
      prm.declare_entry("Adaptive margin",
                        "0",
                        Double(0.),
                        "m_e: FE cells within m_e element sizes of a crack "
                        "become PD, at the start and whenever a crack grows; "
                        "0: the PD region of the mesh never changes.");
      prm.declare_entry("No-fail nodes",
                        "",
                        Anything(),
                        "Comma-separated node sets (gmsh physical points, see "
                        "Boundary conditions/Dirichlet) whose nodes' bonds "
                        "never break, by any criterion (PDLSM-FEM's NO FAIL "
                        "region). Empty: none. Not with Peridynamics/Model = "
                        "rnp.");
      prm.declare_entry("Crack tips",
                        "inside",
                        Selection("inside|second point"),
                        "Which ends of the 2D pre-existing cracks are tips: "
                        "inside: every end inside the body that touches no "
                        "other crack; second point: the second point of each "
                        "crack only (PDLSM-FEM: a crack is [start, tip]).");
      prm.leave_subsection();
    }

    void
    Fracture::parse(ParameterHandler &prm, const std::string &file)
    {
      prm.enter_subsection("Fracture");
      criterion           = prm.get("Criterion");
      toughness           = prm.get_double("Fracture toughness");
      tensile_strength    = prm.get_double("Tensile strength");
      domain_inner_radius = prm.get_double("Domain inner radius");
      domain_outer_radius = prm.get_double("Domain outer radius");
      front_points        = prm.get_integer("Front points");
      front_half_width    = prm.get_double("Front half-width");
      growth_length       = prm.get_double("Growth length");
      top_k               = prm.get_integer("Top K");
      adaptive_margin     = prm.get_double("Adaptive margin");
      critical_stretch    = prm.get_double("Critical stretch");
      fracture_energy     = prm.get_double("Fracture energy");

      // PDLSM-FEM's choices (pdfem-convert)
      growth_length_absolute = prm.get_double("Absolute growth length");
      no_fail_nodes          = split(prm.get("No-fail nodes"), ',');
      tip_at_second_point    = prm.get("Crack tips") == "second point";
      prm.leave_subsection();
      if (criterion == "mcts" && !(toughness > 0.))
        throw InputError(file,
                         "Fracture/Fracture toughness",
                         "K_Ic = " + number(toughness) +
                           " is not positive (Criterion = mcts needs it)",
                         "K_Ic > 0 [Pa sqrt(m)]");
      if (criterion == "max principal stress" && !(tensile_strength > 0.))
        throw InputError(file,
                         "Fracture/Tensile strength",
                         "sigma_ult = " + number(tensile_strength) +
                           " is not positive (Criterion = max principal "
                           "stress needs it)",
                         "sigma_ult > 0 [Pa]");
      if (criterion == "critical stretch" && !(critical_stretch > 0.) &&
          !(fracture_energy > 0.))
        throw InputError(file,
                         "Fracture/Critical stretch",
                         "neither the critical stretch nor the fracture "
                         "energy is positive (Criterion = critical stretch "
                         "needs one)",
                         "Critical stretch > 0, or Fracture energy > 0 "
                         "[J/m^2]");
      if (!(domain_outer_radius > domain_inner_radius))
        throw InputError(file,
                         "Fracture/Domain outer radius",
                         number(domain_outer_radius) +
                           " is not larger than the inner radius " +
                           number(domain_inner_radius),
                         "Domain outer radius > Domain inner radius");
      if (!(front_half_width > 0.))
        throw InputError(file,
                         "Fracture/Front half-width",
                         number(front_half_width) + " is not positive",
                         "> 0 element sizes");
      if (criterion != "none" && !(growth_length > 0.))
        throw InputError(file,
                         "Fracture/Growth length",
                         number(growth_length) + " is not positive",
                         "> 0 element sizes");
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
      prm.declare_entry("Print timings",
                        "false",
                        Bool(),
                        "Print a table of wall times per phase at the end.");
      prm.leave_subsection();
    }

    void
    Output::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Output");
      directory       = trim(prm.get("Directory"));
      write_vtu       = prm.get_bool("Write vtu");
      write_every     = prm.get_integer("Write every");
      write_nodes_csv = prm.get_bool("Write nodes csv");
      print_timings   = prm.get_bool("Print timings");
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
      RNP::declare(prm);
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

      ParameterHandler prm;
      declare(prm);
      try
        {
          prm.parse_input(file, "", false, true);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(file,
                           "",
                           clean_dealii_message(e.what()),
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
              throw InputError("--set",
                               path,
                               "cannot set it to '" + value +
                                 "': " + clean_dealii_message(e.what()),
                               "see 'pdfem --print-parameters'");
            }
          for (; depth > 0; --depth)
            prm.leave_subsection();
        }
      dim = prm.get_integer("Dimension");
      mesh.parse(prm, file);
      material.parse(prm, file, dim);
      peridynamics.parse(prm, file, dim);
      rnp.parse(prm, file);
      boundary_conditions.parse(prm, file, dim);
      linear_solver.parse(prm, file);
      driver.parse(prm, file, dim);
      fracture.parse(prm, file);
      if (driver.dynamic() && !(material.density > 0.))
        throw InputError(file,
                         "Material/Density",
                         "rho = " + number(material.density) +
                           " for a dynamic run (Driver/Type = " + driver.type +
                           ")",
                         "rho > 0 [kg/m^3]");
      if (driver.type == "newmark" && linear_solver.type == "gmres" &&
          linear_solver.preconditioner == "amg fe")
        throw InputError(file,
                         "Linear solver/Preconditioner",
                         "'amg fe' has no assembled matrix, which Newmark "
                         "factorises once and reuses",
                         "amg or ilu (or Type = direct)");
      output.parse(prm, file);
      if (driver.dynamic() &&
          (fracture.criterion == "mcts" || fracture.adaptive_margin > 0.))
        throw InputError(file,
                         fracture.criterion == "mcts" ?
                           "Fracture/Criterion" :
                           "Fracture/Adaptive margin",
                         "stress-intensity factors (mcts) and the adaptive "
                         "PD region belong to quasi-static runs",
                         "Criterion = none or max principal stress, "
                         "Adaptive margin = 0 with Driver/Type = " +
                           driver.type);
      const bool nonlinear_driver =
        driver.type == "newton" || driver.type == "arc length";
      if (nonlinear_driver && peridynamics.model != "rnp")
        throw InputError(file,
                         "Driver/Type",
                         "the " + driver.type +
                           " driver runs the rnp model only; the " +
                           peridynamics.model + " scene is linear",
                         "static or quasi-static, or Peridynamics/Model = "
                         "rnp");
      if (peridynamics.model == "rnp" &&
          (driver.type == "quasi-static" || driver.dynamic() ||
           fracture.criterion != "none"))
        throw InputError(file,
                         driver.type == "quasi-static" ? "Driver/Type" :
                                                         "Fracture/Criterion",
                         "the rnp model softens its bonds itself: it takes "
                         "no crack criterion and no quasi-static or dynamic "
                         "driver",
                         "Driver/Type = static, newton or arc length with "
                         "Fracture/Criterion = none");
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
