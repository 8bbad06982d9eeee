// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: Linear solver Type = auto, the path of each solve chosen by
// what the solves cost (Solvers::SolverChoice), and the "linear_solver"
// section of summary.json.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    namespace
    {
      /// The memory the kernel can give without swapping (MemAvailable of
      /// /proc/meminfo), in bytes; 0 if unknown.
      double
      available_memory()
      {
        std::ifstream in("/proc/meminfo");
        std::string   key;
        double        kb = 0.;
        while (in >> key)
          {
            if (key == "MemAvailable:" && in >> kb)
              return 1024. * kb;
            in.ignore(256, '\n');
          }
        return 0.;
      }

      std::string
      gigabytes(const double bytes)
      {
        std::ostringstream out;
        out.precision(2);
        out << bytes / 1e9 << " GB";
        return out.str();
      }
    } // namespace

    template <int dim>
    void
    CoupledSystem<dim>::Impl::set_up_choice()
    {
      const Solvers::Settings &ls = settings.linear_solver;
      // Type = auto resolves to cg for a model of forces only: nothing to
      // choose from (no matrix to factorise); write_solver_summary() gives
      // the reason.
      if (choice || !ls.automatic || !layout.tangent)
        return;
      // A nonlinear model on CG leaves it at the first negative curvature.
      solver.stop_at_negative_curvature(ls.conjugate_gradients());
      // The assembled matrix's entries (FE cells and one row block per PD
      // family), and its LU factors at a fill of 10 (2D) or 25 (3D) times
      // that: measured 13 x on a mostly-PD 2D plate (15 k DoFs) and 22 x on
      // tests' through_crack_3d (65 k DoFs, 8.0 M entries, 1.8 GB) with
      // MUMPS. A rough guard, not a prediction: the direct path is only
      // tried where these factors take at most half the memory available
      // to each rank of the machine.
      double entries = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() && !cell_pd[cell->active_cell_index()])
          entries += std::pow(cell->get_fe().n_dofs_per_cell(), 2);
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        entries +=
          dim * dim * double(families.offsets[o + 1] - families.offsets[o] + 1);
      entries               = Utilities::MPI::sum(entries, comm);
      const double bytes    = 8. * (dim == 2 ? 10. : 25.) * entries;
      const double per_rank = Utilities::MPI::min(available_memory(), comm) /
                              Utilities::MPI::n_mpi_processes(comm);
      const bool fits =
        2. * bytes / Utilities::MPI::n_mpi_processes(comm) <= per_rank;
      const std::string note =
        "about " + gigabytes(bytes) + " for the factors of " +
        std::to_string(static_cast<unsigned long>(entries)) +
        " matrix entries; " + gigabytes(per_rank) + " available per rank" +
        (fits ? "" : ": too much, the direct path is not tried");
      choice = std::make_unique<Solvers::SolverChoice>(
        ls.type == "direct" ? Solvers::SolvePath::direct :
                              Solvers::SolvePath::matrix_free,
        ls.choice_reason,
        ls.choose_by_cost,
        fits,
        note,
        ls.iterative() ? ls.type : "gmres");
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::prepare_solver()
    {
      if (!settings.prepare_solver || !matrix_free ||
          settings.linear_solver.model_preconditioner())
        return;
      solver.prepare_preconditioner(auxiliary);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::switch_path(const Solvers::SolvePath path)
    {
      const bool direct = path == Solvers::SolvePath::direct;
      solver.use_direct(direct);
      matrix_free = !direct;
      if (direct)
        {
          if (matrix.m() == 0)
            make_assembled_pattern();
          tangent_stale = tangent_outdated = true;
        }
      else
        {
          // The assembled matrix and its factors go; the auxiliary matrix
          // is assembled as the cracks are now.
          solver.matrix_rebuilt();
          matrix.clear();
          n_matrix_entries = 0;
          if (auxiliary.m() == 0)
            make_auxiliary_pattern();
          auxiliary_cut.clear();
          assemble_auxiliary();
          block_inverse.clear();
        }
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::Impl::solve_on_path(Vector       &du,
                                            const Vector &r,
                                            const double  allowed_residual)
    {
      if (matrix_free && settings.linear_solver.model_preconditioner())
        return solver.solve([this](Vector &y, const Vector &x) { vmult(y, x); },
                            du,
                            r,
                            [this](Vector &z, const Vector &t) {
                              apply_model_preconditioner(z, t);
                            },
                            allowed_residual);
      if (matrix_free)
        {
          if (auxiliary_stale)
            assemble_auxiliary();
          // CG takes the AMG alone (a symmetric preconditioner), so that
          // the block-Jacobi correction, which reads the PD tangent's
          // diagonal blocks, is made for GMRES only: a model of forces
          // only is solved by CG with products alone.
          const bool correct    = !settings.linear_solver.conjugate_gradients();
          cg_solved_since_check = !correct;
          if (correct && block_inverse.empty())
            make_block_jacobi();
          Solvers::LinearSolver::Operator correction;
          if (correct)
            correction = [this](Vector &w, const Vector &t) {
              apply_block_jacobi(w, t);
            };
          return solver.solve([this](Vector       &y,
                                     const Vector &x) { vmult(y, x); },
                              du,
                              r,
                              auxiliary,
                              correction,
                              allowed_residual);
        }
      if (tangent_stale)
        {
          assemble_tangent();
          tangent_stale = false;
        }
      return solver.solve(matrix, du, r, allowed_residual);
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::solve_linear_within(Vector       &du,
                                            const Vector &r,
                                            const double  allowed_residual)
    {
      Impl &s = *impl;
      du.reinit(s.owned, s.comm);
      if (!s.choice)
        return s.solve_on_path(du, r, allowed_residual);

      if (s.choice->reconsider())
        s.switch_path(s.choice->path());
      const unsigned int factorizations = s.solver.n_factorizations();
      auto               start          = std::chrono::steady_clock::now();
      unsigned int       iterations     = 0;
      try
        {
          iterations = s.solve_on_path(du, r, allowed_residual);
        }
      catch (const RunFailure &e)
        {
          // A failed GMRES or CG solve (the same on every rank) goes over to
          // the direct path where that fits, instead of ending the run.
          if (!s.matrix_free || e.exit_state != "linear solver diverged" ||
              !s.choice->matrix_free_failed(e.what()))
            throw;
          s.switch_path(Solvers::SolvePath::direct);
          start      = std::chrono::steady_clock::now();
          iterations = s.solve_on_path(du, r, allowed_residual);
        }
      const double seconds =
        Utilities::MPI::max(std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start)
                              .count(),
                            s.comm);
      s.choice->record(seconds,
                       iterations,
                       s.solver.n_factorizations() > factorizations);
      return iterations;
    }

    template <int dim>
    void
    CoupledSystem<dim>::write_solver_summary(IO::JsonWriter &json) const
    {
      const Impl &s = *impl;
      json.begin_object("linear_solver");
      json.value("type",
                 s.settings.linear_solver.automatic ?
                   std::string("auto") :
                   s.settings.linear_solver.type);
      const Solvers::Settings &ls   = s.settings.linear_solver;
      const std::string        path = s.matrix_free ?
                                        ls.type + " (" + ls.preconditioner + ")" :
                                        to_string(Solvers::SolvePath::direct);
      json.value("path", path);
      json.value("factorizations",
                 static_cast<unsigned long>(s.solver.n_factorizations()));
      json.value("analyses", static_cast<unsigned long>(s.solver.n_analyses()));
      json.value("reused_factorization_solves",
                 static_cast<unsigned long>(
                   s.solver.n_reused_factorization_solves()));
      json.value("reused_factorization_iterations",
                 static_cast<unsigned long>(
                   s.solver.n_reused_factorization_iterations()));
      if (s.choice)
        s.choice->write(json);
      else if (ls.automatic)
        {
          json.begin_object("choice");
          json.value("start", path);
          json.value("reason", ls.choice_reason);
          json.end_object();
        }
      json.end_object();
    }

    template <int dim>
    std::vector<std::string>
    CoupledSystem<dim>::solver_switches() const
    {
      std::vector<std::string> lines;
      if (impl->choice)
        for (const auto &change : impl->choice->switches())
          lines.push_back("linear solver: " + impl->choice->name(change.to) +
                          " from solve " + std::to_string(change.solve) +
                          " on: " + change.reason);
      return lines;
    }

#define INSTANTIATE(dim)                                                   \
  template void CoupledSystem<dim>::Impl::set_up_choice();                 \
  template void CoupledSystem<dim>::Impl::prepare_solver();                \
  template void CoupledSystem<dim>::Impl::switch_path(Solvers::SolvePath); \
  template unsigned int CoupledSystem<dim>::Impl::solve_on_path(           \
    Vector &, const Vector &, double);                                     \
  template unsigned int CoupledSystem<dim>::solve_linear_within(           \
    Vector &, const Vector &, double);                                     \
  template void CoupledSystem<dim>::write_solver_summary(IO::JsonWriter &) \
    const;                                                                 \
  template std::vector<std::string> CoupledSystem<dim>::solver_switches() const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
