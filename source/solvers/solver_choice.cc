// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/json_writer.h>
#include <pdfem/solvers/solver_choice.h>

#include <algorithm>
#include <sstream>

namespace pdfem
{
  namespace Solvers
  {
    namespace
    {
      /// Three significant digits, for the reasons.
      std::string
      number(const double value)
      {
        std::ostringstream out;
        out.precision(3);
        out << value;
        return out.str();
      }
    } // namespace

    std::string
    to_string(const SolvePath path, const std::string &krylov)
    {
      return path == SolvePath::direct ? "direct" : krylov + " (amg fe)";
    }

    SolverChoice::SolverChoice(const SolvePath    start,
                               const std::string &why,
                               const bool         may_switch,
                               const bool         direct_fits,
                               const std::string &memory_note,
                               const std::string &krylov)
      : start_path(start)
      , current(start)
      , start_reason(why)
      , may_switch(may_switch)
      , direct_fits(direct_fits)
      , memory_note(memory_note)
      , krylov(krylov)
    {}

    void
    SolverChoice::record(const double       seconds,
                         const unsigned int iterations,
                         const bool         factorized)
    {
      ++solves;
      if (changed)
        ++after_changes;
      changed = false;
      if (current == SolvePath::matrix_free)
        {
          ++krylov_solves;
          krylov_seconds += seconds;
          krylov_iterations += iterations;
        }
      else if (factorized)
        {
          ++factorizing_solves;
          factorizing_seconds += seconds;
        }
      else
        {
          ++plain_solves;
          plain_seconds += seconds;
        }
    }

    bool
    SolverChoice::reconsider()
    {
      if (!may_switch || settled)
        return false;
      const double phi = solves > 0 ? double(after_changes) / solves : 1.;
      if (current == SolvePath::matrix_free)
        {
          // Many solves with one matrix: a kept factorisation may pay.
          if (tried_direct || !direct_fits || krylov_solves < 3 ||
              3 * after_changes > solves)
            return false;
          tried_direct = true;
          go(SolvePath::direct,
             std::to_string(solves - after_changes) + " of " +
               std::to_string(solves) +
               " solves reused an unchanged matrix and GMRES took " +
               number(krylov_seconds / krylov_solves) + " s (" +
               number(double(krylov_iterations) / krylov_solves) +
               " iterations) per solve: a factorisation kept across solves "
               "is tried");
          return true;
        }
      // On the direct path after trying it: once both of its costs are
      // measured, keep it or go back for good.
      if (!tried_direct || factorizing_solves == 0 || plain_solves < 3 ||
          krylov_solves == 0)
        return false;
      settled                = true;
      const double factorize = factorizing_seconds / factorizing_solves;
      const double solve     = plain_seconds / plain_solves;
      const double direct    = solve + phi * std::max(factorize - solve, 0.);
      const double gmres     = krylov_seconds / krylov_solves;
      verdict = "a factorisation and solve took " + number(factorize) +
                " s, a solve with it " + number(solve) + " s; with " +
                number(100. * phi) +
                " % of the solves after a change of the matrix, " +
                number(direct) + " s per solve against " + number(gmres) +
                " s with GMRES";
      if (direct <= 1.25 * gmres)
        return false;
      go(SolvePath::matrix_free, verdict);
      return true;
    }

    bool
    SolverChoice::matrix_free_failed(const std::string &message)
    {
      return leave_matrix_free((krylov == "cg" ? "CG" : "GMRES") +
                               std::string(" failed: ") + message);
    }

    bool
    SolverChoice::leave_matrix_free(const std::string &reason)
    {
      if (current != SolvePath::matrix_free || !direct_fits)
        return false;
      tried_direct = settled = true;
      go(SolvePath::direct, reason);
      return true;
    }

    void
    SolverChoice::go(const SolvePath to, const std::string &reason)
    {
      current = to;
      changes.push_back({solves + 1, to, reason});
    }

    void
    SolverChoice::write(IO::JsonWriter &json) const
    {
      json.begin_object("choice");
      json.value("start", name(start_path));
      json.value("reason", start_reason);
      json.value("direct_memory", memory_note);
      json.value("solves", solves);
      json.value("solves_after_matrix_change", after_changes);
      // The matrix-free path's counts under its method's name: gmres_solves
      // or cg_solves.
      json.value(krylov + "_solves", krylov_solves);
      if (krylov_solves > 0)
        {
          json.value(krylov + "_seconds_per_solve",
                     krylov_seconds / krylov_solves);
          json.value(krylov + "_iterations_per_solve",
                     double(krylov_iterations) / krylov_solves);
        }
      json.value("direct_solves", factorizing_solves + plain_solves);
      if (factorizing_solves > 0)
        json.value("direct_seconds_per_factorizing_solve",
                   factorizing_seconds / factorizing_solves);
      if (plain_solves > 0)
        json.value("direct_seconds_per_solve", plain_seconds / plain_solves);
      if (!verdict.empty())
        json.value("comparison", verdict);
      json.begin_object("switches");
      for (std::size_t i = 0; i < changes.size(); ++i)
        {
          json.begin_object(std::to_string(i + 1));
          json.value("solve", changes[i].solve);
          json.value("to", name(changes[i].to));
          json.value("reason", changes[i].reason);
          json.end_object();
        }
      json.end_object();
      json.end_object();
    }
  } // namespace Solvers
} // namespace pdfem
