// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/solvers/settings.h>

#include <deal.II/base/parameter_handler.h>

namespace pdfem
{
  namespace Solvers
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    using namespace ParameterTools;

    // --------------------------------------------------------- Linear solver
    void
    Settings::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "direct",
                        Selection("direct|gmres|cg"),
                        "direct (sparse LU), gmres (preconditioned, "
                        "restarted GMRES) or cg (preconditioned conjugate "
                        "gradients: a symmetric operator only, i.e. FE "
                        "alone or a PD model with a symmetric tangent such "
                        "as 'pdlsm energy' or 'rnp'; the collocated 'pdlsm' "
                        "is not symmetric).");
      prm.declare_entry("Direct solver",
                        "mumps",
                        Selection("mumps|klu"),
                        "Amesos package for 'direct': mumps (parallel) or "
                        "klu (serial, gathers on rank 0).");
      prm.declare_entry("Preconditioner",
                        "amg fe",
                        Selection("amg fe|amg|ilu"),
                        "For gmres and cg: 'amg fe' (matrix-free coupled "
                        "operator; "
                        "Trilinos ML algebraic multigrid built from the local "
                        "Q1/P1 stiffness of every cell, PD cells included, "
                        "followed by one block-Jacobi correction with the "
                        "coupled operator), 'amg' (ML built from the "
                        "assembled coupled matrix, kept while bonds break "
                        "until GMRES needs twice its first iteration count) "
                        "or 'ilu' (Ifpack ILU(1) of it). With cg the AMG "
                        "smooths before and after its coarse correction "
                        "and 'amg fe' has no block-Jacobi correction, so "
                        "that the preconditioner is symmetric.");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Double(0.),
                        "gmres, cg: relative residual reduction.");
      prm.declare_entry("Max iterations",
                        "2000",
                        Integer(1),
                        "gmres, cg: iteration limit.");
      prm.declare_entry("GMRES restart",
                        "150",
                        Integer(5, 2000),
                        "gmres: Krylov vectors kept before a restart. A "
                        "restart forgets the search space: on the 3D box, "
                        "30 takes 319 iterations, 150 takes 109 (= no "
                        "restart). Memory: 8 bytes x DoFs x this number.");
      prm.leave_subsection();
    }

    void
    Settings::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Linear solver");
      type           = prm.get("Type");
      direct_solver  = prm.get("Direct solver");
      preconditioner = prm.get("Preconditioner");
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Max iterations");
      restart        = prm.get_integer("GMRES restart");
      prm.leave_subsection();
    }

  } // namespace Solvers
} // namespace pdfem
