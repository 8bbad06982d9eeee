// SPDX-License-Identifier: LGPL-2.1-or-later
// The `max principal stress` crack criterion plugin (PDLSM-FEM's FC 2).
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
       * Bonds whose averaged nodal stress has a principal value above the
       * tensile strength get a virtual crack normal to that direction
       * (specs/004 §3.2, eq. 43-45; CrackGrowth::grow_by_principal_stress).
       */
      template <int dim>
      class MaximumPrincipalStress : public Criterion<dim>
      {
      public:
        void
        initialize(const Settings &settings, const std::string &file) override
        {
          Criterion<dim>::initialize(settings, file);
          if (!(settings.tensile_strength > 0.))
            throw InputError(file,
                             "Fracture/Tensile strength",
                             "sigma_ult = " +
                               number(settings.tensile_strength) +
                               " is not positive (Criterion = max principal "
                               "stress needs it)",
                             "sigma_ult > 0 [Pa]");
        }

        Assessment
        evaluate(CrackGrowth<dim>                  &cracks,
                 Coupling::CoupledSystem<dim>      &system,
                 const Coupling::NodalResults<dim> &results,
                 const bool                         allow_growth) override
        {
          return cracks.grow_by_principal_stress(system, results, allow_growth);
        }

        std::vector<std::string>
        history_columns(const CrackGrowth<dim> &) const override
        {
          return {"max_bond_principal_stress"};
        }

        void
        history_values(const CrackGrowth<dim> &,
                       const Assessment    &assessment,
                       std::vector<double> &row) const override
        {
          row.push_back(assessment.max_driving_value);
        }

        std::string
        progress(const CrackGrowth<dim> &,
                 const Assessment &assessment) const override
        {
          std::ostringstream s;
          s << "  sigma_1/sigma_ult " << std::setprecision(3)
            << assessment.max_driving_value / this->parameters.tensile_strength;
          return s.str();
        }

        void
        write_final(const CrackGrowth<dim> &,
                    const Assessment &assessment,
                    IO::JsonWriter   &json) const override
        {
          json.value("max_bond_principal_stress", assessment.max_driving_value);
        }
      };
    } // namespace

    PDFEM_REGISTER_CRITERION(
      MaximumPrincipalStress,
      "max principal stress",
      "bonds whose averaged nodal stress has a principal value above "
      "'Tensile strength' get a virtual crack normal to that direction "
      "(PDLSM-FEM FC 2; 2D and 3D).")
  } // namespace Fracture
} // namespace pdfem
