// SPDX-License-Identifier: LGPL-2.1-or-later
// The `energy balance` postprocessor of dynamic runs.
#include <pdfem/base/json_writer.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/simulator/postprocess.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * Kinetic and strain energy, external work, dissipated energy and the
       * relative energy error of a dynamic run (Drivers::DynamicRecord;
       * specs/004 §2.3-2.4), per unit thickness times the thickness:
       * history.csv columns and summary.json's "dynamics" section, which
       * opens with the driver's own members (integrator, step, stability).
       */
      template <int dim>
      class EnergyBalance : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          return this->is_dynamic();
        }

        std::vector<std::string>
        history_columns() override
        {
          return {"time_step",
                  "kinetic_energy",
                  "strain_energy",
                  "external_work",
                  "dissipated_energy",
                  "energy_error",
                  "energy_drift"};
        }

        void
        every_time_step() override
        {
          const auto &r = this->get_time_step_record();
          max_abs_error = std::max(max_abs_error, std::abs(r.energy_error));
          max_abs_drift = std::max(max_abs_drift, std::abs(r.energy_drift));
        }

        void
        history_values(std::vector<double> &row) override
        {
          const auto  &r         = this->get_time_step_record();
          const double thickness = this->get_system().thickness();
          row.push_back(r.time_step);
          for (const double e : {r.kinetic_energy,
                                 r.strain_energy,
                                 r.external_work,
                                 r.dissipated_energy})
            row.push_back(thickness * e);
          row.push_back(r.energy_error);
          row.push_back(r.energy_drift);
        }

        void
        finish() override
        {
          // Total mass (lumped, per component, for the thickness).
          total_mass = this->get_system().thickness() *
                       this->get_mutable_system().lumped_mass().l1_norm() / dim;
        }

        void
        write_sections(IO::JsonWriter &json) const override
        {
          const auto  &r         = this->get_time_step_record();
          const double thickness = this->get_system().thickness();
          json.begin_object("dynamics");
          this->get_driver().write_summary(json);
          json.value("mass", this->get_driver().settings().mass);
          json.value("total_mass", total_mass);
          json.value("kinetic_energy", thickness * r.kinetic_energy);
          json.value("strain_energy", thickness * r.strain_energy);
          json.value("external_work", thickness * r.external_work);
          json.value("dissipated_energy", thickness * r.dissipated_energy);
          json.value("energy_error", r.energy_error);
          json.value("max_abs_energy_error", max_abs_error);
          json.value("energy_drift", r.energy_drift);
          json.value("max_abs_energy_drift", max_abs_drift);
          json.end_object();
        }

        void
        save_state(StateArchive &state) override
        {
          state.put("energy balance/max abs error", max_abs_error);
          state.put("energy balance/max abs drift", max_abs_drift);
        }

        void
        load_state(const StateArchive &state) override
        {
          max_abs_error = state.get<double>("energy balance/max abs error");
          max_abs_drift = state.get<double>("energy balance/max abs drift");
        }

      private:
        double max_abs_error = 0.;
        double max_abs_drift = 0.;
        double total_mass    = 0.;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(EnergyBalance,
                                 "energy balance",
                                 "dynamic runs: kinetic and strain energy, "
                                 "external work, dissipation, energy error "
                                 "and the integrator's conserved-energy "
                                 "drift.")
  } // namespace Postprocess
} // namespace pdfem
