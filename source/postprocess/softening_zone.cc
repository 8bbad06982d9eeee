// SPDX-License-Identifier: LGPL-2.1-or-later
// The `softening zone` postprocessor of runs with a nonlinear PD model.
#include <pdfem/base/json_writer.h>
#include <pdfem/simulator/postprocess.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * Where a softening PD model (rnp: damage |S| sqrt|xi| / r_c, 1 where
       * a bond passes its peak force, specs/000 (18)) has softened: per
       * node the largest damage of any recorded state, the nodes past 1
       * ("softened"), how far they reach in x, and per 2D pre-crack its
       * tip advanced to the farthest softened node within a horizon of
       * the crack's line ahead of its first point. history.csv
       * `softened_nodes`, `softened_x_max`, `max_abs_displacement_<c>`,
       * `tip<k>_<c>`; summary.json "final": the same and `tip<k>.advance`.
       */
      template <int dim>
      class SofteningZone : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          if (this->get_system().pd_model().linear() || this->is_dynamic())
            return false;
          const auto &h = this->get_system().horizons();
          horizon = h.empty() ? 0. : *std::max_element(h.begin(), h.end());
          if (dim == 2)
            cracks = this->get_setup().settings.cracks;
          return true;
        }

        std::vector<std::string>
        history_columns() override
        {
          std::vector<std::string> columns = {"softened_nodes",
                                              "softened_x_max"};
          for (const auto &c : Coupling::component_names<dim>())
            columns.push_back("max_abs_displacement_" + c);
          for (unsigned int k = 1; k <= cracks.size(); ++k)
            for (const auto &c : Coupling::component_names<dim>())
              columns.push_back("tip" + std::to_string(k) + "_" + c);
          return columns;
        }

        void
        history_values(std::vector<double> &row) override
        {
          const auto &r = this->get_nodal_results();
          damage.resize(r.damage.size(), 0.);
          Tensor1 u_max;
          for (std::size_t k = 0; k < r.damage.size(); ++k)
            {
              damage[k] = std::max(damage[k], r.damage[k]);
              for (unsigned int c = 0; c < dim; ++c)
                u_max[c] = std::max(u_max[c], std::abs(r.displacement[k][c]));
            }
          measure(r.position);
          row.push_back(n_softened);
          row.push_back(x_max);
          for (unsigned int c = 0; c < dim; ++c)
            row.push_back(u_max[c]);
          for (const auto &tip : tips)
            for (unsigned int c = 0; c < dim; ++c)
              row.push_back(tip.first[c]);
        }

        void
        write_final(IO::JsonWriter &json) const override
        {
          json.value("softened_nodes", static_cast<unsigned long>(n_softened));
          json.value("softened_x_max", x_max);
          const auto comps = Coupling::component_names<dim>();
          for (unsigned int k = 0; k < tips.size(); ++k)
            {
              json.begin_object("tip" + std::to_string(k + 1));
              for (unsigned int c = 0; c < dim; ++c)
                json.value(comps[c], tips[k].first[c]);
              json.value("advance", tips[k].second);
              json.end_object();
            }
        }

      private:
        using Tensor1 = dealii::Tensor<1, dim>;

        /// The softened nodes and the tips from the running damage.
        void
        measure(const std::vector<dealii::Point<dim>> &x)
        {
          n_softened = 0;
          x_max      = 0.;
          for (std::size_t k = 0; k < x.size(); ++k)
            if (damage[k] > 1.)
              {
                x_max = n_softened == 0 ? x[k][0] : std::max(x_max, x[k][0]);
                ++n_softened;
              }
          tips.clear();
          for (const auto &crack : cracks)
            {
              const dealii::Point<dim> &p0      = crack.points[0];
              const dealii::Point<dim> &p1      = crack.points[dim - 1];
              const double              L       = p0.distance(p1);
              const Tensor1             e       = (p1 - p0) / L;
              double                    advance = 0.;
              for (std::size_t k = 0; k < x.size(); ++k)
                if (damage[k] > 1.)
                  {
                    const Tensor1 r = x[k] - p0;
                    const double  s = r * e;
                    if (s > 0. && (r - s * e).norm() <= horizon)
                      advance = std::max(advance, s - L);
                  }
              tips.emplace_back(p1 + advance * e, advance);
            }
        }

        double                                             horizon = 0.;
        std::vector<Mesh::Crack<dim>>                      cracks;
        std::vector<double>                                damage;
        unsigned int                                       n_softened = 0;
        double                                             x_max      = 0.;
        std::vector<std::pair<dealii::Point<dim>, double>> tips;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(
      SofteningZone,
      "softening zone",
      "the nodes a softening PD model (rnp) has taken past the peak bond "
      "force, how far they reach, and the 2D pre-cracks' advanced tips.")
  } // namespace Postprocess
} // namespace pdfem
