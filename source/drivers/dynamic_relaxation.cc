// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/dynamic_relaxation.h>
#include <pdfem/drivers/interface.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "timing.h"

namespace pdfem
{
  namespace Drivers
  {
    namespace
    {
      using internal::clock;
      using internal::seconds_since;

      /// The fixed damping of `Dynamic relaxation/Damping`, or -1 for
      /// adaptive; InputError naming @p file otherwise.
      double
      parse_damping(const std::string &text, const std::string &file)
      {
        if (text == "adaptive")
          return -1.;
        double c = -1.;
        if (!ParameterTools::parse_number(text, c) || !(c >= 0. && c < 2.))
          throw InputError(file,
                           "Driver/Dynamic relaxation/Damping",
                           "'" + text +
                             "' is neither 'adaptive' nor a "
                             "damping coefficient in [0, 2)",
                           "adaptive, or 0 <= c < 2");
        return c;
      }
    } // namespace

    void
    check_relaxation_settings(const Settings &settings, const std::string &file)
    {
      parse_damping(settings.relaxation_damping, file);
      if (!(settings.relaxation_density_factor > 0.))
        throw InputError(file,
                         "Driver/Dynamic relaxation/Density factor",
                         number(settings.relaxation_density_factor) +
                           " is not positive",
                         "factor > 0 (>= 1 is stable for a linear model)");
    }

    void
    check_relaxation_traits(const RunTraits &traits)
    {
      if (!traits.assembled_matrix && !traits.tangent_rows)
        throw InputError(traits.file,
                         "Linear solver/Type",
                         "dynamic relaxation takes its fictitious density "
                         "from the rows of the tangent, which the "
                         "matrix-free solver neither builds nor, for the " +
                           traits.model_name + " model, bounds row by row",
                         "direct, cg or gmres with an assembled "
                         "preconditioner");
    }

    DynamicRelaxation::DynamicRelaxation(const Settings &settings)
      : settings(settings)
      , fixed_damping(parse_damping(settings.relaxation_damping, ""))
    {}

    StepRecord
    DynamicRelaxation::relax(SystemInterface         &system,
                             SystemInterface::Vector &u,
                             const double             t,
                             const double             t_of_u,
                             const unsigned int       step)
    {
      using Vector = SystemInterface::Vector;
      // The load of iteration `it`: from t_of_u to t over the ramp, then t.
      const unsigned int ramp    = settings.relaxation_ramp_iterations;
      const auto         load_at = [&](const unsigned int it) {
        return it >= ramp ? t : t_of_u + (t - t_of_u) * double(it) / ramp;
      };
      if (ramp == 0 && t_of_u > 0. && t != t_of_u)
        u *= t / t_of_u;
      double t_now = load_at(0);
      system.apply_dirichlet(u, t_now);

      StepRecord record;
      record.step        = step;
      record.time        = t;
      record.load_factor = t;

      auto   start = clock::now();
      Vector density, r, r_old, v;
      double norm = system.residual(u, t_now, r, true);
      system.stiffness_row_bounds(density);
      time_spent.assembly += seconds_since(start);
      start                    = clock::now();
      const double   reference = std::max(norm, system.force_scale());
      const MPI_Comm comm      = r.get_mpi_communicator();

      // The updates work on the local arrays (one pass each, no element
      // access through the vector class).
      const unsigned int n      = r.locally_owned_size();
      double            *lambda = density.trilinos_vector()[0];
      for (unsigned int i = 0; i < n; ++i)
        lambda[i] = lambda[i] > 0. ?
                      0.25 * settings.relaxation_density_factor * lambda[i] :
                      1.;
      v     = r;
      r_old = r;
      {
        double       *vv = v.trilinos_vector()[0];
        const double *rv = r.trilinos_vector()[0];
        for (unsigned int i = 0; i < n; ++i)
          vv[i] = 0.5 * rv[i] / lambda[i];
      }
      for (unsigned int it = 0;; ++it)
        {
          const double scale       = std::max(reference, system.force_scale());
          record.relative_residual = scale > 0. ? norm / scale : norm;
          if (!std::isfinite(norm))
            throw RunFailure("diverged",
                             "the residual is not finite at load step " +
                               std::to_string(step) + " after " +
                               std::to_string(it) +
                               " relaxation iterations: a larger Dynamic "
                               "relaxation/Density factor is more stable");
          if (t_now == t && (norm <= settings.residual_tolerance * scale ||
                             (scale == 0. && norm == 0.)))
            break;
          progress([&]() {
            std::ostringstream s;
            s << "  load factor " << t << ": relaxation iteration " << it
              << ", |r|/|f| = " << record.relative_residual;
            return s.str();
          });
          if (it == settings.relaxation_max_iterations)
            {
              std::ostringstream s;
              s << "no equilibrium at load step " << step << " after " << it
                << " relaxation iterations (relative residual "
                << record.relative_residual << ")";
              throw RunFailure("diverged", s.str());
            }
          if (it > 0)
            {
              // The damping from the local stiffness of this iteration.
              double c = fixed_damping;
              if (c < 0.)
                {
                  const double *uv          = u.trilinos_vector()[0];
                  const double *vv          = v.trilinos_vector()[0];
                  const double *rv          = r.trilinos_vector()[0];
                  const double *ro          = r_old.trilinos_vector()[0];
                  double        quotient[2] = {0., 0.};
                  for (unsigned int i = 0; i < n; ++i)
                    if (vv[i] != 0.)
                      {
                        const double K_local =
                          -(rv[i] - ro[i]) / (lambda[i] * vv[i]);
                        quotient[0] += uv[i] * K_local * uv[i];
                        quotient[1] += uv[i] * uv[i];
                      }
                  dealii::Utilities::MPI::sum(
                    dealii::ArrayView<const double>(quotient, 2),
                    comm,
                    dealii::ArrayView<double>(quotient, 2));
                  c = quotient[0] > 0. && quotient[1] > 0. ?
                        2. * std::sqrt(quotient[0] / quotient[1]) :
                        0.;
                  if (c >= 2.)
                    c = 1.9;
                }
              double       *vv = v.trilinos_vector()[0];
              const double *rv = r.trilinos_vector()[0];
              for (unsigned int i = 0; i < n; ++i)
                vv[i] = ((2. - c) * vv[i] + 2. * rv[i] / lambda[i]) / (2. + c);
            }
          u += v;
          r_old = r;
          t_now = load_at(it + 1);
          if (it < ramp)
            system.apply_dirichlet(u, t_now);
          time_spent.solve += seconds_since(start);
          start = clock::now();
          norm  = system.residual(u, t_now, r, false);
          time_spent.assembly += seconds_since(start);
          start = clock::now();
          ++record.newton_iterations;
        }
      time_spent.solve += seconds_since(start);
      total_iterations += record.newton_iterations;
      progress.restart();
      return record;
    }

    void
    DynamicRelaxation::run(
      SystemInterface                               &system,
      SystemInterface::Vector                       &u,
      const std::function<void(const StepRecord &)> &on_step,
      const Resume                                  &resume)
    {
      run_load_steps(
        settings.load_steps,
        resume,
        [&](const double t, const double t_of_u, const unsigned int step) {
          return relax(system, u, t, t_of_u, step);
        },
        on_step);
    }

    namespace
    {
      /// The `dynamic relaxation` driver plugin: DynamicRelaxation over the
      /// host's system; a criterion is evaluated after each step but grows
      /// nothing.
      class DynamicRelaxationRun : public Interface
      {
      public:
        void
        initialize(const Settings    &settings,
                   const std::string &file,
                   const int          dim) override
        {
          Interface::initialize(settings, file, dim);
          check_relaxation_settings(settings, file);
        }

        bool
        needs_assembled_matrix() const override
        {
          return true;
        }

        void
        check(const RunTraits &traits) const override
        {
          Interface::check(traits);
          check_relaxation_traits(traits);
        }

        void
        run(Host &host) override
        {
          driver = std::make_unique<DynamicRelaxation>(parameters);
          driver->set_progress(host.progress_pulse());
          driver->run(
            host.system(),
            host.solution(),
            [&host](const StepRecord &record) {
              host.after_equilibrium(record, false);
            },
            resume_through(host));
        }

        bool
        resumable() const override
        {
          return true;
        }

        bool
        handles_nonlinear_models() const override
        {
          return true;
        }

        void
        write_summary(IO::JsonWriter &json) const override
        {
          json.value("relaxation_iterations",
                     driver ? driver->iterations() : 0ul);
          json.value("density_factor", parameters.relaxation_density_factor);
          json.value("damping", parameters.relaxation_damping);
        }

        std::map<std::string, double>
        timings() const override
        {
          return phase_timings(driver ? &driver->timings() : nullptr);
        }

      private:
        std::unique_ptr<DynamicRelaxation> driver;
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(DynamicRelaxationRun,
                          "dynamic relaxation",
                          "adaptive dynamic relaxation (Kilic & Madenci): "
                          "each of 'Load steps' increments of t relaxed to "
                          "equilibrium by damped pseudo-dynamics; forces only.")
  } // namespace Drivers
} // namespace pdfem
