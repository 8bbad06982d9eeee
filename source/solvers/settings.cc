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
                        Selection("direct|gmres|cg|auto"),
                        "direct (sparse LU), gmres (preconditioned, "
                        "restarted GMRES), cg (preconditioned conjugate "
                        "gradients: a symmetric operator only, i.e. FE "
                        "alone or a PD model with a symmetric tangent such "
                        "as 'pdlsm energy' or 'rnp'; the collocated 'pdlsm' "
                        "is not symmetric; with 'amg fe' also the nonlinear "
                        "'bond based', by products of its tangent while it "
                        "is positive definite, theory.md §13.7) or auto: the "
                        "run chooses between "
                        "matrix-free gmres ('amg fe') and a direct "
                        "factorisation kept across solves by what their "
                        "solves cost, and says why in summary.json "
                        "(linear_solver.choice). The nonlinear 'bond based' "
                        "gets cg with 'amg fe' and goes over to 'direct' "
                        "for good where CG meets negative curvature or the "
                        "tangent is found indefinite; other nonlinear PD "
                        "models, Newmark and dynamic relaxation get "
                        "'direct'; a PD "
                        "model of forces only (lps fft) gets cg with 'amg "
                        "fe', whose products are force evaluations.");
      prm.declare_entry("Direct solver",
                        "mumps",
                        Selection("mumps|klu"),
                        "Amesos package for 'direct': mumps (parallel) or "
                        "klu (serial, gathers on rank 0).");
      prm.declare_entry("Preconditioner",
                        "amg fe",
                        Selection("amg fe|pd model|amg|ilu"),
                        "For gmres and cg: 'amg fe' (matrix-free coupled "
                        "operator; "
                        "Trilinos ML algebraic multigrid built from the local "
                        "Q1/P1 stiffness of every cell, PD cells included, "
                        "followed by one block-Jacobi correction with the "
                        "coupled operator), 'amg' (ML built from the "
                        "assembled coupled matrix, kept while bonds break "
                        "until GMRES needs twice its first iteration count) "
                        "or 'ilu' (Ifpack ILU(1) of it), or 'pd model' "
                        "(matrix-free; an all-PD region whose model has an "
                        "approximate inverse of its own: lps fft, the "
                        "inverse of its periodic operator by FFT). With cg "
                        "the AMG "
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
      prm.declare_entry(
        "Factorization reuse",
        "true",
        Bool(),
        "direct: a matrix whose values changed (a new Newton tangent, "
        "broken bonds) is first solved with the factors of its earlier "
        "values, corrected by GMRES preconditioned with them to 1e-12 of "
        "the right-hand side, while the extra solves since the "
        "factorisation stay below what one factorisation costs (from "
        "MUMPS's counts); only where that does not converge is it "
        "factorised again. "
        "false: every change is factorised (KLU always is).");
      prm.declare_entry("GMRES restart",
                        "150",
                        Integer(5, 2000),
                        "gmres: Krylov vectors kept before a restart. A "
                        "restart forgets the search space: on the 3D box, "
                        "30 takes 319 iterations, 150 takes 109 (= no "
                        "restart). Memory: 8 bytes x DoFs x this number.");
      prm.leave_subsection();
    }

    Settings
    Settings::resolve(const bool nonlinear_model,
                      const bool driver_needs_matrix,
                      const bool forces_only_model,
                      const bool model_preconditioner,
                      const bool tangent_products) const
    {
      if (type != "auto")
        return *this;
      Settings resolved  = *this;
      resolved.automatic = true;
      if (forces_only_model)
        {
          resolved.type = "cg";
          resolved.preconditioner =
            model_preconditioner ? "pd model" : "amg fe";
          resolved.choice_reason =
            std::string("the PD model evaluates forces only: matrix-free "
                        "CG needs no tangent (there is no matrix to "
                        "factorise), ") +
            (model_preconditioner ? "preconditioned by the model's own "
                                    "approximate inverse" :
                                    "preconditioned by AMG of the cells' "
                                    "Q1/P1 stiffness");
        }
      else if (nonlinear_model && tangent_products)
        {
          resolved.type           = "cg";
          resolved.preconditioner = "amg fe";
          resolved.choice_reason =
            "the PD model is nonlinear and applies its symmetric tangent "
            "without assembling it: matrix-free CG preconditioned by AMG of "
            "the cells' Q1/P1 stiffness while the tangent is positive "
            "definite, the assembled tangent factorised from where CG meets "
            "negative curvature or finds it indefinite";
        }
      else if (nonlinear_model || driver_needs_matrix)
        {
          resolved.type = "direct";
          resolved.choice_reason =
            nonlinear_model ? "the PD model is nonlinear: its tangent "
                              "is assembled and factorised, the "
                              "factorisation kept while it is unchanged" :
                              "the driver works with the assembled "
                              "matrix";
        }
      else
        {
          resolved.type           = "gmres";
          resolved.preconditioner = "amg fe";
          resolved.choose_by_cost = true;
          resolved.choice_reason =
            "a linear model: matrix-free GMRES needs no assembled matrix; a "
            "direct factorisation is tried where solves reuse one matrix";
        }
      return resolved;
    }

    void
    Settings::parse(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("Linear solver");
      type                = prm.get("Type");
      direct_solver       = prm.get("Direct solver");
      preconditioner      = prm.get("Preconditioner");
      tolerance           = prm.get_double("Tolerance");
      max_iterations      = prm.get_integer("Max iterations");
      restart             = prm.get_integer("GMRES restart");
      reuse_factorization = prm.get_bool("Factorization reuse");
      prm.leave_subsection();
    }

  } // namespace Solvers
} // namespace pdfem
