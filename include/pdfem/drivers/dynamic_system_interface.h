// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_DYNAMIC_SYSTEM_INTERFACE_H
#define PDFEM_DRIVERS_DYNAMIC_SYSTEM_INTERFACE_H

#include <pdfem/drivers/system_interface.h>

#include <vector>

namespace pdfem
{
  namespace Drivers
  {
    /**
     * What a time integrator sees of a discretised problem, on top of the
     * static SystemInterface: the semi-discrete equation of motion
     * (Liu & Xin, EFM 2021, eq. 27; specs/004 §1.3)
     *
     *   M a + f_int(u) = f_ext(t),
     *
     * with f_int evaluated matrix-free (FE cells and PD families directly),
     * a lumped mass M (one value per DoF) and, for implicit schemes, an
     * effective matrix K_N = c_m M + c_k K that is factorised (or
     * preconditioned) once and reused while K does not change.
     *
     * "Held" DoFs are those the integrator does not solve for: prescribed
     * (Dirichlet, t is physical time) and decoupled PD nodes (no intact
     * bond, no FE cell: held where they are).
     */
    class DynamicSystemInterface : public SystemInterface
    {
    public:
      /// The lumped mass of every owned DoF (FE row-sum lumping over the FE
      /// cells plus rho V_k^pd from the PD cells; specs/004 §1.3).
      virtual const Vector &
      lumped_mass() = 0;

      /// @p f = f_int(@p u) at every owned DoF (held ones included; no
      /// elimination). Linear in u for the PDLSM-FE problem.
      virtual void
      internal_force(const Vector &u, Vector &f) = 0;

      /// @p f = f_ext(@p t) (tractions and body force at time t).
      virtual void
      external_force(double t, Vector &f) = 0;

      /// Owned-local indices of the held DoFs (changes when bonds break).
      virtual const std::vector<unsigned int> &
      held_dofs() const = 0;

      /**
       * Assemble K_N = @p mass_factor M + @p stiffness_factor K(current
       * bonds) with the held rows and columns eliminated (unit-scaled
       * diagonal there), M lumped or consistent (FE cells consistent, PD
       * nodes rho V), and factorise it (direct solver) or build its
       * preconditioner (GMRES). Later solve_effective() calls reuse it.
       */
      virtual void
      factorize_effective(double mass_factor,
                          double stiffness_factor,
                          bool   consistent_mass) = 0;

      /// Solve K_N x = b with the last factorize_effective(); returns the
      /// linear iterations (1 for a direct solver).
      virtual unsigned int
      solve_effective(Vector &x, const Vector &b) = 0;

      /// y = M x with the mass of the last factorize_effective() call
      /// (lumped if none), held rows and columns eliminated (lumped value on
      /// the diagonal there).
      virtual void
      mass_vmult(Vector &y, const Vector &x) = 0;

      /// @p x = values in [-1, 1] that look random from node to node but
      /// depend only on the node positions and components, so the same on
      /// any number of ranks (start vector of the power iteration).
      virtual void
      pseudo_random(Vector &x) const = 0;

      /// The width of a 2D body (forces and energies are per unit thickness;
      /// reports multiply by it); 1 in 3D.
      virtual double
      thickness() const = 0;

      /// The strain energy the model released at fixed u when it accepted
      /// the last state without breaking bonds (PDModels::Interface::
      /// released_energy(); per unit thickness in 2D), to be booked as
      /// dissipated. By default 0.
      virtual double
      released_energy() const
      {
        return 0.;
      }
    };
  } // namespace Drivers
} // namespace pdfem

#endif
