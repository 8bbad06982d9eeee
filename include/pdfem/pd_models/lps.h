// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_LPS_H
#define PDFEM_PD_MODELS_LPS_H

#include <pdfem/pd_models/interface.h>

#include <deal.II/base/tensor.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pdfem
{
  namespace PDModels
  {
    /**
     * The linearised linear peridynamic solid, state based ("lps";
     * specs/002 §1.4, eqs. 27-36; doc/theory.md §15), in the direct
     * (bond-loop) form, with the same constants, weighted volume and
     * broken-bond treatment as the FFT operator of FFT::Model::lps
     * (doc/theory.md §14.2), so that an all-PD scene on a uniform grid
     * gives the same forces either way.
     *
     * With xi = x_j - x_k, eta = u_j - u_k, omega = omega(|xi|) (1 / |xi|
     * or 1), V_j the member's bond volume, d the dimension and the sums
     * over the intact bonds of owner k:
     *
     *   m_k     = sum_j omega |xi|^2 V_j                (specs/002 eq. 29)
     *   theta_k = (d / m_k) sum_j omega xi.eta V_j      (eqs. 28, 34; the
     *             kernel omega xi, not the force kernel: §7 E3)
     *   W_k     = A theta_k^2 / (2 d)
     *           + B / (2 m_k) sum_j omega (xi.eta)^2 / |xi|^2 V_j,
     *
     * A = 3 kappa - 5 mu, B = 15 mu in 3D; A = 2 kappa' - 4 mu, B = 8 mu in
     * 2D (kappa' = lambda + mu with the lambda in use: E / (2 (1 - nu)) in
     * plane stress, kappa + mu / 3 in plane strain). W_k is the LPS energy
     * kappa theta^2 / 2 + (B / (2 m)) sum omega (e^d)^2 V with the
     * linearised extension e = xi.eta / |xi| and e^d = e - theta |xi| / d
     * written out (the discrete m and theta use the same sums, so the
     * identity is exact), positive semi-definite for any Poisson's ratio.
     *
     * The model is the energy E = sum_k V_k W_k (V_k the owner's PD
     * volume) in family-element form (Layout::family_elements): family k's
     * energy acts on its owner and its intact members,
     *
     *   f_j = V_k omega V_j / m_k (A theta_k xi + B (xi.eta) xi / |xi|^2),
     *   f_k = -sum_j f_j,
     *
     * so that the force on a node gathers its own family and the families
     * it belongs to: -V_k times the dual force density of eq. 36 with the
     * variable weighted volume, sum_j omega V_j [A xi (theta_k / m_k +
     * theta_j / m_j) + B (xi.eta) xi / |xi|^2 (1 / m_k + 1 / m_j)]
     * (specs/002 §1.4 "fully consistent variant", §7 E9 (b)). The tangent
     * of family k,
     *
     *   K_ab = V_k [(A / d) c_a (x) c_b
     *              + (B / m_k) sum_j omega V_j n_j (x) n_j
     *                (delta_aj - delta_ak)(delta_bj - delta_bk)],
     *
     * c_j = (d / m_k) omega V_j xi_j, c_k = -sum_j c_j, n_j = xi_j / |xi_j|,
     * couples every pair of the family's nodes through theta (two horizons
     * of columns in the assembled rows). Linear and symmetric; the forces
     * of every family sum to zero. Broken bonds leave m and theta
     * (bonds_changed()); a family without intact bonds carries nothing.
     * One horizon delta = m h for the region (Layout::uniform_horizon),
     * bond volumes as the pairwise models' (pairwise_bond_volumes():
     * cells, or h^dim with Nodal volumes = uniform, the FFT grid's Delta
     * V).
     */
    template <int dim>
    class LPS : public Interface<dim>
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

      /// The least-squares fit of the intact bonds with the weights omega
      /// V_j (the LPS shape tensor sum omega xi (x) xi V_j), for the nodal
      /// stress.
      dealii::Tensor<2, dim>
      displacement_gradient(std::size_t            o,
                            const NodalField<dim> &u) const override;

      double
      nodal_volume(unsigned int k) const override;

      std::vector<std::pair<std::string, double>>
      constants() const override;

      /// theta of owner @p o at @p u (0 without intact bonds).
      double
      dilatation(std::size_t o, const NodalField<dim> &u) const;

      /// m of owner @p o over its intact bonds.
      double
      weighted_volume(std::size_t o) const
      {
        return m[o];
      }

      /// omega(r) of the chosen influence function.
      double
      influence(double r) const;

    private:
      /// m of every family in @p owners over its intact bonds.
      void
      update_weighted_volumes(const std::vector<std::size_t> &owners);

      bool   inverse_distance = true; ///< omega = 1 / r, else 1
      bool   uniform_volumes  = false;
      double dirichlet_layer  = 1.;
      double traction_layer   = 0.;
      double delta = 0., A = 0., B = 0., bulk_modulus = 0.;
      /// Per node: the volume its bonds carry, and V_k^pd / V_k.
      std::vector<double> bond_volume, pd_share;
      /// Per bond (family order): omega V_j, broken or not.
      std::vector<double> bond_weight;
      /// Per owner: the weighted volume over the intact bonds.
      std::vector<double> m;
    };

    /**
     * The constants of the LPS force state for the region's moduli
     * (specs/002 eq. 32): kappa (3D) or the planar kappa' = lambda + mu
     * (2D, lambda* in plane stress), A = 3 kappa - 5 mu, B = 15 mu (3D);
     * A = 2 kappa' - 4 mu, B = 8 mu (2D); and the largest horizon over all
     * ranks. Shared by "lps" and "lps fft"; throws InputError (Material/
     * Poisson's ratio) unless mu > 0 and kappa > 0. Collective.
     */
    struct LpsConstants
    {
      double bulk_modulus = 0., A = 0., B = 0., delta = 0.;
    };

    template <int dim>
    LpsConstants
    lps_constants(const Region<dim> &region);
  } // namespace PDModels
} // namespace pdfem

#endif
