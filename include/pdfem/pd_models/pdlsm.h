// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_PDLSM_H
#define PDFEM_PD_MODELS_PDLSM_H

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  namespace PDModels
  {
    template <int dim>
    struct Region;

    /// Declare Peridynamics/Weight factor (a in the Gaussian weight of the
    /// PDLSM fits), shared by the models that use it.
    void
    declare_weight_factor(dealii::ParameterHandler &prm);

    /// Read Peridynamics/Weight factor from @p prm (inside `Peridynamics`);
    /// InputError naming @p file unless it is positive.
    double
    parse_weight_factor(dealii::ParameterHandler &prm, const std::string &file);

    /// The work space of one family's fit: its bonds xi, their members'
    /// volumes, the weights a and b, and the bonds' indices. One per
    /// thread in fit_every_family().
    template <int dim>
    struct FitWorkspace
    {
      /// xi, volume and bond of family @p o of @p region: all its bonds,
      /// or its intact ones alone (@p intact_only).
      void
      gather(const Region<dim> &region, std::size_t o, bool intact_only);

      std::vector<dealii::Tensor<1, dim>>          xi, a;
      std::vector<double>                          volume;
      std::vector<dealii::SymmetricTensor<2, dim>> b;
      std::vector<std::size_t>                     bond;
    };

    /**
     * Fit every family of @p region with @p fit(o, workspace) (false: the
     * family cannot carry it). The families run in chunks on the threads
     * of ThreadTeam::shared(), each thread with a workspace of its own, so
     * @p fit may write family o's own data (its bonds' and owner's
     * entries) and nothing shared; each family's fit is computed alone,
     * so the weights do not depend on the number of threads.
     *
     * Collective: if any family on any rank cannot, an InputError naming
     * Peridynamics/Horizon factor counts them, shows the first one (the
     * lowest family index, as in a loop over them), names the fit
     * (@p fit_name, with the weight factor @p a) and gives @p advice.
     */
    template <int dim>
    void
    fit_every_family(
      const Region<dim>                                           &region,
      const std::function<bool(std::size_t, FitWorkspace<dim> &)> &fit,
      const std::string                                           &fit_name,
      double                                                       a,
      const std::string                                           &advice);

    /**
     * Peridynamic least squares minimisation (PDLSM; Madenci, Dorduncu & Gu,
     * CMAME 348 (2019) 846; as coupled with FE by Liu & Xin, EFM 252 (2021)
     * 107862 and the PDLSM-FEM manual, eqs. 11-22; specs/004 §1.1-1.2).
     *
     * For a node x_k with family members x_m (bonds xi_m = x_m - x_k, volumes
     * V_m) a second-order Taylor expansion is fitted by weighted least
     * squares with the Gaussian weight omega_m = exp(-(|xi_m| / (a delta))^2):
     *
     *   f(x_m) - f(x_k) ~ p(xi_m) . D,  D = [grad f, second derivatives],
     *   p = [xi_1, xi_2, xi_1^2/2, xi_2^2/2, xi_1 xi_2]            (2D),
     *   p = [xi_i, xi_i^2/2 (i=1..3), xi_1 xi_2, xi_2 xi_3, xi_3 xi_1] (3D).
     *
     * The normal equations M D = sum_m omega_m V_m p_m (f_m - f_k) with the
     * symmetric M = sum_m omega_m V_m p_m p_m^T = R^T R give the per-bond
     * weights
     *
     *   grad f(x_k)     = sum_m a_m (f_m - f_k),
     *   d2f/dx_i dx_j   = sum_m b_m,ij (f_m - f_k).
     *
     * (The papers write A = sum omega xi_hat p^T, which is not symmetric;
     * since xi_hat = S p with S = diag(1, 1, 2, 2, 1) (2D), A^-1 xi_hat =
     * M^-1 p and the weights are the same.) M is never formed: a Householder
     * QR of W^1/2 P in coordinates scaled by delta gives R, with half the
     * condition number in the exponent, and detects a family that cannot
     * carry the fit (too few, or coplanar/collinear, intact bonds).
     *
     * With the isotropic law sigma = lambda tr(eps) I + 2 mu eps, the PD
     * internal force density L = div sigma at x_k is
     *
     *   L_k = sum_m G_m (u_m - u_k),  G_m = (lambda + mu) b_m + mu tr(b_m) I,
     *
     * (manual eq. 19-21; plane stress uses lambda* = E nu / (1 - nu^2)), and
     * the nonlocal stress at x_k is sigma_k = C : sym(sum_m (u_m - u_k) (x)
     * a_m). Linear displacement fields are reproduced exactly (L = 0, exact
     * stress): the basis contains them.
     */
    template <int dim>
    class PDLSM
    {
    public:
      /// Number of Taylor coefficients: 5 in 2D, 9 in 3D.
      static constexpr unsigned int n_coefficients = dim == 2 ? 5 : 9;

      /**
       * @p lambda, @p mu: the Lame constants in use (plane stress: lambda*);
       * @p weight_factor: a in the Gaussian weight.
       */
      PDLSM(double lambda, double mu, double weight_factor);

      /**
       * Weights a_m (gradient) and b_m (second derivatives) for one family:
       * bonds @p xi, member volumes @p volume, horizon @p delta of the owner.
       * Returns false if the family cannot carry the second-order fit.
       */
      bool
      compute_weights(const std::vector<dealii::Tensor<1, dim>>    &xi,
                      const std::vector<double>                    &volume,
                      double                                        delta,
                      std::vector<dealii::Tensor<1, dim>>          &a,
                      std::vector<dealii::SymmetricTensor<2, dim>> &b) const;

      /// G_m = (lambda + mu) b_m + mu tr(b_m) I: the block of L_k on u_m.
      dealii::Tensor<2, dim>
      divergence_block(const dealii::SymmetricTensor<2, dim> &b) const;

      /**
       * The block of the traction sigma_k s on u_m, where s = int N_k n dS is
       * the node's share of a boundary's area vector and a = a_m:
       * T(i, j) = lambda s_i a_j + mu (delta_ij s.a + s_j a_i).
       */
      dealii::Tensor<2, dim>
      traction_block(const dealii::Tensor<1, dim> &s,
                     const dealii::Tensor<1, dim> &a) const;

      /// sigma = lambda tr(eps) I + 2 mu eps with eps = sym(grad_u).
      dealii::SymmetricTensor<2, dim>
      stress(const dealii::Tensor<2, dim> &grad_u) const;

    private:
      double lambda;
      double mu;
      double weight_factor;
    };
  } // namespace PDModels
} // namespace pdfem

#endif
