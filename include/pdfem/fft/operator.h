// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FFT_OPERATOR_H
#define PDFEM_FFT_OPERATOR_H

#include <pdfem/fft/grid.h>

#include <cstddef>
#include <vector>

namespace pdfem
{
  namespace FFT
  {
    /**
     * Which count the damage index divides by (specs/002 §1.6, §7 E10):
     * the whole discrete horizon (the paper's eq. 65: d = 1 - lambda
     * (omega_0 * lambda) / beta_0) or the bonds the body offers the node
     * (PeriFast: beta_0 -> chi_B (omega_0 * chi_B), so that an intact body
     * has d = 0 at its free surfaces too).
     */
    enum class DamageNormalisation
    {
      full_horizon,
      body
    };

    /**
     * A PD operator on a uniform periodic grid with embedded constraints
     * (specs/002 §2.5): the body mask chi_B and the integrity lambda
     * (specs/002 eq. 44) give each node the weight beta = chi_B lambda,
     * and a bond x-x' acts with the weight beta(x) beta(x'). With
     * xi = x' - x, eta = u(x') - u(x) and the midpoint quadrature
     * (specs/002 §2.3), the internal force density is
     *
     *   L(x) = beta(x) sum_{x' in H_x} beta(x') f(xi, eta) Delta V,
     *
     * with f of the model (Material::model):
     *
     * - linear bond based (specs/002 eq. 17): f = C(xi) eta,
     *   C = alpha omega xi (x) xi / |xi|^2;
     * - nonlinear bond based (specs/002 eq. 21):
     *   f = alpha omega / (2 |xi|^2) (2 xi.eta + eta.eta) (xi + eta);
     * - LPS (specs/002 eq. 36 with the variable weighted volume of §1.4):
     *   f = A omega xi (theta / m + theta' / m')
     *     + B omega (xi.eta) xi / |xi|^2 (1 / m + 1 / m'),
     *   m(x) = beta(x) sum beta' omega |xi|^2 Delta V,
     *   theta(x) = (dim / m(x)) beta(x) sum beta' omega xi.eta Delta V,
     *   A = 3 kappa - 5 mu, B = 15 mu in 3D; A = 2 kappa' - 4 mu, B = 8 mu
     *   in 2D (1 / m := 0 where m = 0).
     *
     * Two implementations give the same numbers to round-off: FftOperator
     * (convolutions by FFT, O(N log N) per evaluation, O(N) memory) and
     * DirectOperator (the neighbour sum, O(N M) for M bonds per node).
     *
     * "N values" below: the grid's N nodes, or the N = Slab::n_nodes()
     * nodes of the rank's slab for an FftOperator distributed over MPI
     * ranks (fft_operator.h).
     */
    template <int dim>
    class Operator
    {
    public:
      virtual ~Operator() = default;

      /// The grid and the material the operator was made for.
      const Grid<dim> &
      grid() const;

      const Material &
      material() const;

      /**
       * Sets the body mask chi_B and the integrity lambda (N values each,
       * normally 0 or 1; an empty vector means 1 everywhere). The fields
       * that depend on the masks only (the convolutions of beta with the
       * kernels, m) are computed here, once.
       */
      virtual void
      set_masks(const std::vector<double> &body,
                const std::vector<double> &integrity) = 0;

      /// L(u): @p force gets dim N values (resized).
      virtual void
      apply(const std::vector<double> &u, std::vector<double> &force) = 0;

      /**
       * LPS only: the nonlocal dilatation theta(u) (N values; 0 where
       * beta = 0). Throws for the bond-based models.
       */
      virtual void
      dilatation(const std::vector<double> &u, std::vector<double> &theta) = 0;

      /**
       * The strain energy density W(u) in the paper's convention (specs/002
       * eqs. 41, 47; §7 E11), twice the physical one so that W_c = G_0 /
       * delta: the linear bond-based model W = 1/2 beta sum beta' eta.C eta
       * Delta V; LPS W = beta (A / dim theta^2 + B / m sum beta' omega
       * (xi.eta)^2 / |xi|^2 Delta V). Not available for the nonlinear
       * bond-based model (throws).
       */
      virtual void
      energy_density(const std::vector<double> &u, std::vector<double> &W) = 0;

      /**
       * The damage index (specs/002 eq. 65) of the current masks: 0 where
       * chi_B = 0, else d = 1 - beta(x) sum' beta(x') / D(x), sum' over the
       * discrete horizon, D its size (full_horizon) or sum' chi_B(x')
       * (body). A node without bonds in the body has d = 1 - beta.
       */
      virtual void
      damage(std::vector<double> &d, DamageNormalisation normalisation) = 0;

      /**
       * LPS only: the weighted volume m(x) of the current masks (N values).
       */
      virtual const std::vector<double> &
      weighted_volume() const = 0;

      /**
       * The bytes per grid node the operator holds (kernels, mask fields,
       * work space), the caller's fields u and L not included; per node of
       * the rank's slab for a distributed FftOperator.
       */
      virtual double
      bytes_per_node() const = 0;

    protected:
      Operator(const Grid<dim> &grid, const Material &material);

      const Grid<dim> grid_;
      const Material  material_;
    };

    /**
     * The integrity update of the energy criterion (specs/002 eqs. 43, 63):
     * lambda(x) = 0 where W(x) > W_c, unchanged elsewhere (irreversible).
     * Returns the number of nodes that failed in this call.
     */
    std::size_t
    update_integrity(const std::vector<double> &W,
                     double                     critical_energy_density,
                     std::vector<double>       &integrity);

    /// W_c = G_0 / delta (specs/002 eqs. 50-51, the paper's W convention).
    double
    critical_energy_density(double fracture_energy, double horizon);
  } // namespace FFT
} // namespace pdfem

#endif
