// SPDX-License-Identifier: LGPL-2.1-or-later
// Shared parts of the dynamic drivers: stable time step by power iteration,
// energy balance, instability report.
#include <pdfem/base/exceptions.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>

#include "dynamics_internal.h"

namespace pdfem
{
  namespace Drivers
  {
    using dealii::Utilities::MPI::sum;

    StabilityEstimate
    estimate_stable_time_step(DynamicSystemInterface &system,
                              const unsigned int      iterations)
    {
      using internal::Vector;
      const auto    start = internal::clock::now();
      const Vector &m     = system.lumped_mass();
      Vector        x, y;
      system.initialize_vector(x);
      system.initialize_vector(y);
      const auto     held = internal::held_flags(system, x);
      const auto     n    = x.locally_owned_size();
      const double  *mv   = m.begin();
      const MPI_Comm comm = x.get_mpi_communicator();

      // Start vector: pseudo-random from node to node (contains the
      // highest modes), a function of the node positions only, so the
      // estimate does not depend on the number of ranks.
      system.pseudo_random(x);
      double *xv = x.begin();
      for (std::size_t i = 0; i < n; ++i)
        if (held[i])
          xv[i] = 0.;

      StabilityEstimate e;
      double            previous = 0.;
      for (unsigned int it = 0; it < iterations; ++it)
        {
          // y = K x on the free DoFs; z = M^-1 y overwrites y.
          system.internal_force(x, y);
          double *yv      = y.begin();
          xv              = x.begin();
          double local[3] = {0., 0., 0.}; // x.Kx, x.Mx, z.Mz
          for (std::size_t i = 0; i < n; ++i)
            if (held[i] || !(mv[i] > 0.))
              yv[i] = 0.;
            else
              {
                local[0] += xv[i] * yv[i];
                local[1] += xv[i] * mv[i] * xv[i];
                yv[i] /= mv[i];
                local[2] += yv[i] * mv[i] * yv[i];
              }
          double global[3];
          dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, 3),
                                      comm,
                                      dealii::ArrayView<double>(global, 3));
          if (!(global[1] > 0.) || !(global[2] > 0.))
            break;
          const double rayleigh = global[0] / global[1];
          const double ratio    = std::sqrt(global[2] / global[1]);
          const double lambda   = std::max(rayleigh, ratio);
          e.last_change =
            previous > 0. ? std::abs(lambda - previous) / lambda : 1.;
          previous           = lambda;
          e.lambda_max       = lambda;
          e.iterations       = it + 1;
          const double scale = 1. / std::sqrt(global[2]);
          for (std::size_t i = 0; i < n; ++i)
            xv[i] = yv[i] * scale;
        }
      if (e.lambda_max > 0.)
        {
          e.omega_max          = std::sqrt(e.lambda_max);
          e.critical_time_step = 2. / e.omega_max;
        }
      (void)start;
      return e;
    }

    namespace internal
    {
      void
      EnergyAccount::applied_force(const Vector            &f_int,
                                   const Vector            &f_ext,
                                   const std::vector<char> &held,
                                   Vector                  &force) const
      {
        if (force.size() != f_int.size())
          force.reinit(f_int.locally_owned_elements(),
                       f_int.get_mpi_communicator());
        double       *fv = force.begin();
        const double *iv = f_int.begin();
        const double *ev = f_ext.begin();
        for (std::size_t i = 0; i < held.size(); ++i)
          fv[i] = held[i] ? iv[i] : ev[i];
      }

      void
      EnergyAccount::start(const Vector            &u,
                           const Vector            &f_int,
                           const Vector            &f_ext,
                           const std::vector<char> &held,
                           const double             kinetic_energy,
                           MPI_Comm                 communicator)
      {
        comm = communicator;
        u_old.reinit(u.locally_owned_elements(), comm);
        u_old = u;
        applied_force(f_int, f_ext, held, force_old);
        kinetic    = kinetic_energy;
        strain     = 0.5 * (u * f_int);
        e0         = kinetic + strain;
        work       = 0.;
        dissipated = 0.;
        peak       = std::abs(e0);
        peak_total = std::abs(e0);
        totals.assign(1, kinetic + strain);
        errors.clear();
      }

      void
      EnergyAccount::step(const Vector            &u,
                          const Vector            &f_int,
                          const Vector            &f_ext,
                          const std::vector<char> &held,
                          const double             kinetic_energy)
      {
        // W += 1/2 (F_old + F_new) . (u - u_old); strain = 1/2 u . f_int.
        const double *uv       = u.begin();
        double       *ov       = u_old.begin();
        double       *fo       = force_old.begin();
        const double *iv       = f_int.begin();
        const double *ev       = f_ext.begin();
        double        local[2] = {0., 0.};
        for (std::size_t i = 0; i < held.size(); ++i)
          {
            const double f = held[i] ? iv[i] : ev[i];
            local[0] += 0.5 * (fo[i] + f) * (uv[i] - ov[i]);
            local[1] += uv[i] * iv[i];
            fo[i] = f;
            ov[i] = uv[i];
          }
        double global[2];
        dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, 2),
                                    comm,
                                    dealii::ArrayView<double>(global, 2));
        work += global[0];
        strain  = 0.5 * global[1];
        kinetic = kinetic_energy;
        peak    = std::max(peak, std::abs(e0 + work));
        peak_total =
          std::max(peak_total, std::abs(kinetic + strain + dissipated));
        totals.push_back(kinetic + strain + dissipated);
        if (totals.size() > 11)
          totals.pop_front();
        errors.push_back(error());
        if (errors.size() > 4)
          errors.pop_front();
      }

      void
      EnergyAccount::released(const double energy)
      {
        dissipated += energy;
        strain -= energy;
        if (!errors.empty())
          errors.back() = error();
      }

      void
      EnergyAccount::bonds_broke(const Vector &u, const Vector &f_int)
      {
        const double after = 0.5 * (u * f_int);
        dissipated += strain - after;
        strain = after;
        if (!errors.empty())
          errors.back() = error();
      }

      void
      EnergyAccount::record(DynamicRecord &r) const
      {
        r.kinetic_energy    = kinetic;
        r.strain_energy     = strain;
        r.external_work     = work;
        r.dissipated_energy = dissipated;
        r.energy_error      = error();
      }

      double
      EnergyAccount::error() const
      {
        // Relative to the largest energy seen, supplied or present: at
        // most 1 in size when nothing was supplied yet.
        const double imbalance = kinetic + strain + dissipated - work - e0;
        const double scale     = std::max(peak, peak_total);
        return scale > 0. ? imbalance / scale : 0.;
      }

      bool
      EnergyAccount::unstable(const double tolerance) const
      {
        const double e = error();
        if (!std::isfinite(e))
          return true;
        if (!(e > tolerance) || errors.size() < 4 || totals.size() < 4)
          return false;
        // Far more energy present than was ever supplied, however the
        // error oscillates: a growing mode with a complex eigenvalue (the
        // collocated pdlsm's flutter) swings the error between 0.6 and 1
        // and never grew three steps in a row, and ran to 1e28 J
        // 'completed'. A stable central difference holds at most 1 / (1 -
        // (omega dt / 2)^2) times its conserved energy, 1e3 only within
        // 0.9995 dt_crit.
        if (peak > 0. && totals.back() > 1e3 * peak)
          return true;
        // The energy grew in each of the last three steps and the error did
        // not shrink (it saturates near 1 once the growth dominates).
        for (std::size_t i = 1; i < errors.size(); ++i)
          if (!(errors[i] >= errors[i - 1] - 1e-12))
            return false;
        for (std::size_t i = totals.size() - 3; i < totals.size(); ++i)
          if (!(totals[i] > totals[i - 1]))
            return false;
        return true;
      }

      double
      EnergyAccount::growth_per_step() const
      {
        if (totals.size() < 2 || !(totals.front() > 0.))
          return 0.;
        return std::pow(totals.back() / totals.front(),
                        1. / (totals.size() - 1));
      }

      void
      EnergyAccount::save(StateArchive &state, const std::string &prefix) const
      {
        state.put_owned(prefix + "u_old", u_old);
        state.put_owned(prefix + "force_old", force_old);
        state.put(prefix + "scalars",
                  std::array<double, 7>{
                    {e0, work, dissipated, kinetic, strain, peak, peak_total}});
        state.put(prefix + "totals",
                  std::vector<double>(totals.begin(), totals.end()));
        state.put(prefix + "errors",
                  std::vector<double>(errors.begin(), errors.end()));
      }

      void
      EnergyAccount::load(const StateArchive &state,
                          const std::string  &prefix,
                          const Vector       &like)
      {
        comm = like.get_mpi_communicator();
        u_old.reinit(like.locally_owned_elements(), comm);
        force_old.reinit(u_old);
        state.get_owned(prefix + "u_old", u_old);
        state.get_owned(prefix + "force_old", force_old);
        const auto v = state.get<std::array<double, 7>>(prefix + "scalars");
        e0           = v[0];
        work         = v[1];
        dissipated   = v[2];
        kinetic      = v[3];
        strain       = v[4];
        peak         = v[5];
        peak_total   = v[6];
        const auto t = state.get_vector<double>(prefix + "totals");
        const auto e = state.get_vector<double>(prefix + "errors");
        totals.assign(t.begin(), t.end());
        errors.assign(e.begin(), e.end());
      }

      void
      LeapfrogEnergy::start(const Vector &u, MPI_Comm communicator)
      {
        comm = communicator;
        u_last.reinit(u.locally_owned_elements(), comm);
        u_before.reinit(u_last);
        force_last.reinit(u_last);
        u_last  = u;
        n_steps = 0;
        g0 = g = work = dissipated = scale = strain_part = 0.;
      }

      void
      LeapfrogEnergy::step(const Vector              &u,
                           const std::vector<double> &half,
                           const Vector              &mass,
                           const Vector              &f_int,
                           const Vector              &f_ext,
                           const std::vector<char>   &held)
      {
        // local: v.Mv over the free DoFs, u^(s-1) . f_int(u^s), and the
        // work F^(s-1) . (u^s - u^(s-2)) / 2 (u_before = u^(s-2) and
        // force_last = F^(s-1) until they are moved on below).
        const double *uv = u.begin(), *m = mass.begin(), *fi = f_int.begin(),
                     *fe = f_ext.begin();
        double *previous = u_last.begin(), *older = u_before.begin(),
               *force   = force_last.begin();
        double local[3] = {0., 0., 0.};
        for (std::size_t i = 0; i < held.size(); ++i)
          {
            if (!held[i])
              local[0] += m[i] * half[i] * half[i];
            local[1] += previous[i] * fi[i];
            local[2] += force[i] * (uv[i] - older[i]);
            older[i]    = previous[i];
            previous[i] = uv[i];
            force[i]    = held[i] ? fi[i] : fe[i];
          }
        double global[3];
        dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, 3),
                                    comm,
                                    dealii::ArrayView<double>(global, 3));
        strain_part = 0.5 * global[1];
        g           = 0.5 * global[0] + strain_part; // G^(s-1)
        if (n_steps == 0)
          g0 = g;
        else
          work += 0.5 * global[2];
        ++n_steps;
        scale =
          std::max({scale, std::abs(g0 + work), std::abs(g + dissipated)});
      }

      void
      LeapfrogEnergy::bonds_broke(const Vector            &f_int,
                                  const Vector            &f_ext,
                                  const std::vector<char> &held)
      {
        // u_before = u^(s-1) now.
        const double *fi = f_int.begin(), *fe = f_ext.begin(),
                     *older = u_before.begin();
        double *force       = force_last.begin();
        double  local       = 0.;
        for (std::size_t i = 0; i < held.size(); ++i)
          {
            local += older[i] * fi[i];
            force[i] = held[i] ? fi[i] : fe[i];
          }
        const double after = 0.5 * dealii::Utilities::MPI::sum(local, comm);
        dissipated += strain_part - after;
        g += after - strain_part;
        strain_part = after;
      }

      void
      LeapfrogEnergy::released(const double energy)
      {
        dissipated += energy;
        g -= energy;
        strain_part -= energy;
      }

      double
      LeapfrogEnergy::drift() const
      {
        return scale > 0. ? (g + dissipated - g0 - work) / scale : 0.;
      }

      void
      throw_unstable(const EnergyAccount &energy,
                     const double         dt,
                     const double         critical_step,
                     const double         safety,
                     const unsigned int   step,
                     const double         t,
                     const bool           explicit_scheme,
                     const double         correlation,
                     InstabilityReport   &report)
      {
        report.unstable        = true;
        report.growth_per_step = energy.growth_per_step();
        const double       g   = report.growth_per_step;
        std::ostringstream s;
        s.precision(3);
        s << "the energy grew without input (kinetic + strain exceeds the "
             "energy supplied by "
          << energy.error() << " of it) at step " << step << ", t = " << t
          << " s, with dt = " << dt << " s";
        if (g > 1.)
          s << "; it grows by a factor " << std::setprecision(6) << g
            << std::setprecision(3) << " per step";

        const bool step_too_large =
          explicit_scheme &&
          (correlation < 0. || (critical_step > 0. && dt > critical_step));
        if (!step_too_large)
          {
            // Growth in phase from step to step: a growing mode of
            // M a + K u = 0 itself (complex or negative eigenvalues of
            // M^-1 K; the PDLSM-FE K is not symmetric), not of the
            // integrator.
            report.recommended_factor    = 1.;
            report.recommended_time_step = dt;
            if (g > 1.)
              s << " (" << std::log(g) / dt << " per second)";
            s << ", in phase from step to step (velocity correlation "
              << correlation << ")";
            if (explicit_scheme && critical_step > 0.)
              s << " below the stability limit (dt = " << dt / critical_step
                << " dt_crit)";
            s << ": the semi-discrete system has a growing mode, which a "
                 "smaller time step does not remove (a stiffness that is "
                 "not symmetric has such modes: the collocated 'pdlsm' "
                 "does, 'Peridynamics/Model = pdlsm energy' does not)";
            throw RunFailure("unstable", s.str());
          }

        // An unstable central-difference mode has u^n ~ lambda^n with
        // lambda + 1/lambda = 2 - (omega dt)^2, lambda < -1; its energy
        // grows by g = lambda^2 per step. So omega dt / 2 =
        // (sqrt|lambda| + 1/sqrt|lambda|) / 2 and dt_crit = dt / that.
        if (g > 1.)
          {
            const double l = std::sqrt(std::sqrt(g)); // sqrt|lambda|
            report.estimated_critical_step = dt / (0.5 * (l + 1. / l));
            s << ", which puts the stability limit at dt_crit ~ "
              << report.estimated_critical_step << " s";
          }
        double limit = report.estimated_critical_step;
        if (critical_step > 0. && (limit == 0. || critical_step < limit))
          limit = critical_step;
        report.recommended_factor =
          limit > 0. ? std::min(1., safety * limit / dt) : 0.5;
        report.recommended_time_step = report.recommended_factor * dt;
        if (critical_step > 0.)
          s << " (power iteration: " << critical_step << " s)";
        s << ". Reduce the time step by a factor of at least "
          << 1. / report.recommended_factor
          << " (dt <= " << report.recommended_time_step << " s)";
        throw RunFailure("time step too large", s.str());
      }
      void
      LeapfrogEnergy::save(StateArchive &state, const std::string &prefix) const
      {
        state.put_owned(prefix + "u_before", u_before);
        state.put_owned(prefix + "u_last", u_last);
        state.put_owned(prefix + "force_last", force_last);
        state.put(prefix + "steps", n_steps);
        state.put(prefix + "scalars",
                  std::array<double, 6>{
                    {g0, g, work, dissipated, scale, strain_part}});
      }

      void
      LeapfrogEnergy::load(const StateArchive &state,
                           const std::string  &prefix,
                           const Vector       &like)
      {
        start(like, like.get_mpi_communicator());
        state.get_owned(prefix + "u_before", u_before);
        state.get_owned(prefix + "u_last", u_last);
        state.get_owned(prefix + "force_last", force_last);
        n_steps      = state.get<unsigned int>(prefix + "steps");
        const auto v = state.get<std::array<double, 6>>(prefix + "scalars");
        g0           = v[0];
        g            = v[1];
        work         = v[2];
        dissipated   = v[3];
        scale        = v[4];
        strain_part  = v[5];
      }
      void
      TimeLoopState::save(StateArchive &state, const unsigned int next) const
      {
        state.put("driver/next step", next);
        state.put_owned("driver/v", v);
        state.put_owned("driver/a", a);
        state.put_owned("driver/f_int", f_int);
        state.put_owned("driver/f_ext", f_ext);
        state.put("driver/held", held);
        energy.save(state, "driver/energy/");
      }

      unsigned int
      TimeLoopState::load(const StateArchive &state, const Vector &u)
      {
        const std::size_t n = held.size();
        state.get_owned("driver/v", v);
        state.get_owned("driver/a", a);
        state.get_owned("driver/f_int", f_int);
        state.get_owned("driver/f_ext", f_ext);
        held = state.get_vector<char>("driver/held");
        if (held.size() != n)
          throw InputError("",
                           "--restart",
                           "the checkpoint's time integration state does not "
                           "fit this run's vectors");
        energy.load(state, "driver/energy/", u);
        return state.get<unsigned int>("driver/next step");
      }
    } // namespace internal
  }   // namespace Drivers
} // namespace pdfem
