// SPDX-License-Identifier: LGPL-2.1-or-later
// The `critical stretch` crack criterion plugin.
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
       * A bond breaks when its stretch (|xi + eta| - |xi|) / |xi| exceeds
       * s_c, given or from G_c by the bond-based relation (Silling & Askari
       * 2005; Ha & Bobaru 2010; CrackGrowth::break_by_stretch).
       */
      template <int dim>
      class CriticalStretch : public DrivingValueCriterion<dim>
      {
      public:
        CriticalStretch()
          : DrivingValueCriterion<dim>("max_stretch_ratio", "s/s_c")
        {}

        void
        initialize(const Settings &settings, const std::string &file) override
        {
          DrivingValueCriterion<dim>::initialize(settings, file);
          if (!(settings.critical_stretch > 0.) &&
              !(settings.fracture_energy > 0.))
            throw InputError(file,
                             "Fracture/Critical stretch",
                             "neither the critical stretch nor the fracture "
                             "energy is positive (Criterion = critical "
                             "stretch needs one)",
                             "Critical stretch > 0, or Fracture energy > 0 "
                             "[J/m^2]");
        }

        Assessment
        evaluate(CrackGrowth<dim>                  &cracks,
                 Coupling::CoupledSystem<dim>      &system,
                 const Coupling::NodalResults<dim> &results,
                 const bool                         allow_growth) override
        {
          return cracks.break_by_stretch(system, results, allow_growth);
        }
      };
    } // namespace

    PDFEM_REGISTER_CRITERION(
      CriticalStretch,
      "critical stretch",
      "a bond breaks when its stretch (|xi + eta| - |xi|) / |xi| exceeds "
      "'Critical stretch' (2D and 3D; quasi-static and dynamic).")
  } // namespace Fracture
} // namespace pdfem
