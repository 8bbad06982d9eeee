// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_BOND_BASED_H
#define PDFEM_PD_MODELS_BOND_BASED_H

#include <deal.II/base/tensor.h>

namespace pdfem
{
  namespace PDModels
  {
    /**
     * The smooth bond degradation of Hu et al. (specs/003 §1.4, eq. 12,
     * after Hashim et al.):
     *
     *   T(s) = 1                                        s <= s_m
     *        = (1 - tanh(beta (s_m + s_c - 2 s) / (s_m - s_c))) / 2
     *                                                   s_m < s < s_c
     *        = 0                                        s >= s_c,
     *
     * T'(s) = beta / (s_m - s_c) (1 - tanh^2 z) inside (s_m, s_c), 0
     * outside. With beta = 3, T jumps by 2.47e-3 at both ends and
     * T((s_m + s_c) / 2) = 1/2. Without degradation (active = false) T = 1.
     */
    struct BondDegradation
    {
      bool   active   = false;
      double onset    = 0.; ///< s_m
      double critical = 0.; ///< s_c
      double rate     = 3.; ///< beta

      double
      factor(double s) const;

      double
      derivative(double s) const;
    };

    /**
     * The micromodulus c [Pa/m^4 in 3D; per unit thickness in 2D, where
     * nodal volumes are areas] of the bond-based model with horizon
     * @p horizon (specs/003 §1.2): 2D plane stress 9 E / (pi delta^3)
     * (nu = 1/3), plane strain 48 E / (5 pi delta^3) (nu = 1/4), 3D
     * 12 E / (pi delta^4) (nu = 1/4).
     */
    double
    bond_based_micromodulus(double youngs_modulus,
                            double horizon,
                            int    dim,
                            bool   plane_strain);

    /**
     * The micromodulus c = 2 E / (A delta^2) of the one-dimensional
     * bond-based bar of cross-section @p area with horizon @p horizon
     * (specs/003 §1.2; the paper prints 2 E / (pi delta^2 A), a typo: the
     * bar's strain energy density E eps^2 / 2 needs 2 E / (A delta^2)).
     * With bond volumes A dx the bar's interior node then carries
     * E A eps, the bar's force. `Body = uniaxial bar` of the bond-based
     * model (doc/theory.md §13.6).
     */
    double
    bond_based_bar_micromodulus(double youngs_modulus,
                                double horizon,
                                double area);

    /**
     * One bond of the finite-deformation bond-based model (specs/003
     * eqs. 1-4, 13): with xi = x_m - x_k, eta = u_m - u_k, r = xi + eta,
     * L = |xi|, l = |r|, n = r / l and the stretch s = (l - L) / L, the
     * force density on k from m is
     *
     *   t = c T s n,
     *
     * and its derivative with respect to u_m (specs/003 §3.3, eq. 14
     * corrected: the degradation term multiplies the scalar s / l)
     *
     *   dt/du_m = c [(T + s T') / L n n^T + T s / l (I - n n^T)],
     *
     * the axial stiffness (T + s T') c / L and the geometric one T s c / l
     * (negative in compression).
     */
    template <int dim>
    struct BondBasedBond
    {
      static double
      stretch(const dealii::Tensor<1, dim> &xi,
              const dealii::Tensor<1, dim> &eta);

      /// t = c_T s n with c_T = c T (the degraded micromodulus).
      static dealii::Tensor<1, dim>
      force(const dealii::Tensor<1, dim> &xi,
            const dealii::Tensor<1, dim> &eta,
            double                        c_T);

      /// dt/du_m with @p c, T and T' (0 for a bond that is not loading).
      static dealii::Tensor<2, dim>
      stiffness(const dealii::Tensor<1, dim> &xi,
                const dealii::Tensor<1, dim> &eta,
                double                        c,
                double                        T,
                double                        dT);
    };
  } // namespace PDModels
} // namespace pdfem

#endif
