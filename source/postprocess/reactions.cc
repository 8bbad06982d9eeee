// SPDX-License-Identifier: LGPL-2.1-or-later
// The `reactions` postprocessor: support reactions per Dirichlet set.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/io/history.h>
#include <pdfem/simulator/postprocess.h>
#include <pdfem/simulator/summary.h>

#include <array>
#include <cmath>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The reaction force of every Dirichlet set (f_int - f_ext summed over
       * its DoFs) and of the reaction group "RF" (PDLSM-FEM's RF command):
       * history.csv `reaction_<set>_<c>`, summary.json "reaction" in
       * "final" and the largest of each over the run in "peak_reaction".
       */
      template <int dim>
      class Reactions : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          names = this->get_system().reaction_names();
          group = this->get_setup().reaction_group;
          peaks.assign(names.size() + 1, {});
          return true;
        }

        std::vector<std::string>
        history_columns() override
        {
          std::vector<std::string> columns;
          const auto               comps = Coupling::component_names<dim>();
          for (const auto &set : names)
            for (const auto &c : comps)
              columns.push_back("reaction_" + IO::History::column_name(set) +
                                "_" + c);
          if (!group.empty())
            for (const auto &c : comps)
              columns.push_back("reaction_RF_" + c);
          return columns;
        }

        void
        history_values(std::vector<double> &row) override
        {
          const auto         reactions = this->get_system().reactions();
          const unsigned int step      = this->is_dynamic() ?
                                           this->get_time_step_record().step :
                                           this->get_step_record().step;
          const double       t         = this->get_load_factor();
          for (std::size_t s = 0; s < reactions.size(); ++s)
            for (unsigned int c = 0; c < dim; ++c)
              {
                row.push_back(reactions[s][c]);
                peaks[s][c].update(reactions[s][c], step, t);
              }
          if (!group.empty())
            {
              const auto R = group_sum(reactions);
              for (unsigned int c = 0; c < dim; ++c)
                {
                  row.push_back(R[c]);
                  peaks.back()[c].update(R[c], step, t);
                }
            }
        }

        void
        write_final(IO::JsonWriter &json) const override
        {
          Summary::write_reactions<dim>(json,
                                        names,
                                        this->get_system().reactions(),
                                        group);
        }

        void
        write_sections(IO::JsonWriter &json) const override
        {
          const auto comps = Coupling::component_names<dim>();
          json.begin_object("peak_reaction");
          for (std::size_t s = 0; s < peaks.size(); ++s)
            {
              if (s == names.size() && group.empty())
                continue;
              json.begin_object(s < names.size() ? names[s] : "RF");
              for (unsigned int c = 0; c < dim; ++c)
                {
                  json.value(comps[c], peaks[s][c].value);
                  json.value(comps[c] + "_step",
                             static_cast<unsigned long>(peaks[s][c].step));
                  json.value(comps[c] + "_load_factor", peaks[s][c].load);
                }
              json.end_object();
            }
          json.end_object();
        }

        void
        save_state(StateArchive &state) override
        {
          state.put("reactions/peaks", peaks);
        }

        void
        load_state(const StateArchive &state) override
        {
          const auto saved =
            state.get_vector<std::array<Peak, dim>>("reactions/peaks");
          if (saved.size() == peaks.size())
            peaks = saved;
          else
            throw InputError("",
                             "--restart",
                             "the checkpoint has peaks of " +
                               std::to_string(saved.size()) +
                               " support sets, this run " +
                               std::to_string(peaks.size()));
        }

      private:
        /// The reaction (component) of largest magnitude seen, and when.
        struct Peak
        {
          double       value = 0.;
          unsigned int step  = 0;
          double       load  = 0.;
          void
          update(const double v, const unsigned int s, const double t)
          {
            if (std::abs(v) > std::abs(value) || step == 0)
              {
                value = v;
                step  = s;
                load  = t;
              }
          }
        };

        dealii::Tensor<1, dim>
        group_sum(const std::vector<dealii::Tensor<1, dim>> &reactions) const
        {
          dealii::Tensor<1, dim> R;
          for (const unsigned int s : group)
            R += reactions[s];
          return R;
        }

        std::vector<std::string>           names;
        std::vector<unsigned int>          group;
        std::vector<std::array<Peak, dim>> peaks;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(Reactions,
                                 "reactions",
                                 "reaction force of every Dirichlet set and of "
                                 "the reaction group RF, and their peaks.")
  } // namespace Postprocess
} // namespace pdfem
