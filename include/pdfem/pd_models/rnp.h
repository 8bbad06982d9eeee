// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_RNP_H
#define PDFEM_PD_MODELS_RNP_H

#include <deal.II/base/tensor.h>

namespace pdfem
{
  namespace PDModels
  {
    /**
     * The RNP bond potential g(r) = C (1 - exp(-beta r^2)) (specs/000 §1.2,
     * eq. (10) corrected: the paper prints exp(-beta r), which is not even in
     * r and gives a force at zero strain). g = h(r^2) with the concave
     * h(s) = C (1 - exp(-beta s)); g(inf) = C is the energy of a fully
     * softened bond, g''(0) = 2 C beta the initial stiffness, and the
     * inflection point (peak bond force, onset of softening) is
     * r_c = 1 / sqrt(2 beta).
     */
    class RNPPotential
    {
    public:
      RNPPotential(double C, double beta);

      double
      g(double r) const;
      /// g'(r) = 2 C beta r exp(-beta r^2).
      double
      dg(double r) const;
      /// g''(r) = 2 C beta (1 - 2 beta r^2) exp(-beta r^2).
      double
      d2g(double r) const;
      /// g'''(r) = 4 C beta^2 r (2 beta r^2 - 3) exp(-beta r^2).
      double
      d3g(double r) const;
      /// The inflection point r_c = 1 / sqrt(2 beta).
      double
      r_c() const;

      double C;
      double beta;
    };

    /** The influence function J(|xi| / epsilon) on [0, 1]. */
    enum class RNPInfluence
    {
      constant, ///< J = 1 (the paper's prototype)
      linear    ///< J = 1 - r
    };

    /**
     * Normalisation of the bond force: `paper` is eq. (26)/(27),
     * g'(sqrt|xi| S) / sqrt|xi|, the one the calibration below holds for;
     * `prototype` is the Python prototype's g'(sqrt|xi| S) / |xi|
     * (specs/000 §2.4), kept to regress against its results.
     */
    enum class RNPForceScaling
    {
      paper,
      prototype
    };

    /** Material and discretisation constants of the RNP model. */
    struct RNPSettings
    {
      double          C         = 1.;
      double          beta      = 1.;
      double          horizon   = 1.; // epsilon
      RNPInfluence    influence = RNPInfluence::constant;
      RNPForceScaling scaling   = RNPForceScaling::paper;
    };

    /// M_d = int_0^1 J(rho) rho^d d rho (specs/000 §1.5).
    double
    rnp_moment(RNPInfluence influence, int dim);

    /// omega_d: the volume of the unit ball (omega_0 = 1, omega_1 = 2, ...).
    double
    unit_ball_volume(int dim);

    /**
     * The product C beta that gives Young's modulus @p E in @p dim
     * dimensions (specs/000 §1.5, corrected). Homogeneous small strain gives
     * the continuum energy density
     *   Psi = C beta M_d / (d + 2) [(tr eps)^2 + 2 eps : eps],
     * so lambda = mu = 2 C beta M_d / (d + 2) (d >= 2) and E = 2 C beta M_1
     * in 1D. Hence (J = 1): 1D E = C beta; 2D E = 4 C beta / 9 with
     * nu = 1/3 (plane stress; plane strain has E = 5 mu / 2 with
     * nu = 1/4); 3D E = C beta / 4 with nu = 1/4. @p plane_strain only
     * matters in 2D.
     */
    double
    rnp_c_beta(double E, RNPInfluence influence, int dim, bool plane_strain);

    /// The Poisson's ratio a bond-based model has: 1/3 in 2D plane stress,
    /// 1/4 in 3D and 2D plane strain (0 in 1D).
    double
    rnp_poissons_ratio(int dim, bool plane_strain);

    /**
     * C from the fracture energy: G_c = 2 (omega_{d-1} / omega_d) C M_d
     * (J = 1: 1D G_c = C / 2, 2D 4 C / (3 pi), 3D 3 C / 8; the paper's
     * (39) C = 16/6 K_IC^2 / E is the 3D formula).
     */
    double
    rnp_c_from_fracture_energy(double G_c, RNPInfluence influence, int dim);

    /**
     * One RNP bond (specs/000 eqs. (5), (8), (11)-(12), (27), (34)
     * corrected; specs/001 eqs. (6), (15)), in pdfem's sign convention: the
     * nodal internal force of node i is
     *   f_int,i = -V_i sum_j c J(|xi|/eps) phi(|xi|) g'(sqrt|xi| S) e V_j,
     * c = 2 / (eps^(d+1) omega_d), phi = |xi|^-1/2 (paper) or |xi|^-1
     * (prototype), S = (u_j - u_i) . e / |xi|, e = xi / |xi|. This is the
     * gradient of the discrete energy sum_i V_i sum_j |xi| W(S) V_j, so the
     * tangent K = d f_int / d u is its (symmetric) Hessian, with blocks
     *   K_ij = -V_i V_j c J phi(|xi|) sqrt|xi| g''(sqrt|xi| S) / |xi| e(x)e,
     *   K_ii = -sum_j K_ij
     * (the paper's (33) has the opposite sign on K_ii and its tangent omits
     * V_j; its prototype's is not the Jacobian of its own force).
     */
    template <int dim>
    class RNP
    {
    public:
      explicit RNP(const RNPSettings &settings);

      /// The bond strain S = eta . xi / |xi|^2, eta = u_j - u_i.
      static double
      strain(const dealii::Tensor<1, dim> &xi,
             const dealii::Tensor<1, dim> &eta);

      /// r = sqrt|xi| S: the argument of g.
      static double
      r(const dealii::Tensor<1, dim> &xi, const dealii::Tensor<1, dim> &eta);

      /**
       * The pairwise force density on i from j per unit volume of both:
       * t = c J phi g'(sqrt|xi| S) e, so that f_int,i = -V_i sum_j t V_j.
       */
      dealii::Tensor<1, dim>
      force(const dealii::Tensor<1, dim> &xi,
            const dealii::Tensor<1, dim> &eta) const;

      /**
       * a(xi, eta) = d t / d eta = c J phi sqrt|xi| g'' / |xi| e (x) e, so
       * that K_ij = -V_i V_j a, K_ii = V_i sum_j a V_j.
       */
      dealii::Tensor<2, dim>
      stiffness(const dealii::Tensor<1, dim> &xi,
                const dealii::Tensor<1, dim> &eta) const;

      /// |S| sqrt|xi| / r_c: 1 where the bond reaches its peak force
      /// (specs/000 (18) corrected).
      double
      damage(const dealii::Tensor<1, dim> &xi,
             const dealii::Tensor<1, dim> &eta) const;

      /// J(|xi| / eps) (0 outside the horizon).
      double
      influence(double length) const;

      const RNPSettings &
      settings() const
      {
        return s;
      }
      const RNPPotential &
      potential() const
      {
        return g;
      }

    private:
      RNPSettings  s;
      RNPPotential g;
      double       c; // 2 / (eps^(d+1) omega_d)
    };
  } // namespace PDModels
} // namespace pdfem

#endif
