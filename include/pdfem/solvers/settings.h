// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_SETTINGS_H
#define PDFEM_SOLVERS_SETTINGS_H

#include <array>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  namespace Solvers
  {
    /** `subsection Linear solver`. */
    struct Settings
    {
      std::string  type           = "direct"; // direct | gmres | cg | auto
      std::string  direct_solver  = "mumps";  // mumps | klu
      std::string  preconditioner = "amg fe"; // amg fe | pd model | amg | ilu
      double       tolerance      = 1e-10;    // relative residual (gmres)
      unsigned int max_iterations = 2000;
      unsigned int restart        = 150; // gmres: Krylov vectors kept
      /// direct: a changed matrix is first solved by GMRES preconditioned
      /// with the factors of its earlier values (LinearSolver).
      bool reuse_factorization = true;
      /// Type = auto, resolved by resolve(): the system chooses between the
      /// matrix-free and the direct path by their measured costs
      /// (SolverChoice), starting as type says, for choice_reason.
      bool        automatic      = false;
      bool        choose_by_cost = false;
      std::string choice_reason;

      /// A Krylov method (gmres or cg), not a factorisation.
      bool
      iterative() const
      {
        return type != "direct";
      }

      /// Conjugate gradients: the operator must be symmetric.
      bool
      conjugate_gradients() const
      {
        return type == "cg";
      }

      /// The coupled operator is applied without assembling it ('amg fe',
      /// 'pd model').
      bool
      matrix_free() const
      {
        return iterative() &&
               (preconditioner == "amg fe" || preconditioner == "pd model");
      }

      /**
       * Type = auto made concrete for a run:
       * - a nonlinear PD model that applies its symmetric tangent to
       *   vectors and bounds its rows without assembling it (@p
       *   tangent_products: bond based) gets matrix-free CG ('amg fe'),
       *   which goes over to the direct path for good where CG meets
       *   negative curvature, fails, or finds the tangent indefinite at a
       *   stability check (theory.md §13.7);
       * - another nonlinear PD model, or a driver that works with the
       *   assembled matrix (Newmark, dynamic relaxation), gets the direct
       *   path;
       * - a PD model of forces only (no tangent, PDModels::Layout::tangent
       *   false) gets matrix-free CG ('amg fe', which needs no PD tangent
       *   with CG, or the model's own 'pd model' where it has one) and no
       *   choice by cost: there is no matrix to factorise;
       * - otherwise matrix-free GMRES ('amg fe'), with choose_by_cost set so
       *   that the system may go over to a direct factorisation where that
       *   is cheaper.
       * Other types are returned as they are.
       */
      Settings
      resolve(bool nonlinear_model,
              bool driver_needs_matrix,
              bool forces_only_model    = false,
              bool model_preconditioner = false,
              bool tangent_products     = false) const;

      /// Preconditioner = pd model: the PD model's own approximate inverse
      /// (matrix-free; no auxiliary matrix).
      bool
      model_preconditioner() const
      {
        return iterative() && preconditioner == "pd model";
      }

      /// Matrix-free CG: solves with products of the operator alone (the
      /// 'amg fe' preconditioner without its block-Jacobi correction, or
      /// 'pd model'), so that a linear, symmetric PD model of forces only
      /// can be solved.
      bool
      solves_with_products_only() const
      {
        return matrix_free() && conjugate_gradients();
      }

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

  } // namespace Solvers
} // namespace pdfem

#endif
