// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FRACTURE_CRACK_GROWTH_H
#define PDFEM_FRACTURE_CRACK_GROWTH_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/fracture/interaction_integral.h>
#include <pdfem/fracture/settings.h>
#include <pdfem/mesh/cracks.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pdfem
{
  class StateArchive;

  namespace Fracture
  {
    /**
     * One crack tip (2D), or one point of a straight crack front (3D), where
     * the SIFs are evaluated: where it is, where it heads, and its last SIFs.
     */
    template <int dim>
    struct Tip
    {
      unsigned int           crack  = 0;    // crack path (2D), front (3D)
      double                 s      = 0.;   // 3D: distance along the front
      bool                   at_end = true; // last point (else the first)
      dealii::Point<dim>     position;
      dealii::Tensor<1, dim> direction;     // unit, along the crack to the tip
      bool                   active = true; // false once it left the body
      /// Where the last SIFs were computed (the tip before it grew).
      dealii::Point<dim> evaluated_at;
      StressIntensity    sif;
      double             K_eq  = 0.; // equivalent SIF (MCTS)
      double             theta = 0.; // kink angle theta_c [rad]
    };

    /** What one evaluation of the criterion found and did. */
    struct Assessment
    {
      /// Bonds broken by this evaluation (on all ranks).
      unsigned long broken_bonds = 0;
      /// Critical over current load, for a load proportional to t: the
      /// load at which the criterion would be met if nothing grew (infinite
      /// when nothing loads the crack).
      double critical_load_ratio = 0.;
      /// The largest bond principal stress (FC2), K_eq (FC1) or stretch over
      /// critical stretch seen.
      double max_driving_value = 0.;
      /// Pieces of the body (only counted after growth, else 1).
      unsigned int pieces = 1;
    };

    /**
     * Crack paths and the growth criteria of specs/004 §3, for any number of
     * cracks and tips:
     *
     * - `mcts` (PDLSM-FEM's FC 1): at every active tip the interaction
     *   integral gives K_I, K_II (InteractionIntegral); the maximum
     *   circumferential tensile stress gives the kink angle
     *   theta_c = 2 atan[(K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)]
     *   (the peer's two-branch formula in one, manual eq. 41) and
     *   K_eq = K_I cos^3(theta_c/2) - 3/2 K_II cos(theta_c/2) sin(theta_c)
     *   (eq. 42). A tip with K_eq > K_Ic advances by d_c along
     *   alpha + theta_c, and every bond crossing the new segment breaks.
     * - `max principal stress` (FC 2): every intact bond (k, m) with the
     *   largest eigenvalue of (sigma_k + sigma_m)/2 above the tensile
     *   strength is a candidate (eq. 43-44); the Top K largest (all if 0)
     *   get a virtual crack through the bond's midpoint, normal to the
     *   principal direction, of length d (a segment in 2D, a disc of
     *   diameter d in 3D, eq. 45), and every bond crossing one breaks.
     * - `critical stretch`: a bond breaks when its stretch (|xi + eta| -
     *   |xi|)/|xi| exceeds s_c, given or from G_c by the bond-based
     *   relation (Silling & Askari 2005; Ha & Bobaru 2010); for dynamic
     *   fracture, where cracks may branch freely.
     *
     * Ends of the initial cracks are tips when they lie inside the body and
     * touch no other crack (a central crack given as two cracks from its
     * centre, as the peer's examples do, has two tips), unless the tips are
     * listed explicitly (PDLSM-FEM: the second point of each crack).
     *
     * In 3D (cracks given as triangles) the tips are `Front points` points
     * on each straight front (InteractionIntegral::straight_fronts()), both
     * ends included, where mcts computes K_I, K_II, K_III and J
     * (doc/theory.md §9.2). 3D fronts do not grow: a front point with K_eq
     * above K_Ic stops the run (exit state `unsupported`).
     */
    template <int dim>
    class CrackGrowth
    {
    public:
      /**
       * The crack state of @p initial_cracks in @p system. In 2D the tips
       * are found (or taken from @p tip_at_end); in 3D with @p fronts_3d,
       * the straight fronts and their points (for stress-intensity
       * factors).
       */
      CrackGrowth(const Settings                      &settings,
                  const FE::ElasticMaterial           &material,
                  const std::vector<Mesh::Crack<dim>> &initial_cracks,
                  const Coupling::CoupledSystem<dim>  &system,
                  const std::vector<bool>             &tip_at_end = {},
                  bool                                 fronts_3d  = false);
      ~CrackGrowth();

      /**
       * `mcts`: at every active tip K_I, K_II (and K_III, J) by the
       * interaction integral, the MCTS kink angle and K_eq; where
       * @p allow_growth and K_eq > K_Ic the tip advances and the bonds
       * crossing the new segment break. Collective.
       */
      Assessment
      grow_at_tips(Coupling::CoupledSystem<dim>      &system,
                   const Coupling::NodalResults<dim> &results,
                   bool                               allow_growth);

      /// `max principal stress` (FC 2): virtual cracks through the most
      /// stressed bonds above the tensile strength. Collective.
      Assessment
      grow_by_principal_stress(Coupling::CoupledSystem<dim>      &system,
                               const Coupling::NodalResults<dim> &results,
                               bool                               allow_growth);

      /// `critical stretch`: bonds stretched beyond s_c break. Collective.
      Assessment
      break_by_stretch(Coupling::CoupledSystem<dim>      &system,
                       const Coupling::NodalResults<dim> &results,
                       bool                               allow_growth);

      /// The smallest piece of a body of @p n_nodes nodes that counts as a
      /// piece: max(3, 1 % of the nodes); smaller ones are fragments.
      static unsigned int
      smallest_piece(unsigned int n_nodes)
      {
        return n_nodes / 100 > 3u ? n_nodes / 100 : 3u;
      }

      /// After bonds broke: count the pieces of the body into @p a.
      static void
      count_pieces(Assessment                         &a,
                   const Coupling::CoupledSystem<dim> &system,
                   const Coupling::NodalResults<dim>  &results);

      /// The material (for criteria stated in energies or moduli).
      const FE::ElasticMaterial &
      material() const;

      /// Re-attach to a rebuilt system (same mesh, another PD region).
      void
      attach(const Coupling::CoupledSystem<dim> &system);

      /// Put the paths, tips, segments and fronts into a checkpoint.
      void
      save_state(StateArchive &state) const;

      /// Take them back from a checkpoint (restart).
      void
      load_state(const StateArchive &state);

      const std::vector<Tip<dim>> &
      tips() const;

      /// Every crack segment so far: the initial cracks, their growth and
      /// the virtual cracks of FC2 (what a rebuilt system must cut).
      const std::vector<Mesh::Crack<dim>> &
      segments() const;

      /// The crack paths as polylines (initial cracks with their growth).
      const std::vector<std::vector<dealii::Point<dim>>> &
      paths() const;

      /// Write the paths and virtual cracks as a legacy VTK polydata file
      /// (lines) for ParaView, and as CSV (crack, x, y[, z]).
      void
      write_paths(const std::string &vtk_file,
                  const std::string &csv_file) const;

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };

    /**
     * The adaptive PD region (specs/004 §3.1 item 8, m_e): every FE cell
     * that comes within @p margin of its own sizes (measure^(1/dim)) of one
     * of @p cracks becomes PD. Returns how many cells changed.
     */
    template <int dim>
    unsigned int
    extend_pd_region(const dealii::Triangulation<dim, dim> &tria,
                     const std::vector<Mesh::Crack<dim>>   &cracks,
                     double                                 margin,
                     std::vector<bool>                     &cell_is_pd);

    /**
     * The kink angle theta_c of the maximum circumferential tensile stress
     * criterion and the equivalent SIF (specs/004 §3.1 eq. 41-42).
     */
    std::pair<double, double>
    mcts_angle_and_keq(double K_I, double K_II);
  } // namespace Fracture
} // namespace pdfem

#endif
