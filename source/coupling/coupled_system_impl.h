// SPDX-License-Identifier: LGPL-2.1-or-later
// Private state of Coupling::CoupledSystem, shared by its translation units.
#ifndef PDFEM_SOURCE_COUPLING_COUPLED_SYSTEM_IMPL_H
#define PDFEM_SOURCE_COUPLING_COUPLED_SYSTEM_IMPL_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/solvers/linear_solver.h>
#include <pdfem/solvers/solver_choice.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <vector>

class Epetra_BlockMapData;
class Epetra_Import;

namespace pdfem
{
  namespace Coupling
  {
    using dealii::types::global_dof_index;

    /// @p p as a point of 3D space (the muparser functions take x, y, z).
    template <int dim>
    inline dealii::Point<3>
    to_3d(const dealii::Point<dim> &p)
    {
      dealii::Point<3> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] = p[d];
      return q;
    }

    /// State of the dynamic methods (coupled_system_dynamics.cc).
    struct DynamicData;

    template <int dim>
    struct CoupledSystem<dim>::Impl
    {
      Impl(const dealii::parallel::shared::Triangulation<dim, dim> &tria,
           const std::vector<bool>                                 &cell_is_pd,
           const Settings<dim>                                     &settings);

      // ----- set-up steps (coupled_system_setup.cc, _families.cc)
      void
      make_fe_and_dofs();
      void
      make_nodes();
      void
      make_pd_boundary();
      /// Adds to @p area[k] the area vector int N_k n dS of node k over the
      /// faces (cell, f) of PD cells for which @p selected is true (outward
      /// from the cell) and returns their total area.
      double
      add_face_area_vectors(
        const std::function<
          bool(const typename dealii::DoFHandler<dim>::active_cell_iterator &,
               unsigned int)>               &selected,
        std::vector<dealii::Tensor<1, dim>> &area) const;
      /// The families of the owned PD nodes, cut by the pre-existing
      /// cracks; the model's per-bond data come later (initialize_model()).
      void
      make_families();
      /// The PD model's per-bond data over its whole initial families, then
      /// the bonds cut by the pre-existing cracks.
      void
      initialize_model();
      void
      make_sparsity();
      /// Add the entries of the locally owned FE cells (@p all_cells: every
      /// cell) and every owned diagonal to @p sp.
      void
      add_cell_entries(dealii::TrilinosWrappers::SparsityPattern &sp,
                       bool all_cells) const;
      /// With Settings::prepare_solver and the matrix-free path: the AMG of
      /// the auxiliary matrix now (before initialize_model()).
      void
      prepare_solver();
      /// The pattern of the "amg fe" auxiliary matrix (every cell).
      void
      make_auxiliary_pattern();
      /// The pattern of the assembled coupled tangent.
      void
      make_assembled_pattern();
      // ----- Linear solver Type = auto (coupled_system_solver_choice.cc)
      /// Create the choice (once), with the estimate of the direct
      /// factors' memory.
      void
      set_up_choice();
      /// Solve on the path the choice says (or the one configured).
      unsigned int
      solve_on_path(dealii::TrilinosWrappers::MPI::Vector       &du,
                    const dealii::TrilinosWrappers::MPI::Vector &r,
                    double allowed_residual);
      /// Go over to @p path: build what it needs, drop what it no longer
      /// does.
      void
      switch_path(Solvers::SolvePath path);
      void
      make_boundary_conditions();
      /// The nodes of @p nodes, and the PD nodes within @p layer of any of
      /// them or of @p points (sorted, unique).
      std::vector<unsigned int>
      with_boundary_layer(std::vector<unsigned int>              nodes,
                          const std::vector<dealii::Point<dim>> &points,
                          double                                 layer) const;

      // ----- assembly (coupled_system_assembly.cc)
      /// The FE-cells part of f_int, once (linear, it never changes), and for
      /// "amg fe" the auxiliary matrix: FE stiffness of every cell.
      void
      assemble_fe_matrix();
      /**
       * Add factor(c) K_c to @p target for every locally owned cell c with
       * select(c) (cell indices), K_c its Q1/P1 stiffness
       * (FE::cell_stiffness()), rows and columns of prescribed DoFs
       * dropped when @p eliminate; returns the number of cells. On the
       * threads of ThreadTeam::shared() (factor() is called on them), the
       * matrix the same bit for bit on any number of threads
       * (coupled_system_cell_matrix.cc). No compress().
       */
      unsigned int
      add_cell_stiffness(dealii::TrilinosWrappers::SparseMatrix    &target,
                         const std::function<bool(unsigned int)>   &select,
                         const std::function<double(unsigned int)> &factor,
                         bool eliminate) const;
      /// The "amg fe" preconditioner's matrix: the FE stiffness of every
      /// cell, cells cut by broken bonds weakened (cut_cell_stiffness).
      void
      assemble_auxiliary();
      /// Per active cell: broken bonds split its vertices into two or more
      /// groups joined by intact bonds (a crack runs through it).
      std::vector<bool>
      cells_cut_by_broken_bonds() const;
      // ----- matrix-free operator (coupled_system_operator.cc)
      /**
       * The PD internal forces of the owned families for the displacement
       * @p x (ghosted: owned and relevant entries), into pd_force: owner k
       * gets the sum over intact bonds of (-V_k G_m + T_m)(x_m - x_k). Works
       * on the raw local arrays, in chunks on the threads of
       * ThreadTeam::shared(). The calling thread first runs @p fe_product
       * (which may communicate: MPI stays on that thread) and then joins
       * the kernel. With @p tangent_state (ghosted) the rows are instead
       * the products of the model's tangent at that state with @p x
       * (PDModels::Interface::tangent_products(): a nonlinear model).
       */
      void
      compute_pd_forces(const dealii::TrilinosWrappers::MPI::Vector &x,
                        const std::function<void()>                 &fe_product,
                        const dealii::TrilinosWrappers::MPI::Vector
                          *tangent_state = nullptr) const;
      /// Add pd_force to the owned entries of @p y.
      void
      add_pd_forces(dealii::TrilinosWrappers::MPI::Vector &y) const;
      /// @p ghosted (owned and relevant entries) = @p v (owned), through a
      /// kept Epetra_Import.
      void
      import_ghosts(const dealii::TrilinosWrappers::MPI::Vector &v,
                    dealii::TrilinosWrappers::MPI::Vector       &ghosted) const;
      /// The kept import from @p owned_vector's map to @p ghosted_vector's.
      const Epetra_Import &
      ghost_import(
        const dealii::TrilinosWrappers::MPI::Vector &owned_vector,
        const dealii::TrilinosWrappers::MPI::Vector &ghosted_vector) const;
      /// y (owned) += the sum over ranks of @p contributions (a vector in
      /// the ghosted layout whose ghost entries are this rank's
      /// contributions to other ranks' DoFs): the reverse of the import.
      void
      scatter_add(const dealii::TrilinosWrappers::MPI::Vector &contributions,
                  dealii::TrilinosWrappers::MPI::Vector       &y) const;
      /// Family o's nodes as a family-element model sees them: the owner,
      /// then its intact members in family order.
      std::vector<unsigned int>
      family_nodes(std::size_t o) const;
      /// Family-element models: column j (vector j) of every owned node's
      /// diagonal tangent block, summed over the families it is in.
      std::vector<dealii::TrilinosWrappers::MPI::Vector>
      family_diagonal_blocks(const PDModels::NodalField<dim> &field) const;
      /// Split the owners into pd_chunks and size pd_force, once the
      /// families are made.
      void
      make_pd_chunks();
      /// Run @p caller_first on the calling thread, and @p owners on the
      /// owner ranges of pd_chunks, shared by every thread of the team
      /// (the caller joins once its own work is done).
      void
      for_each_pd_chunk(
        const std::function<void()>                         &caller_first,
        const std::function<void(std::size_t, std::size_t)> &owners) const;
      /// After bonds of the families @p changed broke: the model updates
      /// its bond data (refits them with @p free_surfaces), decoupled and
      /// held DoFs are listed again; the block-Jacobi inverse and the
      /// auxiliary matrix are rebuilt by the next solve.
      void
      bonds_changed(const std::vector<std::size_t> &changed,
                    bool                            free_surfaces);
      /// Break the intact bonds b of owners o (not no-fail) for which
      /// @p breaks(o, b), as one predicate event; returns how many broke
      /// over all ranks.
      unsigned long
      break_bonds_where(
        const std::function<bool(std::size_t, std::size_t)> &breaks);
      /// After the decoupled owners changed: held DoFs listed again, the
      /// block-Jacobi inverse and the auxiliary matrix rebuilt by the next
      /// solve.
      void
      decoupled_changed();
      /// The field @p x (ghosted) as the model reads it.
      PDModels::NodalField<dim>
      nodal_field(const dealii::TrilinosWrappers::MPI::Vector &x) const
      {
        return {x.trilinos_vector()[0], relevant_lid.data()};
      }
      /// The state the tangent is taken at, as the model reads it: the last
      /// internal force's for a linear model (any state), u_tangent (the
      /// last residual's) for a nonlinear one.
      PDModels::NodalField<dim>
      tangent_field() const
      {
        return nodal_field(model->linear() ? u_ghosted : u_tangent);
      }
      /// Tractions and body force at load factor @p t, into f_ext.
      void
      assemble_external(double t);
      /// traction_layers (after the model's initialisation).
      void
      make_traction_layers();
      /// The traction layers' body forces at @p t, added to f_ext.
      void
      add_traction_layers(double t);
      /// f_int(u) = K_FE u + PD(u), into f_int (owned).
      void
      compute_internal_force(const dealii::TrilinosWrappers::MPI::Vector &u);
      /// y = K x with prescribed and decoupled DoFs eliminated, without a
      /// global matrix (gmres with "amg fe").
      void
      vmult(dealii::TrilinosWrappers::MPI::Vector       &y,
            const dealii::TrilinosWrappers::MPI::Vector &x) const;
      /// Inverse node blocks (dim x dim) of the tangent's diagonal, for the
      /// block-Jacobi correction of the "amg fe" preconditioner.
      void
      make_block_jacobi();
      /// z = P r with the PD model's own preconditioner on its owners' rows
      /// (PDModels::Interface::precondition()) and r / (held diagonal) on
      /// the held DoFs ('pd model').
      void
      apply_model_preconditioner(
        dealii::TrilinosWrappers::MPI::Vector       &z,
        const dealii::TrilinosWrappers::MPI::Vector &r) const;
      /// w = D^-1 t with the node blocks of make_block_jacobi().
      void
      apply_block_jacobi(dealii::TrilinosWrappers::MPI::Vector       &w,
                         const dealii::TrilinosWrappers::MPI::Vector &t) const;
      /// The assembled tangent (direct solvers, "amg", "ilu").
      void
      assemble_tangent();
      /**
       * use(row) for every owned row of the FE matrix that is not
       * prescribed, with @p cols and @p values holding its nonzero entries
       * in columns that are not prescribed (read as Epetra views: deal.II's
       * Trilinos row iterator extracts the row again at every step, and
       * the tangent took 231 s instead of 2 s on the box).
       */
      template <typename Use>
      void
      for_each_free_fe_row(std::vector<global_dof_index> &cols,
                           std::vector<double>           &values,
                           const Use                     &use) const
      {
        const Epetra_CrsMatrix &A = fe_matrix.trilinos_matrix();
        for (int local_row = 0; local_row < A.NumMyRows(); ++local_row)
          {
            const global_dof_index row = A.GRID(local_row);
            if (dof_fixed[row])
              continue;
            int     n = 0;
            double *v = nullptr;
            int    *c = nullptr;
            A.ExtractMyRowView(local_row, n, v, c);
            cols.clear();
            values.clear();
            for (int e = 0; e < n; ++e)
              {
                const global_dof_index col = A.GCID(c[e]);
                if (!dof_fixed[col] && v[e] != 0.)
                  {
                    cols.push_back(col);
                    values.push_back(v[e]);
                  }
              }
            use(row);
          }
      }
      /// check_stability() on the matrix-free path: from the Ritz values
      /// of the last CG solve (LinearSolver::last_ritz_values()).
      Drivers::StabilityReport
      matrix_free_stability();
      /// stiffness_row_bounds() on the matrix-free path: from the FE
      /// matrix and the model's tangent rows at u_tangent.
      void
      matrix_free_row_bounds(
        dealii::TrilinosWrappers::MPI::Vector &bounds) const;
      /// use(o, blocks) with the model's tangent row of every owner o that
      /// is not decoupled, at @p field.
      template <typename Use>
      void
      for_each_tangent_row(const PDModels::NodalField<dim> &field,
                           const Use                       &use) const
      {
        std::vector<dealii::Tensor<2, dim>> blocks;
        for (std::size_t o = 0; o < families.owners.size(); ++o)
          if (!decoupled[o])
            {
              model->tangent_row(o, field, blocks);
              use(o, blocks);
            }
      }
      /// use(nodes, blocks) with family o's nodes (family_nodes()) and
      /// its tangent blocks (family_tangent(), or with @p diagonal only
      /// its diagonal blocks, family_diagonal_blocks()) for every owner o
      /// that is not decoupled, at @p field (family-element models).
      template <typename Use>
      void
      for_each_family_tangent(const PDModels::NodalField<dim> &field,
                              const Use                       &use,
                              const bool diagonal = false) const
      {
        std::vector<dealii::Tensor<2, dim>> blocks;
        for (std::size_t o = 0; o < families.owners.size(); ++o)
          if (!decoupled[o])
            {
              if (diagonal)
                model->family_diagonal_blocks(o, field, blocks);
              else
                model->family_tangent(o, field, blocks);
              const std::vector<unsigned int> nodes = family_nodes(o);
              AssertThrow(blocks.size() ==
                            nodes.size() * (diagonal ? 1 : nodes.size()),
                          dealii::ExcMessage(
                            "a family-element PD model's tangent must have "
                            "(1 + intact bonds)^2 blocks, and 1 + intact "
                            "bonds diagonal blocks"));
              use(nodes, blocks);
            }
      }
      /// @p out = K(@p u) @p w on every DoF, unconstrained (FE cells and
      /// the model's tangent rows); @p u and @p w ghosted.
      void
      tangent_product(const dealii::TrilinosWrappers::MPI::Vector &u,
                      const dealii::TrilinosWrappers::MPI::Vector &w,
                      dealii::TrilinosWrappers::MPI::Vector       &out) const;
      /// Add a local block (rows x cols) to @p target; with @p eliminate,
      /// rows and columns of prescribed DoFs are dropped.
      void
      add_to_matrix(dealii::TrilinosWrappers::SparseMatrix &target,
                    const std::vector<global_dof_index>    &rows,
                    const std::vector<global_dof_index>    &cols,
                    const std::vector<double>              &values,
                    bool eliminate = true) const;
      /// Diagonal entries of prescribed and decoupled DoFs in @p target,
      /// except those @p already_added marks (by owned-local index).
      /// Returns the number added.
      unsigned int
      add_held_diagonal(dealii::TrilinosWrappers::SparseMatrix &target,
                        const std::vector<bool> *already_added = nullptr) const;
      /// List the held DoFs (prescribed, or of decoupled nodes): their local
      /// index and diagonal entry. Call after the bond states change.
      void
      update_held();
      /// The size of a held DoF's diagonal entry: E Delta^(dim-2).
      double
      held_diagonal(global_dof_index i) const;

      /// Add the crack faces' share to boundary_area (free_crack_faces, 2D).
      void
      add_crack_face_area(const std::vector<Mesh::Crack<dim>> &cracks);

      /// Per node the smallest node index of its piece (nodes joined by FE
      /// cells or intact bonds); the same on every rank. Collective.
      std::vector<unsigned int>
      piece_labels() const;

      /// Owners without any intact bond and without FE cells: nothing ties
      /// them to the body any more, so they are held where they are.
      void
      update_decoupled();

      /**
       * The FE part of nodal_results(): per locally owned FE cell, the
       * weights W[v][a][d] = sum_q X(v, q) d_d phi_a(x_q) that give the
       * displacement gradient at vertex v, grad u[c][d] = sum_a u_a^c
       * W[v][a][d], as the Q1/P1 interpolant X of the Gauss-point gradients.
       * The cells and the mapping never change, so this is built once, on
       * first use (make_vertex_gradients()); nodal_results() then needs no
       * FEValues. Q1 and P1 have one scalar shape function per vertex.
       */
      struct VertexGradients
      {
        bool built = false;
        /// Per cell, its vertex count n; nodes[start[j] .. + 2 n) holds the
        /// node of each scalar shape function a, then the node of each
        /// vertex v; weights[weight_start[j] ..) holds W[v][a][d].
        std::vector<unsigned int> n, nodes;
        std::vector<std::size_t>  start, weight_start;
        std::vector<double>       weights;
      };
      VertexGradients vertex_gradients;
      void
      make_vertex_gradients();

      MPI_Comm                                                 comm;
      const dealii::parallel::shared::Triangulation<dim, dim> &tria;
      std::vector<bool>                                        cell_pd;
      /// Any PD cell (the shared triangulation: the same on every rank).
      bool
      has_pd_cells() const
      {
        return std::find(cell_pd.begin(), cell_pd.end(), true) != cell_pd.end();
      }
      Settings<dim> settings;
      /// The PD term (settings.pd_model, or pdlsm) and what it reads.
      std::shared_ptr<PDModels::Interface<dim>> model;
      PDModels::Layout                          layout; // model->layout()
      PDModels::Region<dim>                     region;

      dealii::hp::FECollection<dim>      fe;        // FE_Q(1)^dim, P1^dim
      dealii::hp::FECollection<dim>      fe_scalar; // FE_Q(1), P1
      dealii::hp::MappingCollection<dim> mapping;
      dealii::hp::QCollection<dim>       quadrature;
      dealii::hp::QCollection<dim - 1>   face_quadrature;
      dealii::DoFHandler<dim>            dofs;
      dealii::DoFHandler<dim>            node_dofs_handler;

      // ----- nodes (replicated: every rank knows every node)
      unsigned int                    n_nodes = 0;
      std::vector<unsigned int>       vertex_to_node;
      std::vector<dealii::Point<dim>> x;
      std::vector<double>             volume;    // all cells
      std::vector<double>             pd_volume; // PD cells
      std::vector<double>             horizon;
      double spacing = 0.; // the largest PD cell's size V^(1/dim)
      std::vector<std::uint8_t>                      is_pd, is_fe;
      std::vector<std::uint8_t>                      no_fail; // bonds kept
      std::vector<unsigned int>                      n_fe_cells;
      std::vector<std::array<global_dof_index, dim>> node_dof;
      std::vector<unsigned int>                      node_of_scalar;
      std::vector<unsigned int>                      dof_to_node;
      std::vector<dealii::Tensor<1, dim>>            boundary_area; // s_k
      unsigned long                                  n_pd_boundary_faces = 0;

      // ----- ownership and PD families
      dealii::IndexSet          owned, relevant;
      std::vector<unsigned int> owned_nodes;
      /// Owners: the owned PD nodes, then (pairwise models with FE nodes
      /// in the families) the owned FE nodes bonded to a PD node.
      PD::Families families;
      /// Per node: its index in families.owners, or families.owners.size()
      /// if it owns no family here.
      std::vector<std::size_t>  family_of;
      std::vector<std::uint8_t> decoupled; // per family owner (see above)
      /// The families and the bonds the pre-existing cracks cut
      /// (make_families(), for initialize_model()).
      std::vector<std::size_t> families_cut_at_start, bonds_cut_at_start;
      /// The wall seconds of the constructor's phases (setup_phases()).
      std::vector<std::pair<std::string, double>> setup_phases;
      /// Per family owner: held as part of a fragment (hold_fragments()).
      std::vector<std::uint8_t> fragment;
      /// What broke bonds or held nodes since construction, in order:
      /// replayed by restore_fracture_state(), so that a restarted run has
      /// the same bonds, and the same condensed stiffness to the bit.
      struct FractureEvent
      {
        enum Kind : std::uint8_t
        {
          cut,       ///< break_bonds(cracks)
          predicate, ///< break_bonds_if(): the (owner, member) pairs broken
          fragments  ///< hold_fragments(min_nodes)
        };
        Kind                                     kind = cut;
        std::vector<Mesh::Crack<dim>>            cracks;
        std::vector<std::array<unsigned int, 2>> bonds;
        unsigned int                             min_nodes = 0;
      };
      std::vector<FractureEvent> events;
      /// Local index of each DoF of a node in the ghosted (relevant) vectors
      /// and, for owned nodes, in the owned vectors.
      std::vector<std::array<unsigned int, dim>> relevant_lid, owned_lid;

      // ----- boundary conditions
      std::vector<std::uint8_t> dof_fixed;     // all DoFs (replicated)
      std::vector<int>          dof_dirichlet; // condition index or -1
      std::vector<std::unique_ptr<dealii::FunctionParser<3>>> dirichlet_fn;
      std::vector<std::string>                                set_names;
      std::vector<std::vector<unsigned int>>                  set_nodes;
      std::vector<std::unique_ptr<dealii::FunctionParser<3>>> traction_fn;
      std::unique_ptr<dealii::FunctionParser<3>>              body_fn;
      /// Per traction condition with PDModels::Layout::traction_layer: its
      /// owned layer nodes, the outward normal of each (its nearest
      /// boundary node's) and the layer's thickness V / A
      /// (coupled_system_traction_layer.cc).
      struct TractionLayer
      {
        bool                                active = false;
        std::vector<unsigned int>           nodes;
        std::vector<dealii::Tensor<1, dim>> normal;
        double                              thickness = 0.;
      };
      std::vector<TractionLayer> traction_layers;

      // ----- linear algebra
      std::vector<dealii::Tensor<2, dim>> block_inverse; // per owned node
      std::vector<unsigned int>           held_lid;      // owned-local index
      std::vector<double>                 held_value;    // its diagonal entry
      /// gmres with "amg fe": no assembled tangent, products on the fly.
      bool                                   matrix_free = false;
      dealii::TrilinosWrappers::SparseMatrix fe_matrix; // FE cells, full
      dealii::TrilinosWrappers::SparseMatrix matrix;    // assembled tangent
      dealii::TrilinosWrappers::SparseMatrix auxiliary; // "amg fe" only
      /// Bonds broke since the auxiliary matrix was assembled.
      bool auxiliary_stale = false;
      /// The cut cells and the held DoFs (by owned-local index) the
      /// auxiliary matrix was assembled with (empty: not assembled yet).
      std::vector<bool> auxiliary_cut;
      std::vector<bool> auxiliary_held;
      /// The factor of a cut cell's stiffness in the auxiliary matrix.
      double                                        cut_cell_stiffness = 1e-3;
      mutable dealii::TrilinosWrappers::MPI::Vector x_ghosted, x_masked;
      /// Family-element models: contributions in the ghosted layout, and
      /// their sums at the owners (scatter_add()).
      mutable dealii::TrilinosWrappers::MPI::Vector scatter_ghosted,
        scatter_owned;
      /// Owner ranges [pd_chunks[i], pd_chunks[i + 1]) with about equal
      /// numbers of bonds, for the threads of compute_pd_forces().
      std::vector<std::size_t> pd_chunks;
      /// PD forces per owner (dim entries each), see compute_pd_forces();
      /// family-element models: per owner and per bond.
      mutable std::vector<double> pd_force;
      /// Owned -> ghosted imports by the identity of their maps' data
      /// (import_ghosts()): the maps of a vector stay while it lives.
      struct GhostImport
      {
        const Epetra_BlockMapData     *source, *target;
        std::shared_ptr<Epetra_Import> import;
      };
      mutable std::vector<GhostImport>      ghost_imports;
      dealii::TrilinosWrappers::MPI::Vector f_int, f_ext, u_ghosted;
      /// The displacement the tangent is assembled at (nonlinear models).
      dealii::TrilinosWrappers::MPI::Vector u_tangent;
      Solvers::LinearSolver                 solver;
      /// Linear solver Type = auto: the measured choice of path.
      std::unique_ptr<Solvers::SolverChoice> choice;
      double                                 force_scale = 0.;
      bool tangent_stale = false; // residual() asked, solve_linear builds
      /// A matrix-free CG solve ran since the last stability check (its
      /// Ritz values are of this step's tangent).
      bool cg_solved_since_check = false;
      /// A linear model's tangent changes only with the bonds, the held
      /// DoFs and the pattern: the assembled one is kept (and its direct
      /// factorisation) until one of them changes. plate_with_hole with 10
      /// load steps: 1 factorisation instead of 10.
      bool                                tangent_outdated = true;
      std::vector<dealii::Tensor<1, dim>> last_reactions;
      std::size_t                         n_matrix_entries = 0;
      /// Mass, effective-matrix factorisation (shared_ptr: the type is
      /// complete only in coupled_system_dynamics.cc).
      std::shared_ptr<DynamicData> dynamics;
    };
  } // namespace Coupling
} // namespace pdfem

#endif
