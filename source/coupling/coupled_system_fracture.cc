// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: what crack growth needs (breaking bonds, listing the intact
// ones, counting the pieces the body is in).
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/base/thread_team.h>

#include <deal.II/base/mpi.h>

#include <atomic>
#include <numeric>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    template <int dim>
    void
    CoupledSystem<dim>::Impl::bonds_changed(
      const std::vector<std::size_t> &changed,
      const bool                      free_surfaces)
    {
      model->bonds_changed(changed, free_surfaces);
      update_decoupled();
      decoupled_changed();
    }

    template <int dim>
    void
    CoupledSystem<dim>::Impl::decoupled_changed()
    {
      update_held();
      block_inverse.clear(); // rebuilt by the next solve
      auxiliary_stale  = matrix_free;
      tangent_outdated = true;
      if (choice)
        choice->matrix_changed();
    }

    template <int dim>
    unsigned long
    CoupledSystem<dim>::break_bonds(const std::vector<Mesh::Crack<dim>> &cracks)
    {
      Impl         &s = *impl;
      unsigned long n = 0;
      if (!cracks.empty())
        {
          // A bond can only meet a crack if its owner is within its longest
          // bond of the crack's bounding box; each owner tests only those
          // cracks (one box around all new segments spanned the whole plate
          // once two tips grew apart, and every bond was tested), and each bond
          // only those whose box meets its own (a 3D growth step of the
          // maximum principal stress criterion cuts with 100 discs of 12
          // triangles each: on the 14.6 k-DoF box the tests took 6 s of a
          // 9.6 s run). The margin, 1e-9 of the extents, is far above the
          // exact tests' tolerances. Owners in chunks on the threads; each
          // owner writes its own bonds only.
          std::vector<Mesh::Box<dim>> boxes;
          for (const auto &crack : cracks)
            boxes.push_back(crack.bounding_box());
          PD::Families &f = s.families;
          // The bonds of family o that a crack cuts, broken; their number.
          const auto cut_family = [&](const std::size_t          o,
                                      std::vector<unsigned int> &near) {
            const unsigned int k = f.owners[o];
            if (s.no_fail[k])
              return 0ul;
            // The owner's reach, its longest bond (a member lies within
            // the larger of the two horizons): on the 3D growth run of
            // doc/benchmarks/scaling.md two horizons let about 8 times as
            // many of the 1 200 crack triangles near each owner.
            double reach = 0.;
            for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
              reach =
                std::max(reach, s.x[k].distance_square(s.x[f.members[b]]));
            reach = std::sqrt(reach);
            near.clear();
            for (unsigned int c = 0; c < cracks.size(); ++c)
              if (Mesh::boxes_meet(Mesh::segment_box(s.x[k], s.x[k]),
                                   boxes[c],
                                   reach))
                near.push_back(c);
            unsigned long cut = 0;
            for (std::size_t b = f.offsets[o];
                 !near.empty() && b < f.offsets[o + 1];
                 ++b)
              {
                const unsigned int m = f.members[b];
                if (!f.intact[b] || s.no_fail[m])
                  continue;
                const Mesh::Box<dim> bond = Mesh::segment_box(s.x[k], s.x[m]);
                for (const unsigned int c : near)
                  if (Mesh::boxes_meet(bond, boxes[c]) &&
                      cracks[c].cuts(s.x[k], s.x[m]))
                    {
                      f.intact[b] = 0;
                      ++cut;
                      break;
                    }
              }
            return cut;
          };
          const std::size_t          n_owners = f.owners.size();
          constexpr std::size_t      chunk    = 256;
          ThreadTeam                &team     = ThreadTeam::shared();
          std::vector<unsigned long> counts(team.size(), 0);
          std::vector<char>          lost(n_owners, 0);
          std::atomic<std::size_t>   next{0};

          const auto chunks = [&](const unsigned int member) {
            std::vector<unsigned int> near;
            for (std::size_t first; (first = chunk * next++) < n_owners;)
              {
                const std::size_t last = std::min(first + chunk, n_owners);
                for (std::size_t o = first; o < last; ++o)
                  {
                    const unsigned long cut = cut_family(o, near);
                    counts[member] += cut;
                    lost[o] = cut > 0;
                  }
              }
          };
          team.run(chunks);
          n = std::accumulate(counts.begin(), counts.end(), 0ul);
          std::vector<std::size_t> cut_families;
          for (std::size_t o = 0; o < n_owners; ++o)
            if (lost[o])
              cut_families.push_back(o);
          if (s.settings.free_crack_faces)
            s.add_crack_face_area(cracks);
          typename Impl::FractureEvent event;
          event.cracks = cracks;
          s.events.push_back(std::move(event));
          n = Utilities::MPI::sum(n, s.comm);
          if (n > 0)
            s.bonds_changed(cut_families, s.settings.free_crack_faces);
        }
      return n;
    }

    template <int dim>
    unsigned long
    CoupledSystem<dim>::Impl::break_bonds_where(
      const std::function<bool(std::size_t, std::size_t)> &breaks)
    {
      PD::Families            &f = families;
      unsigned long            n = 0;
      std::vector<std::size_t> changed;
      FractureEvent            event;
      event.kind = FractureEvent::predicate;
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        {
          const unsigned int k = f.owners[o];
          if (no_fail[k])
            continue;
          bool lost = false;
          for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
            if (f.intact[b] && !no_fail[f.members[b]] && breaks(o, b))
              {
                f.intact[b] = 0;
                event.bonds.push_back({{k, f.members[b]}});
                ++n;
                lost = true;
              }
          if (lost)
            changed.push_back(o);
        }
      n = Utilities::MPI::sum(n, comm);
      if (n > 0)
        {
          bonds_changed(changed, false);
          events.push_back(std::move(event));
        }
      return n;
    }

    template <int dim>
    unsigned long
    CoupledSystem<dim>::break_bonds_if(
      const std::function<bool(unsigned int, unsigned int)> &breaks)
    {
      if (!impl->layout.bonds || !impl->layout.breakable_bonds)
        throw InputError(impl->settings.source_file,
                         "Peridynamics/Model",
                         "this PD model cannot break single bonds (it has "
                         "node masks only)",
                         "a PD model with bonds, e.g. lps instead of lps fft");
      const PD::Families &f = impl->families;
      return impl->break_bonds_where(
        [&](const std::size_t o, const std::size_t b) {
          return breaks(f.owners[o], f.members[b]);
        });
    }

    template <int dim>
    unsigned long
    CoupledSystem<dim>::accept_state(const Vector &u)
    {
      Impl &s = *impl;
      if (!s.layout.history)
        return 0;
      s.import_ghosts(u, s.u_ghosted);
      s.model->commit_state(s.nodal_field(s.u_ghosted));
      return s.break_bonds_where([&s](std::size_t, const std::size_t b) {
        return s.model->bond_failed(b);
      });
    }

    template <int dim>
    double
    CoupledSystem<dim>::released_energy() const
    {
      return impl->layout.history ? impl->model->released_energy() : 0.;
    }

    template <int dim>
    PDModels::DegradationState
    CoupledSystem<dim>::degradation_state(const Vector &u,
                                          const double  onset_fraction)
    {
      Impl &s = *impl;
      s.import_ghosts(u, s.u_ghosted);
      PDModels::DegradationState state =
        s.model->degradation_state(s.nodal_field(s.u_ghosted), onset_fraction);
      const MPI_Comm comm = s.comm;
      state.n_beyond_threshold =
        Utilities::MPI::sum(state.n_beyond_threshold, comm);
      state.n_failed        = Utilities::MPI::sum(state.n_failed, comm);
      state.degradation     = Utilities::MPI::sum(state.degradation, comm);
      state.max_onset_ratio = Utilities::MPI::max(state.max_onset_ratio, comm);
      return state;
    }

    template <int dim>
    const std::vector<double> &
    CoupledSystem<dim>::horizons() const
    {
      return impl->horizon;
    }

    template <int dim>
    const PD::Families &
    CoupledSystem<dim>::families() const
    {
      return impl->families;
    }

    template <int dim>
    const TrilinosWrappers::SparseMatrix &
    CoupledSystem<dim>::preconditioner_matrix()
    {
      if (impl->auxiliary_stale)
        impl->assemble_auxiliary();
      return impl->auxiliary;
    }

    template <int dim>
    std::vector<unsigned int>
    CoupledSystem<dim>::Impl::piece_labels() const
    {
      const Impl &s = *this;
      // Union-find over the local edges, then the smallest node index of
      // each component, agreed on by all ranks (MPI min) until nothing
      // changes: every rank ends with the same labels.
      std::vector<unsigned int> parent(s.n_nodes);
      std::iota(parent.begin(), parent.end(), 0u);
      const auto find = [&](unsigned int a) {
        while (parent[a] != a)
          a = parent[a] = parent[parent[a]];
        return a;
      };
      const auto unite = [&](const unsigned int a, const unsigned int b) {
        const unsigned int ra = find(a), rb = find(b);
        if (ra != rb)
          parent[std::max(ra, rb)] = std::min(ra, rb);
      };
      for (const auto &cell : s.tria.active_cell_iterators())
        if (cell->is_locally_owned() && !s.cell_pd[cell->active_cell_index()])
          for (unsigned int v = 1; v < cell->n_vertices(); ++v)
            unite(s.vertex_to_node[cell->vertex_index(0)],
                  s.vertex_to_node[cell->vertex_index(v)]);
      const PD::Families &f = s.families;
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
          if (f.intact[b])
            unite(f.owners[o], f.members[b]);

      std::vector<unsigned int> label(s.n_nodes), previous;
      while (true)
        {
          for (unsigned int k = 0; k < s.n_nodes; ++k)
            label[k] = find(k);
          Utilities::MPI::min(label, s.comm, label);
          if (label == previous)
            break;
          // Fold the agreed labels back into the local forest.
          for (unsigned int k = 0; k < s.n_nodes; ++k)
            unite(k, label[k]);
          previous = label;
        }

      return label;
    }

    template <int dim>
    unsigned int
    CoupledSystem<dim>::count_pieces(const unsigned int min_nodes) const
    {
      const Impl                     &s     = *impl;
      const std::vector<unsigned int> label = s.piece_labels();
      std::vector<unsigned int>       size(s.n_nodes, 0);
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        ++size[label[k]];
      unsigned int pieces = 0;
      for (const unsigned int n : size)
        pieces += n >= std::max(min_nodes, 2u);
      return pieces;
    }

    template <int dim>
    unsigned long
    CoupledSystem<dim>::hold_fragments(const unsigned int min_nodes)
    {
      Impl                           &s     = *impl;
      const std::vector<unsigned int> label = s.piece_labels();
      std::vector<unsigned int>       size(s.n_nodes, 0);
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        ++size[label[k]];
      unsigned long held = 0;
      for (std::size_t o = 0; o < s.families.owners.size(); ++o)
        {
          const unsigned int k = s.families.owners[o];
          if (!s.fragment[o] && !s.decoupled[o] && !s.is_fe[k] &&
              size[label[k]] < min_nodes)
            {
              s.fragment[o] = 1;
              ++held;
            }
        }
      held = Utilities::MPI::sum(held, s.comm);
      if (held > 0)
        {
          s.update_decoupled();
          s.decoupled_changed();
          typename Impl::FractureEvent event;
          event.kind      = Impl::FractureEvent::fragments;
          event.min_nodes = min_nodes;
          s.events.push_back(std::move(event));
        }
      return held;
    }

    template <int dim>
    void
    CoupledSystem<dim>::save_fracture_state(StateArchive &state) const
    {
      const auto &events = impl->events;
      state.put("system/events", events.size());
      for (std::size_t e = 0; e < events.size(); ++e)
        {
          const std::string prefix = "system/event " + std::to_string(e) + "/";
          state.put(prefix + "kind", events[e].kind);
          state.put(prefix + "cracks", events[e].cracks);
          state.put(prefix + "bonds", events[e].bonds);
          state.put(prefix + "min nodes", events[e].min_nodes);
        }
      impl->model->save_state(state);
    }

    template <int dim>
    void
    CoupledSystem<dim>::forget_preconditioner()
    {
      Impl &s = *impl;
      s.solver.forget_preconditioner();
      // The auxiliary matrix is assembled whole at the next solve, not
      // updated in place (which rounds differently).
      s.auxiliary_cut.clear();
      s.auxiliary_stale = s.matrix_free;
    }

    template <int dim>
    void
    CoupledSystem<dim>::restore_fracture_state(const StateArchive &state)
    {
      AssertThrow(impl->events.empty(),
                  ExcMessage("restore_fracture_state() on a system whose "
                             "bonds already changed"));
      using Event                = typename Impl::FractureEvent;
      const std::size_t n_events = state.get<std::size_t>("system/events");
      for (std::size_t e = 0; e < n_events; ++e)
        {
          const std::string prefix = "system/event " + std::to_string(e) + "/";
          switch (state.get<typename Event::Kind>(prefix + "kind"))
            {
              case Event::cut:
                break_bonds(
                  state.get_vector<Mesh::Crack<dim>>(prefix + "cracks"));
                break;
              case Event::predicate:
                {
                  auto bonds = state.get_vector<std::array<unsigned int, 2>>(
                    prefix + "bonds");
                  std::sort(bonds.begin(), bonds.end());
                  break_bonds_if(
                    [&bonds](const unsigned int k, const unsigned int m) {
                      return std::binary_search(bonds.begin(),
                                                bonds.end(),
                                                std::array<unsigned int, 2>{
                                                  {k, m}});
                    });
                  break;
                }
              case Event::fragments:
                hold_fragments(state.get<unsigned int>(prefix + "min nodes"));
                break;
              default:
                throw InputError("",
                                 "--restart",
                                 "the checkpoint's fracture history has an "
                                 "event of unknown kind");
            }
        }
      impl->model->restore_state(state);
      // As the checkpointed run did right after its checkpoint.
      forget_preconditioner();
    }

    template <int dim>
    const PDModels::Interface<dim> &
    CoupledSystem<dim>::pd_model() const
    {
      return *impl->model;
    }

#define INSTANTIATE(dim)                                                         \
  template void CoupledSystem<dim>::Impl::bonds_changed(                         \
    const std::vector<std::size_t> &, bool);                                     \
  template unsigned long CoupledSystem<dim>::break_bonds(                        \
    const std::vector<Mesh::Crack<dim>> &);                                      \
  template unsigned long CoupledSystem<dim>::break_bonds_if(                     \
    const std::function<bool(unsigned int, unsigned int)> &);                    \
  template unsigned long CoupledSystem<dim>::Impl::break_bonds_where(            \
    const std::function<bool(std::size_t, std::size_t)> &);                      \
  template unsigned long CoupledSystem<dim>::accept_state(const Vector &);       \
  template double        CoupledSystem<dim>::released_energy() const;            \
  template PDModels::DegradationState CoupledSystem<dim>::degradation_state(     \
    const Vector &, double);                                                     \
  template const std::vector<double>      &CoupledSystem<dim>::horizons() const; \
  template const PD::Families             &CoupledSystem<dim>::families() const; \
  template const PDModels::Interface<dim> &CoupledSystem<dim>::pd_model()        \
    const;                                                                       \
  template unsigned int  CoupledSystem<dim>::count_pieces(unsigned int) const;   \
  template unsigned long CoupledSystem<dim>::hold_fragments(unsigned int);       \
  template void CoupledSystem<dim>::save_fracture_state(StateArchive &) const;   \
  template void CoupledSystem<dim>::restore_fracture_state(                      \
    const StateArchive &);                                                       \
  template void CoupledSystem<dim>::forget_preconditioner();                     \
  template std::vector<unsigned int> CoupledSystem<dim>::Impl::piece_labels()    \
    const;                                                                       \
  template const TrilinosWrappers::SparseMatrix &                                \
  CoupledSystem<dim>::preconditioner_matrix();
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
