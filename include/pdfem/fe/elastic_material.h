// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FE_ELASTIC_MATERIAL_H
#define PDFEM_FE_ELASTIC_MATERIAL_H

#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class FEValues;
}

namespace pdfem
{
  namespace FE
  {
    /**
     * Isotropic linear elasticity, sigma = lambda tr(eps) I + 2 mu eps, with
     * mu = E / (2 (1 + nu)) and
     *   lambda = E nu / ((1 + nu)(1 - 2 nu))  (3D and plane strain),
     *   lambda = E nu / (1 - nu^2)            (plane stress: the in-plane
     *                                          law with sigma_zz = 0).
     * Plane strain output adds sigma_zz = nu (sigma_xx + sigma_yy).
     */
    struct ElasticMaterial
    {
      double youngs_modulus = 0.;
      double poissons_ratio = 0.;
      double density        = 0.;
      bool   plane_stress   = false; // only meaningful in 2D
      double thickness      = 1.;    // 2D: forces are reported for it

      /// lambda in use (lambda* in plane stress).
      double
      lambda() const;
      /// mu = E / (2 (1 + nu)).
      double
      mu() const;
    };

    /**
     * The elasticity stiffness of one cell, the FE cell term of the
     * coupled system (Liu & Xin 2021, eq. 26):
     *
     *   K_ij = int_cell lambda div(phi_i) div(phi_j)
     *                   + 2 mu eps(phi_i) : eps(phi_j) dx,
     *
     * by the quadrature of @p fv (gradients and JxW), for a primitive
     * vector element (Q1^dim, P1^dim); row-major n x n into @p K.
     */
    template <int dim>
    void
    cell_stiffness(const dealii::FEValues<dim, dim> &fv,
                   const ElasticMaterial            &material,
                   std::vector<double>              &K);
  } // namespace FE
} // namespace pdfem

#endif
