// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/solvers/envelope_cholesky.h>
#include <pdfem/solvers/ml_coarse_solve.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <ml_MultiLevelPreconditioner.h>
#include <ml_include.h>
#include <ml_rap.h>

namespace pdfem
{
  namespace Solvers
  {
    namespace
    {
      /**
       * The coarse factors in single precision. Measured against double
       * factors (one rank, the same GMRES iterations in all three runs):
       * the mixed-mode plate 0.076 against 0.145 ms per coarse solve (KLU
       * 0.34 ms), plateCrack FC1 0.090 against 0.145 ms (KLU 0.44 ms), the
       * 3D box 0.031 against 0.036 ms (KLU 0.20 ms).
       */
      using CoarseFactors = EnvelopeCholesky<float>;

      /**
       * A coarse matrix whose factorisation would take more multiply-adds
       * keeps KLU (tens of milliseconds at the envelope's rate). The coarse
       * levels measured factorise in 1.5 ms (the mixed-mode plate, 1 360
       * rows) and 0.1-1.5 ms (the 3D boxes of the scaling benchmark, 108-896
       * rows).
       */
      constexpr double max_coarse_operations = 5e7;

      /// ML's smoother interface: x = A^{-1} rhs whatever x holds, as the
      /// Amesos coarse solve it replaces.
      int
      envelope_coarse_solve(ML_Smoother *smoother,
                            const int /*in_length*/,
                            double *x,
                            const int /*out_length*/,
                            double *rhs)
      {
        static_cast<const CoarseFactors *>(smoother->smoother->data)
          ->solve(rhs, x);
        return 0;
      }

      void
      delete_coarse_factors(void *factors)
      {
        delete static_cast<CoarseFactors *>(factors);
      }

      /// The rows of an ML operator without communication; false if a
      /// column lies outside the square matrix.
      bool
      rows_of(ML_Operator         *A,
              std::vector<int>    &row_starts,
              std::vector<int>    &columns,
              std::vector<double> &values)
      {
        const int n = A->outvec_leng;
        row_starts.assign(1, 0);
        int     allocated = 0, length = 0;
        int    *row_columns = nullptr;
        double *row_values  = nullptr;
        bool    inside      = true;
        for (int row = 0; row < n && inside; ++row)
          {
            ML_get_matrix_row(
              A, 1, &row, &allocated, &row_columns, &row_values, &length, 0);
            for (int k = 0; k < length; ++k)
              inside = inside && row_columns[k] >= 0 && row_columns[k] < n;
            columns.insert(columns.end(), row_columns, row_columns + length);
            values.insert(values.end(), row_values, row_values + length);
            row_starts.push_back(columns.size());
          }
        ML_free(row_columns);
        ML_free(row_values);
        return inside;
      }

      /// Solve the coarsest level of @p amg's hierarchy, built without a
      /// coarse solve ('coarse: type' do-nothing), by envelope factors;
      /// false where they do not apply.
      bool
      add_envelope_coarse_solve(
        const dealii::TrilinosWrappers::PreconditionAMG &amg)
      {
        const auto *ml_preconditioner =
          dynamic_cast<const ML_Epetra::MultiLevelPreconditioner *>(
            &amg.trilinos_operator());
        if (ml_preconditioner == nullptr ||
            ml_preconditioner->GetML() == nullptr)
          return false;
        ML          *ml    = const_cast<ML *>(ml_preconditioner->GetML());
        const int    level = ml->ML_coarsest_level;
        ML_Smoother &post  = ml->post_smoother[level];
        ML_Smoother &pre   = ml->pre_smoother[level];
        if (post.smoother == nullptr || post.smoother->func_ptr != nullptr ||
            (pre.smoother != nullptr && pre.smoother->func_ptr != nullptr))
          return false;

        ML_Operator *A = &ml->Amat[level];
        if (A->outvec_leng <= 0 || A->invec_leng != A->outvec_leng)
          return false;
        std::vector<int>    row_starts, columns;
        std::vector<double> values;
        if (!rows_of(A, row_starts, columns, values))
          return false;
        auto factors = std::make_unique<CoarseFactors>();
        if (!factors->factorize(A->outvec_leng,
                                row_starts.data(),
                                columns.data(),
                                values.data(),
                                max_coarse_operations))
          return false;
        static char label[] = "envelope Cholesky";
        ML_Set_Smoother(ml,
                        level,
                        ML_POSTSMOOTHER,
                        factors.get(),
                        envelope_coarse_solve,
                        label);
        // ML frees a smoother's data with the smoother's own function.
        post.data_destroy = delete_coarse_factors;
        factors.release();
        return true;
      }
    } // namespace

    bool
    initialize_amg_with_envelope_coarse_solve(
      dealii::TrilinosWrappers::PreconditionAMG    &amg,
      const dealii::TrilinosWrappers::SparseMatrix &matrix,
      Teuchos::ParameterList                        list)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(
            matrix.get_mpi_communicator()) == 1)
        {
          Teuchos::ParameterList without_coarse_solve(list);
          without_coarse_solve.set("coarse: type", std::string("do-nothing"));
          amg.initialize(matrix, without_coarse_solve);
          if (add_envelope_coarse_solve(amg))
            return true;
        }
      amg.initialize(matrix, list);
      return false;
    }
  } // namespace Solvers
} // namespace pdfem
