// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_PDLSM_ENERGY_H
#define PDFEM_PD_MODELS_PDLSM_ENERGY_H

#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/pdlsm.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace pdfem
{
  namespace PDModels
  {
    /**
     * The energy form of the PDLSM operator ("pdlsm energy"; issue 16,
     * doc/theory.md §12): the PD forces are the gradient of
     *
     *   E = sum_k V_k^pd [ W(eps_k) + (G_s / 2) sum_i beta_i |z_i|^2 ],
     *   eps_k = sym(H_k),  H_k = sum_{a in k's family and k} u_a (x) g_ka,
     *   z_i = u_{m_i} - u_k - H_k xi_i,
     *
     * with W the isotropic strain energy density (lambda, mu in use), the
     * least-squares gradient weights g_ka of the family of k (linear fit, or
     * PDLSM's quadratic one; g_kk = -sum of the members'), and beta_i =
     * omega_i V_i / (|xi_i|^2 sum omega V) the normalised Gaussian weights.
     *
     * - Integration-constraint correction (variationally consistent nodal
     *   integration, Chen et al. 2001): g_ka += (P_k c)_a, with P_k = W_k
     *   (I - Pi_k) the weighted residual of the linear fit over the family
     *   (so constant and linear fields keep their exact gradients), and c
     *   solving sum_k V_k P_k c = s - sum_k V_k g_k by preconditioned CG
     *   (symmetric positive semi-definite, consistent right-hand side).
     *   Then sum_k V_k g_kj = s_j, the node's share of the PD region's
     *   boundary vector, and the coupled patch test is exact.
     * - Stabilisation (Silling, CMAME 322 (2017)): the bond penalty on the
     *   non-affine part z_i, modulus G_s = Stabilisation x mu; it vanishes
     *   on linear fields and removes the zero-energy modes of the nodal
     *   integration.
     *
     * E is a sum of quadratic forms of u, so the model is linear, the
     * tangent symmetric and the forces of every family sum to zero (H is
     * unchanged by a translation), with or without broken bonds.
     *
     * Bonds cut by a pre-existing crack leave their families at set-up:
     * the weights are fitted again over the intact bonds, without the
     * correction (doc/theory.md §12.3). Bonds broken during a run (Energy
     * form/Broken bonds): "condense" replaces the family's quadratic
     * energy E_k(u) = 1/2 u^T K_k u by its minimum over the displacements
     * of the members it lost, the Schur complement
     *
     *   K_k' = K_rr - K_rb K_bb^+ K_br   (r: owner and intact members,
     *                                     b: the lost members),
     *
     * so that E_k'(u) <= E_k(u) for every u: breaking can only release
     * energy (theory.md §12.3); "refit" fits the weights again as at
     * set-up (the energy may rise).
     */
    template <int dim>
    class PDLSMEnergy : public Interface<dim>
    {
    public:
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &file) override;

      Layout
      layout() const override;

      void
      initialize(const Region<dim> &region) override;

      void
      bonds_changed(const std::vector<std::size_t> &changed,
                    bool                            free_surfaces) override;

      void
      reference_bonds_cut(const std::vector<std::size_t> &changed,
                          bool free_surfaces) override;

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

      void
      family_forces(std::size_t                          o,
                    const NodalField<dim>               &u,
                    std::vector<dealii::Tensor<1, dim>> &f) const override;

      void
      family_tangent(std::size_t                          o,
                     const NodalField<dim>               &u,
                     std::vector<dealii::Tensor<2, dim>> &K) const override;

      /// O(n) for an intact family (its tangent's diagonal blocks alone).
      void
      family_diagonal_blocks(
        std::size_t                          o,
        const NodalField<dim>               &u,
        std::vector<dealii::Tensor<2, dim>> &D) const override;

      dealii::Tensor<2, dim>
      displacement_gradient(std::size_t            o,
                            const NodalField<dim> &u) const override;

      std::vector<std::pair<std::string, double>>
      constants() const override;

    private:
      /// Fit the gradient weights of family @p o over its intact bonds
      /// (and set their Gaussian weights) in the work space @p ws; false if
      /// they cannot carry the fit (gradient weights left zero). Writes
      /// family o's bonds and owner entries only.
      bool
      fit(std::size_t o, FitWorkspace<dim> &ws);
      /// stabilisation_weight and n_in_fit of family @p o from its bonds
      /// in the fit and their bond_weight.
      void
      set_stabilisation_weights(std::size_t o);
      /// Solve for the integration-constraint correction of every family,
      /// once at set-up (collective; pdlsm_energy_correction.cc).
      void
      solve_integration_constraint();
      /// What the energy of one family reads: its nodes (owner, intact
      /// members), their gradient weights, the bonds and the
      /// stabilisation weights.
      struct FamilyWeights
      {
        std::vector<unsigned int>           nodes;
        std::vector<dealii::Tensor<1, dim>> g, bond_vector;
        std::vector<double>                 beta;
      };
      /// Family @p o's FamilyWeights (written into @p family, whose
      /// vectors keep their capacity).
      void
      family_weights(std::size_t o, FamilyWeights &family) const;
      /// Family @p o's FamilyWeights.
      FamilyWeights
      family_weights(std::size_t o) const;
      /// Blocks of the stiffness of the energy of @p weights, family
      /// volume @p V: K[i n_c + j] = K_ab for the nodes a = rows[i], b =
      /// columns[j] (n_c columns; every node where a list is null), or
      /// with @p diagonal K[i] = K_aa, a = rows[i].
      void
      weights_tangent(const FamilyWeights                 &weights,
                      double                               V,
                      std::vector<dealii::Tensor<2, dim>> &K,
                      const std::vector<std::size_t>      *rows    = nullptr,
                      const std::vector<std::size_t>      *columns = nullptr,
                      bool diagonal = false) const;
      /// Condense the members family @p o lost out of its stiffness (the
      /// Schur complement; the first time from its weights).
      void
      condense(std::size_t o);
      /**
       * A family condensed by condense(). Schur complements compose (the
       * complement of K's complement over b_1 taken over b_2 is K's over
       * b_1 and b_2), so the family keeps the energy of its weights before
       * the first break, K (@p original, its volume), and the pseudo-
       * inverse of K_LL over all the members it lost, and applies
       * K' = K_rr - K_rL K_LL^+ K_Lr as y = K [u_r; 0], u_L = -K_LL^+ y_L,
       * f = (K [u_r; u_L])_r: two products with the weights and one with a
       * dim |L| square matrix, instead of the n^2 dense blocks of K' (n ~
       * 200 in 3D, |L| ~ 10 a break: 1.5 MB a family).
       */
      struct CondensedFamily
      {
        /// The family's nodes' indices in original.nodes: kept (the owner
        /// first, increasing: the owner and its intact bonds in family
        /// order) and lost.
        std::vector<std::size_t> kept, lost;
        /// The bonds of original.nodes[1..].
        std::vector<std::size_t> original_bonds;
        FamilyWeights            original;
        double                   volume = 0.;
        /// K_LL^+, dim |lost| square, row major.
        std::vector<double> lost_inverse;
      };

      /// K' of a condensed family, n_r^2 blocks (kept nodes), or with
      /// @p diagonal its n_r diagonal blocks.
      void
      condensed_tangent(const CondensedFamily               &c,
                        std::vector<dealii::Tensor<2, dim>> &K,
                        bool diagonal = false) const;

      /// f = K u over the family @p w, volume @p V, u[a] the displacement
      /// of its node a (the owner a = 0).
      void
      weights_forces(const FamilyWeights                       &w,
                     const std::vector<dealii::Tensor<1, dim>> &u,
                     double                                     V,
                     std::vector<dealii::Tensor<1, dim>>       &f) const;

      double                      weight_factor   = 0.33;
      bool                        quadratic_fit   = false;
      double                      stabilisation   = 1.;
      bool                        correct         = true;
      bool                        condense_broken = true;
      std::unique_ptr<PDLSM<dim>> pdlsm;
      /// Gradient weights g (corrected once at set-up, refitted plain
      /// when a family loses bonds): per bond (zero when broken) and per
      /// owner.
      std::vector<dealii::Tensor<1, dim>> weight, owner_weight;
      /// Per bond the Gaussian weight omega V of the fits, the projector
      /// and the stabilisation (zero when broken).
      std::vector<double>       bond_weight;
      std::vector<std::uint8_t> fitted;
      /// Per bond: intact when its family was last fitted (the bonds of
      /// the family's weights; condense() reads them before the refit).
      std::vector<std::uint8_t> in_fit;
      /// Per bond of the last fit its normalised stabilisation weight
      /// beta_i = omega_i V_i / (|xi_i|^2 sum omega V); per owner the
      /// number of those bonds.
      std::vector<double>       stabilisation_weight;
      std::vector<unsigned int> n_in_fit;
      /// Per owner: its condensed energy (null while it has none).
      std::vector<std::unique_ptr<CondensedFamily>> condensed;
      /// |sum_k V_k g_kj - s_j| / |s| after the solve, and its CG
      /// iterations.
      double       constraint_residual   = 0.;
      unsigned int correction_iterations = 0;
      /// fit()'s work space after set-up (initialize() fits on the
      /// threads, with one each).
      FitWorkspace<dim> workspace;
    };
  } // namespace PDModels
} // namespace pdfem

#endif
