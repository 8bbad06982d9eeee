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
      std::string  type           = "direct"; // direct | gmres | cg
      std::string  direct_solver  = "mumps";  // mumps | klu
      std::string  preconditioner = "amg fe"; // amg fe | amg | ilu
      double       tolerance      = 1e-10;    // relative residual (gmres)
      unsigned int max_iterations = 2000;
      unsigned int restart        = 150; // gmres: Krylov vectors kept

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

      /// The coupled operator is applied without assembling it ('amg fe').
      bool
      matrix_free() const
      {
        return iterative() && preconditioner == "amg fe";
      }

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file);
    };

  } // namespace Solvers
} // namespace pdfem

#endif
