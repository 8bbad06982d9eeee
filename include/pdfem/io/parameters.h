// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_PARAMETERS_H
#define PDFEM_IO_PARAMETERS_H

#include <pdfem/drivers/settings.h>
#include <pdfem/fracture/settings.h>
#include <pdfem/solvers/settings.h>

#include <array>
#include <memory>
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
      std::string model = "auto";
      /// m in delta_i = m * Delta_i, Delta_i = V_i^(1/dim).
      double horizon_factor = 3.;
      /// a in omega = exp(-(|xi| / (a delta))^2).
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

    /// The linear solver's parameters (declared and parsed in solvers/).
    using LinearSolver = Solvers::Settings;
    /// The driver's parameters (declared and parsed in drivers/).
    using Driver = Drivers::Settings;
    /// A monitored node of a dynamic run.
    using MonitorPoint = Drivers::MonitorPoint;
    /// The crack criterion's parameters (declared and parsed in fracture/).
    using Fracture = ::pdfem::Fracture::Settings;

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

      /// Read what the rnp model plugin declared (PDModels, rnp_bonds.cc).
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

    /** `subsection Output`. */
    struct Output
    {
      std::string  directory; // empty: "output-<scene name>"
      bool         write_vtu          = true;
      unsigned int write_every        = 0; // VTU every n steps; 0: last only
      bool         write_nodes_csv    = false;
      bool         print_timings      = false;
      std::string  patch_test         = "auto"; // auto|true|false
      unsigned int checkpoint_steps   = 0;      // 0: not by count
      double       checkpoint_minutes = 0.;     // 0: not by time
      double       progress_interval  = 5.;     // [s] within long steps

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
      /// The file as read (with overrides): plugins read their own
      /// parameters from it (e.g. PDModels::Interface::parse_parameters()).
      std::shared_ptr<dealii::ParameterHandler> handler;

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
