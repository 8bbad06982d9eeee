// SPDX-License-Identifier: LGPL-2.1-or-later
// The `stability` postprocessor of runs with a nonlinear PD model.
#include <pdfem/base/json_writer.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/simulator/postprocess.h>

#include <algorithm>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The stability of the equilibrium path (specs/001 §2.4): history.csv
       * `stable` (1 if the last check of the tangent's inertia found it
       * positive definite, 0 if not, -1 if no check was made yet) and
       * summary.json "stability": what the Newton or arc-length driver saw
       * (the last stable and the failed load factor, step cuts, unstable
       * states, snap-backs passed, the negative eigenvalues of the last
       * check) and the largest load factor of a recorded state. Runs of a
       * nonlinear PD model with a static driver.
       */
      template <int dim>
      class Stability : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          return !this->get_system().pd_model().linear() && !this->is_dynamic();
        }

        std::vector<std::string>
        history_columns() override
        {
          return {"stable"};
        }

        void
        history_values(std::vector<double> &row) override
        {
          const Drivers::StabilityReport *check =
            this->get_last_stability_check();
          row.push_back(check == nullptr ? -1. : check->stable() ? 1. : 0.);
          peak_load = std::max(peak_load, this->get_load_factor());
        }

        void
        write_sections(IO::JsonWriter &json) const override
        {
          const Drivers::NewtonOutcome *outcome = this->get_driver().outcome();
          json.begin_object("stability");
          json.value("peak_load_factor", peak_load);
          if (outcome != nullptr)
            {
              json.value("last_stable_load_factor", outcome->last_stable_load);
              json.value("failure_load_factor", outcome->failure_load);
              json.value("step_cuts",
                         static_cast<unsigned long>(outcome->n_cuts));
              json.value("unstable_states",
                         static_cast<unsigned long>(
                           outcome->n_unstable_states));
              json.value("snap_backs",
                         static_cast<unsigned long>(outcome->n_snap_backs));
              json.value("path_states",
                         static_cast<unsigned long>(outcome->n_path_states));
              json.value("negative_eigenvalues",
                         static_cast<unsigned long>(
                           outcome->last_check.n_negative));
              json.value("smallest_relative_pivot",
                         outcome->last_check.smallest_relative_pivot);
            }
          json.end_object();
        }

        void
        save_state(StateArchive &state) override
        {
          state.put("stability/peak load", peak_load);
        }

        void
        load_state(const StateArchive &state) override
        {
          peak_load = state.get<double>("stability/peak load");
        }

      private:
        double peak_load = 0.;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(
      Stability,
      "stability",
      "history.csv 'stable' and summary.json 'stability' (inertia checks, "
      "step cuts, snap-backs, peak load) of nonlinear PD models.")
  } // namespace Postprocess
} // namespace pdfem
