// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_PARAMETERS_H
#define PDFEM_IO_PARAMETERS_H

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  /**
   * The parameters of one scene (a `.prm` file), grouped by module. Each group
   * declares its entries (with defaults and documentation, printed by
   * `pdfem --print-parameters`) and parses and validates them; a bad value
   * throws InputError naming the file, the parameter and the allowed values.
   */
  namespace Parameters
  {
    /** `subsection Mesh`: where the cells come from and which are PD. */
    struct Mesh
    {
      /// A gmsh `.msh` file, or a `.geo` script meshed with the gmsh
      /// executable.
      std::string input_file;
      /// Global refinements applied after reading.
      unsigned int refinements = 0;
      /// For .geo input: gmsh's -clscale (every element size times this).
      double size_factor = 1.;
      /// Physical names of the PD cells; "all" or "none" are also allowed.
      std::vector<std::string> pd_regions;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

    /** The 2D kinematic assumption. */
    enum class PlaneModel
    {
      plane_stress,
      plane_strain
    };

    /** `subsection Material`: isotropic linear elasticity (FE and PD alike). */
    struct Material
    {
      double     youngs_modulus = 0.; // E   [Pa]
      double     poissons_ratio = 0.; // nu  [-]
      double     density        = 0.; // rho [kg/m^3]
      PlaneModel plane          = PlaneModel::plane_stress;
      double     thickness = 1.; // 2D only [m]; forces are per this thickness

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file, int dim);
    };

    /** `subsection Peridynamics`: the PD discretisation of the PD cells. */
    struct Peridynamics
    {
      std::string model = "pdlsm";
      /// m in delta_i = m * Delta_i, Delta_i = V_i^(1/dim).
      double horizon_factor = 3.;
      /// a in omega = exp(-(|xi| / (a delta))^2).
      double weight_factor = 0.33;
      /// Whether FE-only nodes may be family members ("all nodes"), or only
      /// PD nodes ("pd nodes").
      bool fe_nodes_in_families = true;
      /// Crack faces as free surfaces (one-sided fits and a face term) rather
      /// than PDLSM-FEM's cut bonds alone.
      bool free_crack_faces = false;
      /// Pre-existing cracks: 2D segments "(x1, y1) -- (x2, y2)", 3D
      /// triangles "(x,y,z) -- (x,y,z) -- (x,y,z)", separated by ';'.
      std::vector<std::vector<std::array<double, 3>>> cracks;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file, int dim);
    };

    /**
     * One boundary condition: "name: component = expression", component one
     * of x, y, z (and `normal` for tractions); the expression is a muparser
     * function of x, y, z and t.
     */
    struct BoundaryEntry
    {
      std::string  boundary;
      unsigned int component = 0; // 0..dim-1, or dim for "normal"
      std::string  expression;
    };

    /** `subsection Boundary conditions`. */
    struct BoundaryConditions
    {
      std::vector<BoundaryEntry> dirichlet;
      std::vector<BoundaryEntry> traction;
      std::vector<std::string>   body_force; // dim expressions of x, y, z, t
      /// Dirichlet targets whose reactions are also summed as "RF"
      /// (history.csv reaction_RF_<c>, summary.json reaction_RF; the RF
      /// command of PDLSM-FEM).
      std::vector<std::string> reaction_group;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file, int dim);
    };

    /** `subsection Linear solver`. */
    struct LinearSolver
    {
      std::string  type           = "direct"; // direct | gmres
      std::string  direct_solver  = "mumps";  // mumps | klu
      std::string  preconditioner = "amg fe"; // amg fe | amg | ilu
      double       tolerance      = 1e-10;    // relative residual (gmres)
      unsigned int max_iterations = 2000;
      unsigned int restart        = 150; // gmres: Krylov vectors kept

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

    /** A node whose displacement history.csv records every step. */
    struct MonitorPoint
    {
      std::string           name;
      std::array<double, 3> point = {{0., 0., 0.}};
    };

    /**
     * `subsection Driver`: static equilibrium, or a dynamic run (explicit
     * central difference or Newmark) in physical time t.
     */
    struct Driver
    {
      /// static | quasi-static | newton | arc length | explicit | newmark
      std::string  type       = "static";
      unsigned int load_steps = 1;
      /// quasi-static: the nominal increment of t (0: 1 / Load steps).
      double load_increment = 0.;
      /// quasi-static: the first solve is at this t (PDLSM-FEM: 0).
      double initial_load = -1.; // < 0: one increment (Initial load)
      /// quasi-static: jump to the extrapolated critical load when it is
      /// nearer than the nominal increment (PDLSM-FEM's rule).
      bool jump_to_critical_load = true;
      /// quasi-static: keep t while cracks grow (PDLSM-FEM); if false, t
      /// follows its schedule whatever breaks (load histories).
      bool         hold_load_while_growing = true;
      double       residual_tolerance = 1e-9; // relative to |f_ext| (or |r_0|)
      unsigned int max_iterations     = 10;
      // newton only: load step cutting, line search, stability check
      unsigned int max_step_cuts    = 4;
      double       step_cut_factor  = 0.25;
      bool         line_search      = true;
      bool         stability_check  = true;
      unsigned int arc_length_steps = 50; // arc length only

      /// @name Dynamic runs (Type = explicit or newmark)
      /// @{
      /// Time step [s]; 0 = automatic (explicit only): safety factor times
      /// the critical step 2 / omega_max.
      double time_step = 0.;
      /// End time [s] (> 0 for a dynamic run).
      double end_time = 0.;
      /// Explicit: the automatic step is this times 2 / omega_max.
      double safety_factor = 0.9;
      /// Power iterations for the largest eigenvalue of M^-1 K.
      unsigned int eigenvalue_iterations = 50;
      /// Newmark parameters (average acceleration by default).
      double newmark_beta  = 0.25;
      double newmark_gamma = 0.5;
      /// HHT-alpha in [-1/3, 0] (0: plain Newmark); if not 0, beta =
      /// (1 - alpha)^2 / 4 and gamma = 1/2 - alpha.
      double hht_alpha = 0.;
      /// lumped | consistent (consistent: Newmark only).
      std::string mass = "lumped";
      /// Newmark: reuse the factorisation of K_N while no bond breaks.
      bool reuse_factorization = true;
      /// Initial velocity: dim expressions of x, y, z (empty: at rest).
      std::vector<std::string> initial_velocity;
      /// The run stops ('time step too large') when the energy exceeds the
      /// energy supplied by more than this fraction of the peak supplied.
      double energy_tolerance = 0.5;
      /// Write a history row every this many steps (and the last one).
      unsigned int history_interval = 1;
      /// Nodes whose displacement is written to history.csv.
      std::vector<MonitorPoint> monitor_points;
      /// @}

      bool
      dynamic() const
      {
        return type == "explicit" || type == "newmark";
      }

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file, int dim);
    };

    /**
     * `subsection Peridynamics/RNP`: the RNP bond model (Model = rnp;
     * specs/000 §1). C and beta are given, or calibrated: C beta from
     * Material/Young's modulus, C from the fracture energy.
     */
    struct RNP
    {
      std::string calibration      = "moduli"; // moduli | constants
      double      C                = 0.;
      double      beta             = 0.;
      double      fracture_energy  = 0.;         // G_c (calibration = moduli)
      std::string influence        = "constant"; // constant | linear
      std::string force_scaling    = "paper";    // paper | prototype
      std::string nodal_volumes    = "cells";    // cells | uniform
      double      dirichlet_layer  = 1.;         // layer thickness / horizon
      std::string tangent          = "analytic"; // analytic | finite difference
      std::string interface_energy = "full bonds"; // full bonds | partition

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

    /** `subsection Fracture`: crack-tip analysis and growth. */
    struct Fracture
    {
      /// none | mcts (K by interaction integral, maximum circumferential
      /// tensile stress; PDLSM-FEM FC 1) | max principal stress (FC 2).
      std::string criterion        = "none";
      double      toughness        = 0.; // K_Ic [Pa sqrt(m)]
      double      tensile_strength = 0.; // sigma_ult [Pa]
      /// Interaction-integral domain: r_in <= r <= r_out, in element sizes
      /// of the cell nearest the tip.
      double domain_inner_radius = 4.;
      double domain_outer_radius = 10.;
      /// 3D: points per straight crack front (ends included) and the
      /// half-width of the weight along the front, in element sizes.
      unsigned int front_points     = 5;
      double       front_half_width = 2.;
      /// d_c (mcts) and the virtual crack length (FC 2), in element sizes
      /// at the tip or bond; growth_length_absolute > 0 overrides [m].
      double       growth_length          = 1.;
      double       growth_length_absolute = 0.;
      unsigned int top_k                  = 0; // FC 2: 0 = every candidate
      /// m_e: FE cells within m_e element sizes of a crack become PD (at the
      /// start and as cracks grow); 0 = the PD region never changes.
      double adaptive_margin = 0.;
      /// critical stretch: s_c; 0 = from fracture_energy (G_c) by the
      /// bond-based relation (2D: sqrt(4 pi G_c / (9 E delta)), 3D:
      /// sqrt(5 G_c / (9 K delta))).
      double critical_stretch = 0.;
      double fracture_energy  = 0.; // G_c [J/m^2]
      /// Node sets (gmsh physical points) whose nodes' bonds never break
      /// (PDLSM-FEM's NO FAIL region).
      std::vector<std::string> no_fail_nodes;
      /// Crack tips: false = every crack end inside the body that touches
      /// no other crack; true = the second point of each 2D crack only
      /// (PDLSM-FEM: a crack is [start, tip]).
      bool tip_at_second_point = false;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

    /** `subsection Output`. */
    struct Output
    {
      std::string  directory; // empty: "output-<scene name>"
      bool         write_vtu       = true;
      unsigned int write_every     = 0; // VTU every n steps; 0: last only
      bool         write_nodes_csv = false;
      bool         print_timings   = false;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

    /** All of a scene's parameters. */
    struct Scene
    {
      int                dim = 2;
      std::string        file;     // the .prm file (for messages)
      std::string        base_dir; // its folder: relative paths start here
      std::string        name;     // its stem: default output folder name
      Mesh               mesh;
      Material           material;
      Peridynamics       peridynamics;
      RNP                rnp;
      BoundaryConditions boundary_conditions;
      LinearSolver       linear_solver;
      Driver             driver;
      Fracture           fracture;
      Output             output;

      static void
      declare(dealii::ParameterHandler &prm);
      /**
       * Read and validate @p file (throws InputError). Each of @p overrides
       * ("Section/Subsection/Entry", "value") replaces the file's value, as
       * `pdfem --set` does.
       */
      void
      read(
        const std::string                                      &file,
        const std::vector<std::pair<std::string, std::string>> &overrides = {});
    };

    /** Read `set Dimension = 2|3` from a parameter file before anything else.
     */
    int
    read_dimension(const std::string &file);

    /** Print every parameter with its default and documentation. */
    void
    print_all(std::ostream &out);
  } // namespace Parameters
} // namespace pdfem

#endif
