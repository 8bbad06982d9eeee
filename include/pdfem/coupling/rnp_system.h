// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_COUPLING_RNP_SYSTEM_H
#define PDFEM_COUPLING_RNP_SYSTEM_H

#include <pdfem/drivers/newton_driver.h>
#include <pdfem/drivers/system_interface.h>
#include <pdfem/pd_models/rnp.h>
#include <pdfem/solvers/banded_ldlt.h>

#include <deal.II/base/point.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace pdfem
{
  namespace Coupling
  {
    /** Analytic tangent, or central differences of the nodal forces. */
    enum class RNPTangent
    {
      analytic,
      finite_difference
    };

    /**
     * A peridynamic body of RNP bonds (specs/000 §2): nodes x_i with volumes
     * V_i, every pair closer than the horizon bonded unless a pre-crack cuts
     * it (bonds soften, they never break). Unknowns u_(dim i + c).
     *
     * Nodal forces (force units, rows scaled by V_i so that the tangent is
     * symmetric, specs/001 §2.2): f_int,i = -V_i sum_j t(xi_ij, eta_ij) V_j
     * with the bond force density t of PDModels::RNP, f_ext from the loads,
     * r = f_ext - f_int on the free DoFs, K = d f_int / d u. K is assembled
     * on the free DoFs into a band matrix (reverse Cuthill-McKee order) and
     * factorised by LDL^T, whose negative pivots count the negative
     * eigenvalues: the stability check of the Newton driver.
     *
     * Finite elements may share the nodes (LinearElements): an RNP region
     * coupled to FE through the interface nodes, one matrix.
     *
     * Serial: all nodes on one process (MPI_COMM_SELF vectors).
     */
    template <int dim>
    class RNPSystem : public Drivers::SystemInterface,
                      public Drivers::StabilityInterface
    {
    public:
      /** Prescribed displacements and external forces. */
      struct Loads
      {
        /// Per DoF: 1 if its displacement is prescribed.
        std::vector<std::uint8_t> constrained;
        /// Write the prescribed values at load factor t into the
        /// constrained entries of a DoF vector (others untouched).
        std::function<void(double, std::vector<double> &)> prescribed;
        /// Write the external nodal forces at load factor t (every entry).
        std::function<void(double, std::vector<double> &)> external_force;
      };

      /**
       * Linear elements sharing the nodes (the finite elements around an
       * RNP region): per element its DoFs and its symmetric stiffness
       * (row-major). They add K_e u_e to f_int and K_e to the tangent.
       */
      struct LinearElements
      {
        std::vector<std::vector<unsigned int>> dofs;
        std::vector<std::vector<double>>       matrices;

        /// y += K_FE x (all elements).
        void
        add_product(const std::vector<double> &x, std::vector<double> &y) const
        {
          for (std::size_t e = 0; e < dofs.size(); ++e)
            {
              const std::size_t n  = dofs[e].size();
              const double     *Ke = matrices[e].data();
              for (std::size_t a = 0; a < n; ++a)
                for (std::size_t b = 0; b < n; ++b)
                  y[dofs[e][a]] += Ke[a * n + b] * x[dofs[e][b]];
            }
        }
      };

      /// @p cut(x_i, x_j): is the bond cut by a pre-crack? @p pd_node: the
      /// nodes that own families (empty: all); @p elements: FE cells;
      /// @p fe_members: non-PD nodes are family members too (bonds PD-FE
      /// within the horizon, acting on both nodes). @p energy_weight: per
      /// node the share w_i of its volume that is PD material (1: all PD,
      /// 0: FE); empty: 1 everywhere. Each bond's energy, force and
      /// stiffness are scaled by (w_i + w_j) / 2, so that the bonds count
      /// only the energy of the PD material they stand for, not that of the
      /// FE cells next to them (theory.md §8.3, energy partition).
      RNPSystem(const std::vector<dealii::Point<dim>>                 &x,
                const std::vector<double>                             &volume,
                const PDModels::RNPSettings                           &settings,
                const std::function<bool(const dealii::Point<dim> &,
                                         const dealii::Point<dim> &)> &cut,
                const Loads                                           &loads,
                RNPTangent                       tangent = RNPTangent::analytic,
                const std::vector<std::uint8_t> &pd_node = {},
                const LinearElements            &elements      = {},
                bool                             fe_members    = false,
                const std::vector<double>       &energy_weight = {});

      // ---- Drivers::SystemInterface
      void
      initialize_vector(Vector &v) const override;
      void
      apply_dirichlet(Vector &u, double t) const override;
      double
      residual(const Vector &u,
               double        t,
               Vector       &r,
               bool          assemble_tangent) override;
      double
      force_scale() const override;
      unsigned int
      solve_linear(Vector &du, const Vector &r) override;

      // ---- Drivers::StabilityInterface
      Drivers::StabilityReport
      check_stability() override;

      // ---- plain access (tests, benchmarks, output)
      unsigned int
      n_nodes() const
      {
        return x.size();
      }
      unsigned int
      n_dofs() const
      {
        return dim * x.size();
      }
      /// Undirected bonds kept, and cut by the pre-cracks.
      std::size_t
      n_bonds() const
      {
        return members.size() / 2;
      }
      std::size_t
      n_cut_bonds() const
      {
        return n_cut;
      }
      /// Nodes without a bond or an element, held at zero displacement.
      unsigned int
      n_decoupled_nodes() const
      {
        return n_decoupled;
      }
      /// Bond count of each node (its family size).
      unsigned int
      family_size(unsigned int i) const
      {
        return offsets[i + 1] - offsets[i];
      }
      const std::vector<dealii::Point<dim>> &
      positions() const
      {
        return x;
      }
      const PDModels::RNP<dim> &
      model() const
      {
        return rnp;
      }

      /// f_int(u) on every DoF.
      void
      internal_force(const std::vector<double> &u,
                     std::vector<double>       &f) const;

      /**
       * K(u) v on every DoF (no constraints), analytic: the bonds' blocks
       * a_ij of eq. (34) (corrected, theory.md §8.2) and the FE matrices,
       * without assembling K. The arc-length continuation under hard
       * loading needs it for d r / d t = -K_fp d u_p / d t: how the
       * residual on the free DoFs changes with the prescribed values.
       */
      void
      tangent_product(const std::vector<double> &u,
                      const std::vector<double> &v,
                      std::vector<double>       &Kv) const;

      /// K(u) on every DoF (no constraints), dense row-major; small systems.
      void
      dense_tangent(const std::vector<double> &u,
                    std::vector<double>       &K,
                    RNPTangent                 method) const;

      /// Assemble K(u) on the free DoFs into the band matrix.
      void
      assemble_tangent(const std::vector<double> &u, RNPTangent method);

      /// Per node: max over its bonds of |S| sqrt|xi| / r_c (specs/000 (18)).
      std::vector<double>
      damage(const std::vector<double> &u) const;

      /// Fold damage(u) into the running maximum (call per converged step).
      void
      update_damage_history(const std::vector<double> &u);
      const std::vector<double> &
      damage_history() const
      {
        return max_damage;
      }

      /// f_int and f_ext of the last residual() call.
      const std::vector<double> &
      last_internal_force() const
      {
        return f_int;
      }
      const std::vector<double> &
      last_external_force() const
      {
        return f_ext;
      }
      const Solvers::BandedLDLT &
      matrix() const
      {
        return K;
      }

    private:
      /// f_int of node i alone (its dim entries into @p f).
      void
      node_force(const std::vector<double> &u, unsigned int i, double *f) const;

      std::vector<dealii::Point<dim>> x;
      std::vector<double>             volume;
      PDModels::RNP<dim>              rnp;
      Loads                           loads;
      RNPTangent                      method;
      LinearElements                  fe;
      // families, CSR, symmetric (j in F(i) iff i in F(j))
      std::vector<std::size_t>  offsets;
      std::vector<unsigned int> members;
      // per bond (as members): (w_i + w_j) / 2 of the energy partition
      std::vector<double> weight;
      std::size_t         n_cut       = 0;
      unsigned int        n_decoupled = 0;
      // free DoF -> band row (-1: constrained)
      std::vector<long>   band_row;
      Solvers::BandedLDLT K;
      double              fd_step = 0.;
      // state of the last residual()
      std::vector<double> f_int, f_ext;
      double              scale = 0.;
      std::vector<double> max_damage;
    };
  } // namespace Coupling
} // namespace pdfem

#endif
