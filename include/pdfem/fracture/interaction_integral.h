// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FRACTURE_INTERACTION_INTEGRAL_H
#define PDFEM_FRACTURE_INTERACTION_INTEGRAL_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/fe/elastic_material.h>
#include <pdfem/mesh/cracks.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <vector>

namespace pdfem
{
  namespace Fracture
  {
    /** Stress-intensity factors and J at one crack tip. */
    struct StressIntensity
    {
      double K_I  = 0.; // [Pa sqrt(m)]
      double K_II = 0.; // [Pa sqrt(m)]
      double J    = 0.; // [J/m^2]
    };

    /**
     * The interaction integral in its equivalent domain form (Moran & Shih
     * 1987; Yau, Wang & Corten 1980), in the crack-tip axes (x1 along the
     * crack, x2 normal to it):
     *
     *   I^(M) = int_A [ sigma_ij du^M_i/dx1 + sigma^M_ij du_i/dx1
     *                   - sigma_ik eps^M_ik delta_1j ] dq/dx_j dA,
     *   K_M   = E' I^(M) / 2,   E' = E (plane stress), E / (1 - nu^2),
     *   J     = int_A [ sigma_ij du_i/dx1 - W delta_1j ] dq/dx_j dA,
     *
     * with the auxiliary fields (u^M, sigma^M) the Williams near-tip fields of
     * unit K_M (kappa = (3 - nu)/(1 + nu) or 3 - 4 nu; sigma^M = C : eps^M,
     * so that they are consistent with the material law in use) and q a
     * smooth weight: 1 for r <= r_in, 0 for r >= r_out, the cubic smoothstep
     * in between. dq/dx vanishes near the tip, so the least accurate fields
     * there do not enter. specs/004 §3.1 gives the peer's line-contour form
     * of the same integral; the domain form does not depend on how the
     * contour meets the elements.
     *
     * The fields: in FE cells, grad u of the Q1/P1 interpolant; in PD cells,
     * the PDLSM nodal gradient interpolated with the cell's shape functions
     * over the vertices that the quadrature point "sees" (the segment between
     * them meets no crack), so that values from the two faces of a crack are
     * never mixed. Stresses are C : sym(grad u). Everything is computed from
     * replicated nodal results: every rank gets the same numbers.
     *
     * 2D only (3D straight fronts: not yet; compute() throws there).
     */
    template <int dim>
    class InteractionIntegral
    {
    public:
      InteractionIntegral(const Coupling::CoupledSystem<dim> &system,
                          const FE::ElasticMaterial          &material);
      ~InteractionIntegral();

      /**
       * K_I, K_II and J at @p tip, the crack running towards the tip along
       * @p direction; the domain is the annulus r_in <= r <= r_out (q
       * varies there); @p cracks decide which vertices a point sees.
       */
      StressIntensity
      compute(const Coupling::NodalResults<dim>   &results,
              const dealii::Point<dim>            &tip,
              const dealii::Tensor<1, dim>        &direction,
              double                               r_in,
              double                               r_out,
              const std::vector<Mesh::Crack<dim>> &cracks) const;

      /// The size of the cell nearest to @p p: measure^(1/dim).
      double
      element_size(const dealii::Point<dim> &p) const;

      /// Is @p p inside the mesh (inside one of its cells)?
      bool
      inside(const dealii::Point<dim> &p) const;

      /// Is @p p inside a PD cell?
      bool
      inside_pd_region(const dealii::Point<dim> &p) const;

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };
  } // namespace Fracture
} // namespace pdfem

#endif
