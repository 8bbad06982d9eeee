// SPDX-License-Identifier: LGPL-2.1-or-later
// The `force balance` postprocessor: do the internal forces sum to zero?
#include <pdfem/base/json_writer.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/simulator/postprocess.h>

#include <algorithm>
#include <iomanip>
#include <ostream>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The resultant of the internal forces relative to the applied load,
       * |sum_j f_int,j| / load (Coupling::ForceBalance), at every recorded
       * step: history.csv `force_imbalance`, summary.json "force_balance"
       * (the largest value, whether the load was self-balanced, the
       * warning). A conservative operator (FE, pdlsm energy, rnp) gives
       * round-off; the collocated pdlsm does not once the body holds a
       * crack. Under a self-balanced load the supports then carry that
       * share of it: more than 1 % gives one warning line.
       */
      template <int dim>
      class ForceBalanceOutput : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          return this->get_system().size().n_pd_nodes > 0;
        }

        std::vector<std::string>
        history_columns() override
        {
          return {"force_imbalance"};
        }

        void
        history_values(std::vector<double> &row) override
        {
          const Coupling::ForceBalance<dim> balance =
            this->get_system().force_balance();
          const double imbalance = balance.imbalance();
          row.push_back(imbalance);
          max_imbalance = std::max(max_imbalance, imbalance);
          if (balance.self_balanced())
            {
              self_balanced = true;
              if (imbalance > warning_level && !warned)
                {
                  warned = true;
                  if (std::ostream *out = this->get_progress_stream())
                    *out << "  Warning: the supports carry "
                         << std::setprecision(3) << 100. * imbalance
                         << " % of a self-balanced load: the PD operator's "
                            "internal forces do not sum to zero (the "
                            "collocated pdlsm with a crack; Peridynamics/"
                            "Model = pdlsm energy is conservative)"
                         << std::endl;
                }
            }
        }

        void
        write_sections(IO::JsonWriter &json) const override
        {
          json.begin_object("force_balance");
          json.value("max_imbalance", max_imbalance);
          json.value("self_balanced_load", self_balanced);
          json.value("supports_carry_load", warned);
          json.end_object();
        }

        void
        save_state(StateArchive &state) override
        {
          state.put("force balance/max imbalance", max_imbalance);
          state.put("force balance/self balanced", self_balanced);
          state.put("force balance/warned", warned);
        }

        void
        load_state(const StateArchive &state) override
        {
          max_imbalance = state.get<double>("force balance/max imbalance");
          self_balanced = state.get<bool>("force balance/self balanced");
          warned        = state.get<bool>("force balance/warned");
        }

      private:
        static constexpr double warning_level = 0.01;
        double                  max_imbalance = 0.;
        bool                    self_balanced = false;
        bool                    warned        = false;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(
      ForceBalanceOutput,
      "force balance",
      "the resultant of the internal forces relative to the applied load "
      "(history.csv force_imbalance; a warning when the supports carry more "
      "than 1 % of a self-balanced load).")
  } // namespace Postprocess
} // namespace pdfem
