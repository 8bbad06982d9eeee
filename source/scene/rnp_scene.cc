// SPDX-License-Identifier: LGPL-2.1-or-later
// The run of a scene with Peridynamics/Model = rnp: every mesh vertex is an
// RNP node (specs/000; the model is set up by rnp_model.cc), solved by the
// Newton driver with its stability check (or the static driver), history.csv
// and summary.json as for every scene.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/io/history.h>
#include <pdfem/io/json_writer.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>

#include "rnp_model.h"
#include "rnp_output.h"
#include "scene_internal.h"
#include <sys/resource.h>

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      using namespace dealii;
      using Coupling::component_names;

      namespace
      {
        using clock = std::chrono::steady_clock;

        /// Where an RNP run got to: its last converged state, what the
        /// driver said, and how it ended.
        struct RNPRun
        {
          std::vector<double> last_u;
          double              last_load = 0., peak_load = 0.;
          unsigned int        n_steps = 0;
          /// 1: stable, 0: not, -1: not checked.
          double                 last_stable = -1.;
          Drivers::NewtonOutcome outcome;
          std::string            exit_state = "completed", message;
        };

        /// 2D pre-cracks: the tip p1 advanced to the farthest softened node
        /// (d > 1) within a horizon of the crack's line, ahead of p0. Per
        /// crack: the tip and its advance (none in 3D).
        template <int dim>
        std::vector<std::pair<Point<dim>, double>>
        crack_tips(const RNPModel<dim>                 &m,
                   const std::vector<Mesh::Crack<dim>> &cracks,
                   const std::vector<double>           &d)
        {
          const auto        &x      = m.x;
          const auto        &model  = m.settings;
          const unsigned int n_tips = dim == 2 ? cracks.size() : 0;
          std::vector<std::pair<Point<dim>, double>> tips; // tip, advance
          for (unsigned int k = 0; k < n_tips; ++k)
            {
              const Point<dim>    &p0      = cracks[k].points[0];
              const Point<dim>    &p1      = cracks[k].points[dim - 1];
              const double         L       = p0.distance(p1);
              const Tensor<1, dim> e       = (p1 - p0) / L;
              double               advance = 0.;
              for (unsigned int i = 0; i < x.size(); ++i)
                if (d[i] > 1.)
                  {
                    const Tensor<1, dim> r = x[i] - p0;
                    const double         s = r * e;
                    if (s > 0. && (r - s * e).norm() <= model.horizon)
                      advance = std::max(advance, s - L);
                  }
              tips.emplace_back(p1 + advance * e, advance);
            }
          return tips;
        }

        /// Per Dirichlet set: f_int - f_ext summed over its nodes, times
        /// @p thickness.
        template <int dim>
        std::vector<Tensor<1, dim>>
        reactions(const RNPModel<dim>            &m,
                  const Coupling::RNPSystem<dim> &system,
                  const double                    thickness)
        {
          std::vector<Tensor<1, dim>> R(m.set_names.size());
          const auto                 &fi = system.last_internal_force();
          const auto                 &fe = system.last_external_force();
          for (std::size_t s = 0; s < m.set_names.size(); ++s)
            {
              std::vector<unsigned int> nodes = m.set_nodes[s];
              std::sort(nodes.begin(), nodes.end());
              nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
              for (const unsigned int i : nodes)
                for (unsigned int c = 0; c < dim; ++c)
                  R[s][c] += thickness * (fi[dim * i + c] - fe[dim * i + c]);
            }
          return R;
        }

        /// The softened nodes (d > 1): how many, and their largest x.
        template <int dim>
        void
        softened(const std::vector<Point<dim>> &x,
                 const std::vector<double>     &d,
                 unsigned int                  &count,
                 double                        &x_max)
        {
          count = 0;
          x_max = 0.;
          for (unsigned int i = 0; i < x.size(); ++i)
            if (d[i] > 1.)
              {
                x_max = count == 0 ? x[i][0] : std::max(x_max, x[i][0]);
                ++count;
              }
        }

        /// The columns of history.csv: the common ones first
        /// (scene_internal.h, design.md), then the RNP ones: softened nodes
        /// (d > 1), how far they reach in x, whether the state is stable (1),
        /// not (0), or was not checked (-1), the largest displacements and
        /// the @p n_tips crack tips (see crack_tips()).
        template <int dim>
        std::vector<std::string>
        history_columns(const std::vector<std::string> &set_names,
                        const unsigned int              n_tips)
        {
          std::vector<std::string> columns =
            base_history_columns<dim>(set_names, false);
          for (const char *c : {"softened_nodes", "softened_x_max", "stable"})
            columns.push_back(c);
          for (const auto &c : component_names<dim>())
            columns.push_back("max_abs_displacement_" + c);
          for (unsigned int k = 1; k <= n_tips; ++k)
            for (const char *c : {"_x", "_y"})
              columns.push_back("tip" + std::to_string(k) + c);
          columns.push_back("wall_seconds");
          return columns;
        }

        /**
         * Run the driver of @p setup (arc length, newton or static) on
         * @p system from @p u. The driver's timings go to setup.timings, and
         * the Newton driver's outcome to @p outcome, also when it fails.
         */
        template <int dim>
        void
        run_driver(
          Setup<dim>                                                  &setup,
          const Parameters::Scene                                     &prm,
          const RNPModel<dim>                                         &m,
          Coupling::RNPSystem<dim>                                    &system,
          TrilinosWrappers::MPI::Vector                               &u,
          const std::function<void(const Drivers::StepRecord &)>      &on_step,
          const std::function<void(const Drivers::StabilityReport &)> &on_check,
          Drivers::NewtonOutcome                                      &outcome)
        {
          const auto        &loads   = m.loads;
          const unsigned int n_dofs  = m.n_dofs();
          auto              &timings = setup.timings;
          // f_ext(t) = t q and prescribed values affine in t,
          // u_p(t) = u_p(0) + t w: soft loading (w = 0), hard loading
          // (q = 0) or both. d r / d t = q - K_fp(u) w on the free
          // DoFs.
          std::vector<double> f0(n_dofs), f1(n_dofs), fh(n_dofs),
            u0(n_dofs, 0.), u1(n_dofs, 0.), uh(n_dofs, 0.);
          loads.external_force(0., f0);
          loads.external_force(1., f1);
          loads.external_force(0.5, fh);
          loads.prescribed(0., u0);
          loads.prescribed(1., u1);
          loads.prescribed(0.5, uh);
          double fmax = 0., fdev = 0., umax = 0., udev = 0.;
          auto   w = std::make_shared<std::vector<double>>(n_dofs, 0.);
          for (unsigned int d = 0; d < n_dofs; ++d)
            {
              fmax = std::max(fmax, std::abs(f1[d]));
              fdev = std::max(
                {fdev, std::abs(f0[d]), std::abs(fh[d] - 0.5 * f1[d])});
              if (loads.constrained[d])
                {
                  (*w)[d] = u1[d] - u0[d];
                  umax    = std::max(umax, std::abs((*w)[d]));
                  udev =
                    std::max(udev, std::abs(uh[d] - 0.5 * (u0[d] + u1[d])));
                }
            }
          const bool linear_in_t =
            !(fdev > 1e-12 * fmax || udev > 1e-12 * umax ||
              (fmax == 0. && umax == 0.));
          auto q = std::make_shared<std::vector<double>>(n_dofs, 0.);
          for (unsigned int d = 0; d < n_dofs; ++d)
            if (!loads.constrained[d])
              (*q)[d] = f1[d];
          Drivers::NewtonDriver::LoadDerivative dr_dt;
          if (linear_in_t)
            dr_dt =
              [&system, q, w, umax, n_dofs, constrained = loads.constrained](
                const TrilinosWrappers::MPI::Vector &u,
                double,
                TrilinosWrappers::MPI::Vector &out) {
                system.initialize_vector(out);
                std::vector<double> Kw(n_dofs, 0.);
                if (umax > 0.)
                  system.tangent_product(
                    std::vector<double>(u.begin(), u.end()), *w, Kw);
                for (unsigned int d = 0; d < n_dofs; ++d)
                  if (!constrained[d])
                    out[d] = (*q)[d] - Kw[d];
                out.compress(VectorOperation::insert);
              };

          /// What the driver plugin sees of the RNP run.
          class Host : public Drivers::Host
          {
          public:
            Host(
              Coupling::RNPSystem<dim>                               &system,
              TrilinosWrappers::MPI::Vector                          &u,
              const Drivers::NewtonDriver::LoadDerivative            &dr_dt,
              const bool                                              hard,
              const std::function<void(const Drivers::StepRecord &)> &on_step,
              const std::function<void(const Drivers::StabilityReport &)>
                &on_check)
              : rnp(system)
              , u(u)
              , dr_dt(dr_dt)
              , hard(hard)
              , on_step(on_step)
              , on_check(on_check)
            {}
            Drivers::SystemInterface &
            system() override
            {
              return rnp;
            }
            Drivers::DynamicSystemInterface &
            dynamic_system() override
            {
              // The drivers' check() keeps time integrators away from rnp.
              throw RunFailure("unsupported", "the rnp system has no mass");
            }
            Drivers::SystemInterface::Vector &
            solution() override
            {
              return u;
            }
            void
            initial_velocity(Drivers::SystemInterface::Vector &) override
            {}
            Drivers::StabilityInterface *
            stability() override
            {
              return &rnp;
            }
            // Arc length: whenever loads are linear in t. Newton: the
            // snap-back continuation under hard loading only; under force
            // control a fold is the end of quasi-static growth (the jump is
            // the dynamic, unstable growth).
            Drivers::NewtonDriver::LoadDerivative
            load_derivative(const bool arc_length) override
            {
              return arc_length || hard ?
                       dr_dt :
                       Drivers::NewtonDriver::LoadDerivative();
            }
            Drivers::GrowthCheck
            after_equilibrium(const Drivers::StepRecord &record, bool) override
            {
              on_step(record);
              return Drivers::GrowthCheck();
            }
            void
            after_stability_check(const Drivers::StabilityReport &r) override
            {
              on_check(r);
            }
            bool
            after_time_step(const Drivers::SystemInterface::Vector &,
                            double) override
            {
              return false;
            }
            void
            record_time_step(const Drivers::DynamicRecord &) override
            {}

          private:
            Coupling::RNPSystem<dim>                               &rnp;
            TrilinosWrappers::MPI::Vector                          &u;
            const Drivers::NewtonDriver::LoadDerivative            &dr_dt;
            const bool                                              hard;
            const std::function<void(const Drivers::StepRecord &)> &on_step;
            const std::function<void(const Drivers::StabilityReport &)>
              &on_check;
          } host(system, u, dr_dt, umax > 0., on_step, on_check);

          auto driver = Drivers::create(setup.driver.type, prm.file);
          driver->initialize(setup.driver, prm.file, dim);
          // the driver's outcome and timings, also when it fails
          const auto keep = [&](const bool completed) {
            for (const auto &[phase, seconds] : driver->timings())
              timings[phase] = seconds;
            if (driver->outcome())
              outcome = *driver->outcome();
            else if (completed) // a driver without a stability check
              outcome.last_stable_load = 1.;
          };
          try
            {
              driver->run(host);
            }
          catch (...)
            {
              keep(false);
              throw;
            }
          keep(true);
        }

        /// nodes.csv: position, displacement and damage of each node.
        template <int dim>
        void
        write_nodes_csv(const Setup<dim>               &setup,
                        const std::vector<Point<dim>>  &x,
                        const std::vector<double>      &last_u,
                        const Coupling::RNPSystem<dim> &system)
        {
          std::ofstream out(setup.out_dir + "/nodes.csv");
          out << std::setprecision(12);
          const auto names = component_names<dim>();
          for (const auto &c : names)
            out << c << ",";
          for (const auto &c : names)
            out << "u_" << c << ",";
          out << "damage\n";
          for (unsigned int i = 0; i < x.size(); ++i)
            {
              for (unsigned int c = 0; c < dim; ++c)
                out << x[i][c] << ",";
              for (unsigned int c = 0; c < dim; ++c)
                out << last_u[dim * i + c] << ",";
              out << system.damage_history()[i] << "\n";
            }
        }

        /// summary.json of the run.
        template <int dim>
        void
        write_summary(Setup<dim>                     &setup,
                      MPI_Comm                        comm,
                      const RNPModel<dim>            &m,
                      const Coupling::RNPSystem<dim> &system,
                      const RNPPatchTest             &patch,
                      const RNPRun                   &run,
                      const double                    thickness)
        {
          const auto   &x        = m.x;
          const auto   &elements = m.elements;
          const auto   &model    = m.settings;
          const auto   &outcome  = run.outcome;
          auto         &timings  = setup.timings;
          const auto    R        = reactions(m, system, thickness);
          struct rusage usage;
          getrusage(RUSAGE_SELF, &usage);

          std::ofstream  out(setup.out_dir + "/summary.json");
          IO::JsonWriter json(out);
          json.begin_object();
          {
            // the problem sizes every driver writes (scene_internal.h); the
            // RNP-only ones go to "rnp"
            Coupling::ProblemSize size;
            size.n_nodes    = x.size();
            size.n_pd_nodes = std::count(m.pd_node.begin(), m.pd_node.end(), 1);
            std::vector<std::uint8_t> in_fe(x.size(), 0);
            for (const auto &dofs : elements.dofs)
              for (const unsigned int d : dofs)
                in_fe[d / dim] = 1;
            for (unsigned int i = 0; i < x.size(); ++i)
              size.n_interface_nodes += m.pd_node[i] && in_fe[i];
            size.n_cells = setup.tria->n_active_cells();
            size.n_pd_cells =
              setup.tria->n_active_cells() - elements.dofs.size();
            size.n_dofs  = m.n_dofs();
            size.n_bonds = system.n_bonds();
            size.n_matrix_entries =
              system.matrix().size() * (system.matrix().bandwidth() + 1);
            Coupling::ProblemSize final_size = size;
            final_size.n_decoupled_nodes     = system.n_decoupled_nodes();
            write_summary_header(
              json, setup, comm, run.exit_state, run.message, size, final_size);
          }
          json.begin_object("rnp");
          json.value("fe_cells",
                     static_cast<unsigned long>(elements.dofs.size()));
          json.value("cut_bonds",
                     static_cast<unsigned long>(system.n_cut_bonds()));
          json.value("bandwidth",
                     static_cast<unsigned long>(system.matrix().bandwidth()));
          json.value("C", model.C);
          json.value("beta", model.beta);
          json.value("horizon", model.horizon);
          json.value("spacing", m.spacing);
          json.value("r_c", 1. / std::sqrt(2. * model.beta));
          json.end_object();
          if (patch.modes > 0)
            {
              json.begin_object("patch_test");
              json.value("strain_modes",
                         static_cast<unsigned long>(patch.modes));
              json.value("held_nodes",
                         static_cast<unsigned long>(patch.held_nodes));
              json.value("max_relative_error", patch.error);
              json.value("max_relative_ghost_force", patch.ghost_force);
              json.end_object();
            }
          json.value("steps", static_cast<unsigned long>(run.n_steps));
          json.begin_object("stability");
          json.value("last_stable_load_factor", outcome.last_stable_load);
          json.value("failure_load_factor", outcome.failure_load);
          json.value("peak_load_factor", run.peak_load);
          json.value("step_cuts", static_cast<unsigned long>(outcome.n_cuts));
          json.value("unstable_states",
                     static_cast<unsigned long>(outcome.n_unstable_states));
          json.value("snap_backs",
                     static_cast<unsigned long>(outcome.n_snap_backs));
          json.value("path_states",
                     static_cast<unsigned long>(outcome.n_path_states));
          json.value("negative_eigenvalues",
                     static_cast<unsigned long>(outcome.last_check.n_negative));
          json.value("smallest_relative_pivot",
                     outcome.last_check.smallest_relative_pivot);
          json.end_object();

          json.begin_object("final");
          json.value("load_factor", run.last_load);
          const auto comps = component_names<dim>();
          for (const bool take_max : {true, false})
            {
              json.begin_object(take_max ? "max_displacement" :
                                           "min_displacement");
              for (unsigned int c = 0; c < dim; ++c)
                {
                  double value = take_max ?
                                   -std::numeric_limits<double>::infinity() :
                                   std::numeric_limits<double>::infinity();
                  for (unsigned int i = 0; i < x.size(); ++i)
                    value = take_max ?
                              std::max(value, run.last_u[dim * i + c]) :
                              std::min(value, run.last_u[dim * i + c]);
                  json.value(comps[c], value);
                }
              json.end_object();
            }
          const auto  &d = system.damage_history();
          unsigned int n_soft;
          double       soft_x;
          softened(x, d, n_soft, soft_x);
          json.value("max_damage", *std::max_element(d.begin(), d.end()));
          json.value("softened_nodes", static_cast<unsigned long>(n_soft));
          json.value("softened_x_max", soft_x);
          {
            const auto tips = crack_tips(m, setup.settings.cracks, d);
            for (unsigned int k = 0; k < tips.size(); ++k)
              {
                json.begin_object("tip" + std::to_string(k + 1));
                for (unsigned int c = 0; c < dim; ++c)
                  json.value(comps[c], tips[k].first[c]);
                json.value("advance", tips[k].second);
                json.end_object();
              }
          }
          json.begin_object("reaction");
          for (std::size_t s = 0; s < m.set_names.size(); ++s)
            {
              json.begin_object(m.set_names[s]);
              for (unsigned int c = 0; c < dim; ++c)
                json.value(comps[c], R[s][c]);
              json.end_object();
            }
          json.end_object();
          json.end_object();
          json.begin_object("timings");
          for (const char *phase :
               {"mesh", "setup", "assembly", "solve", "output", "total"})
            json.value(phase, timings[phase]);
          json.end_object();
          json.value("peak_memory_mb_rank0", usage.ru_maxrss / 1024.);
          json.end_object();
        }
      } // namespace

      template <int dim>
      int
      execute_rnp(Setup<dim>              &setup,
                  const Parameters::Scene &prm,
                  const RunOptions        &options,
                  MPI_Comm                 comm)
      {
        const auto         &tria      = *setup.tria;
        const auto         &settings  = setup.settings;
        const RNPModel<dim> m         = make_rnp_model(setup, prm, comm);
        const auto         &x         = m.x;
        const auto         &pd_node   = m.pd_node;
        const auto         &model     = m.settings;
        const unsigned int  n_dofs    = m.n_dofs();
        const double        thickness = dim == 2 ? prm.material.thickness : 1.;

        std::function<bool(const Point<dim> &, const Point<dim> &)> cut;
        if (!settings.cracks.empty())
          cut = [cracks = settings.cracks](const Point<dim> &a,
                                           const Point<dim> &b) {
            return Mesh::cut_by_any<dim>(cracks, a, b);
          };
        Coupling::RNPSystem<dim> system(
          x,
          m.volume,
          model,
          cut,
          m.loads,
          prm.rnp.tangent == "analytic" ?
            Coupling::RNPTangent::analytic :
            Coupling::RNPTangent::finite_difference,
          pd_node,
          m.elements,
          m.fe_members,
          m.energy_weight);
        const RNPPatchTest patch = rnp_patch_test(setup, m);

        auto &timings          = setup.timings;
        timings["setup"]       = seconds_since(setup.setup_start);
        std::ostream *progress = options.quiet ? nullptr : &std::cout;
        if (progress)
          *progress << "pdfem " << PDFEM_VERSION << ": " << setup.file << "\n"
                    << "  " << dim << "D RNP, " << x.size() << " nodes ("
                    << std::count(pd_node.begin(), pd_node.end(), 1) << " PD, "
                    << m.elements.dofs.size() << " FE cells), "
                    << system.n_bonds() << " bonds (" << system.n_cut_bonds()
                    << " cut by pre-cracks), horizon " << model.horizon
                    << ", C = " << model.C << ", beta = " << model.beta
                    << ", band " << system.matrix().bandwidth() << std::endl;
        if (progress && patch.modes > 0)
          *progress << "  patch test of the RNP-FE coupling (" << patch.modes
                    << " strain modes, " << patch.held_nodes
                    << " boundary nodes held): max error " << patch.error
                    << " of the affine field, ghost force " << patch.ghost_force
                    << " sigma h^(d-1)" << std::endl;

        const unsigned int n_tips = dim == 2 ? settings.cracks.size() : 0;
        IO::History        history(setup.out_dir + "/history.csv",
                            history_columns<dim>(m.set_names, n_tips),
                            true);

        TrilinosWrappers::MPI::Vector u;
        system.initialize_vector(u);
        RNPRun run;
        run.last_u.assign(n_dofs, 0.);
        // -1: not checked; the Newton driver records stable states only,
        // the arc length driver reports every check before the step
        run.last_stable     = -1.;
        const auto on_check = [&](const Drivers::StabilityReport &report) {
          run.last_stable = report.stable() ? 1. : 0.;
        };
        const auto on_step = [&](const Drivers::StepRecord &record) {
          run.n_steps = record.step;
          run.last_u.assign(u.begin(), u.end());
          run.last_load = record.load_factor;
          run.peak_load = std::max(run.peak_load, run.last_load);
          system.update_damage_history(run.last_u);
          const auto  &d    = system.damage_history();
          const double dmax = *std::max_element(d.begin(), d.end());
          unsigned int n_soft;
          double       soft_x;
          softened(x, d, n_soft, soft_x);
          std::vector<double> row = {double(record.step),
                                     record.time,
                                     record.load_factor,
                                     double(record.newton_iterations),
                                     double(record.linear_iterations),
                                     record.relative_residual,
                                     0.,
                                     dmax};
          for (const auto &R : reactions(m, system, thickness))
            for (unsigned int c = 0; c < dim; ++c)
              row.push_back(R[c]);
          row.push_back(n_soft);
          row.push_back(soft_x);
          row.push_back(run.last_stable);
          for (unsigned int c = 0; c < dim; ++c)
            {
              double u_max = 0.;
              for (unsigned int i = 0; i < x.size(); ++i)
                u_max = std::max(u_max, std::abs(run.last_u[dim * i + c]));
              row.push_back(u_max);
            }
          for (const auto &tip : crack_tips(m, settings.cracks, d))
            for (unsigned int c = 0; c < dim; ++c)
              row.push_back(tip.first[c]);
          row.push_back(seconds_since(setup.total_start));
          history.add_row(row);
          if (progress)
            *progress << "Step " << std::setw(4) << record.step
                      << "  t = " << std::setw(8) << std::setprecision(5)
                      << record.load_factor << "  iterations "
                      << record.newton_iterations
                      << "  |r|/|f| = " << std::scientific
                      << std::setprecision(2) << record.relative_residual
                      << std::defaultfloat << "  max damage "
                      << std::setprecision(4) << dmax << "  softened nodes "
                      << n_soft << std::endl;
        };

        try
          {
            run_driver(
              setup, prm, m, system, u, on_step, on_check, run.outcome);
          }
        catch (const RunFailure &e)
          {
            run.exit_state = e.exit_state;
            run.message    = e.what();
            std::cerr << "pdfem: run stopped: " << run.message << std::endl;
          }

        // ---- results: the last converged state
        const auto start = clock::now();
        {
          TrilinosWrappers::MPI::Vector v, r;
          system.initialize_vector(v);
          for (unsigned int d = 0; d < n_dofs; ++d)
            v[d] = run.last_u[d];
          v.compress(VectorOperation::insert);
          system.residual(v, run.last_load, r, false);
        }
        if (setup.write_vtu)
          write_rnp_vtu<dim>(setup.out_dir,
                             tria,
                             m.node_of,
                             run.last_u,
                             system.damage_history(),
                             pd_node,
                             run.last_load);
        if (setup.write_nodes_csv)
          write_nodes_csv(setup, x, run.last_u, system);
        timings["output"] = seconds_since(start);
        timings["total"]  = seconds_since(setup.total_start);
        write_summary(setup, comm, m, system, patch, run, thickness);

        if (progress)
          *progress << "Exit state: " << run.exit_state << ". Results in "
                    << setup.out_dir << "/" << std::endl;
        return run.exit_state == "completed" ? ExitCode::completed :
                                               ExitCode::run_failure;
      }

#define INSTANTIATE(dim)                                   \
  template int execute_rnp<dim>(Setup<dim> &,              \
                                const Parameters::Scene &, \
                                const RunOptions &,        \
                                MPI_Comm);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem