// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "bond based": the finite-deformation bond-based model with
// the smooth tanh degradation of Hu et al. (specs/003 §1, §3) as a term of
// the coupled system.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/bond_based.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/rnp.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>

#include "pairwise_tools.h"

namespace pdfem
{
  namespace PDModels
  {
    using namespace dealii;

    // ------------------------------------------------------- the bond law
    double
    BondDegradation::factor(const double s) const
    {
      if (!active || s <= onset)
        return 1.;
      if (s >= critical)
        return 0.;
      return 0.5 * (1. - std::tanh(rate * (onset + critical - 2. * s) /
                                   (onset - critical)));
    }

    double
    BondDegradation::derivative(const double s) const
    {
      if (!active || s <= onset || s >= critical)
        return 0.;
      const double t =
        std::tanh(rate * (onset + critical - 2. * s) / (onset - critical));
      return rate / (onset - critical) * (1. - t * t);
    }

    double
    bond_based_micromodulus(const double E,
                            const double delta,
                            const int    dim,
                            const bool   plane_strain)
    {
      if (dim == 3)
        return 12. * E / (M_PI * std::pow(delta, 4));
      return (plane_strain ? 48. / (5. * M_PI) : 9. / M_PI) * E /
             std::pow(delta, 3);
    }

    double
    bond_based_bar_micromodulus(const double E,
                                const double delta,
                                const double area)
    {
      return 2. * E / (area * delta * delta);
    }

    template <int dim>
    double
    BondBasedBond<dim>::stretch(const Tensor<1, dim> &xi,
                                const Tensor<1, dim> &eta)
    {
      const double L = xi.norm();
      return ((xi + eta).norm() - L) / L;
    }

    template <int dim>
    Tensor<1, dim>
    BondBasedBond<dim>::force(const Tensor<1, dim> &xi,
                              const Tensor<1, dim> &eta,
                              const double          c_T)
    {
      const Tensor<1, dim> r = xi + eta;
      const double         L = xi.norm(), l = r.norm();
      // c T s r / l with s = (l - L) / L: c T (1 / L - 1 / l) r.
      return c_T * (1. / L - 1. / l) * r;
    }

    template <int dim>
    Tensor<2, dim>
    BondBasedBond<dim>::stiffness(const Tensor<1, dim> &xi,
                                  const Tensor<1, dim> &eta,
                                  const double          c,
                                  const double          T,
                                  const double          dT)
    {
      const Tensor<1, dim> r = xi + eta;
      const double         L = xi.norm(), l = r.norm();
      const double         s     = (l - L) / L;
      const double         axial = c * (T + s * dT) / L;
      const double         cross = c * T * s / l;
      Tensor<2, dim>       K;
      for (unsigned int p = 0; p < dim; ++p)
        for (unsigned int q = 0; q < dim; ++q)
          K[p][q] =
            (axial - cross) * r[p] * r[q] / (l * l) + (p == q ? cross : 0.);
      return K;
    }

    // ------------------------------------------------------------ the model
    namespace
    {
      /// `subsection Bond based` inside `subsection Peridynamics`.
      void
      declare_bond_based_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Bond based");
        prm.declare_entry("Degradation",
                          "none",
                          Patterns::Selection("none|tanh"),
                          "none: bonds never soften; tanh: the smooth "
                          "degradation T(s) of specs/003 eq. 12 between the "
                          "onset stretch s_m and the critical stretch s_c.");
        prm.declare_entry("Onset stretch",
                          "0",
                          Patterns::Double(),
                          "s_m: the stretch at which bonds start to soften "
                          "(tanh).");
        prm.declare_entry("Critical stretch",
                          "0",
                          Patterns::Double(),
                          "s_c > s_m: the stretch at which a bond carries no "
                          "force (tanh); it then breaks for good.");
        prm.declare_entry("Degradation rate",
                          "3",
                          Patterns::Double(),
                          "beta > 0 in T(s): how sharply bonds soften (the "
                          "paper: 3).");
        prm.declare_entry(
          "Damage history",
          "irreversible",
          Patterns::Selection("irreversible|reversible"),
          "irreversible: T follows the largest stretch of every accepted "
          "state (an unloading bond keeps its softening, specs/003 §1.4); "
          "reversible: T follows the current stretch.");
        prm.declare_entry(
          "Body",
          "continuum",
          Patterns::Selection("continuum|uniaxial bar"),
          "continuum: the micromodulus of the dimension and plane model; "
          "uniaxial bar: a one-dimensional bar along x (specs/003 case A): "
          "only the bonds along x act, c = 2 E / (A delta^2) with A the "
          "cross-section one line of nodes carries. Needs Dimension = 2, a "
          "PD region one square cell tall along x (two lines of nodes, each "
          "a bar of half the strip), Poisson's ratio 0 and the transverse "
          "displacements held (doc/theory.md §13.6).");
        prm.declare_entry("Volume correction",
                          "partial volumes",
                          Patterns::Selection("partial volumes|none"),
                          "partial volumes: v = (delta + h/2 - |xi|) / h for "
                          "bonds within h/2 of the horizon (specs/003 §1.5); "
                          "none: v = 1.");
        prm.declare_entry("Surface correction",
                          "energy",
                          Patterns::Selection("energy|none"),
                          "energy: every bond is scaled by mu_km so that a "
                          "uniaxial strain gives the continuum energy at "
                          "every node (Madenci & Oterkus, specs/003 §1.5); "
                          "none: mu = 1.");
        declare_lattice_parameters(prm);
        prm.leave_subsection();
      }
    } // namespace

    /**
     * The bond-based model (specs/003 §1, §3) as a term of the coupled
     * system:
     *
     *   F_k = -V_k sum_m c mu_km v_km V_m T(s_km) s_km n_km
     *
     * over the intact bonds, n = (xi + eta) / |xi + eta|, s the stretch,
     * c the micromodulus of bond_based_micromodulus() for the one horizon
     * delta = m h, v the partial-volume factor, mu the energy surface
     * correction (mu_km = mu_mk), V the bond volumes (pairwise_bond_volumes())
     * and T the degradation of BondDegradation, at the bond's largest
     * stretch of the accepted states (Damage history = irreversible) or at
     * its current one. Pairwise and symmetric: the tangent
     *
     *   dF_k/du_m = -V_k mu v V_m dt/du_m,  dF_k/du_k = -sum_m dF_k/du_m
     *
     * (BondBasedBond::stiffness(), T' only on bonds stretched beyond their
     * largest stretch) is symmetric, indefinite where bonds soften or are
     * compressed. Bonds whose largest stretch reached s_c break for good
     * (bond_failed()). The Poisson's ratio must be the model's (1/3 plane
     * stress, 1/4 plane strain and 3D).
     *
     * Body = uniaxial bar (specs/003 §5.1 case A, theory.md §13.6): the
     * strip one square cell h tall along x is two bars of cross-section
     * A = h/2 (per unit thickness); only the bonds along x act, with
     * c = 2 E / (A delta^2) (bond_based_bar_micromodulus()), nu = 0.
     */
    template <int dim>
    class BondBased : public Interface<dim>
    {
    public:
      void
      parse_parameters(ParameterHandler &prm, const std::string &file) override
      {
        prm.enter_subsection("Bond based");
        degradation.active   = prm.get("Degradation") == "tanh";
        degradation.onset    = prm.get_double("Onset stretch");
        degradation.critical = prm.get_double("Critical stretch");
        degradation.rate     = prm.get_double("Degradation rate");
        irreversible         = prm.get("Damage history") == "irreversible";
        volume_correction  = prm.get("Volume correction") == "partial volumes";
        surface_correction = prm.get("Surface correction") == "energy";
        uniform_volumes    = prm.get("Nodal volumes") == "uniform";
        dirichlet_layer    = prm.get_double("Dirichlet layer");
        bar                = prm.get("Body") == "uniaxial bar";
        prm.leave_subsection();
        if (bar && dim != 2)
          throw InputError(file,
                           "Peridynamics/Bond based/Body",
                           "a uniaxial bar is modelled in a 2D scene, this "
                           "one has Dimension = " +
                             std::to_string(dim),
                           "continuum (or Dimension = 2 for uniaxial bar)");
        if (!degradation.active)
          return;
        const std::string section = "Peridynamics/Bond based/";
        if (!(degradation.onset > 0.))
          throw InputError(
            file,
            section + "Onset stretch",
            "s_m = " + number(degradation.onset) + " is not positive",
            "0 < s_m < Critical stretch with Degradation = tanh");
        if (!(degradation.critical > degradation.onset))
          throw InputError(file,
                           section + "Critical stretch",
                           "s_c = " + number(degradation.critical) +
                             " is not above the onset stretch s_m = " +
                             number(degradation.onset),
                           "s_c > s_m");
        if (!(degradation.rate > 0.))
          throw InputError(file,
                           section + "Degradation rate",
                           "beta = " + number(degradation.rate) +
                             " is not positive",
                           "beta > 0 (the paper: 3)");
      }

      Layout
      layout() const override
      {
        Layout l             = pairwise_layout(dirichlet_layer);
        l.history            = degradation.active && irreversible;
        l.smooth_degradation = degradation.active;
        // A bar's bonds along x give no stiffness in y.
        l.stiffless_component = bar ? 1 : -1;
        l.tangent_products    = true;
        return l;
      }

      void
      initialize(const Region<dim> &r) override
      {
        this->region    = r;
        const double nu = bar ? 0. : rnp_poissons_ratio(dim, r.plane_strain);
        if (std::abs(r.poissons_ratio - nu) > 1e-3)
          throw InputError(
            r.source_file,
            "Material/Poisson's ratio",
            "nu = " + number(r.poissons_ratio) +
              " cannot be represented by the bond-based model, whose "
              "Poisson's ratio is " +
              number(nu) +
              (bar      ? " as a uniaxial bar (Body = uniaxial bar)" :
               dim == 2 ? (r.plane_strain ? " in plane strain" :
                                            " in plane stress") :
                          " in 3D"),
            number(nu) + " (or a state-based model: pdlsm, pdlsm energy)");
        if (bar)
          check_bar_strip();
        const PD::Families &f = *r.families;
        double              h = 0.;
        for (const unsigned int k : f.owners)
          h = std::max(h, (*r.horizon)[k]);
        delta = Utilities::MPI::max(h, r.comm);
        if (!(delta > 0.))
          delta = 1.; // no PD node anywhere: no bond either
        // A bar: each of the strip's two lines of nodes carries half its
        // height (per unit thickness, like the 2D micromoduli).
        c = bar ? bond_based_bar_micromodulus(r.youngs_modulus,
                                              delta,
                                              0.5 * r.spacing) :
                  bond_based_micromodulus(r.youngs_modulus,
                                          delta,
                                          dim,
                                          r.plane_strain);
        pairwise_bond_volumes(r, uniform_volumes, bond_volume, pd_share);

        // Per bond: v V_m, then mu v V_m.
        const auto &x = *r.position;
        volume_weight.assign(f.n_bonds(), 0.);
        bond_length.assign(f.n_bonds(), 0.);
        inverse_length.assign(f.n_bonds(), 0.);
        for (std::size_t o = 0; o < f.owners.size(); ++o)
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            {
              const Tensor<1, dim> xi = x[f.members[j]] - x[f.owners[o]];
              const double         L  = xi.norm();
              bond_length[j]          = L;
              inverse_length[j]       = 1. / L;
              // A bar keeps the bonds along x only (weight 0: no force, no
              // stiffness, no share of the damage).
              const bool off_axis = bar && std::abs(xi[0]) < (1. - 1e-9) * L;
              volume_weight[j]    = off_axis ? 0. :
                                               bond_volume[f.members[j]] *
                                              partial_volume(L, r.spacing);
            }
        weight = volume_weight;
        if (surface_correction)
          apply_surface_correction();
        largest_stretch.assign(f.n_bonds(), 0.);
      }

      void
      bonds_changed(const std::vector<std::size_t> &, bool) override
      {}

      bool
      linear() const override
      {
        return false;
      }

      bool
      symmetric() const override
      {
        return true;
      }

      void
      forces(const std::size_t      begin,
             const std::size_t      end,
             const NodalField<dim> &u,
             double                *f_out) const override
      {
        // The bond law of BondBasedBond<dim>::force() written out on raw
        // arrays with |xi| and 1/|xi| kept per bond: one square root and
        // one division per bond (two near or past the onset) instead of four
        // square roots, three divisions and the tensor temporaries. Case 2 of
        // Hu et al. (square_hole.prm, 75 k bonds) relaxed in 40 load steps (8
        // 378 iterations): see doc/changes/20261126_bond_based_kernel.md for
        // the times.
        const PD::Families &f  = *this->region.families;
        const auto         &x  = *this->region.position;
        const double       *uv = u.values;
        const auto         *id = u.local_index;
        for (std::size_t o = begin; o < end; ++o)
          {
            const unsigned int k = f.owners[o];
            double             uk[dim], sum[dim] = {};
            for (unsigned int d = 0; d < dim; ++d)
              uk[d] = uv[id[k][d]];
            for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
              if (f.intact[j])
                {
                  const unsigned int m = f.members[j];
                  double             r[dim], rr = 0.;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      r[d] = (x[m][d] - x[k][d]) + (uv[id[m][d]] - uk[d]);
                      rr += r[d] * r[d];
                    }
                  const double L = bond_length[j], l = std::sqrt(rr);
                  double       T = 1.;
                  if (may_degrade(j, L, l))
                    T = degradation.factor(history_stretch(j, (l - L) / L));
                  const double a = c * T * (inverse_length[j] - 1. / l);
                  for (unsigned int d = 0; d < dim; ++d)
                    sum[d] += weight[j] * (a * r[d]);
                }
            for (unsigned int d = 0; d < dim; ++d)
              f_out[dim * o + d] = -bond_volume[k] * sum[d];
          }
      }

      void
      tangent_products(const std::size_t      begin,
                       const std::size_t      end,
                       const NodalField<dim> &u,
                       const NodalField<dim> &v,
                       double                *f_out) const override
      {
        // Row k of K(u) v = -V_k sum_m w_km K_km (v_m - v_k) with the bond
        // stiffness of BondBasedBond<dim>::stiffness() applied without
        // forming it: K w = (a - b) (r . w) r / l^2 + b w, a = c (T + s T')
        // / L, b = c T s / l. Below the onset (T = 1, T' = 0) a = c / L and
        // b = c (1/L - 1/l), the forces() kernel's scalar. One product
        // costs about one force evaluation.
        const PD::Families &f  = *this->region.families;
        const auto         &x  = *this->region.position;
        const double       *uv = u.values;
        const double       *vv = v.values;
        const auto         *id = u.local_index;
        for (std::size_t o = begin; o < end; ++o)
          {
            const unsigned int k = f.owners[o];
            double             uk[dim], vk[dim], sum[dim] = {};
            for (unsigned int d = 0; d < dim; ++d)
              {
                uk[d] = uv[id[k][d]];
                vk[d] = vv[id[k][d]];
              }
            for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
              if (f.intact[j])
                {
                  const unsigned int m = f.members[j];
                  double             r[dim], w[dim], rr = 0., rw = 0.;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      r[d] = (x[m][d] - x[k][d]) + (uv[id[m][d]] - uk[d]);
                      w[d] = vv[id[m][d]] - vk[d];
                      rr += r[d] * r[d];
                      rw += r[d] * w[d];
                    }
                  const double L = bond_length[j], l = std::sqrt(rr);
                  double       axial = c * inverse_length[j],
                         cross       = c * (inverse_length[j] - 1. / l);
                  if (may_degrade(j, L, l))
                    {
                      const double s   = (l - L) / L;
                      const double s_h = history_stretch(j, s);
                      const double T   = degradation.factor(s_h);
                      // T' only while the bond is loading (tangent_row()).
                      const double dT =
                        s >= s_h ? degradation.derivative(s) : 0.;
                      axial = c * (T + s * dT) / L;
                      cross = c * T * s / l;
                    }
                  const double along = (axial - cross) * rw / rr;
                  for (unsigned int d = 0; d < dim; ++d)
                    sum[d] += weight[j] * (along * r[d] + cross * w[d]);
                }
            for (unsigned int d = 0; d < dim; ++d)
              f_out[dim * o + d] = -bond_volume[k] * sum[d];
          }
      }

      void
      tangent_row(const std::size_t            o,
                  const NodalField<dim>       &u,
                  std::vector<Tensor<2, dim>> &blocks) const override
      {
        const PD::Families  &f  = *this->region.families;
        const auto          &x  = *this->region.position;
        const unsigned int   k  = f.owners[o];
        const Tensor<1, dim> uk = u[k];
        blocks.assign(1, Tensor<2, dim>());
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            {
              const unsigned int   m   = f.members[j];
              const Tensor<1, dim> xi  = x[m] - x[k];
              const Tensor<1, dim> eta = u[m] - uk;
              const double         s   = BondBasedBond<dim>::stretch(xi, eta);
              const double         s_h = history_stretch(j, xi, eta);
              // T' only while the bond is loading (s is its largest stretch).
              const double dT = s >= s_h ? degradation.derivative(s) : 0.;
              const Tensor<2, dim> B =
                -bond_volume[k] * weight[j] *
                BondBasedBond<dim>::stiffness(
                  xi, eta, c, degradation.factor(s_h), dT);
              blocks.push_back(B);
              blocks[0] -= B;
            }
      }

      Tensor<2, dim>
      displacement_gradient(const std::size_t      o,
                            const NodalField<dim> &u) const override
      {
        return fitted_gradient(this->region, o, u, [](std::size_t) {
          return 1.;
        });
      }

      /// phi_k = 1 - sum T v V_m / sum v V_m over the family's bonds
      /// (broken ones T = 0): the broken-bond fraction without degradation
      /// (specs/003 §1.4).
      double
      damage(const std::size_t o, const NodalField<dim> &u) const override
      {
        const PD::Families  &f       = *this->region.families;
        const auto          &x       = *this->region.position;
        const unsigned int   k       = f.owners[o];
        const Tensor<1, dim> uk      = u[k];
        double               carried = 0., total = 0.;
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          {
            total += volume_weight[j];
            if (f.intact[j])
              {
                const unsigned int m = f.members[j];
                carried += volume_weight[j] *
                           degradation.factor(
                             history_stretch(j, x[m] - x[k], u[m] - uk));
              }
          }
        return total > 0. ? 1. - carried / total : 0.;
      }

      double
      nodal_volume(const unsigned int k) const override
      {
        return uniform_volumes ? bond_volume[k] * pd_share[k] :
                                 (*this->region.pd_volume)[k];
      }

      std::vector<std::pair<std::string, double>>
      constants() const override
      {
        std::vector<std::pair<std::string, double>> list{
          {"micromodulus", c},
          {"horizon", delta},
          {"spacing", this->region.spacing}};
        if (bar)
          list.emplace_back("bar cross-section", 0.5 * this->region.spacing);
        if (degradation.active)
          {
            list.emplace_back("onset stretch", degradation.onset);
            list.emplace_back("critical stretch", degradation.critical);
            list.emplace_back("degradation rate", degradation.rate);
          }
        return list;
      }

      void
      commit_state(const NodalField<dim> &u) override
      {
        if (!degradation.active || !irreversible)
          return;
        const auto &x = *this->region.position;
        for_each_bond([&](const std::size_t  j,
                          const unsigned int k,
                          const unsigned int m,
                          const bool         intact) {
          if (intact)
            largest_stretch[j] =
              std::max(largest_stretch[j],
                       BondBasedBond<dim>::stretch(x[m] - x[k], u[m] - u[k]));
        });
      }

      bool
      bond_failed(const std::size_t j) const override
      {
        return degradation.active && irreversible &&
               largest_stretch[j] >= degradation.critical;
      }

      DegradationState
      degradation_state(const NodalField<dim> &u,
                        const double           onset_fraction) const override
      {
        DegradationState state;
        if (!degradation.active)
          return state;
        const double s_t = onset_fraction * degradation.onset;
        const auto  &x   = *this->region.position;
        for_each_bond([&](const std::size_t  j,
                          const unsigned int k,
                          const unsigned int m,
                          const bool         intact) {
          if (intact)
            {
              const double s = history_stretch(j, x[m] - x[k], u[m] - u[k]);
              state.n_beyond_threshold += s > s_t;
              state.degradation += 1. - degradation.factor(s);
              state.max_onset_ratio =
                std::max(state.max_onset_ratio, s / degradation.onset);
            }
          else if (bond_failed(j))
            {
              ++state.n_beyond_threshold;
              ++state.n_failed;
              state.degradation += 1.;
            }
        });
        return state;
      }

      void
      save_state(StateArchive &state) const override
      {
        state.put("pd model/largest stretch", largest_stretch);
      }

      void
      restore_state(const StateArchive &state) override
      {
        const auto saved = state.get_vector<double>("pd model/largest stretch");
        if (saved.size() != largest_stretch.size())
          throw InputError("",
                           "--restart",
                           "the checkpoint's bond history has " +
                             std::to_string(saved.size()) +
                             " bonds, this run's families " +
                             std::to_string(largest_stretch.size()));
        largest_stretch = saved;
      }

    private:
      /// @p visit(j, k, m, intact) for every bond j (owner k, member m) of
      /// this rank's families.
      template <typename Visit>
      void
      for_each_bond(const Visit &visit) const
      {
        const PD::Families &f = *this->region.families;
        for (std::size_t o = 0; o < f.owners.size(); ++o)
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            visit(j, f.owners[o], f.members[j], bool(f.intact[j]));
      }

      /// The stretch T is evaluated at: the largest of the accepted states
      /// and the current one (irreversible), or the current one.
      double
      history_stretch(const std::size_t     j,
                      const Tensor<1, dim> &xi,
                      const Tensor<1, dim> &eta) const
      {
        return history_stretch(j, BondBasedBond<dim>::stretch(xi, eta));
      }

      /// The stretch T is evaluated at for bond @p j at stretch @p s: the
      /// largest accepted one with an irreversible history (theory.md
      /// §13.2).
      double
      history_stretch(const std::size_t j, const double s) const
      {
        return irreversible ? std::max(s, largest_stretch[j]) : s;
      }

      /**
       * Can bond @p j (length @p L, deformed length @p l) have T < 1? False
       * only where it is clearly below the onset, decided without the
       * division s = (l - L) / L (the margin keeps the rounded s below s_m
       * too): the kernels forces() and tangent_products() then take T = 1,
       * T' = 0.
       */
      bool
      may_degrade(const std::size_t j, const double L, const double l) const
      {
        return degradation.active &&
               ((irreversible && largest_stretch[j] > degradation.onset) ||
                l - L > (1. - 1e-12) * degradation.onset * L);
      }

      /**
       * Body = uniaxial bar needs its PD nodes on the two edges of a strip
       * one square cell tall along x: two lines y = y_0 and y_0 + h (h the
       * spacing), each a bar of cross-section h/2 (per unit thickness).
       */
      void
      check_bar_strip() const
      {
        const Region<dim> &r  = this->region;
        double             lo = HUGE_VAL, hi = -HUGE_VAL;
        for (unsigned int k = 0; k < r.position->size(); ++k)
          if ((*r.pd_volume)[k] > 0.)
            {
              lo = std::min(lo, (*r.position)[k][1]);
              hi = std::max(hi, (*r.position)[k][1]);
            }
        const double tol = 1e-6 * r.spacing;
        bool two_lines   = lo <= hi && std::abs(hi - lo - r.spacing) <= tol;
        for (unsigned int k = 0; two_lines && k < r.position->size(); ++k)
          if ((*r.pd_volume)[k] > 0.)
            {
              const double y = (*r.position)[k][1];
              two_lines = std::abs(y - lo) <= tol || std::abs(y - hi) <= tol;
            }
        if (!two_lines)
          throw InputError(
            r.source_file,
            "Peridynamics/Bond based/Body",
            "a uniaxial bar needs the PD region to be a strip of square "
            "cells one cell tall along x, and its PD nodes span y = " +
              number(lo) + " to " + number(hi) + " with cells of size " +
              number(r.spacing),
            "uniaxial bar on such a strip (two lines of nodes), or "
            "continuum");
      }

      /// v(|xi|): 1 up to delta - h/2, then linear to 0 at delta + h/2.
      double
      partial_volume(const double length, const double h) const
      {
        if (!volume_correction || length <= delta - 0.5 * h)
          return 1.;
        return std::clamp((delta + 0.5 * h - length) / h, 0., 1.);
      }

      /**
       * mu_km = [sum_d (n_d / G_d)^2]^(-1/2), G_d = (g_d,k + g_d,m) / 2,
       * g_d,k = W_classical / W_k^PD under the uniaxial strain eps e_d:
       * W_k^PD = 1/4 sum_m c s^2 |xi| v V_m with s = eps n_d^2 (small
       * strain), W_classical = (lambda + 2 mu) eps^2 / 2. PD nodes only;
       * g = 1 for the FE nodes that own reverse families.
       */
      void
      apply_surface_correction()
      {
        const Region<dim>  &r           = this->region;
        const PD::Families &f           = *r.families;
        const auto         &x           = *r.position;
        const unsigned int  n           = x.size();
        const double        W_classical = 0.5 * (r.lambda + 2. * r.mu);
        std::vector<double> g(dim * n, 0.), known(n, 0.);
        for (std::size_t o = 0; o < f.owners.size(); ++o)
          {
            const unsigned int k = f.owners[o];
            if (!((*r.pd_volume)[k] > 0.))
              continue;
            Tensor<1, dim> W;
            for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
              {
                const Tensor<1, dim> xi = x[f.members[j]] - x[k];
                const double         L  = xi.norm();
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const double s = xi[d] * xi[d] / (L * L);
                    W[d] += 0.25 * c * s * s * L * volume_weight[j];
                  }
              }
            for (unsigned int d = 0; d < dim; ++d)
              g[dim * k + d] = W[d] > 0. ? W_classical / W[d] : 1.;
            known[k] = 1.;
          }
        Utilities::MPI::sum(g, r.comm, g);
        Utilities::MPI::sum(known, r.comm, known);
        for (unsigned int k = 0; k < n; ++k)
          if (known[k] == 0.)
            for (unsigned int d = 0; d < dim; ++d)
              g[dim * k + d] = 1.;
        for (std::size_t o = 0; o < f.owners.size(); ++o)
          {
            const unsigned int k = f.owners[o];
            for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
              {
                const unsigned int   m   = f.members[j];
                const Tensor<1, dim> xi  = x[m] - x[k];
                double               sum = 0.;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const double G   = 0.5 * (g[dim * k + d] + g[dim * m + d]);
                    const double n_d = xi[d] / xi.norm();
                    sum += (n_d / G) * (n_d / G);
                  }
                weight[j] = volume_weight[j] / std::sqrt(sum);
              }
          }
      }

      BondDegradation degradation;
      /// Body = uniaxial bar: bonds along x, c = 2 E / (A delta^2).
      bool   bar                = false;
      bool   irreversible       = true;
      bool   volume_correction  = true;
      bool   surface_correction = true;
      bool   uniform_volumes    = false;
      double dirichlet_layer    = 1.;
      double c = 0., delta = 0.;
      /// Per node: the volume its bonds carry, and V_k^pd / V_k.
      std::vector<double> bond_volume, pd_share;
      /// Per bond (family order): v V_m, mu v V_m, and the largest stretch
      /// of the accepted states.
      std::vector<double> volume_weight, weight, largest_stretch;
      /// Per bond: |xi| and 1 / |xi|, for forces().
      std::vector<double> bond_length, inverse_length;
    };

#define INSTANTIATE(dim) template struct BondBasedBond<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem

PDFEM_REGISTER_PD_MODEL(
  pdfem::PDModels::BondBased,
  "bond based",
  "finite-deformation bond-based PD with the smooth tanh degradation "
  "(Hu et al.); nonlinear, symmetric tangent; nu = 1/3 plane stress, 1/4 "
  "plane strain and 3D",
  pdfem::PDModels::declare_bond_based_parameters)
