// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the fracture module: what the bond criteria (max principal
// stress, critical stretch) report alike.
#ifndef PDFEM_SOURCE_FRACTURE_DRIVING_VALUE_CRITERION_H
#define PDFEM_SOURCE_FRACTURE_DRIVING_VALUE_CRITERION_H

#include <pdfem/base/json_writer.h>
#include <pdfem/fracture/criterion.h>

#include <iomanip>
#include <sstream>
#include <string>

namespace pdfem
{
  namespace Fracture
  {
    /**
     * A criterion whose state is one number, the largest driving value over
     * the bonds (Assessment::max_driving_value): one history.csv column and
     * one summary.json member named @p column, and a progress fragment
     * "label value / scale".
     */
    template <int dim>
    class DrivingValueCriterion : public Criterion<dim>
    {
    public:
      DrivingValueCriterion(const std::string &column, const std::string &label)
        : column(column)
        , label(label)
      {}

      std::vector<std::string>
      history_columns(const CrackGrowth<dim> &) const override
      {
        return {column};
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
        s << "  " << label << " " << std::setprecision(3)
          << assessment.max_driving_value / scale();
        return s.str();
      }

      void
      write_final(const CrackGrowth<dim> &,
                  const Assessment &assessment,
                  IO::JsonWriter   &json) const override
      {
        json.value(column, assessment.max_driving_value);
      }

    protected:
      /// The progress line shows the driving value over this.
      virtual double
      scale() const
      {
        return 1.;
      }

    private:
      const std::string column;
      const std::string label;
    };
  } // namespace Fracture
} // namespace pdfem

#endif
