// SPDX-License-Identifier: LGPL-2.1-or-later
// The `pd region` postprocessor of runs with an adaptive PD region.
#include <pdfem/simulator/postprocess.h>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The number of PD cells at every step (history.csv `pd_cells`) when
       * the PD region follows the cracks (Fracture/Adaptive margin > 0).
       */
      template <int dim>
      class PDRegion : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          return this->get_setup().fracture.adaptive_margin > 0.;
        }

        std::vector<std::string>
        history_columns() override
        {
          return {"pd_cells"};
        }

        void
        history_values(std::vector<double> &row) override
        {
          row.push_back(this->get_system().size().n_pd_cells);
        }
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(PDRegion,
                                 "pd region",
                                 "the number of PD cells per step when the PD "
                                 "region follows the cracks.")
  } // namespace Postprocess
} // namespace pdfem
