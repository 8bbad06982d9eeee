// SPDX-License-Identifier: LGPL-2.1-or-later
// The `mcts` crack criterion plugin (PDLSM-FEM's FC 1).
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/fracture/criterion.h>

#include <iomanip>
#include <sstream>

namespace pdfem
{
  namespace Fracture
  {
    namespace
    {
      /**
       * Stress-intensity factors at every crack tip (2D) or straight-front
       * point (3D) by the interaction integral; a tip with K_eq > K_Ic
       * advances by d_c in the direction of the maximum circumferential
       * tensile stress (specs/004 §3.1, eq. 41-42; CrackGrowth::grow_at_tips).
       */
      template <int dim>
      class MaximumCircumferentialStress : public Criterion<dim>
      {
      public:
        void
        initialize(const Settings &settings, const std::string &file) override
        {
          Criterion<dim>::initialize(settings, file);
          if (!(settings.toughness > 0.))
            throw InputError(file,
                             "Fracture/Fracture toughness",
                             "K_Ic = " + number(settings.toughness) +
                               " is not positive (Criterion = mcts needs it)",
                             "K_Ic > 0 [Pa sqrt(m)]");
        }

        void
        check(const CriterionTraits &traits) const override
        {
          if (traits.dynamic_driver)
            throw InputError(traits.file,
                             "Fracture/Criterion",
                             "stress-intensity factors (mcts) belong to "
                             "quasi-static runs",
                             "Criterion = none, max principal stress or "
                             "critical stretch with Driver/Type = " +
                               traits.driver_name);
        }

        bool
        tracks_tips() const override
        {
          return true;
        }

        Assessment
        evaluate(CrackGrowth<dim>                  &cracks,
                 Coupling::CoupledSystem<dim>      &system,
                 const Coupling::NodalResults<dim> &results,
                 const bool                         allow_growth) override
        {
          return cracks.grow_at_tips(system, results, allow_growth);
        }

        std::vector<std::string>
        history_columns(const CrackGrowth<dim> &cracks) const override
        {
          std::vector<std::string> columns;
          for (unsigned int k = 0; k < cracks.tips().size(); ++k)
            {
              const std::string i = std::to_string(k);
              columns.insert(columns.end(),
                             {"tip" + i + "_x", "tip" + i + "_y"});
              if (dim == 3) // a crack-front point, with K_III
                columns.insert(columns.end(), {"tip" + i + "_z", "K_III" + i});
              columns.insert(columns.end(),
                             {"K_I" + i, "K_II" + i, "K_eq" + i, "J" + i});
            }
          return columns;
        }

        void
        history_values(const CrackGrowth<dim> &cracks,
                       const Assessment &,
                       std::vector<double> &row) const override
        {
          for (const auto &tip : cracks.tips())
            {
              row.insert(row.end(), {tip.evaluated_at[0], tip.evaluated_at[1]});
              if (dim == 3)
                row.insert(row.end(),
                           {tip.evaluated_at[dim - 1], tip.sif.K_III});
              row.insert(row.end(),
                         {tip.sif.K_I, tip.sif.K_II, tip.K_eq, tip.sif.J});
            }
        }

        std::string
        progress(const CrackGrowth<dim> &cracks,
                 const Assessment &) const override
        {
          double K = 0.;
          for (const auto &tip : cracks.tips())
            K = std::max(K, tip.K_eq);
          std::ostringstream s;
          s << "  K_eq/K_Ic " << std::setprecision(3)
            << K / this->parameters.toughness;
          return s.str();
        }

        void
        write_final(const CrackGrowth<dim> &cracks,
                    const Assessment &,
                    IO::JsonWriter &json) const override
        {
          json.begin_object("crack_tips");
          for (unsigned int k = 0; k < cracks.tips().size(); ++k)
            {
              const auto &tip = cracks.tips()[k];
              json.begin_object("tip" + std::to_string(k));
              json.value("x", tip.position[0]);
              json.value("y", tip.position[1]);
              if (dim == 3) // a crack-front point
                {
                  json.value("z", tip.position[dim - 1]);
                  json.value("front", static_cast<unsigned long>(tip.crack));
                  json.value("s", tip.s);
                  json.value("K_III", tip.sif.K_III);
                }
              json.value("active", tip.active ? "true" : "false");
              json.value("K_I", tip.sif.K_I);
              json.value("K_II", tip.sif.K_II);
              json.value("K_eq", tip.K_eq);
              json.value("J", tip.sif.J);
              json.end_object();
            }
          json.end_object();
        }
      };
    } // namespace

    PDFEM_REGISTER_CRITERION(
      MaximumCircumferentialStress,
      "mcts",
      "stress-intensity factors K_I, K_II and J at every crack tip by the "
      "domain interaction integral; a tip grows by 'Growth length' in the "
      "direction of the maximum circumferential tensile stress when K_eq > "
      "'Fracture toughness' (2D; PDLSM-FEM FC 1).")
  } // namespace Fracture
} // namespace pdfem
