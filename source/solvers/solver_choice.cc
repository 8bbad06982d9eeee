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
    to_string(const SolvePath path)
    {
      return path == SolvePath::direct ? "direct" : "gmres (amg fe)";
    }

    SolverChoice::SolverChoice(const SolvePath    start,
                               const std::string &why,
                               const bool         may_switch,
                               const bool         direct_fits,
                               const std::string &memory_note)
      : start_path(start)
      , current(start)
      , start_reason(why)
      , may_switch(may_switch)
      , direct_fits(direct_fits)
      , memory_note(memory_note)
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
          ++gmres_solves;
          gmres_seconds += seconds;
          gmres_iterations += iterations;
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
          if (tried_direct || !direct_fits || gmres_solves < 3 ||
              3 * after_changes > solves)
            return false;
          tried_direct = true;
          go(SolvePath::direct,
             std::to_string(solves - after_changes) + " of " +
               std::to_string(solves) +
               " solves reused an unchanged matrix and GMRES took " +
               number(gmres_seconds / gmres_solves) + " s (" +
               number(double(gmres_iterations) / gmres_solves) +
               " iterations) per solve: a factorisation kept across solves "
               "is tried");
          return true;
        }
      // On the direct path after trying it: once both of its costs are
      // measured, keep it or go back for good.
      if (!tried_direct || factorizing_solves == 0 || plain_solves < 3 ||
          gmres_solves == 0)
        return false;
      settled                = true;
      const double factorize = factorizing_seconds / factorizing_solves;
      const double solve     = plain_seconds / plain_solves;
      const double direct    = solve + phi * std::max(factorize - solve, 0.);
      const double gmres     = gmres_seconds / gmres_solves;
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
      if (current != SolvePath::matrix_free || !direct_fits)
        return false;
      tried_direct = settled = true;
      go(SolvePath::direct, "GMRES failed: " + message);
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
      json.value("start", to_string(start_path));
      json.value("reason", start_reason);
      json.value("direct_memory", memory_note);
      json.value("solves", solves);
      json.value("solves_after_matrix_change", after_changes);
      json.value("gmres_solves", gmres_solves);
      if (gmres_solves > 0)
        {
          json.value("gmres_seconds_per_solve", gmres_seconds / gmres_solves);
          json.value("gmres_iterations_per_solve",
                     double(gmres_iterations) / gmres_solves);
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
          json.value("to", to_string(changes[i].to));
          json.value("reason", changes[i].reason);
          json.end_object();
        }
      json.end_object();
      json.end_object();
    }
  } // namespace Solvers
} // namespace pdfem
