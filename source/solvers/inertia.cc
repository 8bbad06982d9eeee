// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/solvers/inertia.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

namespace pdfem
{
  namespace Solvers
  {
    namespace
    {
      // MUMPS's arrays, numbered from 1 as in its manual.
      MUMPS_INT &
      icntl(DMUMPS_STRUC_C &id, const int i)
      {
        return id.icntl[i - 1];
      }
      MUMPS_INT
      infog(const DMUMPS_STRUC_C &id, const int i)
      {
        return id.infog[i - 1];
      }

      /// A MUMPS instance, terminated (JOB = -2) whatever happens.
      struct MumpsInstance
      {
        explicit MumpsInstance(const MPI_Comm comm)
        {
          id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
          id.par          = 1; // the host (rank 0) works too
          id.sym          = 2; // general symmetric: LDL^T, 2x2 pivots
          id.job          = -1;
          dmumps_c(&id);
        }
        ~MumpsInstance()
        {
          id.job = -2;
          dmumps_c(&id);
        }
        MumpsInstance(const MumpsInstance &) = delete;
        MumpsInstance &
        operator=(const MumpsInstance &) = delete;

        DMUMPS_STRUC_C id{};
      };

      /// MUMPS's errors that go away with more workspace (ICNTL(14)).
      bool
      workspace_too_small(const int error)
      {
        return error == -8 || error == -9 || error == -14 || error == -15 ||
               error == -17 || error == -20;
      }
    } // namespace

    Inertia
    compute_inertia(const dealii::TrilinosWrappers::SparseMatrix &A,
                    const double null_pivot_tolerance)
    {
      if (A.m() != A.n())
        throw std::invalid_argument(
          "compute_inertia: the matrix is not square (" +
          std::to_string(A.m()) + " x " + std::to_string(A.n()) + ")");
      const Epetra_CrsMatrix &M    = A.trilinos_matrix();
      const MPI_Comm          comm = A.get_mpi_communicator();

      // The lower triangle of the locally owned rows, numbered from 1, and
      // a zero diagonal entry for every row (MUMPS sums duplicates), so that
      // an empty row is still given to MUMPS as a variable (a null pivot).
      std::vector<MUMPS_INT> rows, columns;
      std::vector<double>    values;
      const std::size_t      reserve = M.NumMyNonzeros() / 2 + M.NumMyRows();
      rows.reserve(reserve);
      columns.reserve(reserve);
      values.reserve(reserve);
      for (int r = 0; r < M.NumMyRows(); ++r)
        {
          const int row     = M.GRID(r);
          int       n       = 0;
          double   *entries = nullptr;
          int      *indices = nullptr;
          M.ExtractMyRowView(r, n, entries, indices);
          for (int k = 0; k < n; ++k)
            {
              const int column = M.GCID(indices[k]);
              if (column <= row)
                {
                  rows.push_back(row + 1);
                  columns.push_back(column + 1);
                  values.push_back(entries[k]);
                }
            }
          rows.push_back(row + 1);
          columns.push_back(row + 1);
          values.push_back(0.);
        }

      Inertia result;
      result.n_rows               = A.m();
      result.null_pivot_tolerance = null_pivot_tolerance;
      if (result.n_rows == 0)
        return result;

      MumpsInstance   mumps(comm);
      DMUMPS_STRUC_C &id = mumps.id;
      if (infog(id, 1) >= 0)
        {
          icntl(id, 1)   = -1; // no error messages
          icntl(id, 2)   = -1; // no diagnostics
          icntl(id, 3)   = -1; // no global information
          icntl(id, 4)   = 0;
          icntl(id, 5)   = 0; // assembled matrix
          icntl(id, 13)  = 1; // no ScaLAPACK at the root: exact inertia
          icntl(id, 18)  = 3; // distributed entries
          icntl(id, 24)  = 1; // null pivot detection
          id.cntl[3 - 1] = null_pivot_tolerance;
          id.n           = static_cast<MUMPS_INT>(result.n_rows);
          id.nnz_loc     = static_cast<MUMPS_INT8>(rows.size());
          id.nz_loc      = static_cast<MUMPS_INT>(rows.size());
          id.irn_loc     = rows.data();
          id.jcn_loc     = columns.data();
          id.a_loc       = values.data();
          id.job         = 4; // analysis and factorisation
          dmumps_c(&id);
          for (unsigned int retry = 0;
               retry < 4 && workspace_too_small(infog(id, 1));
               ++retry)
            {
              icntl(id, 14) = 2 * std::max<MUMPS_INT>(icntl(id, 14), 20);
              id.job        = 2; // factorisation again
              dmumps_c(&id);
            }
        }
      // The host's (rank 0's) numbers, so that every rank surely agrees.
      int       status[3] = {infog(id, 1), infog(id, 12), infog(id, 28)};
      const int error2    = infog(id, 2);
      MPI_Bcast(status, 3, MPI_INT, 0, comm);
      if (status[0] < 0 && status[0] != -10)
        throw RunFailure(
          "linear solver failure",
          "MUMPS failed in the inertia computation: INFOG(1) = " +
            std::to_string(status[0]) +
            ", INFOG(2) = " + std::to_string(error2));
      result.n_negative = static_cast<std::size_t>(std::max(status[1], 0));
      result.n_null     = static_cast<std::size_t>(std::max(status[2], 0));
      result.singular   = status[0] == -10 || result.n_null > 0;
      return result;
    }
  } // namespace Solvers
} // namespace pdfem
