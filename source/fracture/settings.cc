// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/fracture/criterion.h>
#include <pdfem/fracture/settings.h>

#include <deal.II/base/parameter_handler.h>


namespace pdfem
{
  namespace Fracture
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    using namespace ParameterTools;

    // -------------------------------------------------------------- Fracture
    void
    Settings::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Fracture");
      prm.declare_entry("Criterion",
                        "none",
                        Selection(registry<2>().selection({"none"})),
                        "none: cracks never grow. " + registry<2>().summary() +
                          "In static runs the criterion is only evaluated "
                          "and reported (pdfem --list-plugins).");
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
      prm.declare_entry("Automatic region",
                        "0",
                        Double(0., 1.),
                        "f in (0, 1]: after each equilibrium, FE cells where "
                        "the largest principal stress at a node reaches f x "
                        "Tensile strength become PD, with the FE cells "
                        "within Adaptive margin element sizes of them, and "
                        "the step is solved again at the same load; the load "
                        "jumps no further than to where an FE cell reaches "
                        "it. A scene may then start all FE (PD regions = "
                        "none). Needs Tensile strength > 0 and Adaptive "
                        "margin > 0; quasi-static runs. 0: off.");
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
    Settings::parse(ParameterHandler &prm, const std::string &file)
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
      automatic_region    = prm.get_double("Automatic region");
      critical_stretch    = prm.get_double("Critical stretch");
      fracture_energy     = prm.get_double("Fracture energy");

      // PDLSM-FEM's choices (pdfem-convert)
      growth_length_absolute = prm.get_double("Absolute growth length");
      no_fail_nodes          = split(prm.get("No-fail nodes"), ',');
      tip_at_second_point    = prm.get("Crack tips") == "second point";
      prm.leave_subsection();
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
      if (automatic_region > 0. && !(tensile_strength > 0.))
        throw InputError(file,
                         "Fracture/Automatic region",
                         "the indicator is a fraction of the Tensile "
                         "strength, which is 0",
                         "Tensile strength > 0, or Automatic region = 0");
      if (automatic_region > 0. && !(adaptive_margin > 0.))
        throw InputError(file,
                         "Fracture/Automatic region",
                         "the cells that reach the indicator grow by the "
                         "Adaptive margin, which is 0",
                         "Adaptive margin > 0 (e.g. 3), or Automatic region "
                         "= 0");
    }

  } // namespace Fracture
} // namespace pdfem
