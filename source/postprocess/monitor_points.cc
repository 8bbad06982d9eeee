// SPDX-License-Identifier: LGPL-2.1-or-later
// The `monitor points` postprocessor of dynamic runs.
#include <pdfem/io/history.h>
#include <pdfem/simulator/postprocess.h>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The displacement of the node nearest to each of `Driver/Monitor
       * points`, as history.csv columns u_<name>_<component>.
       */
      template <int dim>
      class MonitorPoints : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          points = this->get_setup().driver.monitor_points;
          for (const auto &mp : points)
            {
              dealii::Point<dim> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = mp.point[d];
              nodes.push_back(this->get_system().nearest_node(p));
            }
          return !points.empty();
        }

        std::vector<std::string>
        history_columns() override
        {
          std::vector<std::string> columns;
          for (const auto &mp : points)
            for (const auto &c : Coupling::component_names<dim>())
              columns.push_back("u_" + IO::History::column_name(mp.name) + "_" +
                                c);
          return columns;
        }

        void
        history_values(std::vector<double> &row) override
        {
          for (const unsigned int k : nodes)
            {
              const auto d =
                this->get_system().node_displacement(this->get_solution(), k);
              for (unsigned int c = 0; c < dim; ++c)
                row.push_back(d[c]);
            }
        }

      private:
        std::vector<Drivers::MonitorPoint> points;
        std::vector<unsigned int>          nodes;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(MonitorPoints,
                                 "monitor points",
                                 "the displacement of the nodes nearest to "
                                 "Driver/Monitor points, every history row.")
  } // namespace Postprocess
} // namespace pdfem
