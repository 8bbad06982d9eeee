// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: the matrix-free operator (PD kernel, K x, internal force)
// and the block-Jacobi correction of the "amg fe" preconditioner.
#include <pdfem/base/config.h>
#include <pdfem/base/thread_team.h>

#include <algorithm>
#include <atomic>

#include "coupled_system_impl.h"
#include <Epetra_FEVector.h>
#include <Epetra_Import.h>

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    const Epetra_Import &
    CoupledSystem<dim>::Impl::ghost_import(
      const TrilinosWrappers::MPI::Vector &owned_vector,
      const TrilinosWrappers::MPI::Vector &ghosted_vector) const
    {
      // deal.II's assignment builds a new Epetra_Import at every call (on
      // plateCrack FC1, 7 % of the run); the imports are kept instead, one
      // per pair of maps (compared by identity: Epetra's SameAs compares
      // every index).
      const Epetra_BlockMap &source = owned_vector.trilinos_vector().Map();
      const Epetra_BlockMap &target = ghosted_vector.trilinos_vector().Map();
      const auto            *from   = source.DataPtr();
      const auto            *to     = target.DataPtr();
      auto                   kept   = std::find_if(ghost_imports.begin(),
                               ghost_imports.end(),
                               [&](const auto &g) {
                                 return g.source == from && g.target == to;
                               });
      if (kept == ghost_imports.end())
        {
          if (ghost_imports.size() == 4)
            ghost_imports.erase(ghost_imports.begin());
          ghost_imports.push_back(
            {from, to, std::make_shared<Epetra_Import>(target, source)});
          kept = ghost_imports.end() - 1;
        }
      return *kept->import;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::import_ghosts(
      const TrilinosWrappers::MPI::Vector &v,
      TrilinosWrappers::MPI::Vector       &ghosted) const
    {
      AssertThrow(ghosted.trilinos_vector().Import(v.trilinos_vector(),
                                                   ghost_import(v, ghosted),
                                                   Insert) == 0,
                  ExcMessage("ghost import failed"));
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::scatter_add(
      const TrilinosWrappers::MPI::Vector &contributions,
      TrilinosWrappers::MPI::Vector       &y) const
    {
      // The reverse of the ghost import, summing: every rank's
      // contributions to a DoF (owned or ghost there) reach its owner.
      Epetra_FEVector &sum = scatter_owned.trilinos_vector();
      sum.PutScalar(0.);
      AssertThrow(sum.Export(contributions.trilinos_vector(),
                             ghost_import(scatter_owned, contributions),
                             Add) == 0,
                  ExcMessage("scatter of PD contributions failed"));
      y += scatter_owned;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_pd_chunks()
    {
      // About 8 chunks per thread with equal work, one unit per owner and
      // per bond (owners only for a model without bonds): the threads
      // steal chunks, so one that also ran the FE product takes fewer.
      const std::size_t n_owners = families.owners.size();
      const std::size_t n_chunks =
        std::min<std::size_t>(8 * ThreadTeam::shared().size(), n_owners);
      pd_chunks.assign(1, 0);
      const double per_chunk =
        static_cast<double>(families.n_bonds() + n_owners) /
        std::max<std::size_t>(1, n_chunks);
      for (std::size_t o = 0; o < n_owners; ++o)
        if (families.offsets[o + 1] + o + 1 >= per_chunk * pd_chunks.size() &&
            pd_chunks.size() < n_chunks)
          pd_chunks.push_back(o + 1);
      if (pd_chunks.back() != n_owners)
        pd_chunks.push_back(n_owners);
      pd_force.assign(dim * (n_owners +
                             (layout.family_elements ? families.n_bonds() : 0)),
                      0.);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::compute_pd_forces(
      const TrilinosWrappers::MPI::Vector &x,
      const std::function<void()>         &fe_product,
      const TrilinosWrappers::MPI::Vector *tangent_state) const
    {
      // The model's rows, chunk by chunk on the threads; decoupled owners
      // (held) get none. A model that evaluates all owners at once does it
      // in prepare_forces(), before the chunks.
      const PDModels::NodalField<dim> field = nodal_field(x);
      model->prepare_forces(field);
      if (layout.family_elements)
        {
          // Family o's forces at pd_force[dim (o + offsets[o]) ..]: its
          // owner, then one slot per bond (0 for broken ones).
          const auto owners = [&](const std::size_t begin,
                                  const std::size_t end) {
            std::vector<Tensor<1, dim>> f;
            for (std::size_t o = begin; o < end; ++o)
              {
                double *slot = &pd_force[dim * (o + families.offsets[o])];
                std::fill(slot,
                          slot + dim * (1 + families.offsets[o + 1] -
                                        families.offsets[o]),
                          0.);
                if (decoupled[o])
                  continue;
                model->family_forces(o, field, f);
                std::size_t n = 0;
                for (unsigned int c = 0; c < dim; ++c)
                  slot[c] = f[0][c];
                for (std::size_t j = families.offsets[o];
                     j < families.offsets[o + 1];
                     ++j)
                  if (families.intact[j])
                    {
                      ++n;
                      for (unsigned int c = 0; c < dim; ++c)
                        slot[dim * (1 + j - families.offsets[o]) + c] = f[n][c];
                    }
                AssertThrow(n + 1 == f.size(),
                            ExcMessage("a family-element PD model must give "
                                       "one force per intact bond and one "
                                       "on the owner"));
              }
          };
          for_each_pd_chunk(fe_product, owners);
          return;
        }
      const PDModels::NodalField<dim> state =
        tangent_state ? nodal_field(*tangent_state) : field;
      const auto owners = [&](const std::size_t begin, const std::size_t end) {
        if (tangent_state)
          model->tangent_products(begin, end, state, field, pd_force.data());
        else
          model->forces(begin, end, field, pd_force.data());
        for (std::size_t o = begin; o < end; ++o)
          if (decoupled[o])
            for (unsigned int c = 0; c < dim; ++c)
              pd_force[dim * o + c] = 0.;
      };
      for_each_pd_chunk(fe_product, owners);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::for_each_pd_chunk(
      const std::function<void()>                         &caller_first,
      const std::function<void(std::size_t, std::size_t)> &owners) const
    {
      std::atomic<std::size_t> next_chunk{0};
      ThreadTeam::shared().run([&](const unsigned int member) {
        if (member == 0 && caller_first)
          caller_first();
        for (std::size_t i = next_chunk++; i + 1 < pd_chunks.size();
             i             = next_chunk++)
          owners(pd_chunks[i], pd_chunks[i + 1]);
      });
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::add_pd_forces(
      TrilinosWrappers::MPI::Vector &y) const
    {
      if (layout.family_elements)
        {
          scatter_ghosted.trilinos_vector().PutScalar(0.);
          double *g = scatter_ghosted.trilinos_vector()[0];
          for (std::size_t o = 0; o < families.owners.size(); ++o)
            {
              const double *slot = &pd_force[dim * (o + families.offsets[o])];
              for (unsigned int c = 0; c < dim; ++c)
                g[relevant_lid[families.owners[o]][c]] += slot[c];
              for (std::size_t j = families.offsets[o];
                   j < families.offsets[o + 1];
                   ++j)
                for (unsigned int c = 0; c < dim; ++c)
                  g[relevant_lid[families.members[j]][c]] +=
                    slot[dim * (1 + j - families.offsets[o]) + c];
            }
          scatter_add(scatter_ghosted, y);
          return;
        }
      double *yv = y.trilinos_vector()[0];
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        for (unsigned int c = 0; c < dim; ++c)
          yv[owned_lid[families.owners[o]][c]] += pd_force[dim * o + c];
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::compute_internal_force(
      const TrilinosWrappers::MPI::Vector &u)
    {
      // f_int = K_FE u + PD(u); every PD row is owned. The FE product and
      // the PD kernel run side by side.
      import_ghosts(u, u_ghosted);
      compute_pd_forces(u_ghosted, [&] { fe_matrix.vmult(x_masked, u); });
      f_int = 0.;
      f_int += x_masked;
      add_pd_forces(f_int);
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::vmult(
      TrilinosWrappers::MPI::Vector       &y,
      const TrilinosWrappers::MPI::Vector &x) const
    {
      // y = K x with held DoFs eliminated: x with its held entries zeroed
      // through the FE matrix and the PD kernel (side by side), then the
      // diagonal on the held rows.
      x_masked         = x;
      double       *xm = x_masked.trilinos_vector()[0];
      const double *xv = x.trilinos_vector()[0];
      for (unsigned int i = 0; i < held_lid.size(); ++i)
        xm[held_lid[i]] = 0.;
      import_ghosts(x_masked, x_ghosted);
      // A nonlinear model: the products of its tangent at the state of the
      // last residual that asked for one (Layout::tangent_products).
      compute_pd_forces(
        x_ghosted,
        [&] { fe_matrix.vmult(y, x_masked); },
        model->linear() ? nullptr : &u_tangent);
      add_pd_forces(y);
      double *yv = y.trilinos_vector()[0];
      for (unsigned int i = 0; i < held_lid.size(); ++i)
        yv[held_lid[i]] = held_value[i] * xv[held_lid[i]];
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::make_block_jacobi()
    {
      // D_k = FE diagonal block + PD block d(row k)/d(u_k); held DoFs get
      // their diagonal entry alone.
      block_inverse.assign(owned_nodes.size(), Tensor<2, dim>());
      const PDModels::NodalField<dim> field = tangent_field();
      std::vector<Tensor<2, dim>>     row;
      // Family-element models: the diagonal blocks of every family a node
      // belongs to, gathered at its owner column by column.
      std::vector<TrilinosWrappers::MPI::Vector> element_diagonal;
      if (layout.family_elements)
        element_diagonal = family_diagonal_blocks(field);
      for (std::size_t n = 0; n < owned_nodes.size(); ++n)
        {
          const unsigned int k = owned_nodes[n];
          Tensor<2, dim>     D;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              D[i][j] = fe_matrix.el(node_dof[k][i], node_dof[k][j]);
          const std::size_t o = family_of[k];
          if (layout.family_elements)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                D[i][j] += element_diagonal[j][node_dof[k][i]];
          else if (o < families.owners.size() && !decoupled[o])
            {
              model->tangent_row(o, field, row);
              D += row[0];
            }
          for (unsigned int i = 0; i < dim; ++i)
            if (dof_fixed[node_dof[k][i]] ||
                (o < families.owners.size() && decoupled[o]))
              {
                for (unsigned int j = 0; j < dim; ++j)
                  D[i][j] = D[j][i] = 0.;
                D[i][i] = held_diagonal(node_dof[k][i]);
              }
          block_inverse[n] = invert(D);
        }
    }

    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector>
    CoupledSystem<dim>::Impl::family_diagonal_blocks(
      const PDModels::NodalField<dim> &field) const
    {
      // Column j of every node's diagonal block, summed over the families
      // it belongs to, one ghosted vector per column.
      std::vector<TrilinosWrappers::MPI::Vector> ghosted(dim), columns(dim);
      std::vector<double *>                      g(dim);
      for (unsigned int j = 0; j < dim; ++j)
        {
          ghosted[j].reinit(owned, relevant, comm);
          g[j] = ghosted[j].trilinos_vector()[0];
        }
      for_each_family_tangent(
        field,
        [&](const auto &nodes, const auto &blocks) {
          for (std::size_t a = 0; a < nodes.size(); ++a)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                g[j][relevant_lid[nodes[a]][i]] += blocks[a][i][j];
        },
        true);
      for (unsigned int j = 0; j < dim; ++j)
        {
          columns[j].reinit(owned, comm);
          scatter_add(ghosted[j], columns[j]);
        }
      return columns;
    }

    template <int dim>
    std::vector<unsigned int>
    CoupledSystem<dim>::Impl::family_nodes(const std::size_t o) const
    {
      std::vector<unsigned int> nodes{families.owners[o]};
      for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
           ++j)
        if (families.intact[j])
          nodes.push_back(families.members[j]);
      return nodes;
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::apply_block_jacobi(
      TrilinosWrappers::MPI::Vector       &w,
      const TrilinosWrappers::MPI::Vector &t) const
    {
      const double  *tv = t.trilinos_vector()[0];
      double        *wv = w.trilinos_vector()[0];
      Tensor<1, dim> tk;
      for (std::size_t n = 0; n < owned_nodes.size(); ++n)
        {
          const auto &lid = owned_lid[owned_nodes[n]];
          for (unsigned int c = 0; c < dim; ++c)
            tk[c] = tv[lid[c]];
          const Tensor<1, dim> wk = block_inverse[n] * tk;
          for (unsigned int c = 0; c < dim; ++c)
            wv[lid[c]] = wk[c];
        }
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::apply_model_preconditioner(
      TrilinosWrappers::MPI::Vector       &z,
      const TrilinosWrappers::MPI::Vector &r) const
    {
      // Held rows are decoupled from the rest (vmult()): they enter the
      // model's preconditioner as zeros and get their own diagonal.
      const double       *rv = r.trilinos_vector()[0];
      double             *zv = z.trilinos_vector()[0];
      std::vector<double> r_rows(dim * families.owners.size()), z_rows;
      std::vector<bool>   held(owned.n_elements(), false);
      for (const unsigned int lid : held_lid)
        held[lid] = true;
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const unsigned int lid = owned_lid[families.owners[o]][c];
            r_rows[dim * o + c]    = held[lid] ? 0. : rv[lid];
          }
      model->precondition(r_rows, z_rows);
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        for (unsigned int c = 0; c < dim; ++c)
          zv[owned_lid[families.owners[o]][c]] = z_rows[dim * o + c];
      for (unsigned int i = 0; i < held_lid.size(); ++i)
        zv[held_lid[i]] = rv[held_lid[i]] / held_value[i];
    }

#define INSTANTIATE(dim)                                                     \
  template void CoupledSystem<dim>::Impl::make_pd_chunks();                  \
  template void CoupledSystem<dim>::Impl::for_each_pd_chunk(                 \
    const std::function<void()> &,                                           \
    const std::function<void(std::size_t, std::size_t)> &) const;            \
  template void CoupledSystem<dim>::Impl::import_ghosts(                     \
    const TrilinosWrappers::MPI::Vector &, TrilinosWrappers::MPI::Vector &)  \
    const;                                                                   \
  template void CoupledSystem<dim>::Impl::compute_internal_force(            \
    const TrilinosWrappers::MPI::Vector &);                                  \
  template void CoupledSystem<dim>::Impl::vmult(                             \
    TrilinosWrappers::MPI::Vector &, const TrilinosWrappers::MPI::Vector &)  \
    const;                                                                   \
  template void CoupledSystem<dim>::Impl::make_block_jacobi();               \
  template void CoupledSystem<dim>::Impl::scatter_add(                       \
    const TrilinosWrappers::MPI::Vector &, TrilinosWrappers::MPI::Vector &)  \
    const;                                                                   \
  template std::vector<unsigned int> CoupledSystem<dim>::Impl::family_nodes( \
    std::size_t) const;                                                      \
  template void CoupledSystem<dim>::Impl::apply_block_jacobi(                \
    TrilinosWrappers::MPI::Vector &, const TrilinosWrappers::MPI::Vector &)  \
    const;                                                                   \
  template void CoupledSystem<dim>::Impl::apply_model_preconditioner(        \
    TrilinosWrappers::MPI::Vector &, const TrilinosWrappers::MPI::Vector &)  \
    const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
