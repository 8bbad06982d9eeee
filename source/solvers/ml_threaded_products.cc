// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/thread_team.h>
#include <pdfem/solvers/ml_threaded_products.h>

#include <deal.II/lac/trilinos_precondition.h>

#include <algorithm>
#include <atomic>

#include <Epetra_CrsMatrix.h>
#include <ml_MultiLevelPreconditioner.h>
#include <ml_epetra_utils.h>
#include <ml_include.h>
#include <ml_mat_formats.h>

namespace pdfem
{
  namespace Solvers
  {
    namespace
    {
      /// Products smaller than this run on the calling thread alone: the
      /// team's hand-over (a few microseconds) would cost more than it saves.
      constexpr int min_nonzeros_to_share = 20000;

      /// The team of the last thread_ml_products() call.
      std::atomic<ThreadTeam *> products_team{nullptr};

      /// y_i = sum_k values[k] x[cols[k]] over row i's entries, in order,
      /// for rows [begin, end).
      void
      csr_rows(const int    *rowptr,
               const int    *cols,
               const double *values,
               const double *x,
               double       *y,
               const int     begin,
               const int     end)
      {
        for (int i = begin; i < end; ++i)
          {
            double sum = 0.;
            for (int k = rowptr[i]; k < rowptr[i + 1]; ++k)
              sum += values[k] * x[cols[k]];
            y[i] = sum;
          }
      }

      /// y = A x for a CSR matrix of @p n_rows rows, the rows split among
      /// the team in blocks of equal numbers of entries.
      void
      shared_csr_product(const int    *rowptr,
                         const int    *cols,
                         const double *values,
                         const int     n_rows,
                         const double *x,
                         double       *y)
      {
        ThreadTeam        *team  = products_team.load();
        const unsigned int parts = team == nullptr ? 1 : team->size();
        if (parts < 2 || rowptr[n_rows] < min_nonzeros_to_share)
          {
            csr_rows(rowptr, cols, values, x, y, 0, n_rows);
            return;
          }
        const auto first_row = [&](const unsigned int part) {
          if (part == parts)
            return n_rows;
          const long entries = static_cast<long>(rowptr[n_rows]) * part / parts;
          return static_cast<int>(
            std::lower_bound(rowptr, rowptr + n_rows, entries) - rowptr);
        };
        team->run([&](const unsigned int member) {
          csr_rows(rowptr,
                   cols,
                   values,
                   x,
                   y,
                   first_row(member),
                   first_row(member + 1));
        });
      }

      /// Replaces ML_Epetra_CrsMatrix_matvec: the operator's data is the
      /// Epetra_CrsMatrix.
      int
      shared_epetra_product(ML_Operator *op,
                            const int    in_length,
                            double      *x,
                            const int    out_length,
                            double      *y)
      {
        auto   *A = static_cast<Epetra_CrsMatrix *>(ML_Get_MyMatvecData(op));
        int    *rowptr = nullptr, *cols = nullptr;
        double *values = nullptr;
        if (A->Importer() != nullptr || A->Exporter() != nullptr ||
            out_length != A->NumMyRows() ||
            A->ExtractCrsDataPointers(rowptr, cols, values) != 0)
          return ML_Epetra_CrsMatrix_matvec(op, in_length, x, out_length, y);
        shared_csr_product(rowptr, cols, values, out_length, x, y);
        return 1;
      }

      /// Replaces CSR_matvec for operators without communication.
      int
      shared_ml_csr_product(ML_Operator *op,
                            const int /*in_length*/,
                            double *x,
                            const int /*out_length*/,
                            double *y)
      {
        const auto *csr = static_cast<const ML_CSR_MSRdata *>(op->data);
        shared_csr_product(
          csr->rowptr, csr->columns, csr->values, op->getrow->Nrows, x, y);
        return 1;
      }

      /// Does the exchange @p comm leave a vector of @p n entries as it is?
      /// No neighbours, and no remapping or the identity (ML's restriction
      /// carries an identity remap in serial).
      bool
      without_communication(const ML_CommInfoOP *comm, const int n)
      {
        if (comm == nullptr)
          return true;
        if (comm->N_neighbors != 0)
          return false;
        if (comm->remap == nullptr)
          return true;
        if (comm->remap_length != n)
          return false;
        for (int i = 0; i < n; ++i)
          if (comm->remap[i] != i)
            return false;
        return true;
      }
    } // namespace

    unsigned int
    thread_ml_products(const dealii::TrilinosWrappers::PreconditionAMG &amg,
                       ThreadTeam                                      &team)
    {
      if (team.size() < 2)
        return 0;
      products_team = &team;
      const auto *ml_preconditioner =
        dynamic_cast<const ML_Epetra::MultiLevelPreconditioner *>(
          &amg.trilinos_operator());
      if (ml_preconditioner == nullptr)
        return 0;
      const ML    *ml      = ml_preconditioner->GetML();
      unsigned int changed = 0;
      for (int level = 0; level < ml->ML_num_levels; ++level)
        for (ML_Operator *op :
             {&ml->Amat[level], &ml->Rmat[level], &ml->Pmat[level]})
          {
            if (op->matvec == nullptr || op->getrow == nullptr)
              continue;
            auto &product = op->matvec->func_ptr;
            if (product == ML_Epetra_CrsMatrix_matvec)
              {
                product = shared_epetra_product;
                ++changed;
              }
            else if (product == CSR_matvec && op->data != nullptr &&
                     static_cast<const ML_CSR_MSRdata *>(op->data)->rowptr !=
                       nullptr &&
                     op->getrow->Nrows == op->outvec_leng &&
                     without_communication(op->getrow->pre_comm,
                                           op->invec_leng) &&
                     without_communication(op->getrow->post_comm,
                                           op->outvec_leng))
              {
                product = shared_ml_csr_product;
                ++changed;
              }
          }
      return changed;
    }
  } // namespace Solvers
} // namespace pdfem
