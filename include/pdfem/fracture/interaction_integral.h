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
    /** Stress-intensity factors and J at one crack tip or front point. */
    struct StressIntensity
    {
      double K_I   = 0.; // [Pa sqrt(m)]
      double K_II  = 0.; // [Pa sqrt(m)]
      double K_III = 0.; // [Pa sqrt(m)], 3D only (0 in 2D)
      double J     = 0.; // [J/m^2]
    };

    /**
     * A straight crack front (3D): the segment [begin, end] of the boundary
     * of a crack surface that lies inside the body (doc/theory.md §9.2).
     * The front axes: x1 = @p direction (in the crack plane, normal to the
     * front, away from the crack), x3 = (end - begin)/|end - begin| and
     * x2 = x3 x x1 (normal to the crack plane), right-handed. In 2D a tip is
     * a front of one point (begin = end).
     */
    template <int dim>
    struct Front
    {
      dealii::Point<dim>     begin, end;
      dealii::Tensor<1, dim> direction;
      /// x3, unit (zero in 2D).
      dealii::Tensor<1, dim>
      tangent() const;
      /// The length of the front.
      double
      length() const;
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
     * In 3D, at a point s_k of a straight front (compute_front()), the
     * same integrands in the front axes (x1 normal to the front in the crack
     * plane, x2 normal to the crack plane, x3 along the front) over a volume,
     * with q(x) = q_r(r) q_s(x3 - s_k), r = (x1^2 + x2^2)^(1/2), q_s the
     * bump cos^2(pi d / 2w) of half-width w, divided by the virtual crack
     * advance int q_s ds (doc/theory.md §9.2, eq. 9.4-9.7; Shih, Moran &
     * Nakamura 1986; Walters, Paulino & Dodds 2005). The auxiliary fields
     * are the plane-strain Williams fields and the mode-III field, with
     * K_M = E' I^(M)/2 (E' = E/(1 - nu^2)) and K_III = mu I^(III). For a
     * straight front and sigma^M = C : eps^M the integrand is
     * divergence-free, so no volume term is left.
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

      /**
       * K_I, K_II, K_III and J at the point @p s (0 <= s <= length) of the
       * straight @p front (3D, eq. 9.4-9.7): q_r is the annulus r_in..r_out
       * of compute(), q_s the bump of half-width @p half_width. 2D: the tip
       * @p front.begin, as compute().
       */
      StressIntensity
      compute_front(const Coupling::NodalResults<dim>   &results,
                    const Front<dim>                    &front,
                    double                               s,
                    double                               r_in,
                    double                               r_out,
                    double                               half_width,
                    const std::vector<Mesh::Crack<dim>> &cracks) const;

      /**
       * The straight fronts of @p cracks (3D, triangles): the edges of the
       * crack surfaces used by one triangle only, whose outside (a point
       * just beyond the edge in the crack plane) is inside the body, joined
       * when they continue each other on a line. Empty in 2D.
       */
      std::vector<Front<dim>>
      straight_fronts(const std::vector<Mesh::Crack<dim>> &cracks) const;

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
