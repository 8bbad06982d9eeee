// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: the FE cells' stiffness added into a Trilinos matrix on the
// threads (the FE matrix and the "amg fe" preconditioner's matrix).
#include <pdfem/base/config.h>
#include <pdfem/base/thread_team.h>

#include <deal.II/hp/fe_values.h>

#include <algorithm>
#include <atomic>
#include <map>

#include "coupled_system_impl.h"
#include <Epetra_CrsMatrix.h>

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    namespace
    {
      /// Cells whose stiffness is computed before it is added: 256 hexes'
      /// 24 x 24 blocks are 1.2 MB.
      constexpr std::size_t cells_per_block = 256;
      /// Cells a thread takes at a time while computing a block.
      constexpr std::size_t cells_per_chunk = 16;
      /// Fewer cells (a crack's cut cells) are computed one by one: their
      /// shapes would cost a pass over the whole mesh.
      constexpr std::size_t min_cells_for_shapes = 256;
      /// Owned rows go to the threads in runs of this many (row / run
      /// modulo the threads), so that two threads seldom write one cache
      /// line and a block's rows spread over all of them.
      constexpr int rows_per_run = 64;
      /// A column left out (a prescribed DoF); -1 is a column not in the
      /// pattern, which is an error.
      constexpr int dropped = -2;

      /**
       * The cells of @p cells grouped by shape. With a linear mapping a
       * cell's stiffness depends only on its finite element and on its
       * vertices' offsets from its first vertex: translates of one cell
       * (equal offsets, bit for bit) share it. Structured meshes have few
       * shapes (the peer's box, 32 000 hexahedra: 600, as the coordinates'
       * rounding varies), unstructured ones as many as cells.
       *
       * Fills shape_of (per cell of @p cells) and representatives (per
       * shape, the first selected cell of the whole mesh, in the order of
       * the active cells: on every rank the same cell, so that all ranks
       * add the same numbers) and returns true, or returns false as soon
       * as the shapes would not save work (more than a quarter of the
       * selected cells seen so far, after the first 1 024) or memory (more
       * than @p max_shapes).
       */
      template <int dim, typename Iterator, typename Select>
      bool
      group_cells_by_shape(const DoFHandler<dim>       &dofs,
                           const Select                &select,
                           const std::vector<Iterator> &cells,
                           const std::size_t            max_shapes,
                           std::vector<unsigned int>   &shape_of,
                           std::vector<Iterator>       &representatives)
      {
        std::map<std::vector<double>, unsigned int> shapes;
        std::vector<double>                         key;
        std::size_t                                 n_seen = 0, next = 0;
        shape_of.clear();
        representatives.clear();
        for (const auto &cell : dofs.active_cell_iterators())
          {
            if (!select(cell->active_cell_index()))
              continue;
            ++n_seen;
            key.assign(1, cell->active_fe_index());
            const Point<dim> origin = cell->vertex(0);
            for (unsigned int v = 1; v < cell->n_vertices(); ++v)
              for (unsigned int d = 0; d < dim; ++d)
                key.push_back(cell->vertex(v)[d] - origin[d]);
            const auto [at, added] =
              shapes.emplace(key, static_cast<unsigned int>(shapes.size()));
            if (added)
              {
                representatives.push_back(cell);
                if (shapes.size() > max_shapes ||
                    (n_seen > 1024 && 4 * shapes.size() > n_seen))
                  return false;
              }
            if (next < cells.size() && cells[next] == cell)
              {
                shape_of.push_back(at->second);
                ++next;
              }
          }
        return 4 * shapes.size() <= n_seen;
      }
    } // namespace

    template <int dim>
    unsigned int
    CoupledSystem<dim>::Impl::add_cell_stiffness(
      TrilinosWrappers::SparseMatrix            &target,
      const std::function<bool(unsigned int)>   &select,
      const std::function<double(unsigned int)> &factor,
      const bool                                 eliminate) const
    {
      // Each block of cells in two team jobs: the threads compute the
      // cells' stiffness (FEValues, FE::cell_stiffness()) into the block's
      // slots, then each thread adds the rows it owns (a share of the
      // owned rows) for every cell of the block in cell order, straight
      // into the rows of the Epetra matrix. Every entry thus gets its
      // cells' values in cell order, as in a loop over the cells: the
      // matrix is the same bit for bit on any number of threads. Rows of
      // other ranks (deal.II's add(), not thread-safe) are added by the
      // calling thread, in cell order too. Prescribed rows and columns are
      // dropped when @p eliminate. On the 3D box (55 539 DoFs, one thread)
      // the FE assembly was 0.54 s of the 1.35 s set-up, two thirds of it
      // in deal.II's add() (a hash lookup of every column in every row).
      std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() && select(cell->active_cell_index()))
          cells.push_back(cell);
      if (cells.empty())
        return 0;

      const Epetra_CrsMatrix &A         = target.trilinos_matrix();
      const Epetra_BlockMap  &row_map   = A.RowMap();
      const Epetra_BlockMap  &col_map   = A.ColMap();
      const unsigned int      max_dofs  = fe.max_dofs_per_cell();
      ThreadTeam             &team      = ThreadTeam::shared();
      const unsigned int      n_members = team.size();
      // A filled Epetra matrix has each row's column indices sorted
      // (FillComplete() sorts them): found by bisection below; an entry
      // not found there throws, so nothing is added in the wrong place.
      AssertThrow(A.Filled() && A.IndicesAreLocal(),
                  ExcMessage("the cell matrix needs a compressed pattern"));

      // K is the cell's stiffness (its own, or its shape's), added
      // times factor: 1 where the cell's own K was scaled already.
      struct Slot
      {
        std::vector<global_dof_index> dofs;
        std::vector<double>           own_K;
        const double                 *K      = nullptr;
        double                        factor = 1.;
      };
      std::vector<Slot> slots(cells_per_block);
      for (Slot &s : slots)
        s.own_K.reserve(max_dofs * max_dofs);
      std::vector<std::unique_ptr<hp::FEValues<dim>>> fe_values(n_members);
      const auto fe_values_of = [&](const unsigned int member) -> auto &
      {
        if (!fe_values[member])
          fe_values[member] = std::make_unique<hp::FEValues<dim>>(
            mapping, fe, quadrature, update_gradients | update_JxW_values);
        return *fe_values[member];
      };

      // The stiffness of each shape, computed once where the cells have
      // few shapes (at most 64 MB of it). On the peer's box
      // (boxVpd4_static.in, 600 shapes among 32 000 cells) the set-up's
      // phase "fe_matrix" (both patterns, the FE cells' and all cells'
      // stiffness) went from 0.49-0.52 s to 0.37-0.41 s.
      std::vector<unsigned int>                                   shape_of;
      std::vector<typename DoFHandler<dim>::active_cell_iterator> shapes;
      std::vector<std::vector<double>>                            shape_K;
      if (cells.size() >= min_cells_for_shapes &&
          group_cells_by_shape(dofs,
                               select,
                               cells,
                               (64u << 20) /
                                 (sizeof(double) * max_dofs * max_dofs),
                               shape_of,
                               shapes))
        {
          Assert(shape_of.size() == cells.size(), ExcInternalError());
          shape_K.resize(shapes.size());
          std::atomic<std::size_t> next{0};
          team.run([&](const unsigned int member) {
            hp::FEValues<dim> &fv = fe_values_of(member);
            for (std::size_t i; (i = next++) < shapes.size();)
              {
                fv.reinit(shapes[i]);
                FE::cell_stiffness(fv.get_present_fe_values(),
                                   settings.material,
                                   shape_K[i]);
              }
          });
        }
      // The local row and column of every DoF (-1: none here), read from
      // the maps once: Epetra_BlockMap::LID() (a hash lookup) of every
      // cell's DoFs took 3.4 % of the box's set-up (55 539 DoFs, perf).
      std::vector<int> row_lid(dofs.n_dofs(), -1), col_lid(dofs.n_dofs(), -1);
      for (int i = 0; i < row_map.NumMyElements(); ++i)
        row_lid[row_map.GID64(i)] = i;
      for (int i = 0; i < col_map.NumMyElements(); ++i)
        col_lid[col_map.GID64(i)] = i;

      struct Scratch
      {
        std::vector<int>              columns;
        std::vector<global_dof_index> cols;
        std::vector<double>           values;
      };
      std::vector<Scratch> scratch(n_members);

      for (std::size_t begin = 0; begin < cells.size();
           begin += cells_per_block)
        {
          const std::size_t n = std::min(cells_per_block, cells.size() - begin);
          std::atomic<std::size_t> next{0};
          team.run([&](const unsigned int member) {
            for (std::size_t first; (first = cells_per_chunk * next++) < n;)
              for (std::size_t i = first;
                   i < std::min(first + cells_per_chunk, n);
                   ++i)
                {
                  const auto  &cell = cells[begin + i];
                  Slot        &s    = slots[i];
                  const double f    = factor(cell->active_cell_index());
                  if (shape_K.empty())
                    {
                      hp::FEValues<dim> &fv = fe_values_of(member);
                      fv.reinit(cell);
                      FE::cell_stiffness(fv.get_present_fe_values(),
                                         settings.material,
                                         s.own_K);
                      if (f != 1.)
                        for (double &k : s.own_K)
                          k *= f;
                      s.K      = s.own_K.data();
                      s.factor = 1.;
                    }
                  else
                    {
                      s.K      = shape_K[shape_of[begin + i]].data();
                      s.factor = f;
                    }
                  s.dofs.resize(cell->get_fe().n_dofs_per_cell());
                  cell->get_dof_indices(s.dofs);
                }
          });
          team.run([&](const unsigned int member) {
            Scratch &w = scratch[member];
            for (std::size_t i = 0; i < n; ++i)
              {
                const Slot       &s      = slots[i];
                const std::size_t n_dofs = s.dofs.size();
                w.columns.resize(n_dofs);
                for (std::size_t j = 0; j < n_dofs; ++j)
                  w.columns[j] = eliminate && dof_fixed[s.dofs[j]] ?
                                   dropped :
                                   col_lid[s.dofs[j]];
                for (std::size_t r = 0; r < n_dofs; ++r)
                  {
                    const global_dof_index row = s.dofs[r];
                    if (eliminate && dof_fixed[row])
                      continue;
                    const int lid = row_lid[row];
                    if (lid < 0)
                      {
                        if (member != 0)
                          continue;
                        w.cols.clear();
                        w.values.clear();
                        for (std::size_t j = 0; j < n_dofs; ++j)
                          if (!eliminate || !dof_fixed[s.dofs[j]])
                            {
                              w.cols.push_back(s.dofs[j]);
                              w.values.push_back(s.factor *
                                                 s.K[r * n_dofs + j]);
                            }
                        target.add(row,
                                   w.cols.size(),
                                   w.cols.data(),
                                   w.values.data(),
                                   false,
                                   false);
                        continue;
                      }
                    if ((lid / rows_per_run) % n_members != member)
                      continue;
                    int     n_entries = 0;
                    double *values    = nullptr;
                    int    *indices   = nullptr;
                    A.ExtractMyRowView(lid, n_entries, values, indices);
                    for (std::size_t j = 0; j < n_dofs; ++j)
                      if (w.columns[j] != dropped)
                        {
                          const int *at = std::lower_bound(indices,
                                                           indices + n_entries,
                                                           w.columns[j]);
                          AssertThrow(at != indices + n_entries &&
                                        *at == w.columns[j],
                                      ExcMessage("a cell's entry is not in "
                                                 "the matrix's pattern"));
                          values[at - indices] +=
                            s.factor * s.K[r * n_dofs + j];
                        }
                  }
              }
          });
        }
      return cells.size();
    }

#define INSTANTIATE(dim)                                              \
  template unsigned int CoupledSystem<dim>::Impl::add_cell_stiffness( \
    TrilinosWrappers::SparseMatrix &,                                 \
    const std::function<bool(unsigned int)> &,                        \
    const std::function<double(unsigned int)> &,                      \
    bool) const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
