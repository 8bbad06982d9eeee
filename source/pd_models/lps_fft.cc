// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "lps fft": the LPS model of "lps" evaluated for all owners
// at once by FFT on the uniform grid of an all-PD region (doc/theory.md
// §14-15, doc/user_guide.md §2a‴).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/fft/fft_operator.h>
#include <pdfem/fft/grid.h>
#include <pdfem/fft/slab_exchange.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/lps.h>
#include <pdfem/pd_models/lps_fft.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "pairwise_tools.h"

namespace pdfem
{
  namespace PDModels
  {
    using namespace dealii;

    namespace
    {
      /// The entry @p entry of the current subsection; "" where not
      /// declared.
      std::string
      entry_or_empty(ParameterHandler &prm, const std::string &entry)
      {
        try
          {
            return prm.get(entry);
          }
        catch (const ExceptionBase &)
          {
            return "";
          }
      }

      /// The entry @p entry of the top-level subsection @p section, read
      /// from inside `subsection Peridynamics`; "" where not declared (a
      /// model made outside a scene, e.g. in a test).
      std::string
      scene_entry(ParameterHandler  &prm,
                  const std::string &section,
                  const std::string &entry)
      {
        prm.leave_subsection();
        prm.enter_subsection(section);
        const std::string value = entry_or_empty(prm, entry);
        prm.leave_subsection();
        prm.enter_subsection("Peridynamics");
        return value;
      }

      /// The smallest n >= @p at_least whose prime factors are 2, 3, 5, 7
      /// (sizes FFTW transforms fastest).
      unsigned int
      fft_size(const unsigned int at_least)
      {
        for (unsigned int n = std::max(1u, at_least);; ++n)
          {
            unsigned int r = n;
            for (const unsigned int p : {2u, 3u, 5u, 7u})
              while (r % p == 0)
                r /= p;
            if (r == 1)
              return n;
          }
      }

      /// `subsection LPS fft` inside `subsection Peridynamics`: the damage
      /// of the energy criterion (the LPS constants are those of "lps").
      void
      declare_lps_fft_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("LPS fft");
        prm.declare_entry(
          "Damage",
          "none",
          Patterns::Selection("none|energy"),
          "none: nodes never fail; energy: the pointwise energy criterion of "
          "specs/002 §1.6: after every time step a node whose strain energy "
          "density W (the paper's convention, twice the physical one) "
          "exceeds W_c = G_0 / delta fails for good and loses all its "
          "bonds (explicit dynamics).");
        prm.declare_entry("Fracture energy",
                          "0",
                          Patterns::Double(),
                          "G_0 [J/m^2] of Damage = energy (> 0).");
        prm.declare_entry(
          "Keep mask fields",
          "true",
          Patterns::Bool(),
          "true: the fields that depend on the masks only ([g_i beta] and "
          "(1/m) [K_ij beta] + [K_ij (beta/m)], 9 per node in 3D, 5 in 2D) "
          "are computed when the masks change and kept at the nodes within "
          "two horizons of the body's surface, a hole or a failed node (the "
          "layer; elsewhere they are constants; summary.json: fft layer "
          "nodes); false (lean): recomputed in every force evaluation, up "
          "to 72 bytes per box node less in 3D (40 in 2D) for about 2.3 "
          "times the transforms (FFT::FftOptions::keep_mask_fields, "
          "doc/benchmarks/fft.md \"Memory\").");
        prm.declare_entry(
          "Damage index",
          "body",
          Patterns::Selection("body|full horizon"),
          "The damage in the output, d = 1 - lambda sum lambda' / D (specs/002 "
          "eq. 65): body: D the node's neighbours in the body (0 in an "
          "intact body, PeriFast); full horizon: D the whole discrete "
          "horizon (the paper; surface nodes start above 0).");
        prm.leave_subsection();
      }

      template <int dim>
      std::string
      point_text(const Point<dim> &p)
      {
        std::ostringstream s;
        s << '(';
        for (unsigned int c = 0; c < dim; ++c)
          s << (c ? ", " : "") << p[c];
        s << ')';
        return s.str();
      }
    } // namespace

    template <int dim>
    NodeGrid<dim>
    detect_node_grid(const std::vector<Point<dim>> &x, const std::string &file)
    {
      const std::string allowed =
        "a structured mesh of equal cells whose nodes form a uniform grid "
        "(e.g. gmsh transfinite), or Peridynamics/Model = lps";
      NodeGrid<dim> g;
      if (x.empty())
        throw InputError(file, "Peridynamics/Model", "lps fft: no nodes");
      for (unsigned int c = 0; c < dim; ++c)
        {
          std::vector<double> v(x.size());
          for (std::size_t k = 0; k < x.size(); ++k)
            v[k] = x[k][c];
          std::sort(v.begin(), v.end());
          const double extent = v.back() - v.front();
          double       gap    = extent;
          for (std::size_t k = 1; k < v.size(); ++k)
            if (v[k] - v[k - 1] > 1e-10 * extent)
              gap = std::min(gap, v[k] - v[k - 1]);
          if (!(extent > 0.))
            throw InputError(file,
                             "Peridynamics/Model",
                             "lps fft: the nodes span no length in direction " +
                               std::to_string(c),
                             allowed);
          g.n[c] = static_cast<unsigned int>(std::lround(extent / gap)) + 1;
          g.spacing[c] = extent / (g.n[c] - 1);
          g.origin[c]  = v.front();
        }
      // Every node on the grid first (a jittered mesh has tiny gaps, so a
      // huge grid), then one node per grid point.
      g.index.resize(x.size());
      for (std::size_t k = 0; k < x.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const double s = (x[k][c] - g.origin[c]) / g.spacing[c];
            const long   i = std::lround(s);
            if (std::abs(s - i) > 1e-8)
              throw InputError(file,
                               "Peridynamics/Model",
                               "lps fft needs the PD nodes on a uniform grid; "
                               "node " +
                                 std::to_string(k) + " at " + point_text(x[k]) +
                                 " is off the grid of spacing " +
                                 number(g.spacing[c]) + " in direction " +
                                 std::to_string(c),
                               allowed);
            g.index[k][c] = static_cast<unsigned int>(i);
          }
      double n_points = 1.;
      for (unsigned int c = 0; c < dim; ++c)
        n_points *= g.n[c];
      if (n_points > 64. * double(x.size()))
        throw InputError(file,
                         "Peridynamics/Model",
                         "lps fft: the " + std::to_string(x.size()) +
                           " nodes fill less than 1/64 of the " +
                           number(n_points) +
                           " points of their grid (spacing the smallest gap "
                           "between node coordinates)",
                         allowed);
      std::vector<std::uint8_t> taken(static_cast<std::size_t>(n_points), 0);
      for (std::size_t k = 0; k < x.size(); ++k)
        {
          std::size_t flat = 0;
          for (unsigned int c = 0; c < dim; ++c)
            flat = flat * g.n[c] + g.index[k][c];
          if (taken[flat]++)
            throw InputError(file,
                             "Peridynamics/Model",
                             "lps fft: two nodes at the grid point of node " +
                               std::to_string(k) + " " + point_text(x[k]),
                             allowed);
        }
      return g;
    }

    template <int dim>
    LpsFft<dim>::LpsFft() = default;

    template <int dim>
    LpsFft<dim>::~LpsFft() = default;

    template <int dim>
    void
    LpsFft<dim>::parse_parameters(ParameterHandler  &prm,
                                  const std::string &file)
    {
      // The LPS subsection of "lps" (declared there).
      source_file = file;
      prm.enter_subsection("LPS");
      inverse_distance = prm.get("Influence function") == "1/r";
      dirichlet_layer  = prm.get_double("Dirichlet layer");
      traction_layer   = prm.get_double("Traction layer");
      const bool cells = prm.get("Nodal volumes") == "cells";
      prm.leave_subsection();
      prm.enter_subsection("LPS fft");
      damage_on        = prm.get("Damage") == "energy";
      keep_mask_fields = prm.get_bool("Keep mask fields");
      fracture_energy  = prm.get_double("Fracture energy");
      normalisation    = prm.get("Damage index") == "body" ?
                           FFT::DamageNormalisation::body :
                           FFT::DamageNormalisation::full_horizon;
      prm.leave_subsection();
      if (damage_on && !(fracture_energy > 0.))
        throw InputError(file,
                         "Peridynamics/LPS fft/Fracture energy",
                         "G_0 = " + number(fracture_energy) +
                           " is not positive, and Damage = energy needs "
                           "W_c = G_0 / delta",
                         "G_0 > 0 [J/m^2] with Damage = energy");
      const std::string model = "Peridynamics/Model";
      if (cells)
        throw InputError(file,
                         model,
                         "lps fft gives every node the grid's volume h^dim, "
                         "and LPS/Nodal volumes = cells asks for each node's "
                         "share of its cells",
                         "LPS/Nodal volumes = uniform with lps fft, or Model "
                         "= lps");
      // Drivers that need a tangent, pre-existing cracks and crack criteria
      // are refused by make_plugins() (Layout::tangent, breakable_bonds).
      const std::string driver = scene_entry(prm, "Driver", "Type");
      if (damage_on && !driver.empty() && driver != "explicit")
        throw InputError(file,
                         "Peridynamics/LPS fft/Damage",
                         "the energy criterion fails nodes after time steps "
                         "of explicit dynamics, and Driver/Type = " +
                           driver + " has none",
                         "Damage = none, or Driver/Type = explicit");
    }

    template <int dim>
    Layout
    LpsFft<dim>::layout() const
    {
      Layout l;
      l.uniform_horizon  = true;
      l.dirichlet_layer  = dirichlet_layer;
      l.traction_layer   = traction_layer;
      l.nodal_body_force = true;
      l.free_crack_faces = false;
      l.history          = damage_on;
      l.tangent          = false;
      l.breakable_bonds  = false;
      l.preconditioner   = true;
      l.bonds            = false;
      return l;
    }

    template <int dim>
    void
    LpsFft<dim>::initialize(const Region<dim> &r)
    {
      this->region            = r;
      const std::string model = "Peridynamics/Model";
      const auto       &x     = *r.position;
      for (std::size_t k = 0; k < x.size(); ++k)
        if ((*r.has_fe_cells)[k] || !((*r.pd_volume)[k] > 0.))
          throw InputError(
            r.source_file,
            model,
            "lps fft needs an all-PD region, and node " + std::to_string(k) +
              " at " + point_text(x[k]) + " belongs to an FE cell",
            "Mesh/PD regions = all with lps fft, or Model = lps");
      body_grid          = detect_node_grid(x, r.source_file);
      double cell_volume = 1.;
      for (unsigned int c = 0; c < dim; ++c)
        cell_volume *= body_grid.spacing[c];
      node_volume = std::pow(r.spacing, dim);
      if (std::abs(node_volume - cell_volume) > 1e-8 * cell_volume)
        throw InputError(r.source_file,
                         model,
                         "lps fft needs cells of one size, and the largest "
                         "cell (" +
                           number(node_volume) +
                           ") is larger than the grid's (" +
                           number(cell_volume) + ")",
                         "a structured mesh of equal cells, or Model = lps");

      // The constants of "lps" (specs/002 eq. 32).
      const LpsConstants c  = lps_constants(r);
      bulk_modulus          = c.bulk_modulus;
      A                     = c.A;
      B                     = c.B;
      delta                 = c.delta;
      const PD::Families &f = *r.families;

      // The box: the body's grid and a gap of more than a horizon after it
      // in each direction (the periodic images never bond).
      FFT::Grid<dim> grid;
      for (unsigned int c = 0; c < dim; ++c)
        {
          const auto reach = static_cast<unsigned int>(
            std::floor(delta * (1. + 1e-10) / body_grid.spacing[c]));
          box[c]          = fft_size(body_grid.n[c] + reach + 1);
          grid.n[c]       = box[c];
          grid.spacing[c] = body_grid.spacing[c];
        }
      n_box = grid.n_nodes();
      // This rank's slab of the box (all of it with one rank), chi_B = 1
      // at its grid points that are nodes (every rank has every node).
      slab                = FFT::local_slab(grid, r.comm);
      const std::size_t N = slab.n_nodes();
      body.assign(N, 0.);
      const auto at = [&](const unsigned int k) {
        std::array<unsigned int, dim> i;
        for (unsigned int c = 0; c < dim; ++c)
          i[c] = body_grid.index[k][c];
        return grid.node(i);
      };
      for (std::size_t k = 0; k < x.size(); ++k)
        if (slab.contains(at(k)))
          body[at(k) - slab.begin] = 1.;
      box_node.resize(f.owners.size());
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        box_node[o] = at(f.owners[o]);
      exchange = std::make_unique<FFT::SlabExchange>(box_node, slab, r.comm);

      // The bonds of the output's gradient fit: the grid's discrete horizon
      // (the bonds the FFT sums).
      stencil = FFT::horizon_offsets(grid, delta);

      FFT::Material material;
      material.model         = FFT::Model::lps;
      material.horizon       = delta;
      material.bulk_modulus  = bulk_modulus;
      material.shear_modulus = r.mu;
      if (!inverse_distance)
        material.influence = [](double) { return 1.; };
      FFT::FftOptions options;
      options.threads          = ThreadTeam::shared().size();
      options.communicator     = r.comm;
      options.keep_mask_fields = keep_mask_fields;
      op = std::make_unique<FFT::FftOperator<dim>>(grid, material, options);
      lambda.assign(N, 1.);
      op->set_masks(body, lambda);
      op->damage(d_box, normalisation);
      d_owner.resize(box_node.size());
      exchange->pull(d_box, 1, d_owner.data());
      u_box.assign(dim * N, 0.);
      r_box.clear(); // push() zeroes it at its first use
      inverse_made = false;
      W_box.clear();
      // The paper's calibration (specs/002 eqs. 50-51): a delta-thick layer
      // of dead nodes releases A delta W_c = A G_0.
      W_c =
        damage_on ? FFT::critical_energy_density(fracture_energy, delta) : 0.;
      n_last_failed = 0;
      failed        = FailedNodes<dim>();
      count_operator_bytes();
    }

    template <int dim>
    void
    LpsFft<dim>::count_operator_bytes()
    {
      operator_bytes = Utilities::MPI::sum(op->bytes(), this->region.comm);
      layer_nodes =
        Utilities::MPI::sum(double(op->n_layer_nodes()), this->region.comm);
      largest_rank_bytes = Utilities::MPI::max(op->bytes(), this->region.comm);
    }

    template <int dim>
    void
    LpsFft<dim>::bonds_changed(const std::vector<std::size_t> &changed, bool)
    {
      if (!changed.empty())
        throw InputError(source_file,
                         "Peridynamics/Model",
                         "lps fft cannot break single bonds (the FFT form has "
                         "node masks only)",
                         "no bond-breaking with lps fft, or Model = lps");
    }

    template <int dim>
    void
    LpsFft<dim>::gather(const NodalField<dim> &u)
    {
      const PD::Families &f = *this->region.families;
      owner_values.resize(dim * f.owners.size());
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        for (unsigned int c = 0; c < dim; ++c)
          owner_values[dim * o + c] = u(f.owners[o], c);
      exchange->push(owner_values.data(), dim, u_box);
    }

    template <int dim>
    void
    LpsFft<dim>::prepare_forces(const NodalField<dim> &u)
    {
      gather(u);
      op->apply(u_box, L_box);
      L_owner.resize(dim * box_node.size());
      exchange->pull(L_box, dim, L_owner.data());
    }

    template <int dim>
    void
    LpsFft<dim>::precondition(const std::vector<double> &r,
                              std::vector<double>       &z)
    {
      // The stiffness of the owners' rows is Delta V (-dL/du): its periodic
      // inverse is G^-1 / Delta V. The symbol is made at the first call:
      // its bytes are counted then (collective: a flag, not the slab's
      // size, which is 0 on a rank without planes).
      const bool first = !inverse_made;
      inverse_made     = true;
      exchange->push(r.data(), dim, r_box);
      op->apply_periodic_inverse(r_box, z_box);
      z.resize(dim * box_node.size());
      exchange->pull(z_box, dim, z.data());
      for (double &value : z)
        value /= node_volume;
      if (first)
        count_operator_bytes();
    }

    template <int dim>
    void
    LpsFft<dim>::commit_state(const NodalField<dim> &u)
    {
      n_last_failed = 0;
      released      = 0.;
      if (!damage_on)
        return;
      // specs/002 eqs. 43, 63: lambda = 0 where W > W_c, irreversible; the
      // forces of the next step use the new masks (one-step lag).
      gather(u);
      op->energy_density(u_box, W_box);
      n_last_failed =
        Utilities::MPI::sum(FFT::update_integrity(W_box, W_c, lambda),
                            this->region.comm);
      if (n_last_failed > 0)
        {
          // The strain energy sum chi_B W / 2 Delta V (W the paper's, twice
          // the physical density) at u with the old masks and the new ones:
          // what the failed nodes released (one more evaluation of W on
          // the steps where nodes fail).
          const auto energy = [&](const std::vector<double> &W) {
            double E = 0.;
            for (std::size_t k = 0; k < body.size(); ++k)
              E += body[k] * W[k];
            return 0.5 * node_volume * E;
          };
          const double before = energy(W_box);
          op->set_masks(body, lambda);
          std::vector<double> W_after;
          op->energy_density(u_box, W_after);
          released =
            Utilities::MPI::sum(before - energy(W_after), this->region.comm);
          op->damage(d_box, normalisation);
          exchange->pull(d_box, 1, d_owner.data());
          count_failed_nodes();
          count_operator_bytes(); // the kept fields' layer has grown
        }
    }

    template <int dim>
    void
    LpsFft<dim>::count_failed_nodes()
    {
      // The failed body nodes of this slab, their bounding box, then over
      // the ranks.
      FailedNodes<dim>        e;
      std::array<double, dim> lo, hi;
      lo.fill(std::numeric_limits<double>::max());
      hi.fill(-std::numeric_limits<double>::max());
      unsigned long         n    = 0;
      const FFT::Grid<dim> &grid = op->grid();
      for (std::size_t k = 0; k < slab.n_nodes(); ++k)
        if (body[k] > 0. && !(lambda[k] > 0.))
          {
            const auto i = grid.indices(slab.begin + k);
            for (unsigned int c = 0; c < dim; ++c)
              {
                const double x =
                  body_grid.origin[c] + i[c] * body_grid.spacing[c];
                lo[c] = std::min(lo[c], x);
                hi[c] = std::max(hi[c], x);
              }
            ++n;
          }
      const MPI_Comm comm = this->region.comm;
      e.n                 = Utilities::MPI::sum(n, comm);
      for (unsigned int c = 0; c < dim && e.n > 0; ++c)
        {
          e.lo[c] = Utilities::MPI::min(lo[c], comm);
          e.hi[c] = Utilities::MPI::max(hi[c], comm);
        }
      failed = e;
    }

    template <int dim>
    double
    LpsFft<dim>::damage(const std::size_t o, const NodalField<dim> &) const
    {
      return d_owner[o];
    }

    template <int dim>
    void
    LpsFft<dim>::save_state(StateArchive &state) const
    {
      state.put("pd model/integrity", lambda);
    }

    template <int dim>
    void
    LpsFft<dim>::restore_state(const StateArchive &state)
    {
      const auto saved = state.get_vector<double>("pd model/integrity");
      if (saved.size() != lambda.size())
        throw InputError("",
                         "--restart",
                         "the checkpoint's node integrity has " +
                           std::to_string(saved.size()) +
                           " box nodes on this rank, this run's FFT slab " +
                           std::to_string(lambda.size()));
      lambda = saved;
      op->set_masks(body, lambda);
      op->damage(d_box, normalisation);
      exchange->pull(d_box, 1, d_owner.data());
      count_failed_nodes();
      count_operator_bytes();
    }

    template <int dim>
    void
    LpsFft<dim>::forces(const std::size_t begin,
                        const std::size_t end,
                        const NodalField<dim> &,
                        double *f) const
    {
      for (std::size_t o = begin; o < end; ++o)
        for (unsigned int c = 0; c < dim; ++c)
          f[dim * o + c] = -node_volume * L_owner[dim * o + c];
    }

    template <int dim>
    void
    LpsFft<dim>::tangent_row(std::size_t,
                             const NodalField<dim> &,
                             std::vector<Tensor<2, dim>> &) const
    {
      throw InputError(source_file,
                       "Peridynamics/Model",
                       "lps fft evaluates forces only, without a tangent, "
                       "which this run needs",
                       "Driver/Type = explicit, or static with Linear "
                       "solver/Type = cg, with lps fft; or Model = lps");
    }

    template <int dim>
    void
    LpsFft<dim>::prepare_results(const NodalField<dim> &u)
    {
      // The fit of "lps" over the grid's bonds within the body, each with
      // omega Delta V: G = [sum omega eta (x) xi] [sum omega xi (x) xi]^-1,
      // eta = u(x + xi) - u(x), for every owner. The bonds reach other
      // ranks' slabs: with several ranks u and chi_B of the whole box are
      // summed on every rank for this once (output only), and freed.
      gather(u);
      const bool parallel =
        Utilities::MPI::n_mpi_processes(this->region.comm) > 1;
      std::vector<double> whole;
      if (parallel)
        {
          whole.assign((dim + 1) * n_box, 0.);
          const std::size_t N = slab.n_nodes();
          for (std::size_t k = 0; k < N; ++k)
            {
              for (unsigned int c = 0; c < dim; ++c)
                whole[c * n_box + slab.begin + k] = u_box[c * N + k];
              whole[dim * n_box + slab.begin + k] = body[k];
            }
          Utilities::MPI::sum(whole, this->region.comm, whole);
        }
      // With one rank the slab is the box.
      const double *u_all = parallel ? whole.data() : u_box.data();
      const double *body_all =
        parallel ? whole.data() + dim * n_box : body.data();

      const FFT::Grid<dim> &grid = op->grid();
      const PD::Families   &f    = *this->region.families;
      gradient.resize(box_node.size());
      const auto fit = [&](const std::size_t o) {
        const auto       &i = body_grid.index[f.owners[o]];
        const std::size_t k = box_node[o];
        Tensor<2, dim>    A, B;
        for (const auto &p : stencil)
          {
            std::array<unsigned int, dim> j;
            bool                          inside = true;
            for (unsigned int c = 0; c < dim && inside; ++c)
              {
                const long jc = long(i[c]) + p.p[c];
                inside        = jc >= 0 && jc < long(body_grid.n[c]);
                j[c]          = static_cast<unsigned int>(jc);
              }
            if (!inside)
              continue;
            const std::size_t m = grid.node(j);
            if (!(body_all[m] > 0.))
              continue;
            Tensor<1, dim> xi, eta;
            for (unsigned int c = 0; c < dim; ++c)
              {
                xi[c]  = p.xi[c];
                eta[c] = u_all[c * n_box + m] - u_all[c * n_box + k];
              }
            const double w = inverse_distance ? 1. / p.length : 1.;
            A += w * outer_product(eta, xi);
            B += w * outer_product(xi, xi);
          }
        gradient[o] =
          std::abs(determinant(B)) <= 1e-12 * std::pow(trace(B), dim) ?
            Tensor<2, dim>() :
            A * invert(B);
      };
      ThreadTeam &team = ThreadTeam::shared();
      team.run([&](const unsigned int member) {
        const std::size_t n = box_node.size();
        for (std::size_t o = n * member / team.size();
             o < n * (member + 1) / team.size();
             ++o)
          fit(o);
      });
    }

    template <int dim>
    Tensor<2, dim>
    LpsFft<dim>::displacement_gradient(const std::size_t o,
                                       const NodalField<dim> &) const
    {
      if (o >= gradient.size())
        throw std::logic_error("lps fft: displacement_gradient() before "
                               "prepare_results()");
      return gradient[o];
    }

    template <int dim>
    double
    LpsFft<dim>::nodal_volume(const unsigned int) const
    {
      return node_volume;
    }

    template <int dim>
    std::vector<std::pair<std::string, double>>
    LpsFft<dim>::constants() const
    {
      std::vector<std::pair<std::string, double>> extent;
      if (damage_on)
        {
          const std::array<char, 3> axis = {{'x', 'y', 'z'}};
          extent.emplace_back("failed nodes", double(failed.n));
          for (unsigned int c = 0; c < dim && failed.n > 0; ++c)
            {
              extent.emplace_back(std::string("failed nodes min ") + axis[c],
                                  failed.lo[c]);
              extent.emplace_back(std::string("failed nodes max ") + axis[c],
                                  failed.hi[c]);
            }
        }
      std::vector<std::pair<std::string, double>> all = {
        {"horizon", delta},
        {"spacing", this->region.spacing},
        {dim == 3 ? "bulk modulus" : "planar bulk modulus", bulk_modulus},
        {"shear modulus", this->region.mu},
        {"A", A},
        {"B", B},
        {"fft box nodes", double(n_box)},
        {"critical energy density", W_c},
        {"fft bytes per box node", operator_bytes / double(n_box)},
        {"fft bytes per body node",
         operator_bytes / double(this->region.position->size())},
        {"fft bytes per rank (largest)", largest_rank_bytes},
        {"fft layer nodes", layer_nodes}};
      all.insert(all.end(), extent.begin(), extent.end());
      return all;
    }

#define INSTANTIATE(dim)                                                   \
  template class LpsFft<dim>;                                              \
  template NodeGrid<dim> detect_node_grid(const std::vector<Point<dim>> &, \
                                          const std::string &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem

PDFEM_REGISTER_PD_MODEL(
  pdfem::PDModels::LpsFft,
  "lps fft",
  "the LPS model of lps with LPS/Nodal volumes = uniform, evaluated for all "
  "nodes at once by FFT (specs/002 §2): all-PD regions on a uniform grid, "
  "explicit dynamics, no broken bonds; damage by the paper's nodal energy "
  "criterion (LPS fft/Damage = energy)",
  pdfem::PDModels::declare_lps_fft_parameters)
