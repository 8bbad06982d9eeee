// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_COUPLING_COUPLED_SYSTEM_H
#define PDFEM_COUPLING_COUPLED_SYSTEM_H

#include <pdfem/drivers/dynamic_system_interface.h>
#include <pdfem/drivers/newton_driver.h>
#include <pdfem/fe/elastic_material.h>
#include <pdfem/mesh/cracks.h>
#include <pdfem/pd_models/degradation_state.h>
#include <pdfem/solvers/settings.h>

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
  namespace parallel
  {
    namespace shared
    {
      template <int dim, int spacedim>
      class Triangulation;
    }
  } // namespace parallel
  namespace TrilinosWrappers
  {
    class SparseMatrix;
  }
  namespace hp
  {
    template <int dim, int spacedim>
    class MappingCollection;
  }
} // namespace dealii

namespace pdfem
{
  class StateArchive;
  namespace IO
  {
    class JsonWriter;
  }
  namespace PD
  {
    struct Families;
  }
  namespace PDModels
  {
    template <int dim>
    class Interface;
  }

  namespace Coupling
  {
    /**
     * A boundary condition resolved against the mesh: a named boundary (its
     * boundary ids), a single node at a point, or an explicit list of mesh
     * vertices (Dirichlet only; PDLSM-FEM node sets); one component
     * (0..dim-1, or dim = normal for tractions) and a muparser expression of
     * x, y, z, t.
     */
    template <int dim>
    struct BoundaryCondition
    {
      std::string               name;
      std::vector<unsigned int> boundary_ids;
      bool                      at_point = false;
      dealii::Point<dim>        point;
      std::vector<unsigned int> vertices; // triangulation vertex indices
      unsigned int              component = 0;
      std::string               expression;
    };

    /** Everything the coupled system needs besides the mesh. */
    template <int dim>
    struct Settings
    {
      FE::ElasticMaterial material;
      double              horizon_factor = 3.;
      /// The PD model of the PD cells (a PDModels plugin, its parameters
      /// read); empty: PDLSM collocation (pdlsm) with @p weight_factor.
      std::shared_ptr<PDModels::Interface<dim>> pd_model;
      double                                    weight_factor        = 0.33;
      bool                                      fe_nodes_in_families = true;
      /// Crack faces as free surfaces: families that lose bonds to a crack
      /// are refitted over their intact bonds, and the crack faces carry the
      /// boundary term s_k (2D). Otherwise PDLSM-FEM's cut bonds alone.
      bool                                free_crack_faces = false;
      std::vector<Mesh::Crack<dim>>       cracks;
      std::vector<BoundaryCondition<dim>> dirichlet;
      std::vector<BoundaryCondition<dim>> traction;
      std::vector<std::string>            body_force;
      /// Vertices whose bonds never break (PDLSM-FEM's no-fail region).
      std::vector<unsigned int> no_fail_vertices;
      Solvers::Settings         linear_solver;
      /// Build the matrix-free path's preconditioner (the AMG of the FE
      /// stiffness, "amg fe") during construction, before the PD model's
      /// per-bond data, instead of at the first solve: the peak memory is
      /// then the larger of the two, not their sum. For runs that solve
      /// (Drivers::Interface::solves_linear_systems()).
      bool prepare_solver = false;
      /// The input file, named in error messages.
      std::string source_file;
    };

    /**
     * The patch test of the coupling (CoupledSystem::patch_test()): how far
     * the linearised coupled operator is from reproducing affine fields.
     */
    struct PatchTest
    {
      /// Unit strain modes tested (0: no FE cells, nothing to test).
      unsigned int strain_modes = 0;
      /// Nodes held at the affine field.
      unsigned int held_nodes = 0;
      /// max_k |u_k - eps (x_k - x_c)| / max_k |eps (x_k - x_c)|.
      double max_relative_error = 0.;
      /// max over free nodes |K u_affine|_k / (|sigma| h^(dim-1)).
      double max_relative_ghost_force = 0.;
    };

    /**
     * The balance of the forces at the last residual() (or internal_force()
     * and external_force()) state: a conservative PD operator's internal
     * forces sum to zero for any displacement, so under a self-balanced
     * load the supports carry nothing (issue 16).
     */
    template <int dim>
    struct ForceBalance
    {
      /// sum_j f_int,j and sum_j f_ext,j over every DoF (2D: per unit
      /// thickness).
      dealii::Tensor<1, dim> internal_resultant, external_resultant;
      /// The applied load: half the sum of |f_ext,j| over every DoF, or,
      /// when no force is applied (displacement loading), half the sum of
      /// the reactions' |f_int,j - f_ext,j| over the held DoFs.
      double load = 0.;

      /// |sum f_int| / load: what the supports carry beyond the applied
      /// load's own resultant, relative to it (0 without a load).
      double
      imbalance() const
      {
        return load > 0. ? internal_resultant.norm() / load : 0.;
      }

      /// Are the applied forces balanced among themselves (|sum f_ext| <=
      /// 1e-8 of the load, and some force applied)?
      bool
      self_balanced() const
      {
        return load > 0. && external_resultant.norm() <= 1e-8 * load;
      }
    };

    /** Counts that summary.json reports. */
    struct ProblemSize
    {
      unsigned long n_nodes             = 0;
      unsigned long n_pd_nodes          = 0;
      unsigned long n_interface_nodes   = 0;
      unsigned long n_cells             = 0;
      unsigned long n_pd_cells          = 0;
      unsigned long n_dofs              = 0;
      unsigned long n_bonds             = 0;
      unsigned long n_broken_bonds      = 0;
      unsigned long n_decoupled_nodes   = 0;
      unsigned long n_pd_boundary_faces = 0;
      unsigned long n_matrix_entries    = 0;
      /// Entries of the FE cells' stiffness matrix (all ranks): what the
      /// FE part of every internal force streams.
      unsigned long n_fe_matrix_entries = 0;
    };

    /**
     * Per-node results, replicated on every rank (index = node number).
     * Stress is the PDLSM nonlocal stress at PD nodes and the extrapolated
     * Gauss-point stress of the adjacent FE cells, all contributions averaged
     * with equal weight (as PDLSM-FEM does).
     */
    template <int dim>
    struct NodalResults
    {
      std::vector<dealii::Point<dim>>              position;
      std::vector<dealii::Tensor<1, dim>>          displacement;
      std::vector<dealii::SymmetricTensor<2, dim>> stress;
      /// grad u (component i, direction j): the PDLSM nonlocal gradient at
      /// PD nodes, the extrapolated FE gradient otherwise, averaged as the
      /// stress is (stress = C : sym(grad u) wherever both are averaged).
      std::vector<dealii::Tensor<2, dim>> displacement_gradient;
      std::vector<double>                 damage;
      /// 1: PD only, 2: FE only, 3: interface (PD and FE).
      std::vector<std::uint8_t> kind;
    };

    /// Names of the displacement components: x, y[, z].
    template <int dim>
    inline std::vector<std::string>
    component_names()
    {
      if constexpr (dim == 2)
        return {"x", "y"};
      else
        return {"x", "y", "z"};
    }

    /// Names of the stress components in output order: xx, yy, xy (2D);
    /// xx, yy, zz, xy, yz, xz (3D). Used by summary.json, VTU and nodes.csv.
    template <int dim>
    inline std::vector<std::string>
    stress_component_names()
    {
      if constexpr (dim == 2)
        return {"xx", "yy", "xy"};
      else
        return {"xx", "yy", "zz", "xy", "yz", "xz"};
    }

    /// Component @p c of @p s, in the order of stress_component_names().
    template <int dim>
    inline double
    stress_component(const dealii::SymmetricTensor<2, dim> &s,
                     const unsigned int                     c)
    {
      if constexpr (dim == 2)
        {
          constexpr unsigned int i[3] = {0, 1, 0}, j[3] = {0, 1, 1};
          return s[i[c]][j[c]];
        }
      else
        {
          constexpr unsigned int i[6] = {0, 1, 2, 0, 1, 0},
                                 j[6] = {0, 1, 2, 1, 2, 2};
          return s[i[c]][j[c]];
        }
    }

    /**
     * The coupled PDLSM-FE problem on one mesh, one DoF numbering and one
     * Trilinos matrix (Liu & Xin, EFM 2021, eq. 26-27; specs/004 §1.3):
     *
     *   sum_FE int grad(dv) : sigma dV                        (FE cells)
     * + sum_k V_k^pd dv_k . (-L_k)                            (PD nodes)
     * + sum_k dv_k . sigma_k^pd s_k,  s_k = int_Spd N_k n dS  (PD boundary)
     * = int_S dv . T dS + int_V dv . b dV.
     *
     * FE cells are Q1 (P1 on simplices) displacement elements; PD nodes are
     * the vertices of PD cells and share the interface nodes with the FE
     * cells. V_k^pd is the node's share of its PD cells' volume; S_pd is the
     * boundary of the PD region (outer boundary and PD/FE interface). The
     * matrix is not symmetric.
     *
     * Parallel layout: the mesh is a parallel::shared::Triangulation (every
     * rank has every cell); each rank assembles its own FE cells and the PD
     * families of the nodes it owns, reading the displacement of every node
     * within a horizon through ghost entries.
     *
     * Prescribed DoFs are eliminated (row and column zero, a positive diagonal
     * entry, zero residual). A PD node whose intact bonds can no longer carry
     * the second-order fit and that has no FE cell is "decoupled": it is held
     * where it is in the same way, so that it never makes the matrix singular.
     *
     * Dynamics (coupled_system_dynamics.cc): M a + f_int(u) = f_ext(t) with
     * the lumped mass of specs/004 §1.3 (FE row sums over the FE cells plus
     * rho V_k^pd over the PD cells, one value per node) or the consistent FE
     * mass plus the PD lumped mass, f_int matrix-free, and the effective
     * matrix K_N = c_m M + c_k K factorised once and reused.
     */
    template <int dim>
    class CoupledSystem : public Drivers::DynamicSystemInterface,
                          public Drivers::StabilityInterface
    {
    public:
      /// Set up nodes, families, DoFs and the sparsity pattern. @p cell_is_pd
      /// is indexed by active cell index.
      CoupledSystem(
        const dealii::parallel::shared::Triangulation<dim, dim> &tria,
        const std::vector<bool>                                 &cell_is_pd,
        const Settings<dim>                                     &settings);
      ~CoupledSystem() override;

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
      unsigned int
      solve_linear_within(Vector       &du,
                          const Vector &r,
                          double        allowed_residual) override;
      void
      stiffness_row_bounds(Vector &bounds) override;

      /// @name Dynamics (Drivers::DynamicSystemInterface)
      /// @{
      const Vector &
      lumped_mass() override;
      void
      internal_force(const Vector &u, Vector &f) override;
      void
      external_force(double t, Vector &f) override;
      const std::vector<unsigned int> &
      held_dofs() const override;
      void
      factorize_effective(double mass_factor,
                          double stiffness_factor,
                          bool   consistent_mass) override;
      unsigned int
      solve_effective(Vector &x, const Vector &b) override;
      void
      mass_vmult(Vector &y, const Vector &x) override;
      double
      thickness() const override;
      /// The PD model's released_energy() of the last accept_state() (0 for
      /// a model without a history).
      double
      released_energy() const override;
      void
      pseudo_random(Vector &x) const override;
      /// Reactions (see reactions()) from the last internal_force() and
      /// external_force() calls, without evaluating them again.
      void
      update_reactions();
      /// Number of factorisations (or preconditioner set-ups) of K_N so far.
      unsigned int
      n_effective_factorizations() const;
      /// @p v = the @p dim expressions of x, y, z (t = 0) at every owned
      /// node (an initial velocity field; the expressions were checked when
      /// the parameter @p parameter was read).
      void
      interpolate(const std::vector<std::string> &expressions,
                  const std::string              &parameter,
                  Vector                         &v) const;
      /// The node nearest to @p p (every rank gives the same answer).
      unsigned int
      nearest_node(const dealii::Point<dim> &p) const;
      /// The position of node @p k.
      dealii::Point<dim>
      node_position(unsigned int k) const;
      /// Displacement of node @p k (collective: every rank gets it).
      dealii::Tensor<1, dim>
      node_displacement(const Vector &u, unsigned int k) const;
      /// @}

      /**
       * The inertia of the tangent of the last residual() (prescribed and
       * held DoFs eliminated, so they add positive eigenvalues only): its
       * negative eigenvalues by the negative pivots of MUMPS's symmetric
       * LDL^T on every rank (Solvers::compute_inertia(); Sylvester's law).
       * For a model with a symmetric tangent (PDModels::Interface::
       * symmetric()); collective.
       */
      Drivers::StabilityReport
      check_stability() override;

      /**
       * d r / d t for loads linear in the load factor t, f_ext(t) = t q
       * and prescribed values u_p(t) = u_p(0) + t w:
       *
       *   d r / d t = q - K_fp(u) w   on the free DoFs (0 on held ones),
       *
       * K_fp the tangent's columns of the prescribed DoFs at u (the FE
       * cells and the model's tangent rows, unconstrained). The arc-length
       * continuation needs it, and the Newton driver's snap-back
       * continuation under hard loading. Empty if the loads are not linear
       * in t, or if @p hard_loading_only and w = 0. Collective.
       */
      Drivers::NewtonDriver::LoadDerivative
      load_derivative(bool hard_loading_only);

      /**
       * The patch test of the PD-FE coupling (theory.md §8.3): for each
       * unit strain mode eps, the affine field u = eps (x - x_c) held on
       * the boundary's nodes and on the PD nodes within a horizon of them
       * (so that the PD surface effect is not counted), the rest solved
       * with the tangent at u = 0. An exact coupling reproduces the affine
       * field; the error and the ghost forces K u_affine on the free nodes
       * measure the coupling's. Runs only with FE and PD cells; leaves the
       * system's state as it was. Collective.
       */
      PatchTest
      patch_test();

      /// Global counts (the same on every rank).
      ProblemSize
      size() const;

      /**
       * The wall seconds of the construction's phases on this rank, in
       * their order: "dofs" (the finite elements and the DoF
       * numbering), "nodes" (node data, boundary conditions, the PD
       * boundary), "families" (the bonds, pre-existing cracks cut),
       * "fe_matrix" (the sparsity patterns and the cells' stiffness, of the FE
       * matrix and the "amg fe" matrix),
       * "preconditioner" (the "amg fe" hierarchy where the driver solves
       * linear systems and the linear solver uses it, else about 0),
       * "pd_model" (the model's initialize(), e.g. the PDLSM fit) and
       * "operator" (traction layers, the PD product's chunks). summary.json
       * lists them under timings.setup_phases.
       */
      const std::vector<std::pair<std::string, double>> &
      setup_phases() const;

      /**
       * The matrix the "amg fe" preconditioner is built from (doc/theory.md
       * §5): the Q1/P1 stiffness of every cell, the cells a crack cuts
       * weakened, the held DoFs with their diagonal. Brought up to date with
       * the bonds first; empty with the other linear solvers. For
       * diagnostics and tests.
       */
      const dealii::TrilinosWrappers::SparseMatrix &
      preconditioner_matrix();

      /// The largest PD node damage (the model's: by default the fraction
      /// of broken bonds) at the last residual's state, over all ranks.
      double
      max_damage() const;

      /**
       * Break every intact bond that crosses one of @p cracks (touching
       * counts), except bonds of no-fail nodes; collective. The tangent,
       * the held DoFs and the preconditioner follow on the next residual()
       * and solve_linear(). Returns the number of bonds broken on all ranks.
       */
      unsigned long
      break_bonds(const std::vector<Mesh::Crack<dim>> &cracks);

      /**
       * Break every intact bond (k, m) of this rank's families for which
       * @p breaks(k, m) is true (node indices), except bonds of no-fail
       * nodes; collective, like break_bonds(). A symmetric predicate breaks
       * both directions of a bond between two PD nodes.
       */
      unsigned long
      break_bonds_if(
        const std::function<bool(unsigned int, unsigned int)> &breaks);

      /**
       * The state @p u was accepted (an equilibrium, a time step): a PD
       * model with a history records it (PDModels::Interface::
       * commit_state()), and the bonds it reports failed for good break
       * as with break_bonds_if(). Returns how many broke, over all ranks.
       * Collective.
       */
      unsigned long
      accept_state(const Vector &u);

      /// How far the PD model's smooth degradation has gone at @p u, over
      /// all ranks (PDModels::DegradationState; the switch threshold is
      /// @p onset_fraction times the onset stretch). Collective.
      PDModels::DegradationState
      degradation_state(const Vector &u, double onset_fraction);

      /// This rank's families and their bond states, read-only (bonds break
      /// only through break_bonds() and break_bonds_if()); a bond between
      /// two PD nodes appears once from each side.
      const PD::Families &
      families() const;

      /// The PD model of the PD cells.
      const PDModels::Interface<dim> &
      pd_model() const;

      /// The horizon delta_k of every node (replicated): m V_k^(1/dim), or
      /// one m h for all (PDModels::Layout::uniform_horizon).
      const std::vector<double> &
      horizons() const;

      /**
       * The number of pieces the body is in: connected components of the
       * graph whose edges are the FE cells' node pairs and the intact bonds,
       * counting only components of at least @p min_nodes nodes (a node
       * that lost every bond is not a piece). Collective.
       */
      unsigned int
      count_pieces(unsigned int min_nodes) const;

      /**
       * Hold the PD nodes of every fragment where they are, like a node
       * that lost every bond: a fragment is a piece (as in count_pieces())
       * of fewer than @p min_nodes nodes. In a static solve a fragment that
       * no prescribed displacement holds makes the matrix singular (two PD
       * nodes bonded only to each other, cut loose by a growing crack).
       * Nodes stay held for the rest of the run (bonds do not heal).
       * Returns the number of nodes held now (collective). For static and
       * quasi-static runs; dynamics lets fragments fly.
       */
      unsigned long
      hold_fragments(unsigned int min_nodes);

      /**
       * Put what broke bonds and held fragments since construction, in
       * order (break_bonds(), break_bonds_if(), hold_fragments()), into a
       * checkpoint.
       */
      void
      save_fracture_state(StateArchive &state) const;

      /**
       * Replay what save_fracture_state() put, on a system built as the
       * saved one was (same mesh, PD region, settings, number of ranks)
       * whose bonds have not changed yet: the same bonds break in the same
       * order, so that the condensed stiffness of the energy form and every
       * force come out the same to the bit. Collective.
       */
      void
      restore_fracture_state(const StateArchive &state);

      /// The linear solver's kept preconditioner is built afresh at the
      /// next solve (Solvers::LinearSolver::forget_preconditioner()), from
      /// an auxiliary matrix assembled whole: what a system rebuilt on
      /// restart does.
      void
      forget_preconditioner();

      /**
       * The rigid motions the prescribed displacements leave free, one
       * line per piece of the body (nodes joined by FE cells or intact
       * bonds, at least two) that they do not hold: its size, where it is
       * and which motions are free ("translation y", "rotation about z",
       * or a combined rotation). A static solve of such a piece is
       * singular (a floating body). The rigid motions m_i hold when the
       * Gram matrix sum over the prescribed DoFs of m_i m_j is regular.
       * Empty: every piece is held. Collective.
       */
      std::vector<std::string>
      unheld_rigid_motions() const;

      /**
       * With a PD model that gives no stiffness in one component
       * (PDModels::Layout::stiffless_component): one line naming the PD
       * nodes without FE cells whose component is not prescribed (how
       * many, the first one), whose static solve would be singular. Empty:
       * every such node is held, or the model has no such component.
       */
      std::string
      unheld_component() const;

      /// The force balance at the last residual() state (collective).
      ForceBalance<dim>
      force_balance() const;

      /// Names of the Dirichlet sets (boundaries or points), in input order.
      std::vector<std::string>
      reaction_names() const;

      /// Reaction force on each Dirichlet set from the last residual() call,
      /// for the 2D thickness: sum over its nodes of f_int - f_ext.
      std::vector<dealii::Tensor<1, dim>>
      reactions() const;

      /// Replicated per-node displacement, stress, damage and kind.
      NodalResults<dim>
      nodal_results(const Vector &u) const;

      /// For output: the vector DoFHandler, the per-node scalar DoFHandler and
      /// its numbering, the mapping collection and the PD flag of the cells.
      /// The collections hold one element per kind of cell the mesh has
      /// (Q1 before P1); a mesh of one kind gives a DoFHandler without hp,
      /// whose cells all have active_fe_index() 0.
      const dealii::DoFHandler<dim, dim> &
      dof_handler() const;
      const dealii::DoFHandler<dim, dim> &
      node_dof_handler() const;
      const std::vector<unsigned int> &
      node_of_scalar_dof() const;
      const dealii::hp::MappingCollection<dim, dim> &
      mapping() const;
      const std::vector<bool> &
      cell_is_pd() const;
      /**
       * summary.json's "linear_solver" section: the configured type, the
       * path the solves take now, their counts (solves, GMRES iterations,
       * direct analyses and factorisations) and, for Type = auto, the
       * choice with its reasons (Solvers::SolverChoice::write()).
       */
      void
      write_solver_summary(IO::JsonWriter &json) const;

      /// Type = auto: the changes of path so far (empty otherwise), for the
      /// progress output.
      std::vector<std::string>
      solver_switches() const;

      /// Per active cell: a crack runs through it (broken bonds split its
      /// vertices into two or more groups; PD cells only, judged from the
      /// locally owned families). The output's "cracked" cell array.
      std::vector<bool>
      cracked_cells() const;

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };
  } // namespace Coupling
} // namespace pdfem

#endif
