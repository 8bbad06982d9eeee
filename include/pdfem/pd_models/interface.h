// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_INTERFACE_H
#define PDFEM_PD_MODELS_INTERFACE_H

#include <pdfem/base/config.h>
#include <pdfem/base/plugins.h>
#include <pdfem/pd_models/degradation_state.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  class StateArchive;

  namespace PD
  {
    struct Families;
  }

  namespace PDModels
  {
    /**
     * What a PD model works on: the nodes of the coupled system (replicated
     * on every rank, index = node number) and the families of the PD nodes
     * this rank owns, with their bond states. Filled by the coupled system,
     * read-only for the model (bonds break only through the system); the
     * pointers stay valid while the system lives.
     */
    template <int dim>
    struct Region
    {
      MPI_Comm                               comm     = MPI_COMM_SELF;
      const std::vector<dealii::Point<dim>> *position = nullptr;
      /// A node's share of the volume of all its cells, and of its PD
      /// cells only (V_k^pd; 0 for FE nodes).
      const std::vector<double> *volume    = nullptr;
      const std::vector<double> *pd_volume = nullptr;
      /// The horizon delta_k of every node: m V_k^(1/dim), or one m h for
      /// all (Layout::uniform_horizon).
      const std::vector<double> *horizon = nullptr;
      /// The spacing h of the PD region: the largest PD cell's size
      /// V_cell^(1/dim).
      double spacing = 0.;
      /// Peridynamics/Family members = all nodes: FE nodes within a horizon
      /// are family members (and, for pairwise models, owners).
      bool fe_nodes_in_families = false;
      /// 1 if the node belongs to an FE cell.
      const std::vector<std::uint8_t> *has_fe_cells = nullptr;
      /// s_k = int_{S_pd} N_k n dS: a node's share of the PD region's
      /// boundary (outer boundary, PD/FE interface, free crack faces).
      const std::vector<dealii::Tensor<1, dim>> *boundary_area = nullptr;
      const PD::Families                        *families      = nullptr;
      /// The elastic constants in use (plane stress: lambda*), E and nu,
      /// and whether a 2D body is in plane strain.
      double lambda = 0., mu = 0., youngs_modulus = 0., poissons_ratio = 0.;
      bool   plane_strain = false;
      /// The input file, named in error messages.
      std::string source_file;
    };

    /**
     * What a model asks of the coupled system's discretisation; the
     * defaults are those of the collocated PDLSM (pdlsm).
     */
    struct Layout
    {
      /// One horizon for the whole region, delta = m h with h the largest
      /// PD cell size (Region::spacing), instead of each node's own
      /// delta_k = m V_k^(1/dim): bond models whose micromodulus assumes
      /// one horizon (specs/000 eq. (11)).
      bool uniform_horizon = false;
      /// Pairwise bonds that act on both their nodes: with FE nodes in the
      /// families, the FE nodes within a horizon of PD nodes own families
      /// too (of those PD nodes only), so that every bond's force reaches
      /// both ends.
      bool pairwise = false;
      /// Prescribed displacements act on every PD node within this many
      /// horizons of a Dirichlet boundary or point (the nonlocal boundary
      /// layer, specs/000 §4.2); 0: the boundary's own nodes.
      double dirichlet_layer = 0.;
      /// The body force on PD nodes as b(x_k) V_k with the model's nodal
      /// volumes (a particle discretisation) instead of integrated over the
      /// PD cells with the FE shape functions.
      bool nodal_body_force = false;
      /// The model is a sum over families of energies E_k(u_k, u_m : m in
      /// the intact bonds of k) (an energy form, specs/004 §4 issue 16):
      /// family k's force acts on its owner and on every member, so that
      /// row j gathers the families of every node within a horizon of j
      /// (two horizons of columns). The system then calls family_forces()
      /// and family_tangent() instead of forces() and tangent_row(), and
      /// scatters their blocks like FE cell contributions.
      bool family_elements = false;
      /// The model reads `Peridynamics/Crack faces = free surface` (the
      /// free_surfaces argument of bonds_changed()): PDLSM's refit with the
      /// crack faces' boundary term. A model that treats crack faces its
      /// own way says false, and the option is refused with it.
      bool free_crack_faces = true;
      /// The model keeps a history of the accepted states (commit_state(),
      /// bond_failed()); without one the system neither passes the states
      /// on nor looks for failed bonds.
      bool history = false;
      /// The model degrades its bonds smoothly past an onset stretch
      /// (degradation_state() says how far), so that a driver may switch
      /// methods on it.
      bool smooth_degradation = false;
      /// The model gives a tangent (tangent_row() or family_tangent()). A
      /// model of forces only says false, and make_plugins() refuses it a
      /// driver that needs one (Drivers::Interface::needs_tangent()).
      bool tangent = true;
      /// A nonlinear row model gives products with its tangent without
      /// assembling it (tangent_products()), so that the matrix-free
      /// Krylov paths ('amg fe', Linear solver) can solve its Newton
      /// systems. A linear model needs none: its products are forces().
      bool tangent_products = false;
      /// Single bonds of the model can be cut and broken (bonds_changed()).
      /// A model that cannot (node masks only) says false, and
      /// make_plugins() refuses it pre-existing cracks and crack criteria.
      bool breakable_bonds = true;
      /// The model offers precondition() (Linear solver/Preconditioner =
      /// pd model).
      bool preconditioner = false;
      /// A displacement component in which the model gives its PD nodes no
      /// stiffness at all (the transverse one of a uniaxial bar), or -1:
      /// none. A static run then needs it prescribed at every PD node that
      /// no FE cell holds (CoupledSystem::unheld_component()).
      int stiffless_component = -1;
      /// The model reads the bonds of the families (Region::families lists
      /// every node within a horizon of each owner). A model that finds its
      /// neighbours on a grid of its own (lps fft) says false: each family
      /// then lists its owner only, without members, so that the set-up
      /// neither searches for neighbours nor stores bonds, and the memory
      /// does not grow with the horizon. Such a model gathers the
      /// displacements it needs itself (prepare_forces(),
      /// prepare_results()) and cannot break single bonds.
      bool bonds = true;
      /// Tractions on the boundary faces of PD cells act as a body force
      /// t / l on the PD nodes within this many horizons of the boundary
      /// (the embedded constraints of specs/002 §2.5; l the layer's volume
      /// over the boundary's area, so that the resultant is t A); 0: on the
      /// boundary faces (the nodes' shares of the face integral).
      double traction_layer = 0.;

      /// The model gives its tangent row by row (tangent_row()): it has a
      /// tangent, and not as family elements.
      bool
      tangent_rows() const
      {
        return tangent && !family_elements;
      }
    };

    /**
     * The displacement (or any nodal vector field) at the nodes a rank's
     * families reach, read from the raw array of a ghosted vector:
     * u(k, c) = values[local_index[k][c]].
     */
    template <int dim>
    struct NodalField
    {
      const double                        *values      = nullptr;
      const std::array<unsigned int, dim> *local_index = nullptr;

      double
      operator()(const unsigned int node, const unsigned int c) const
      {
        return values[local_index[node][c]];
      }

      dealii::Tensor<1, dim>
      operator[](const unsigned int node) const
      {
        dealii::Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = values[local_index[node][c]];
        return v;
      }
    };

    /**
     * A PD model plugin: the PD term of the coupled system (Liu & Xin, EFM
     * 2021, eq. 26; specs/004 §1.3). Its internal force is a sum over the
     * rows of the family owners k,
     *
     *   f_int,k = F_k(u_k, u_m : m in the intact bonds of k),
     *
     * and its tangent row the blocks dF_k / du_k and dF_k / du_m. The
     * coupled system adds the FE cell term, eliminates prescribed DoFs,
     * holds nodes that lost every bond, and assembles, solves and outputs;
     * the model owns its per-bond data (weights, constants) and computes
     * rows. Register one with PDFEM_REGISTER_PD_MODEL at the end of its
     * `.cc` file; it is then a choice of `Peridynamics/Model`.
     *
     * Threads: forces(), tangent_row() and displacement_gradient() are
     * called concurrently for disjoint owners (they must be const and
     * write only their arguments); prepare_forces() and prepare_results()
     * run before them, alone.
     */
    template <int dim>
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /**
       * Read the model's parameters (those its declare function declared)
       * from @p prm, which is inside `subsection Peridynamics`; InputError
       * naming @p file for bad values. By default: none.
       */
      virtual void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &file);

      /// What the model needs of the discretisation (known after
      /// parse_parameters(), before initialize()). By default: PDLSM's.
      virtual Layout
      layout() const;

      /**
       * Bind to @p region and compute the per-bond data of every family
       * over its initial (uncut) members. Collective over region.comm;
       * throws InputError (naming region.source_file and the parameter to
       * change) if a family cannot carry the model.
       */
      virtual void
      initialize(const Region<dim> &region) = 0;

      /**
       * Bonds of the families @p changed (indices into families.owners)
       * were cut or broken. With @p free_surfaces the crack faces are free
       * surfaces (Peridynamics/Crack faces): a model may refit those
       * families over their intact bonds. Called before the rows are asked
       * for again.
       */
      virtual void
      bonds_changed(const std::vector<std::size_t> &changed,
                    bool                            free_surfaces) = 0;

      /**
       * As bonds_changed(), for the bonds a pre-existing crack cuts at
       * set-up: the cracked body is the reference configuration, not a
       * state that lost bonds. The default calls bonds_changed(); "pdlsm
       * energy" refits these families (with Broken bonds = condense, bonds
       * broken during a run are condensed instead).
       */
      virtual void
      reference_bonds_cut(const std::vector<std::size_t> &changed,
                          bool                            free_surfaces)
      {
        bonds_changed(changed, free_surfaces);
      }

      /// Is F linear in u (a constant tangent, so that F(x) = K x)?
      virtual bool
      linear() const = 0;

      /// Is the tangent symmetric (the gradient of an energy)?
      virtual bool
      symmetric() const = 0;

      /**
       * Called once per force evaluation, serially and on every rank
       * (collective over region.comm), before forces() or family_forces()
       * are asked for the owner chunks at the same @p u: a model that
       * evaluates all owners at once (e.g. by FFT on a grid, "lps fft")
       * does it here, and forces() hands out its rows. By default nothing.
       */
      virtual void
      prepare_forces(const NodalField<dim> &u)
      {
        (void)u;
      }

      /**
       * Called once, serially and on every rank (collective over
       * region.comm), before displacement_gradient() is asked for the
       * owners at the same @p u (the nodal results): a model
       * without bonds (Layout::bonds false) gathers there the neighbours'
       * displacements its gradient needs. By default nothing.
       */
      virtual void
      prepare_results(const NodalField<dim> &u)
      {
        (void)u;
      }

      /**
       * z = P r with P an approximate inverse of the stiffness of this
       * model's region, symmetric positive definite, for the Krylov solves
       * of a region that is all PD: @p r and @p z hold dim rows per owner
       * (owner o, component c at dim o + c), as forces(). The rows of held
       * DoFs are set by the caller. For models whose Layout::preconditioner
       * is true (Linear solver/Preconditioner = pd model); the default
       * throws std::logic_error. Collective with several ranks.
       */
      virtual void
      precondition(const std::vector<double> &r, std::vector<double> &z)
      {
        (void)r;
        (void)z;
        throw std::logic_error("this PD model has no preconditioner");
      }

      /**
       * Row models (the default layout) override forces() and
       * tangent_row(); family-element models family_forces() and
       * family_tangent(). The defaults throw std::logic_error.
       *
       * F_k for the owners [@p begin, @p end) at @p u, into
       * f[dim o + c] (force units; overwritten). The system discards the
       * rows of decoupled owners (no intact bond, no FE cell: held).
       */
      virtual void
      forces(std::size_t            begin,
             std::size_t            end,
             const NodalField<dim> &u,
             double                *f) const;

      /**
       * The tangent row of owner @p o at @p u: blocks[0] = dF_k / du_k,
       * blocks[1 + i] = dF_k / du_m for the i-th intact bond of the family
       * in family order (resized here).
       */
      virtual void
      tangent_row(std::size_t                          o,
                  const NodalField<dim>               &u,
                  std::vector<dealii::Tensor<2, dim>> &blocks) const;

      /**
       * With Layout::tangent_products: f = K(@p u) @p v on the owners
       * [@p begin, @p end), into f[dim o + c] (overwritten), with K(u) the
       * tangent whose rows tangent_row() gives, sum over the row's blocks
       * of block times v at its column; without assembling it. The
       * default throws std::logic_error.
       */
      virtual void
      tangent_products(std::size_t            begin,
                       std::size_t            end,
                       const NodalField<dim> &u,
                       const NodalField<dim> &v,
                       double                *f) const;

      /**
       * With Layout::family_elements: the force of family @p o at @p u on
       * its owner (f[0]) and on its i-th intact member (f[1 + i]), in
       * family order (resized here): dE_o / du.
       */
      virtual void
      family_forces(std::size_t                          o,
                    const NodalField<dim>               &u,
                    std::vector<dealii::Tensor<1, dim>> &f) const;

      /**
       * With Layout::family_elements: the tangent of family_forces(),
       * blocks[a (n + 1) + b] = d f_a / d u_b for the n + 1 nodes of the
       * family (owner first, then the intact members; resized here).
       */
      virtual void
      family_tangent(std::size_t                          o,
                     const NodalField<dim>               &u,
                     std::vector<dealii::Tensor<2, dim>> &blocks) const;

      /**
       * With Layout::family_elements: the diagonal blocks of
       * family_tangent(), blocks[a] = d f_a / d u_a (resized here), for a
       * block-Jacobi preconditioner. The default extracts them from
       * family_tangent(); a model overrides it where they cost less alone.
       */
      virtual void
      family_diagonal_blocks(std::size_t                          o,
                             const NodalField<dim>               &u,
                             std::vector<dealii::Tensor<2, dim>> &blocks) const;

      /// The nonlocal displacement gradient grad u (component i, direction
      /// j) at owner @p o, for the nodal stress C : sym(grad u).
      virtual dealii::Tensor<2, dim>
      displacement_gradient(std::size_t o, const NodalField<dim> &u) const = 0;

      /**
       * The damage of owner @p o in the nodal results (output, history):
       * by default the fraction of its bonds that are broken.
       */
      virtual double
      damage(std::size_t o, const NodalField<dim> &u) const;

      /**
       * The PD material volume of node @p k (after initialize()): its mass
       * and, with Layout::nodal_body_force, its body force b(x_k) V_k. By
       * default its share of the PD cells, V_k^pd.
       */
      virtual double
      nodal_volume(unsigned int k) const;

      /// Named constants of the model for summary.json's "pd_model"
      /// section and the run's header (after initialize()). By default
      /// none.
      virtual std::vector<std::pair<std::string, double>>
      constants() const;

      /**
       * @name Models with a history (a bond's largest stretch so far)
       *
       * The forces of such a model depend on u and on the states accepted
       * before it; its Layout says `history`. The system calls
       * commit_state() with every accepted
       * state (an equilibrium of a static driver, a step of a time
       * integrator), serially on each rank, and then breaks the bonds for
       * which bond_failed() is true (they carry no force at any later
       * state: the broken-bond count, the pieces and the held fragments
       * follow them). save_state() and restore_state() put the history
       * into a checkpoint (this rank's families). The defaults: no
       * history.
       */
      /// @{
      virtual void
      commit_state(const NodalField<dim> &u)
      {
        (void)u;
      }

      /**
       * The strain energy that the last commit_state() released at the
       * state it was given, without breaking bonds (its forces changed at
       * fixed u: lps fft's failed nodes), summed over the ranks: E(u)
       * before minus E(u) after, E = 1/2 u . f_int per unit thickness in 2D.
       * A time integrator books it as dissipated. By default 0.
       */
      virtual double
      released_energy() const
      {
        return 0.;
      }

      /// Does bond @p j (an index into families.members) carry no force
      /// for good, after the last commit_state()?
      virtual bool
      bond_failed(std::size_t j) const
      {
        (void)j;
        return false;
      }

      virtual void
      save_state(StateArchive &state) const
      {
        (void)state;
      }

      virtual void
      restore_state(const StateArchive &state)
      {
        (void)state;
      }

      /**
       * This rank's share of how far the smooth degradation has gone at
       * @p u (DegradationState; the switch threshold is
       * @p onset_fraction times the onset stretch). By default all 0 (the
       * model does not degrade smoothly: Layout::smooth_degradation).
       */
      virtual DegradationState
      degradation_state(const NodalField<dim> &u, double onset_fraction) const
      {
        (void)u;
        (void)onset_fraction;
        return {};
      }
      /// @}

    protected:
      /// The region of initialize().
      Region<dim> region;
    };

    /// The registry of PD models for dimension @p dim.
    template <int dim>
    Plugins::Registry<Interface<dim>> &
    registry();

    /// Register @p Class<2> and @p Class<3> (a template on dim).
    template <template <int> class Class>
    bool
    register_pd_model(
      const std::string                                     &name,
      const std::string                                     &description,
      const std::function<void(dealii::ParameterHandler &)> &declare)
    {
      registry<2>().add(name, description, declare, []() {
        return std::unique_ptr<Interface<2>>(new Class<2>());
      });
#if PDFEM_WITH_3D
      registry<3>().add(name, description, declare, []() {
        return std::unique_ptr<Interface<3>>(new Class<3>());
      });
#endif
      return true;
    }

    /// The model @p name, its parameters not read yet (InputError naming
    /// `Peridynamics/Model` if unknown).
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const std::string &name, const std::string &file);

    /// The collocated PDLSM model (pdlsm) with the weight factor
    /// @p weight_factor: what a coupled system uses when it is given none.
    template <int dim>
    std::unique_ptr<Interface<dim>>
    make_pdlsm(double weight_factor);
  } // namespace PDModels
} // namespace pdfem

/**
 * Register the PD model class template @p classname (on dim) under @p name
 * (a `Peridynamics/Model` value) with a one-line @p description; @p declare
 * (a function of ParameterHandler &, or {}) declares its parameters inside
 * `subsection Peridynamics`. At namespace scope in the model's `.cc`.
 */
#define PDFEM_REGISTER_PD_MODEL(classname, name, description, declare)     \
  namespace                                                                \
  {                                                                        \
    const bool PDFEM_PLUGIN_CONCAT(pdfem_pd_model_registered_, __LINE__) = \
      ::pdfem::PDModels::register_pd_model<classname>(name,                \
                                                      description,         \
                                                      declare);            \
  }

#endif
