// SPDX-License-Identifier: LGPL-2.1-or-later
// The `lps fft damage` postprocessor: where the nodes the energy criterion
// of "lps fft" failed lie, every history row (doc/user_guide.md §2a‴).
#include <pdfem/base/config.h>
#include <pdfem/pd_models/lps_fft.h>
#include <pdfem/simulator/postprocess.h>

#include <string>
#include <vector>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * With `Peridynamics/Model = lps fft` and `LPS fft/Damage = energy`
       * (specs/002 §1.6): the failed body nodes (integrity lambda = 0) and
       * their bounding box, as history.csv columns failed_nodes,
       * failed_min_<c> and failed_max_<c> (c = x, y, z; 0 while no node
       * failed). A crack that runs in +x has its tip at failed_max_x, so
       * that the tip speed is the rate of that column; a crack that
       * branches widens the box across its line.
       */
      template <int dim>
      class LpsFftDamage : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          model = dynamic_cast<const PDModels::LpsFft<dim> *>(
            &this->get_system().pd_model());
          return model != nullptr && model->damage_active();
        }

        std::vector<std::string>
        history_columns() override
        {
          std::vector<std::string> columns = {"failed_nodes"};
          const char               axis[3] = {'x', 'y', 'z'};
          for (unsigned int c = 0; c < dim; ++c)
            for (const char *end : {"min", "max"})
              columns.push_back(std::string("failed_") + end + "_" + axis[c]);
          return columns;
        }

        void
        history_values(std::vector<double> &row) override
        {
          const PDModels::FailedNodes<dim> failed = model->failed_nodes();
          row.push_back(double(failed.n));
          for (unsigned int c = 0; c < dim; ++c)
            {
              row.push_back(failed.lo[c]);
              row.push_back(failed.hi[c]);
            }
        }

      private:
        const PDModels::LpsFft<dim> *model = nullptr;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(LpsFftDamage,
                                 "lps fft damage",
                                 "lps fft with LPS fft/Damage = energy: the "
                                 "failed nodes and their bounding box, every "
                                 "history row.")
  } // namespace Postprocess
} // namespace pdfem
