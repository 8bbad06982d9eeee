// SPDX-License-Identifier: LGPL-2.1-or-later
// The `max principal stress` crack criterion plugin (PDLSM-FEM's FC 2).
#include <pdfem/base/exceptions.h>
#include <pdfem/fracture/criterion.h>

#include "driving_value_criterion.h"

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
      class MaximumPrincipalStress : public DrivingValueCriterion<dim>
      {
      public:
        MaximumPrincipalStress()
          : DrivingValueCriterion<dim>("max_bond_principal_stress",
                                       "sigma_1/sigma_ult")
        {}

        void
        initialize(const Settings &settings, const std::string &file) override
        {
          DrivingValueCriterion<dim>::initialize(settings, file);
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

      protected:
        double
        scale() const override
        {
          return this->parameters.tensile_strength;
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
