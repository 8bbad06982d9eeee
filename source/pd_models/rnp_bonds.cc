// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "rnp": regularized nonlinear pairwise bonds (specs/000,
// specs/001) as a term of the coupled system.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/pd/families.h>
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

    namespace
    {
      /// `subsection RNP` inside `subsection Peridynamics`.
      void
      declare_rnp_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("RNP");
        prm.declare_entry(
          "Calibration",
          "moduli",
          Patterns::Selection("moduli|constants"),
          "moduli: C beta from Material/Young's modulus and C "
          "from the fracture energy (doc/theory.md, RNP "
          "calibration); the Poisson's ratio must be the "
          "model's (1/3 plane stress, 1/4 plane strain and 3D). "
          "constants: C and beta as given.");
        prm.declare_entry("C",
                          "0",
                          Patterns::Double(0.),
                          "C in g(r) = C (1 - exp(-beta r^2)) (constants).");
        prm.declare_entry("beta",
                          "0",
                          Patterns::Double(0.),
                          "beta in g(r) = C (1 - exp(-beta r^2)) (constants).");
        prm.declare_entry("Fracture energy",
                          "0",
                          Patterns::Double(0.),
                          "G_c [J/m^2] (moduli): C = G_c omega_d / (2 "
                          "omega_(d-1) M_d).");
        prm.declare_entry(
          "Influence function",
          "constant",
          Patterns::Selection("constant|linear"),
          "J(|xi|/horizon): constant 1 or linear 1 - |xi|/eps.");
        prm.declare_entry("Force scaling",
                          "paper",
                          Patterns::Selection("paper|prototype"),
                          "paper: g'(sqrt|xi| S)/sqrt|xi| (eq. 27, the one the "
                          "calibration holds for); prototype: g'/|xi| (the "
                          "Python prototype, for regression only).");
        prm.declare_entry("Tangent",
                          "analytic",
                          Patterns::Selection("analytic|finite difference"),
                          "analytic (eq. 33-34 corrected) or central finite "
                          "differences of the nodal forces (for comparison).");
        prm.declare_entry(
          "Interface energy",
          "full bonds",
          Patterns::Selection("full bonds|partition"),
          "With FE cells around the RNP region and Family members = all "
          "nodes: full bonds: every bond counts fully (the FE cells next to "
          "the interface are stiffened by the bonds reaching into them); "
          "partition: each bond is weighted by the mean PD share of its two "
          "nodes' volumes, so that bonds and FE cells split the energy "
          "(doc/theory.md, RNP coupling; smaller ghost forces).");
        declare_lattice_parameters(prm);
        prm.leave_subsection();
      }
    } // namespace

    /**
     * The RNP bond model as a term of the coupled system (specs/000 eqs.
     * (5), (8), (11)-(12), (27), (34) corrected; PDModels::RNP):
     *
     *   F_k = -V_k sum_m w_km V_m t(xi_km, eta_km),   eta = u_m - u_k,
     *
     * over the intact bonds. V are the bond volumes: the PD cells' shares
     * V_k^pd, every cell's share with FE nodes in the families (an
     * interface node stands for material on both sides), or h^dim
     * (`Nodal volumes = uniform`, the paper's lattice); w_km = 1, or
     * (w_k + w_m) / 2 with w_k = V_k^pd / V_k (`Interface energy =
     * partition`, theory.md §8.3). It is the gradient of the energy
     * sum_k V_k sum_m w_km |xi| W(S) V_m / 2, so its tangent
     *
     *   dF_k/du_m = -V_k V_m w_km a(xi, eta),  dF_k/du_k = -sum_m dF_k/du_m
     *
     * is symmetric: the layout (Layout) asks for one horizon, symmetric
     * families and, with FE nodes in the families, reverse families owned
     * by those FE nodes, so that every bond acts on both its nodes. The
     * horizon epsilon of the bond constant c = 2 / (eps^(d+1) omega_d) is
     * the horizon factor times the largest PD cell size. Prescribed values
     * act on the PD nodes within `Dirichlet layer` horizons of their
     * boundary, the body force is b(x_k) V_k. C and beta are given or
     * calibrated from E and G_c (specs/000 §1.5, corrected). Nonlinear:
     * bonds soften past r_c = 1 / sqrt(2 beta); the Newton drivers check
     * the tangent's inertia.
     */
    template <int dim>
    class RNPBonds : public Interface<dim>
    {
    public:
      void
      parse_parameters(ParameterHandler &prm, const std::string &file) override
      {
        prm.enter_subsection("RNP");
        calibration               = prm.get("Calibration");
        C                         = prm.get_double("C");
        beta                      = prm.get_double("beta");
        fracture_energy           = prm.get_double("Fracture energy");
        settings.influence        = prm.get("Influence function") == "linear" ?
                                      RNPInfluence::linear :
                                      RNPInfluence::constant;
        settings.scaling          = prm.get("Force scaling") == "prototype" ?
                                      RNPForceScaling::prototype :
                                      RNPForceScaling::paper;
        uniform_volumes           = prm.get("Nodal volumes") == "uniform";
        dirichlet_layer           = prm.get_double("Dirichlet layer");
        finite_difference_tangent = prm.get("Tangent") == "finite difference";
        partition                 = prm.get("Interface energy") == "partition";
        prm.leave_subsection();
        source_file = file;
        if (calibration == "constants" && (!(C > 0.) || !(beta > 0.)))
          throw InputError(file,
                           "Peridynamics/RNP/C, beta",
                           "C = " + number(C) + ", beta = " + number(beta) +
                             ": both must be positive with Calibration = "
                             "constants",
                           "C > 0 and beta > 0");
        if (calibration == "moduli" && !(fracture_energy > 0.))
          throw InputError(file,
                           "Peridynamics/RNP/Fracture energy",
                           "G_c = " + number(fracture_energy) +
                             " is not positive",
                           "G_c > 0 with Calibration = moduli");
      }

      void
      initialize(const Region<dim> &r) override
      {
        this->region = r;
        if (calibration == "constants")
          {
            settings.C    = C;
            settings.beta = beta;
          }
        else
          {
            const double nu = rnp_poissons_ratio(dim, r.plane_strain);
            if (std::abs(r.poissons_ratio - nu) > 1e-3)
              throw InputError(
                r.source_file,
                "Material/Poisson's ratio",
                "nu = " + number(r.poissons_ratio) +
                  " cannot be calibrated: a bond-based (RNP) material has "
                  "nu = " +
                  number(nu),
                number(nu) + " (or Peridynamics/RNP/Calibration = constants)");
            settings.C    = rnp_c_from_fracture_energy(fracture_energy,
                                                    settings.influence,
                                                    dim);
            settings.beta = rnp_c_beta(r.youngs_modulus,
                                       settings.influence,
                                       dim,
                                       r.plane_strain) /
                            settings.C;
          }
        const PD::Families &f       = *r.families;
        double              horizon = 0.;
        for (const unsigned int k : f.owners)
          horizon = std::max(horizon, (*r.horizon)[k]);
        settings.horizon = Utilities::MPI::max(horizon, r.comm);
        if (!(settings.horizon > 0.))
          settings.horizon = 1.; // no PD node anywhere: no bond either
        rnp = std::make_unique<RNP<dim>>(settings);

        pairwise_bond_volumes(r, uniform_volumes, bond_volume, pd_share);
        const double shortest = r.spacing > 0. ? r.spacing : 1.;
        fd_step               = 1e-6 * shortest;
      }

      Layout
      layout() const override
      {
        return pairwise_layout(dirichlet_layer);
      }

      /// The PD material of node k: its bond volume's PD share.
      double
      nodal_volume(const unsigned int k) const override
      {
        return uniform_volumes ? bond_volume[k] * pd_share[k] :
                                 (*this->region.pd_volume)[k];
      }

      std::vector<std::pair<std::string, double>>
      constants() const override
      {
        return {{"C", settings.C},
                {"beta", settings.beta},
                {"horizon", settings.horizon},
                {"spacing", this->region.spacing},
                {"r_c", 1. / std::sqrt(2. * settings.beta)}};
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
        const PD::Families &f = *this->region.families;
        for (std::size_t o = begin; o < end; ++o)
          {
            const Tensor<1, dim> F = owner_force(f, o, u);
            for (unsigned int c = 0; c < dim; ++c)
              f_out[dim * o + c] = F[c];
          }
      }

      void
      tangent_row(const std::size_t            o,
                  const NodalField<dim>       &u,
                  std::vector<Tensor<2, dim>> &blocks) const override
      {
        const PD::Families  &f  = *this->region.families;
        const auto          &x  = *this->region.position;
        const auto          &V  = bond_volume;
        const unsigned int   k  = f.owners[o];
        const Tensor<1, dim> uk = u[k];
        blocks.assign(1, Tensor<2, dim>());
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            {
              const unsigned int   m = f.members[j];
              const Tensor<2, dim> B =
                finite_difference_tangent ?
                  difference_block(f, o, u, m) :
                  -V[k] * V[m] * bond_weight(k, m) *
                    rnp->stiffness(x[m] - x[k], u[m] - uk);
              blocks.push_back(B);
              blocks[0] -= B;
            }
      }

      /// A linear fit of the bonds' deformation (fitted_gradient(), with
      /// the influence function as weight).
      Tensor<2, dim>
      displacement_gradient(const std::size_t      o,
                            const NodalField<dim> &u) const override
      {
        const auto &f = *this->region.families;
        const auto &x = *this->region.position;
        return fitted_gradient(this->region, o, u, [&](const std::size_t j) {
          const unsigned int k = f.owners[o];
          return rnp->influence((x[f.members[j]] - x[k]).norm());
        });
      }

      /// max over the bonds of |S| sqrt|xi| / r_c (specs/000 (18)): 1
      /// where a bond reaches its peak force.
      double
      damage(const std::size_t o, const NodalField<dim> &u) const override
      {
        const PD::Families  &f  = *this->region.families;
        const auto          &x  = *this->region.position;
        const unsigned int   k  = f.owners[o];
        const Tensor<1, dim> uk = u[k];
        double               d  = 0.;
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            d = std::max(d,
                         rnp->damage(x[f.members[j]] - x[k],
                                     u[f.members[j]] - uk));
        return d;
      }

    private:
      /// The energy partition's weight of bond k-m: (w_k + w_m) / 2, or 1.
      double
      bond_weight(const unsigned int k, const unsigned int m) const
      {
        return partition ? 0.5 * (pd_share[k] + pd_share[m]) : 1.;
      }

      /// F_k = -V_k sum_m w_km V_m t(xi, eta) of owner @p o at @p u, with
      /// node @p shifted moved by @p shift (finite differences).
      Tensor<1, dim>
      owner_force(const PD::Families    &f,
                  const std::size_t      o,
                  const NodalField<dim> &u,
                  const Tensor<1, dim>  &shift   = Tensor<1, dim>(),
                  const unsigned int     shifted = ~0u) const
      {
        const auto          &x = *this->region.position;
        const auto          &V = bond_volume;
        const unsigned int   k = f.owners[o];
        const Tensor<1, dim> uk =
          shifted == k ? Tensor<1, dim>(u[k] + shift) : u[k];
        Tensor<1, dim> sum;
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            {
              const unsigned int   m = f.members[j];
              const Tensor<1, dim> um =
                shifted == m ? Tensor<1, dim>(u[m] + shift) : u[m];
              sum +=
                V[m] * bond_weight(k, m) * rnp->force(x[m] - x[k], um - uk);
            }
        return -V[k] * sum;
      }

      /// dF_k / du_m by central differences of owner_force() (Tangent =
      /// finite difference, for comparison with the analytic blocks).
      Tensor<2, dim>
      difference_block(const PD::Families    &f,
                       const std::size_t      o,
                       const NodalField<dim> &u,
                       const unsigned int     m) const
      {
        Tensor<2, dim> B;
        for (unsigned int c = 0; c < dim; ++c)
          {
            Tensor<1, dim> h;
            h[c]                       = fd_step;
            const Tensor<1, dim> plus  = owner_force(f, o, u, h, m);
            const Tensor<1, dim> minus = owner_force(f, o, u, -h, m);
            for (unsigned int i = 0; i < dim; ++i)
              B[i][c] = (plus[i] - minus[i]) / (2. * fd_step);
          }
        return B;
      }

      std::string               calibration = "moduli";
      double                    C = 0., beta = 0., fracture_energy = 0.;
      std::string               source_file;
      RNPSettings               settings;
      std::unique_ptr<RNP<dim>> rnp;
      bool                      uniform_volumes           = false;
      bool                      finite_difference_tangent = false;
      bool                      partition                 = false;
      double                    dirichlet_layer           = 1.;
      double                    fd_step                   = 1e-6;
      /// Per node: the volume its bonds carry, and w_k = V_k^pd / V_k.
      std::vector<double> bond_volume, pd_share;
    };
  } // namespace PDModels
} // namespace pdfem

PDFEM_REGISTER_PD_MODEL(
  pdfem::PDModels::RNPBonds,
  "rnp",
  "regularized nonlinear pairwise cohesive bonds (Diehl & Lipton 2022); "
  "nonlinear, symmetric tangent",
  pdfem::PDModels::declare_rnp_parameters)
