// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_LPS_FFT_H
#define PDFEM_PD_MODELS_LPS_FFT_H

#include <pdfem/fft/grid.h>
#include <pdfem/fft/operator.h>
#include <pdfem/pd_models/interface.h>

#include <deal.II/base/tensor.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pdfem
{
  namespace FFT
  {
    template <int dim>
    class FftOperator;
    class SlabExchange;
  } // namespace FFT

  namespace PDModels
  {
    /**
     * The PD nodes of an all-PD region detected as a uniform grid: n[c]
     * nodes of spacing[c] from origin[c] in direction c, node k at grid
     * indices index[k] (x_k = origin + index . spacing to 1e-8 spacing).
     */
    template <int dim>
    struct NodeGrid
    {
      std::array<unsigned int, dim>              n{};
      std::array<double, dim>                    spacing{}, origin{};
      std::vector<std::array<unsigned int, dim>> index;
    };

    /**
     * The grid of @p x: the spacing of each direction is the smallest gap
     * between distinct coordinates, and every node must lie on it (1e-8
     * spacing) at its own grid point. Throws InputError naming
     * `Peridynamics/Model` and @p file otherwise.
     */
    template <int dim>
    NodeGrid<dim>
    detect_node_grid(const std::vector<dealii::Point<dim>> &x,
                     const std::string                     &file);

    /// The failed body nodes of "lps fft" (integrity 0) and their bounding
    /// box lo-hi (both 0 when none failed).
    template <int dim>
    struct FailedNodes
    {
      std::size_t             n = 0;
      std::array<double, dim> lo{}, hi{};
    };

    /**
     * The linearised LPS model of "lps" (specs/002 §1.4, eqs. 27-36;
     * doc/theory.md §15) evaluated for all owners at once by the fast
     * convolution-based method ("lps fft"; FFT::FftOperator with
     * FFT::Model::lps, specs/002 §2, doc/theory.md §14): the same forces as
     * `Model = lps` with `LPS/Nodal volumes = uniform`, to round-off,
     *
     *   F_k = -Delta V L(x_k),
     *
     * L the LPS force density of FFT::Operator (specs/002 eq. 36 with the
     * variable weighted volume, the "fully consistent variant" of §1.4)
     * and Delta V = h^dim (h the region's spacing).
     *
     * For an all-PD region whose nodes lie on a uniform grid (a structured
     * mesh of equal cells): the grid is detected from the node positions
     * (detect_node_grid()), and the body is embedded in a periodic box with
     * a gap of more than a horizon on every side (specs/002 §2.5), its mask
     * chi_B = 1 at the nodes (any shape; grid points without a node are
     * outside). The box size in each direction is the smallest product of
     * 2, 3, 5, 7 that leaves the gap.
     *
     * A row model (Layout::family_elements false): prepare_forces()
     * evaluates L for every grid point once per state (one FFT operator
     * application, FFTW threads = the thread team's size), and forces()
     * hands each owner chunk its rows. With several ranks the box is split
     * into slabs of whole planes (FFT::FftOperator over region.comm,
     * FFTW's MPI interface): each rank holds and evaluates its slab only,
     * the owners' displacements go to the slabs that hold their grid
     * points and the forces come back (FFT::SlabExchange, one
     * MPI_Alltoallv each way per evaluation).
     *
     * No bonds (Layout::bonds false): the FFT sums over the grid's discrete
     * horizon (FFT::horizon_offsets()), so the coupled system builds no
     * families' members and stores no bonds. The memory is that of the
     * grid's fields and the mesh, O(N) and independent of the horizon
     * (doc/benchmarks/fft.md); the output's displacement gradient loops
     * over the grid's offsets.
     *
     * Damage (`LPS fft/Damage = energy`, doc/theory.md §14.5): the
     * paper's pointwise energy criterion (specs/002 §1.6, eqs. 42-44,
     * 50-51, 63). After every accepted step (commit_state()) the strain
     * energy density W of FFT::Operator::energy_density() (the paper's
     * convention, twice the physical one, §7 E11) is compared with
     *
     *   W_c = G_0 / delta,
     *
     * G_0 = `LPS fft/Fracture energy`, and lambda(x) = 0 where W > W_c, for
     * good (FFT::update_integrity()); the operator's masks become beta =
     * chi_B lambda (FFT::Operator::set_masks()), so that the forces of the
     * next step see the dead nodes (the paper's one-step lag, eq. 63): a
     * dead node carries no force and loses all its bonds to the FFT (no
     * bond breaks in the coupled system, which has none; the damage shows
     * in damage() and max_damage). damage() is the
     * FFT damage index (specs/002 eq. 65) with the normalisation of
     * `LPS fft/Damage index` (body by default: 0 in an intact body).
     *
     * Limits (InputError naming `Peridynamics/Model`): no FE cells; no
     * broken bonds (pre-existing cracks, bond-breaking criteria: the FFT
     * form knows node masks only, not single bonds); no tangent (explicit
     * dynamics, or statics by matrix-free CG, whose products with the
     * stiffness are force evaluations: K x is the internal force of x for
     * this linear model); LPS/Nodal volumes = uniform
     * (every node carries Delta V).
     */
    template <int dim>
    class LpsFft : public Interface<dim>
    {
    public:
      LpsFft();
      ~LpsFft() override;

      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &file) override;

      Layout
      layout() const override;

      /// Detects the grid, makes the FFT operator and its masks.
      void
      initialize(const Region<dim> &region) override;

      /// Refused (InputError): the FFT form has no single broken bonds.
      void
      bonds_changed(const std::vector<std::size_t> &changed,
                    bool                            free_surfaces) override;

      bool
      linear() const override
      {
        return true;
      }

      bool
      symmetric() const override
      {
        return true;
      }

      /// L of every grid point at @p u (the owners' displacements).
      void
      prepare_forces(const NodalField<dim> &u) override;

      /// The rows of the last prepare_forces(): f = -Delta V L(x_k).
      void
      forces(std::size_t            begin,
             std::size_t            end,
             const NodalField<dim> &u,
             double                *f) const override;

      /// The inverse of the periodic operator's stiffness, Delta V G (FFT::
      /// FftOperator::apply_periodic_inverse()): exact for a node whose
      /// horizon lies inside the body, a preconditioner for CG statics.
      void
      precondition(const std::vector<double> &r,
                   std::vector<double>       &z) override;

      /// With damage: W of @p u, the nodes above W_c die for good, the
      /// masks and the damage index follow.
      void
      commit_state(const NodalField<dim> &u) override;

      /// The strain energy the nodes failed by the last commit_state()
      /// released at its u (summed over the ranks; 0 if none failed).
      double
      released_energy() const override
      {
        return released;
      }

      /// Owner @p o's damage index (the masks of the last commit_state()).
      double
      damage(std::size_t o, const NodalField<dim> &u) const override;

      /// The integrity lambda of every box node.
      void
      save_state(StateArchive &state) const override;

      void
      restore_state(const StateArchive &state) override;

      /// Refused (InputError): no tangent (explicit, or static by CG).
      void
      tangent_row(std::size_t                          o,
                  const NodalField<dim>               &u,
                  std::vector<dealii::Tensor<2, dim>> &blocks) const override;

      /// The owners' displacements into the box, for the gradients.
      void
      prepare_results(const NodalField<dim> &u) override;

      /// As "lps" with uniform volumes: the fit of the grid's bonds within
      /// the body (the discrete horizon) with the weights omega Delta V, at
      /// the displacements of the last prepare_results().
      dealii::Tensor<2, dim>
      displacement_gradient(std::size_t            o,
                            const NodalField<dim> &u) const override;

      double
      nodal_volume(unsigned int k) const override;

      /// As "lps", and the FFT box: its nodes, and the operator's bytes
      /// per box node and per body node.
      std::vector<std::pair<std::string, double>>
      constants() const override;

      /// The detected grid of the body's nodes.
      const NodeGrid<dim> &
      node_grid() const
      {
        return body_grid;
      }

      /// The nodes of the periodic box in each direction.
      const std::array<unsigned int, dim> &
      box_size() const
      {
        return box;
      }

      /// Owner @p o's node in the periodic box.
      std::size_t
      box_node_of(const std::size_t o) const
      {
        return box_node[o];
      }

      /// This rank's slab of the box (all of it with one rank): the box
      /// nodes [begin, end) that the fields below hold.
      const FFT::Slab &
      slab_of_box() const
      {
        return slab;
      }

      /// The FFT operator (its grid, material and current masks).
      const FFT::FftOperator<dim> &
      fft_operator() const
      {
        return *op;
      }

      /// chi_B and lambda of the slab's box nodes.
      const std::vector<double> &
      body_mask() const
      {
        return body;
      }

      const std::vector<double> &
      integrity() const
      {
        return lambda;
      }

      /// W of the slab's box nodes at the last commit_state() (empty
      /// before).
      const std::vector<double> &
      energy_density() const
      {
        return W_box;
      }

      /// W_c = G_0 / delta (0 without damage).
      double
      critical_energy_density() const
      {
        return W_c;
      }

      /// Damage = energy?
      bool
      damage_active() const
      {
        return damage_on;
      }

      /// The failed body nodes of all ranks and their bounding box (where
      /// the cracks ran), as of the last commit_state().
      FailedNodes<dim>
      failed_nodes() const
      {
        return failed;
      }

      /// The nodes the last commit_state() failed.
      std::size_t
      last_failed() const
      {
        return n_last_failed;
      }

    private:
      std::string source_file;
      bool        inverse_distance = true;
      double      dirichlet_layer  = 1.;
      double      traction_layer   = 0.;
      /// LPS fft/Keep mask fields (FFT::FftOptions::keep_mask_fields; kept
      /// at the layer nodes only, FFT::FftOperator::n_layer_nodes()).
      bool   keep_mask_fields = true;
      double delta = 0., A = 0., B = 0., bulk_modulus = 0.;
      double node_volume = 0.;
      /// LPS fft/Damage = energy, G_0 and W_c = G_0 / delta.
      bool                     damage_on       = false;
      double                   fracture_energy = 0., W_c = 0.;
      FFT::DamageNormalisation normalisation{};
      std::size_t              n_last_failed = 0;
      double                   released      = 0.;
      /// precondition() has made the periodic inverse.
      bool inverse_made = false;
      /// chi_B, lambda, W and the damage index of the slab's box nodes.
      std::vector<double> body, lambda, W_box, d_box;

      /// The owners' @p u into u_box (the slabs that hold them).
      void
      gather(const NodalField<dim> &u);

      /// The operator's bytes summed over the ranks and the largest rank's
      /// (collective).
      void
      count_operator_bytes();

      /// failed: the failed nodes of every slab (collective).
      void
      count_failed_nodes();

      NodeGrid<dim>                 body_grid;
      std::array<unsigned int, dim> box{};
      std::size_t                   n_box = 0;
      /// Per owner: its grid point in the box.
      std::vector<std::size_t> box_node;
      /// This rank's slab, and the plan that moves the owners' values to
      /// the slabs and back.
      FFT::Slab                          slab;
      std::unique_ptr<FFT::SlabExchange> exchange;
      /// The slab's displacement (dim N_slab, component-major) and L.
      std::vector<double> u_box, L_box;
      /// precondition()'s residual and correction on the slab.
      std::vector<double> r_box, z_box;
      /// Per owner (interleaved): its displacement (scratch), its L and its
      /// damage index, and its gradient of the last prepare_results().
      std::vector<double>                 owner_values, L_owner, d_owner;
      std::vector<dealii::Tensor<2, dim>> gradient;
      FailedNodes<dim>                    failed;
      /// The FFT operator's bytes over all ranks and on the largest rank.
      double operator_bytes     = 0.;
      double largest_rank_bytes = 0.;
      /// The nodes holding kept mask fields, summed over the ranks
      /// (FFT::FftOperator::n_layer_nodes()).
      double                                 layer_nodes = 0.;
      std::unique_ptr<FFT::FftOperator<dim>> op;
      /// The grid offsets of the discrete horizon (the gradient's bonds).
      std::vector<FFT::Offset<dim>> stencil;
    };
  } // namespace PDModels
} // namespace pdfem

#endif
