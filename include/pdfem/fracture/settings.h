// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FRACTURE_SETTINGS_H
#define PDFEM_FRACTURE_SETTINGS_H

#include <array>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  namespace Fracture
  {
    /** `subsection Fracture`: crack-tip analysis and growth. */
    struct Settings
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
      /// f: FE cells whose nodal largest principal stress reaches f times
      /// the tensile strength become PD, with adaptive_margin cells around
      /// them (0 = off).
      double automatic_region = 0.;
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

  } // namespace Fracture
} // namespace pdfem

#endif
