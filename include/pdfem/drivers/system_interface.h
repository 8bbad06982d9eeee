// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_SYSTEM_INTERFACE_H
#define PDFEM_DRIVERS_SYSTEM_INTERFACE_H

#include <stdexcept>

namespace dealii
{
  namespace TrilinosWrappers
  {
    namespace MPI
    {
      class Vector;
    }
  } // namespace TrilinosWrappers
} // namespace dealii

namespace pdfem
{
  namespace Drivers
  {
    /**
     * What a load or time driver sees of a discretised problem: vectors in,
     * vectors out, no dimension. The sign convention is the same everywhere
     * in pdfem: internal force f_int(u), residual r = f_ext - f_int, tangent
     * K = d f_int / d u, Newton step K du = r.
     *
     * The load factor t scales the prescribed displacements and loads (it is
     * the variable t of their expressions).
     */
    class SystemInterface
    {
    public:
      using Vector = dealii::TrilinosWrappers::MPI::Vector;

      virtual ~SystemInterface() = default;

      /// Give @p v the parallel layout of the unknowns (zero).
      virtual void
      initialize_vector(Vector &v) const = 0;

      /// Set the prescribed DoFs of @p u to their values at load factor @p t.
      virtual void
      apply_dirichlet(Vector &u, double t) const = 0;

      /**
       * r = f_ext(t) - f_int(u) with the prescribed (and decoupled) DoFs set
       * to zero; if @p assemble_tangent, K(u) is wanted for the next
       * solve_linear() (which may assemble it then, so that a residual that
       * only confirms convergence costs no assembly). Records the
       * reaction forces. Returns |r|.
       */
      virtual double
      residual(const Vector &u, double t, Vector &r, bool assemble_tangent) = 0;

      /// The force scale of the last residual() call: max(|f_ext| over the
      /// free DoFs, |f_int| over all DoFs, reactions included).
      virtual double
      force_scale() const = 0;

      /// Solve K du = r with the last assembled K; returns the iterations.
      virtual unsigned int
      solve_linear(Vector &du, const Vector &r) = 0;

      /**
       * The same, where an iterative solver may stop once |r - K du| is
       * below @p allowed_residual, even before its own relative tolerance:
       * a Newton step needs no more. By default the same as solve_linear().
       */
      virtual unsigned int
      solve_linear_within(Vector &du, const Vector &r, double allowed_residual)
      {
        (void)allowed_residual;
        return solve_linear(du, r);
      }

      /**
       * The Gershgorin bound of every owned row of the tangent K of the
       * last residual() that asked for it (as solve_linear() uses it):
       * @p bounds_i = sum_j |K_ij| (held rows: their diagonal). Dynamic
       * relaxation's fictitious density (DynamicRelaxation). By default
       * not provided (std::logic_error).
       */
      virtual void
      stiffness_row_bounds(Vector &bounds)
      {
        (void)bounds;
        throw std::logic_error("this system gives no bounds of its tangent");
      }
    };
  } // namespace Drivers
} // namespace pdfem

#endif
