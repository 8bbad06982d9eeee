// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: what the time integrators need (Drivers::
// DynamicSystemInterface): lumped and consistent mass (specs/004 §1.3),
// matrix-free internal force, external force at time t, and the effective
// matrix K_N = c_m M + c_k K factorised once and reused (specs/004 §2.4).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>

#include <deal.II/base/mpi.h>

#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <regex>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    struct DynamicData
    {
      bool                          have_lumped = false;
      TrilinosWrappers::MPI::Vector lumped; // owned
      /// f_ext does not depend on t: assembled once.
      bool                          f_ext_constant = false;
      bool                          f_ext_ready    = false;
      TrilinosWrappers::MPI::Vector f_ext;
      /// The consistent mass with held rows/columns eliminated (lumped
      /// value on their diagonal), once a consistent K_N was asked for.
      bool                           consistent = false;
      TrilinosWrappers::SparseMatrix mass;
      SolverControl                  direct_control{1, 0};
      /// K_N; declared before the solvers that point to it, so that it is
      /// destroyed after them (Amesos_Mumps::Destroy reads the matrix).
      std::unique_ptr<TrilinosWrappers::SparseMatrix>     effective;
      std::unique_ptr<TrilinosWrappers::SolverDirect>     direct;
      std::unique_ptr<TrilinosWrappers::PreconditionBase> precondition;
      unsigned int                                        n_factorizations = 0;
    };

    namespace
    {
      /// Whether a muparser expression mentions the variable t.
      bool
      depends_on_time(const std::string &expression)
      {
        static const std::regex t(R"((^|[^A-Za-z0-9_])t([^A-Za-z0-9_]|$))");
        return std::regex_search(expression, t);
      }

      DynamicData &
      data(std::shared_ptr<DynamicData> &d)
      {
        if (!d)
          d = std::make_shared<DynamicData>();
        return *d;
      }

      /**
       * Consistent mass of one FE cell, M_ij = rho int N_i N_j dV (i, j of
       * the same component), row-major.
       */
      template <int dim>
      void
      cell_mass(const FEValues<dim> &fv,
                const double         rho,
                std::vector<double> &M)
      {
        const auto        &fe = fv.get_fe();
        const unsigned int n  = fv.dofs_per_cell;
        M.assign(n * n, 0.);
        for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              if (fe.system_to_component_index(i).first ==
                  fe.system_to_component_index(j).first)
                M[i * n + j] +=
                  rho * fv.shape_value(i, q) * fv.shape_value(j, q) * fv.JxW(q);
      }
    } // namespace

    template <int dim>
    const typename CoupledSystem<dim>::Vector &
    CoupledSystem<dim>::lumped_mass()
    {
      Impl        &s = *impl;
      DynamicData &d = data(s.dynamics);
      if (d.have_lumped)
        return d.lumped;
      // FE cells: row sums of the consistent mass (Q1: rho V/4 on a
      // parallelogram, P1: rho V/3). PD cells: rho V_k^pd per node
      // (specs/004 §1.3). An interface node gets both shares.
      const double rho = s.settings.material.density;
      d.lumped.reinit(s.owned, s.comm);
      hp::FEValues<dim>             fe_values(s.mapping,
                                  s.fe,
                                  s.quadrature,
                                  update_values | update_JxW_values);
      std::vector<global_dof_index> local_dofs;
      std::vector<double>           M, row;
      for (const auto &cell : s.dofs.active_cell_iterators())
        {
          if (!cell->is_locally_owned() || s.cell_pd[cell->active_cell_index()])
            continue;
          fe_values.reinit(cell);
          const FEValues<dim> &fv = fe_values.get_present_fe_values();
          cell_mass(fv, rho, M);
          const unsigned int n = fv.dofs_per_cell;
          row.assign(n, 0.);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              row[i] += M[i * n + j];
          local_dofs.resize(n);
          cell->get_dof_indices(local_dofs);
          d.lumped.add(local_dofs, row);
        }
      d.lumped.compress(VectorOperation::add);
      // PD nodes: rho times the model's nodal volume (V_k^pd for pdlsm).
      for (const unsigned int k : s.owned_nodes)
        if (s.is_pd[k])
          for (unsigned int c = 0; c < dim; ++c)
            d.lumped[s.node_dof[k][c]] += rho * s.model->nodal_volume(k);
      d.lumped.compress(VectorOperation::add);
      d.have_lumped = true;
      return d.lumped;
    }

    template <int dim>
    void
    CoupledSystem<dim>::internal_force(const Vector &u, Vector &f)
    {
      Impl &s = *impl;
      s.compute_internal_force(u);
      if (f.size() != s.f_int.size() || f.locally_owned_elements() != s.owned ||
          f.has_ghost_elements())
        f.reinit(s.owned, s.comm);
      f = s.f_int;
    }

    template <int dim>
    void
    CoupledSystem<dim>::external_force(const double t, Vector &f)
    {
      Impl        &s = *impl;
      DynamicData &d = data(s.dynamics);
      if (!d.f_ext_ready)
        {
          // Constant loads are assembled once: the boundary-face loop and
          // its muparser calls would otherwise be a large part of an
          // explicit step.
          d.f_ext_constant = true;
          for (const auto &bc : s.settings.traction)
            d.f_ext_constant &= !depends_on_time(bc.expression);
          for (const auto &e : s.settings.body_force)
            d.f_ext_constant &= !depends_on_time(e);
          d.f_ext_ready = true;
          s.assemble_external(t);
          d.f_ext.reinit(s.owned, s.comm);
          d.f_ext = s.f_ext;
        }
      else if (!d.f_ext_constant)
        {
          s.assemble_external(t);
          d.f_ext = s.f_ext;
        }
      if (f.size() != d.f_ext.size() || f.locally_owned_elements() != s.owned ||
          f.has_ghost_elements())
        f.reinit(s.owned, s.comm);
      f = d.f_ext;
    }

    template <int dim>
    const std::vector<unsigned int> &
    CoupledSystem<dim>::held_dofs() const
    {
      return impl->held_lid;
    }

    template <int dim>
    void
    CoupledSystem<dim>::factorize_effective(const double mass_factor,
                                            const double stiffness_factor,
                                            const bool   consistent_mass)
    {
      Impl        &s = *impl;
      DynamicData &d = data(s.dynamics);
      AssertThrow(!s.matrix_free,
                  ExcMessage("K_N needs the assembled matrix (not 'amg fe')"));
      const Vector &m = lumped_mass();

      // Consistent mass (once): FE cells with held DoFs eliminated, PD
      // nodes and held DoFs on the diagonal. The pattern of the FE-cell
      // matrix (every owned row has its diagonal), a subset of the tangent's.
      if (consistent_mass && !d.consistent)
        {
          d.mass.reinit(s.fe_matrix); // FE cells + diagonal: M's pattern
          d.mass                            = 0.;
          const double                  rho = s.settings.material.density;
          hp::FEValues<dim>             fe_values(s.mapping,
                                      s.fe,
                                      s.quadrature,
                                      update_values | update_JxW_values);
          std::vector<global_dof_index> local_dofs;
          std::vector<double>           M;
          for (const auto &cell : s.dofs.active_cell_iterators())
            {
              if (!cell->is_locally_owned() ||
                  s.cell_pd[cell->active_cell_index()])
                continue;
              fe_values.reinit(cell);
              cell_mass(fe_values.get_present_fe_values(), rho, M);
              local_dofs.resize(cell->get_fe().n_dofs_per_cell());
              cell->get_dof_indices(local_dofs);
              s.add_to_matrix(d.mass, local_dofs, local_dofs, M);
            }
          for (const unsigned int k : s.owned_nodes)
            for (unsigned int c = 0; c < dim; ++c)
              {
                const auto i = s.node_dof[k][c];
                if (s.dof_fixed[i])
                  d.mass.add(i, i, m[i]);
                else if (s.is_pd[k])
                  d.mass.add(i, i, rho * s.model->nodal_volume(k));
              }
          d.mass.compress(VectorOperation::add);
          d.consistent = true;
        }

      // K_N = c_k K + c_m M: the tangent (held rows and columns eliminated,
      // E h^(dim-2) on their diagonal), scaled, plus the mass.
      s.assemble_tangent();
      // The old factorisation refers to K_N: release it before K_N changes.
      d.direct.reset();
      d.precondition.reset();
      if (!d.effective)
        d.effective = std::make_unique<TrilinosWrappers::SparseMatrix>();
      TrilinosWrappers::SparseMatrix &A = *d.effective;
      if (A.m() != s.matrix.m())
        A.reinit(s.matrix);
      A.copy_from(s.matrix);
      A *= stiffness_factor;
      if (consistent_mass)
        A.add(mass_factor, d.mass);
      else
        {
          for (const auto i : s.owned)
            if (!s.dof_fixed[i])
              A.add(i, i, mass_factor * m[i]);
          A.compress(VectorOperation::add);
        }

      const auto &ls = s.settings.linear_solver;
      if (!ls.iterative())
        {
          d.direct = std::make_unique<TrilinosWrappers::SolverDirect>(
            d.direct_control,
            TrilinosWrappers::SolverDirect::AdditionalData(
              false,
              ls.direct_solver == "klu" ? "Amesos_Klu" : "Amesos_Mumps"));
          d.direct->initialize(A);
        }
      else if (ls.preconditioner == "ilu")
        {
          auto ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
          ilu->initialize(
            A, TrilinosWrappers::PreconditionILU::AdditionalData(1, 0., 1., 1));
          d.precondition = std::move(ilu);
        }
      else
        {
          // K_N is mass dominated: a symmetric-like, well-conditioned
          // operator; ML AMG with the translation modes, symmetric smoothed
          // aggregation for CG (K_N is then symmetric positive definite).
          auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
          TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
          amg_data.elliptic = ls.conjugate_gradients();
          amg->initialize(A, amg_data);
          d.precondition = std::move(amg);
        }
      ++d.n_factorizations;
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::solve_effective(Vector &x, const Vector &b)
    {
      Impl        &s = *impl;
      DynamicData &d = data(s.dynamics);
      x.reinit(s.owned, s.comm);
      if (d.direct)
        {
          d.direct->solve(x, b);
          if (!std::isfinite(x.l2_norm()))
            throw RunFailure("singular matrix",
                             "the solve with M + beta dt^2 K is not finite");
          return 1;
        }
      const auto   &ls = s.settings.linear_solver;
      SolverControl control(ls.max_iterations,
                            std::max(1e-300, ls.tolerance * b.l2_norm()));
      const char   *name = ls.conjugate_gradients() ? "CG" : "GMRES";
      try
        {
          if (ls.conjugate_gradients())
            {
              TrilinosWrappers::SolverCG cg(control);
              cg.solve(*d.effective, x, b, *d.precondition);
            }
          else
            {
              TrilinosWrappers::SolverGMRES gmres(
                control,
                TrilinosWrappers::SolverGMRES::AdditionalData(false,
                                                              ls.restart));
              gmres.solve(*d.effective, x, b, *d.precondition);
            }
        }
      catch (const std::exception &e)
        {
          throw RunFailure(
            "linear solver diverged",
            std::string(name) + " on M + beta dt^2 K: " +
              ParameterTools::clean_dealii_message(e.what()).substr(0, 200));
        }
      return control.last_step();
    }

    template <int dim>
    void
    CoupledSystem<dim>::mass_vmult(Vector &y, const Vector &x)
    {
      Impl         &s = *impl;
      DynamicData  &d = data(s.dynamics);
      const Vector &m = lumped_mass();
      y.reinit(s.owned, s.comm);
      if (d.consistent)
        {
          d.mass.vmult(y, x);
          return;
        }
      y = x;
      y.scale(m);
    }

    template <int dim>
    double
    CoupledSystem<dim>::thickness() const
    {
      return dim == 2 ? impl->settings.material.thickness : 1.;
    }

    template <int dim>
    void
    CoupledSystem<dim>::update_reactions()
    {
      // As residual(): f_int - f_ext summed over each set's owned nodes, for
      // the 2D thickness. f_int and f_ext hold the last evaluations.
      Impl                                &s = *impl;
      DynamicData                         &d = data(s.dynamics);
      const TrilinosWrappers::MPI::Vector &f_ext =
        d.f_ext_ready ? d.f_ext : s.f_ext;
      // Raw arrays at the owned-local indices: looking up every global
      // index took 0.15 ms of a 1.7 ms explicit step on plateCrack FC2 (a
      // history row per step).
      const double *fi = s.f_int.begin();
      const double *fe = f_ext.begin();
      for (std::size_t set = 0; set < s.set_names.size(); ++set)
        {
          Tensor<1, dim> R;
          for (const unsigned int k : s.set_nodes[set])
            if (const auto &lid = s.owned_lid[k];
                lid[0] != numbers::invalid_unsigned_int)
              for (unsigned int c = 0; c < dim; ++c)
                R[c] += fi[lid[c]] - fe[lid[c]];
          s.last_reactions[set] = thickness() * Utilities::MPI::sum(R, s.comm);
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::pseudo_random(Vector &v) const
    {
      // splitmix64 of the coordinates' bit patterns and the component.
      const Impl &s = *impl;
      v.reinit(s.owned, s.comm);
      for (const unsigned int k : s.owned_nodes)
        for (unsigned int c = 0; c < dim; ++c)
          {
            std::uint64_t h = 0x9E3779B97F4A7C15ull * (c + 1);
            for (unsigned int d = 0; d < dim; ++d)
              {
                std::uint64_t bits = 0;
                const double  xd   = s.x[k][d];
                std::memcpy(&bits, &xd, sizeof bits);
                h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
                h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
                h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
                h ^= h >> 31;
              }
            v[s.node_dof[k][c]] = double(h % 2000001) / 1e6 - 1.;
          }
      v.compress(VectorOperation::insert);
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::n_effective_factorizations() const
    {
      return impl->dynamics ? impl->dynamics->n_factorizations : 0;
    }

    template <int dim>
    void
    CoupledSystem<dim>::interpolate(const std::vector<std::string> &expressions,
                                    const std::string &,
                                    Vector &v) const
    {
      const Impl &s = *impl;
      v.reinit(s.owned, s.comm);
      if (expressions.empty())
        return;
      FunctionParser<3> f(dim);
      f.initialize("x,y,z,t",
                   expressions,
                   std::map<std::string, double>(),
                   true);
      dealii::Vector<double> value(dim);
      for (const unsigned int k : s.owned_nodes)
        {
          f.vector_value(to_3d(s.x[k]), value);
          for (unsigned int c = 0; c < dim; ++c)
            v[s.node_dof[k][c]] = value[c];
        }
      v.compress(VectorOperation::insert);
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::nearest_node(const Point<dim> &p) const
    {
      const Impl  &s    = *impl;
      unsigned int best = 0;
      for (unsigned int k = 1; k < s.n_nodes; ++k)
        if (s.x[k].distance_square(p) < s.x[best].distance_square(p))
          best = k;
      return best;
    }

    template <int dim>
    Point<dim>
    CoupledSystem<dim>::node_position(const unsigned int k) const
    {
      return impl->x[k];
    }

    template <int dim>
    Tensor<1, dim>
    CoupledSystem<dim>::node_displacement(const Vector      &u,
                                          const unsigned int k) const
    {
      const Impl    &s = *impl;
      Tensor<1, dim> value;
      if (s.owned.is_element(s.node_dof[k][0]))
        for (unsigned int c = 0; c < dim; ++c)
          value[c] = u[s.node_dof[k][c]];
      return Utilities::MPI::sum(value, s.comm);
    }

#define INSTANTIATE(dim)                                                         \
  template const CoupledSystem<dim>::Vector               &                                    \
  CoupledSystem<dim>::lumped_mass();                               \
  template void CoupledSystem<dim>::internal_force(const Vector &, Vector &);    \
  template void CoupledSystem<dim>::external_force(double, Vector &);            \
  template const std::vector<unsigned int> &CoupledSystem<dim>::held_dofs()      \
    const;                                                                       \
  template void CoupledSystem<dim>::factorize_effective(double, double, bool);   \
  template unsigned int CoupledSystem<dim>::solve_effective(Vector &,            \
                                                            const Vector &);     \
  template void   CoupledSystem<dim>::mass_vmult(Vector &, const Vector &);      \
  template double CoupledSystem<dim>::thickness() const;                         \
  template void   CoupledSystem<dim>::pseudo_random(Vector &) const;             \
  template void   CoupledSystem<dim>::update_reactions();                        \
  template unsigned int CoupledSystem<dim>::n_effective_factorizations()         \
    const;                                                                       \
  template void CoupledSystem<dim>::interpolate(                                 \
    const std::vector<std::string> &, const std::string &, Vector &) const;      \
  template unsigned int CoupledSystem<dim>::nearest_node(const Point<dim> &)     \
    const;                                                                       \
  template Point<dim>     CoupledSystem<dim>::node_position(unsigned int) const; \
  template Tensor<1, dim> CoupledSystem<dim>::node_displacement(                 \
    const Vector &, unsigned int) const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
