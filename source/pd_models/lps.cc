// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "lps": the linearised linear peridynamic solid (state
// based; specs/002 §1.4) in the direct bond-loop form, as a family-element
// energy (doc/theory.md §15).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/lps.h>

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

    namespace
    {
      /// `subsection LPS` inside `subsection Peridynamics`.
      void
      declare_lps_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("LPS");
        prm.declare_entry("Influence function",
                          "1/r",
                          Patterns::Selection("1/r|1"),
                          "omega(|xi|) of the weighted volume, the "
                          "dilatation and the force state: 1/r (the FFT "
                          "operator's default, specs/002 §1.4) or 1.");
        declare_lattice_parameters(prm);
        declare_traction_layer_parameter(prm);
        prm.leave_subsection();
      }
    } // namespace

    template <int dim>
    void
    LPS<dim>::parse_parameters(ParameterHandler &prm, const std::string &)
    {
      prm.enter_subsection("LPS");
      inverse_distance = prm.get("Influence function") == "1/r";
      uniform_volumes  = prm.get("Nodal volumes") == "uniform";
      dirichlet_layer  = prm.get_double("Dirichlet layer");
      traction_layer   = prm.get_double("Traction layer");
      prm.leave_subsection();
    }

    template <int dim>
    Layout
    LPS<dim>::layout() const
    {
      Layout l;
      l.uniform_horizon  = true;
      l.family_elements  = true;
      l.dirichlet_layer  = dirichlet_layer;
      l.traction_layer   = traction_layer;
      l.nodal_body_force = true;
      l.free_crack_faces = false;
      return l;
    }

    template <int dim>
    double
    LPS<dim>::influence(const double r) const
    {
      return inverse_distance ? 1. / r : 1.;
    }

    template <int dim>
    void
    LPS<dim>::initialize(const Region<dim> &r)
    {
      this->region          = r;
      const LpsConstants c  = lps_constants(r);
      bulk_modulus          = c.bulk_modulus;
      A                     = c.A;
      B                     = c.B;
      delta                 = c.delta;
      const PD::Families &f = *r.families;
      pairwise_bond_volumes(r, uniform_volumes, bond_volume, pd_share);
      const auto &x = *r.position;
      bond_weight.assign(f.n_bonds(), 0.);
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          {
            const double L = (x[f.members[j]] - x[f.owners[o]]).norm();
            bond_weight[j] = influence(L) * bond_volume[f.members[j]];
          }
      m.assign(f.owners.size(), 0.);
      std::vector<std::size_t> all(f.owners.size());
      for (std::size_t o = 0; o < all.size(); ++o)
        all[o] = o;
      update_weighted_volumes(all);
    }

    template <int dim>
    void
    LPS<dim>::update_weighted_volumes(const std::vector<std::size_t> &owners)
    {
      const PD::Families &f = *this->region.families;
      const auto         &x = *this->region.position;
      for (const std::size_t o : owners)
        {
          double sum = 0.;
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            if (f.intact[j])
              sum += bond_weight[j] *
                     (x[f.members[j]] - x[f.owners[o]]).norm_square();
          m[o] = sum;
        }
    }

    template <int dim>
    void
    LPS<dim>::bonds_changed(const std::vector<std::size_t> &changed, bool)
    {
      update_weighted_volumes(changed);
    }

    template <int dim>
    double
    LPS<dim>::dilatation(const std::size_t o, const NodalField<dim> &u) const
    {
      if (!(m[o] > 0.))
        return 0.;
      const PD::Families  &f   = *this->region.families;
      const auto          &x   = *this->region.position;
      const unsigned int   k   = f.owners[o];
      const Tensor<1, dim> uk  = u[k];
      double               sum = 0.;
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (f.intact[j])
          {
            const unsigned int n = f.members[j];
            sum += bond_weight[j] * ((x[n] - x[k]) * (u[n] - uk));
          }
      return dim * sum / m[o];
    }

    template <int dim>
    void
    LPS<dim>::family_forces(const std::size_t            o,
                            const NodalField<dim>       &u,
                            std::vector<Tensor<1, dim>> &f) const
    {
      // f_j = V_k omega V_j / m (A theta xi + B (xi.eta) xi / |xi|^2),
      // f_k = -sum_j f_j (the gradient of V_k W_k).
      const PD::Families  &fam = *this->region.families;
      const auto          &x   = *this->region.position;
      const unsigned int   k   = fam.owners[o];
      const Tensor<1, dim> uk  = u[k];
      f.assign(1, Tensor<1, dim>());
      const double theta = dilatation(o, u);
      const double scale = m[o] > 0. ? nodal_volume(k) / m[o] : 0.;
      for (std::size_t j = fam.offsets[o]; j < fam.offsets[o + 1]; ++j)
        if (fam.intact[j])
          {
            const unsigned int   n  = fam.members[j];
            const Tensor<1, dim> xi = x[n] - x[k];
            const double         xe = xi * (u[n] - uk);
            const Tensor<1, dim> f_j =
              scale * bond_weight[j] * (A * theta + B * xe / (xi * xi)) * xi;
            f.push_back(f_j);
            f[0] -= f_j;
          }
    }

    template <int dim>
    void
    LPS<dim>::family_tangent(const std::size_t o,
                             const NodalField<dim> &,
                             std::vector<Tensor<2, dim>> &K) const
    {
      // K_ab = V_k [(A / d) c_a (x) c_b + (B / m) sum_j omega V_j n_j (x)
      // n_j (delta_aj - delta_ak)(delta_bj - delta_bk)]: the dilatation
      // couples every pair of the family, the bond term only the owner and
      // each member.
      const PD::Families         &fam = *this->region.families;
      const auto                 &x   = *this->region.position;
      const unsigned int          k   = fam.owners[o];
      std::vector<Tensor<1, dim>> c(1);
      std::vector<Tensor<2, dim>> S(1);
      const double                V = nodal_volume(k);
      for (std::size_t j = fam.offsets[o]; j < fam.offsets[o + 1]; ++j)
        if (fam.intact[j])
          {
            const Tensor<1, dim> xi = x[fam.members[j]] - x[k];
            c.push_back(m[o] > 0. ? dim / m[o] * bond_weight[j] * xi :
                                    Tensor<1, dim>());
            c[0] -= c.back();
            S.push_back(m[o] > 0. ? V * B / m[o] * bond_weight[j] / (xi * xi) *
                                      outer_product(xi, xi) :
                                    Tensor<2, dim>());
          }
      const std::size_t n = c.size();
      K.assign(n * n, Tensor<2, dim>());
      const double a = V * A / dim;
      for (std::size_t p = 0; p < n; ++p)
        for (std::size_t q = 0; q < n; ++q)
          K[p * n + q] = a * outer_product(c[p], c[q]);
      for (std::size_t j = 1; j < n; ++j)
        {
          K[j * n + j] += S[j];
          K[0] += S[j];
          K[j] -= S[j];
          K[j * n] -= S[j];
        }
    }

    template <int dim>
    Tensor<2, dim>
    LPS<dim>::displacement_gradient(const std::size_t      o,
                                    const NodalField<dim> &u) const
    {
      // fitted_gradient() weighs a bond with V_j weight / |xi|^2: weight =
      // omega |xi|^2 gives omega V_j.
      const PD::Families &f = *this->region.families;
      const auto         &x = *this->region.position;
      const unsigned int  k = f.owners[o];
      return fitted_gradient(this->region, o, u, [&](const std::size_t j) {
        const double L = (x[f.members[j]] - x[k]).norm();
        return influence(L) * L * L;
      });
    }

    template <int dim>
    double
    LPS<dim>::nodal_volume(const unsigned int k) const
    {
      return uniform_volumes ? bond_volume[k] * pd_share[k] :
                               (*this->region.pd_volume)[k];
    }

    template <int dim>
    std::vector<std::pair<std::string, double>>
    LPS<dim>::constants() const
    {
      return {{"horizon", delta},
              {"spacing", this->region.spacing},
              {dim == 3 ? "bulk modulus" : "planar bulk modulus", bulk_modulus},
              {"shear modulus", this->region.mu},
              {"A", A},
              {"B", B}};
    }

    template <int dim>
    LpsConstants
    lps_constants(const Region<dim> &r)
    {
      LpsConstants c;
      c.bulk_modulus = dim == 3 ? r.lambda + 2. * r.mu / 3. : r.lambda + r.mu;
      c.A            = dim == 3 ? 3. * c.bulk_modulus - 5. * r.mu :
                                  2. * c.bulk_modulus - 4. * r.mu;
      c.B            = dim == 3 ? 15. * r.mu : 8. * r.mu;
      if (!(r.mu > 0.) || !(c.bulk_modulus > 0.))
        throw InputError(r.source_file,
                         "Material/Poisson's ratio",
                         "the LPS model needs a positive shear and bulk "
                         "modulus; mu = " +
                           number(r.mu) + ", kappa = " + number(c.bulk_modulus),
                         "E > 0 and -1 < nu < 1/2");
      double h = 0.;
      for (const unsigned int k : r.families->owners)
        h = std::max(h, (*r.horizon)[k]);
      c.delta = Utilities::MPI::max(h, r.comm);
      return c;
    }

#define INSTANTIATE(dim)   \
  template class LPS<dim>; \
  template LpsConstants lps_constants<dim>(const Region<dim> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem

PDFEM_REGISTER_PD_MODEL(
  pdfem::PDModels::LPS,
  "lps",
  "linearised linear peridynamic solid (state based, specs/002 §1.4) in the "
  "direct form, the same model as the FFT operator's LPS; any Poisson's "
  "ratio; linear, symmetric",
  pdfem::PDModels::declare_lps_parameters)
