// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/fracture/automatic_region.h>
#include <pdfem/fracture/crack_growth.h>
#include <pdfem/pd/families.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>

namespace pdfem
{
  namespace Fracture
  {
    using namespace dealii;

    std::pair<double, double>
    mcts_angle_and_keq(const double K_I, const double K_II)
    {
      // One formula for both signs of K_II (the peer's two branches agree
      // with it); it tends to -2 K_II / K_I as K_II -> 0.
      double theta = 0.;
      if (K_II != 0.)
        theta = 2. * std::atan((K_I - std::sqrt(K_I * K_I + 8. * K_II * K_II)) /
                               (4. * K_II));
      const double c = std::cos(0.5 * theta);
      return {theta, K_I * c * c * c - 1.5 * K_II * c * std::sin(theta)};
    }

    namespace
    {
      /// Distance from @p p to the segment [a, b].
      template <int dim>
      double
      distance_to_segment(const Point<dim> &p,
                          const Point<dim> &a,
                          const Point<dim> &b)
      {
        const Tensor<1, dim> ab = b - a;
        const double         L2 = ab.norm_square();
        const double t = L2 > 0. ? std::clamp((p - a) * ab / L2, 0., 1.) : 0.;
        return p.distance(a + t * ab);
      }

      /// Distance from @p p to a crack (segment in 2D, triangle in 3D).
      template <int dim>
      double
      distance_to_crack(const Point<dim> &p, const Mesh::Crack<dim> &c)
      {
        double d = distance_to_segment(p, c.points[0], c.points[1]);
        if constexpr (dim == 3)
          {
            d = std::min({d,
                          distance_to_segment(p, c.points[1], c.points[2]),
                          distance_to_segment(p, c.points[2], c.points[0])});
            // The projection onto the plane, if it falls inside.
            const Tensor<1, 3> e1 = c.points[1] - c.points[0],
                               e2 = c.points[2] - c.points[0];
            Tensor<1, 3> n        = cross_product_3d(e1, e2);
            if (n.norm() == 0.)
              return d;
            n /= n.norm();
            const double       h   = (p - c.points[0]) * n;
            const Point<3>     q   = p - h * n;
            const Tensor<1, 3> w   = q - c.points[0];
            const double       a11 = e1 * e1, a12 = e1 * e2, a22 = e2 * e2;
            const double b1 = w * e1, b2 = w * e2, det = a11 * a22 - a12 * a12;
            const double s = (b1 * a22 - b2 * a12) / det,
                         t = (a11 * b2 - a12 * b1) / det;
            if (s >= 0. && t >= 0. && s + t <= 1.)
              d = std::min(d, std::abs(h));
          }
        return d;
      }

      /// A virtual crack through @p c, normal to @p n, of diameter @p d: a
      /// segment in 2D, a 12-sided disc (as triangles) in 3D.
      template <int dim>
      void
      add_virtual_crack(const Point<dim>              &c,
                        const Tensor<1, dim>          &n,
                        const double                   d,
                        std::vector<Mesh::Crack<dim>> &out)
      {
        if constexpr (dim == 2)
          {
            const Tensor<1, 2> t({-n[1], n[0]});
            out.push_back(Mesh::Crack<2>{{{c - 0.5 * d * t, c + 0.5 * d * t}}});
          }
        else
          {
            // Two unit vectors spanning the plane normal to n.
            Tensor<1, 3> a;
            a[std::abs(n[0]) < 0.9 ? 0 : 1] = 1.;
            a -= (a * n) * n;
            a /= a.norm();
            const Tensor<1, 3> b = cross_product_3d(n, a);
            // The circumscribed polygon, so that the disc is covered.
            constexpr unsigned int sides = 12;
            const double           R     = 0.5 * d / std::cos(M_PI / sides);
            for (unsigned int i = 0; i < sides; ++i)
              {
                const double p0 = 2. * M_PI * i / sides,
                             p1 = 2. * M_PI * (i + 1) / sides;
                out.push_back(Mesh::Crack<3>{
                  {{c,
                    c + R * (std::cos(p0) * a + std::sin(p0) * b),
                    c + R * (std::cos(p1) * a + std::sin(p1) * b)}}});
              }
          }
      }
    } // namespace

    template <int dim>
    struct CrackGrowth<dim>::Impl
    {
      Settings                                  settings;
      FE::ElasticMaterial                       material;
      std::unique_ptr<InteractionIntegral<dim>> integral;
      std::vector<std::vector<Point<dim>>>      paths;
      std::vector<Tip<dim>>                     tips;
      std::vector<Mesh::Crack<dim>>             segments;
      std::vector<Mesh::Crack<dim>>             virtual_cracks;
      std::vector<Front<dim>>                   fronts; // 3D

      double
      length_at(const Point<dim> &p) const
      {
        return settings.growth_length_absolute > 0. ?
                 settings.growth_length_absolute :
                 settings.growth_length * integral->element_size(p);
      }

      Assessment
      mcts(Coupling::CoupledSystem<dim>      &system,
           const Coupling::NodalResults<dim> &results,
           bool                               allow_growth);
      Assessment
      principal_stress(Coupling::CoupledSystem<dim>      &system,
                       const Coupling::NodalResults<dim> &results,
                       bool                               allow_growth);
      Assessment
      critical_stretch(Coupling::CoupledSystem<dim>      &system,
                       const Coupling::NodalResults<dim> &results,
                       bool                               allow_growth);
    };

    template <int dim>
    CrackGrowth<dim>::CrackGrowth(
      const Settings                      &settings,
      const FE::ElasticMaterial           &material,
      const std::vector<Mesh::Crack<dim>> &initial_cracks,
      const Coupling::CoupledSystem<dim>  &system,
      const std::vector<bool>             &tip_at_end,
      const bool                           fronts_3d)
      : impl(std::make_unique<Impl>())
    {
      Impl &s    = *impl;
      s.settings = settings;
      s.material = material;
      s.integral = std::make_unique<InteractionIntegral<dim>>(system, material);
      s.segments = initial_cracks;
      if constexpr (dim == 2)
        for (unsigned int c = 0; c < initial_cracks.size(); ++c)
          {
            const auto &p = initial_cracks[c].points;
            s.paths.push_back({p[0], p[1]});
            const double L = p[0].distance(p[1]);
            for (const bool at_end : {false, true})
              {
                if (!tip_at_end.empty() && tip_at_end[c] != at_end)
                  continue;
                Tip<dim> tip;
                tip.crack     = c;
                tip.at_end    = at_end;
                tip.position  = at_end ? p[1] : p[0];
                tip.direction = (at_end ? p[1] - p[0] : p[0] - p[1]) / L;
                if (tip_at_end.empty())
                  {
                    // A tip lies inside the body and touches no other crack.
                    if (!s.integral->inside(tip.position +
                                            1e-6 * L * tip.direction))
                      continue;
                    bool touches = false;
                    for (unsigned int o = 0; o < initial_cracks.size(); ++o)
                      touches =
                        touches ||
                        (o != c &&
                         distance_to_segment(tip.position,
                                             initial_cracks[o].points[0],
                                             initial_cracks[o].points[1]) <=
                           1e-9 * L);
                    if (touches)
                      continue;
                  }
                s.tips.push_back(tip);
              }
          }
      else if (fronts_3d)
        {
          // Front points, both ends included (one: the middle).
          s.fronts = s.integral->straight_fronts(initial_cracks);
          if (s.fronts.empty())
            throw RunFailure("unsupported",
                             "mcts in 3D: no pre-existing crack (triangles) "
                             "has a straight front inside the body");
          const unsigned int n = settings.front_points;
          for (unsigned int f = 0; f < s.fronts.size(); ++f)
            for (unsigned int k = 0; k < n; ++k)
              {
                Tip<dim> tip;
                tip.crack = f;
                tip.s     = s.fronts[f].length() *
                        (n == 1 ? 0.5 : double(k) / double(n - 1));
                tip.position =
                  s.fronts[f].begin + tip.s * s.fronts[f].tangent();
                tip.direction = s.fronts[f].direction;
                s.tips.push_back(tip);
              }
        }
    }

    template <int dim>
    CrackGrowth<dim>::~CrackGrowth() = default;

    template <int dim>
    const FE::ElasticMaterial &
    CrackGrowth<dim>::material() const
    {
      return impl->material;
    }

    template <int dim>
    void
    CrackGrowth<dim>::attach(const Coupling::CoupledSystem<dim> &system)
    {
      impl->integral =
        std::make_unique<InteractionIntegral<dim>>(system, impl->material);
    }

    template <int dim>
    void
    CrackGrowth<dim>::save_state(StateArchive &state) const
    {
      const Impl &s = *impl;
      state.put("cracks/paths", s.paths.size());
      for (std::size_t p = 0; p < s.paths.size(); ++p)
        state.put("cracks/path " + std::to_string(p), s.paths[p]);
      state.put("cracks/tips", s.tips);
      state.put("cracks/segments", s.segments);
      state.put("cracks/virtual cracks", s.virtual_cracks);
      state.put("cracks/fronts", s.fronts);
    }

    template <int dim>
    void
    CrackGrowth<dim>::load_state(const StateArchive &state)
    {
      Impl &s = *impl;
      s.paths.resize(state.get<std::size_t>("cracks/paths"));
      for (std::size_t p = 0; p < s.paths.size(); ++p)
        s.paths[p] =
          state.get_vector<Point<dim>>("cracks/path " + std::to_string(p));
      s.tips     = state.get_vector<Tip<dim>>("cracks/tips");
      s.segments = state.get_vector<Mesh::Crack<dim>>("cracks/segments");
      s.virtual_cracks =
        state.get_vector<Mesh::Crack<dim>>("cracks/virtual cracks");
      s.fronts = state.get_vector<Front<dim>>("cracks/fronts");
    }

    template <int dim>
    Assessment
    CrackGrowth<dim>::grow_at_tips(Coupling::CoupledSystem<dim>      &system,
                                   const Coupling::NodalResults<dim> &results,
                                   const bool allow_growth)
    {
      return impl->mcts(system, results, allow_growth);
    }

    template <int dim>
    Assessment
    CrackGrowth<dim>::grow_by_principal_stress(
      Coupling::CoupledSystem<dim>      &system,
      const Coupling::NodalResults<dim> &results,
      const bool                         allow_growth)
    {
      return impl->principal_stress(system, results, allow_growth);
    }

    template <int dim>
    Assessment
    CrackGrowth<dim>::break_by_stretch(
      Coupling::CoupledSystem<dim>      &system,
      const Coupling::NodalResults<dim> &results,
      const bool                         allow_growth)
    {
      return impl->critical_stretch(system, results, allow_growth);
    }

    template <int dim>
    void
    CrackGrowth<dim>::count_pieces(Assessment                         &a,
                                   const Coupling::CoupledSystem<dim> &system,
                                   const Coupling::NodalResults<dim>  &results)
    {
      if (a.broken_bonds > 0)
        {
          // Pieces smaller than 1 % of the nodes are fragments, not a cut.
          a.pieces =
            system.count_pieces(smallest_piece(results.position.size()));
        }
    }

    template <int dim>
    Assessment
    CrackGrowth<dim>::Impl::mcts(Coupling::CoupledSystem<dim>      &system,
                                 const Coupling::NodalResults<dim> &results,
                                 const bool allow_growth)
    {
      Assessment a;
      a.critical_load_ratio = std::numeric_limits<double>::infinity();
      std::vector<Mesh::Crack<dim>> grown;
      for (Tip<dim> &tip : tips)
        {
          if (!tip.active)
            continue;
          const double h   = integral->element_size(tip.position);
          tip.evaluated_at = tip.position;
          if constexpr (dim == 2)
            tip.sif = integral->compute(results,
                                        tip.position,
                                        tip.direction,
                                        settings.domain_inner_radius * h,
                                        settings.domain_outer_radius * h,
                                        segments);
          else
            tip.sif = integral->compute_front(results,
                                              fronts[tip.crack],
                                              tip.s,
                                              settings.domain_inner_radius * h,
                                              settings.domain_outer_radius * h,
                                              settings.front_half_width * h,
                                              segments);
          std::tie(tip.theta, tip.K_eq) =
            mcts_angle_and_keq(tip.sif.K_I, tip.sif.K_II);
          a.max_driving_value = std::max(a.max_driving_value, tip.K_eq);
          if (tip.K_eq > 0.)
            a.critical_load_ratio =
              std::min(a.critical_load_ratio, settings.toughness / tip.K_eq);
        }
      if (!allow_growth)
        return a;
      if constexpr (dim == 3)
        for (const Tip<dim> &tip : tips)
          if (tip.K_eq > settings.toughness)
            throw RunFailure("unsupported",
                             "K_eq = " + number(tip.K_eq) +
                               " exceeds K_Ic at a 3D crack front point; "
                               "3D fronts do not grow (mcts growth is 2D)");
      if constexpr (dim == 2)
        for (Tip<dim> &tip : tips)
          {
            if (!tip.active || !(tip.K_eq > settings.toughness))
              continue;
            const double       c = std::cos(tip.theta), s = std::sin(tip.theta);
            const Tensor<1, 2> d = tip.direction;
            const Tensor<1, 2> e({c * d[0] - s * d[1], s * d[0] + c * d[1]});
            const Point<2> next = tip.position + length_at(tip.position) * e;
            grown.push_back(Mesh::Crack<2>{{{tip.position, next}}});
            auto &path = paths[tip.crack];
            if (tip.at_end)
              path.push_back(next);
            else
              path.insert(path.begin(), next);
            tip.position  = next;
            tip.direction = e;
            tip.active    = integral->inside(next);
          }
      a.broken_bonds = system.break_bonds(grown);
      segments.insert(segments.end(), grown.begin(), grown.end());
      return a;
    }

    template <int dim>
    Assessment
    CrackGrowth<dim>::Impl::principal_stress(
      Coupling::CoupledSystem<dim>      &system,
      const Coupling::NodalResults<dim> &results,
      const bool                         allow_growth)
    {
      Assessment   a;
      const double strength = settings.tensile_strength;
      // Candidates (stress, k, m) with k < m, this rank's first.
      struct Candidate
      {
        double       stress;
        unsigned int k, m;
        bool
        operator<(const Candidate &o) const
        {
          return stress != o.stress ? stress > o.stress :
                 k != o.k           ? k < o.k :
                                      m < o.m;
        }
      };
      const MPI_Comm comm =
        system.dof_handler().get_triangulation().get_communicator();
      // The largest eigenvalue is convex, so a bond's stress is at most the
      // mean of its nodes' largest principal stresses. A bond whose bound
      // (plus a margin far above round-off) reaches neither the largest
      // stress so far nor the strength can change nothing, and its own
      // eigenvalues are skipped. On the plateCrack inputs 1 bond in 1 100
      // (quasi-static FC2) or in 1 500 (explicit FC2, every step) is left.
      const std::size_t   n_nodes = results.stress.size();
      std::vector<double> half_bound(n_nodes);
      for (std::size_t k = 0; k < n_nodes; ++k)
        half_bound[k] = 0.5 * eigenvalues(results.stress[k])[0] +
                        1e-12 * results.stress[k].norm();
      // The families in chunks on the threads (ThreadTeam::shared()), each
      // member with its own largest stress and candidates: the skip test is
      // safe in any order, and the candidates are sorted below, so the
      // result does not depend on the threads (plateCrack explicit FC2:
      // this loop after every step).
      const PD::Families                 &f        = system.families();
      const std::size_t                   n_owners = f.owners.size();
      constexpr std::size_t               chunk    = 512;
      ThreadTeam                         &team     = ThreadTeam::shared();
      std::vector<std::vector<Candidate>> found(team.size());
      std::vector<double>                 member_largest(team.size(), 0.);
      std::atomic<std::size_t>            next{0};
      team.run([&](const unsigned int member) {
        std::vector<Candidate> &mine      = found[member];
        double                 &largest   = member_largest[member];
        double                  threshold = std::min(largest, strength);
        for (std::size_t first; (first = chunk * next++) < n_owners;)
          for (std::size_t o = first; o < std::min(first + chunk, n_owners);
               ++o)
            {
              const unsigned int k = f.owners[o];
              for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
                {
                  const unsigned int m = f.members[b];
                  if (!f.intact[b] ||
                      half_bound[k] + half_bound[m] <= threshold)
                    continue;
                  const double s1 = eigenvalues(
                    0.5 * (results.stress[k] + results.stress[m]))[0];
                  if (s1 > largest)
                    {
                      largest   = s1;
                      threshold = std::min(largest, strength);
                    }
                  if (s1 > strength)
                    mine.push_back({s1, std::min(k, m), std::max(k, m)});
                }
            }
      });
      double largest =
        *std::max_element(member_largest.begin(), member_largest.end());
      std::vector<Candidate> mine = std::move(found[0]);
      for (std::size_t i = 1; i < found.size(); ++i)
        mine.insert(mine.end(), found[i].begin(), found[i].end());
      largest               = Utilities::MPI::max(largest, comm);
      a.max_driving_value   = largest;
      a.critical_load_ratio = largest > 0. ?
                                strength / largest :
                                std::numeric_limits<double>::infinity();
      if (!allow_growth)
        return a;

      // Ties: a symmetric specimen has bonds of equal stress, equal only up
      // to round-off that differs with the number of ranks. Stresses equal
      // to 1e-9 of the largest rank as equal, and the node numbers (the
      // same on any number of ranks) decide, so that every run cuts the
      // same bonds. Each rank keeps its own Top K, then all ranks the Top K
      // of those.
      const double quantum = 1e-9 * largest;
      const auto   top_k   = [&](std::vector<Candidate> &c) {
        for (Candidate &x : c)
          x.stress = quantum * std::round(x.stress / quantum);
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(),
                            c.end(),
                            [](const Candidate &x, const Candidate &y) {
                              return x.k == y.k && x.m == y.m;
                            }),
                c.end());
        if (settings.top_k > 0 && c.size() > settings.top_k)
          c.resize(settings.top_k);
      };
      top_k(mine);
      std::vector<double> packed;
      for (const Candidate &c : mine)
        packed.insert(packed.end(), {c.stress, double(c.k), double(c.m)});
      std::vector<Candidate> all;
      for (const auto &part : Utilities::MPI::all_gather(comm, packed))
        for (std::size_t i = 0; i + 2 < part.size(); i += 3)
          all.push_back({part[i],
                         static_cast<unsigned int>(part[i + 1]),
                         static_cast<unsigned int>(part[i + 2])});
      top_k(all);

      std::vector<Mesh::Crack<dim>> cracks;
      for (const Candidate &c : all)
        {
          const auto mean  = 0.5 * (results.stress[c.k] + results.stress[c.m]);
          const auto pairs = eigenvectors(mean);
          const Point<dim> center =
            Point<dim>(0.5 * (results.position[c.k] + results.position[c.m]));
          add_virtual_crack(center, pairs[0].second, length_at(center), cracks);
        }
      a.broken_bonds = system.break_bonds(cracks);
      segments.insert(segments.end(), cracks.begin(), cracks.end());
      virtual_cracks.insert(virtual_cracks.end(), cracks.begin(), cracks.end());
      return a;
    }

    template <int dim>
    Assessment
    CrackGrowth<dim>::Impl::critical_stretch(
      Coupling::CoupledSystem<dim>      &system,
      const Coupling::NodalResults<dim> &results,
      const bool                         allow_growth)
    {
      // s_c given, or from G_c by the bond-based energy release through a
      // crack plane (Silling & Askari 2005 in 3D; Ha & Bobaru 2010 in plane
      // stress): an approximation for PDLSM, whose bonds carry no energy
      // of their own.
      const double               E        = material.youngs_modulus;
      const double               nu       = material.poissons_ratio;
      const double               K        = E / (3. * (1. - 2. * nu));
      const std::vector<double> &delta    = system.horizons();
      const auto                 critical = [&](const unsigned int k) {
        if (settings.critical_stretch > 0.)
          return settings.critical_stretch;
        const double G = settings.fracture_energy;
        return dim == 2 ? std::sqrt(4. * M_PI * G / (9. * E * delta[k])) :
                                          std::sqrt(5. * G / (9. * K * delta[k]));
      };
      const auto stretch = [&](const unsigned int k, const unsigned int m) {
        const Tensor<1, dim> xi = results.position[m] - results.position[k];
        const Tensor<1, dim> eta =
          results.displacement[m] - results.displacement[k];
        return ((xi + eta).norm() - xi.norm()) / xi.norm();
      };
      const MPI_Comm comm =
        system.dof_handler().get_triangulation().get_communicator();
      double              ratio = 0.; // the largest stretch / critical one
      const PD::Families &f     = system.families();
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        for (std::size_t b = f.offsets[o]; b < f.offsets[o + 1]; ++b)
          if (f.intact[b])
            ratio = std::max(ratio,
                             stretch(f.owners[o], f.members[b]) /
                               critical(f.owners[o]));
      Assessment a;
      a.max_driving_value   = Utilities::MPI::max(ratio, comm);
      a.critical_load_ratio = a.max_driving_value > 0. ?
                                1. / a.max_driving_value :
                                std::numeric_limits<double>::infinity();
      if (allow_growth)
        a.broken_bonds = system.break_bonds_if(
          [&](const unsigned int k, const unsigned int m) {
            return stretch(k, m) > critical(k);
          });
      return a;
    }

    template <int dim>
    const std::vector<Tip<dim>> &
    CrackGrowth<dim>::tips() const
    {
      return impl->tips;
    }

    template <int dim>
    const std::vector<Mesh::Crack<dim>> &
    CrackGrowth<dim>::segments() const
    {
      return impl->segments;
    }

    template <int dim>
    const std::vector<std::vector<Point<dim>>> &
    CrackGrowth<dim>::paths() const
    {
      return impl->paths;
    }

    template <int dim>
    void
    CrackGrowth<dim>::write_paths(const std::string &vtk_file,
                                  const std::string &csv_file) const
    {
      const Impl &s = *impl;
      // Polylines: the paths (2D), then every segment that is not on a path
      // (virtual cracks; 3D: every crack triangle).
      std::vector<std::vector<Point<dim>>> lines = s.paths;
      if constexpr (dim == 2)
        for (const auto &c : s.virtual_cracks)
          lines.push_back({c.points[0], c.points[1]});
      else
        for (const auto &c : s.segments)
          lines.push_back({c.points[0], c.points[1], c.points[2], c.points[0]});
      std::size_t n_points = 0;
      for (const auto &l : lines)
        n_points += l.size();

      std::ofstream vtk(vtk_file);
      vtk << std::setprecision(10);
      vtk << "# vtk DataFile Version 3.0\npdfem crack paths\nASCII\n"
          << "DATASET POLYDATA\nPOINTS " << n_points << " double\n";
      for (const auto &l : lines)
        for (const auto &p : l)
          vtk << p[0] << ' ' << p[1] << ' ' << (dim == 3 ? p[dim - 1] : 0.)
              << '\n';
      vtk << "LINES " << lines.size() << ' ' << n_points + lines.size() << '\n';
      std::size_t next = 0;
      for (const auto &l : lines)
        {
          vtk << l.size();
          for (std::size_t i = 0; i < l.size(); ++i)
            vtk << ' ' << next++;
          vtk << '\n';
        }
      vtk << "CELL_DATA " << lines.size() << "\nSCALARS virtual int 1\n"
          << "LOOKUP_TABLE default\n";
      for (std::size_t i = 0; i < lines.size(); ++i)
        vtk << (i < s.paths.size() ? 0 : 1) << '\n';

      std::ofstream csv(csv_file);
      csv << std::setprecision(10) << "crack,point,x,y"
          << (dim == 3 ? ",z" : "") << '\n';
      for (std::size_t c = 0; c < s.paths.size(); ++c)
        for (std::size_t i = 0; i < s.paths[c].size(); ++i)
          {
            csv << c << ',' << i;
            for (unsigned int d = 0; d < dim; ++d)
              csv << ',' << s.paths[c][i][d];
            csv << '\n';
          }
    }

    template <int dim>
    unsigned int
    extend_pd_region(const Triangulation<dim, dim>       &tria,
                     const std::vector<Mesh::Crack<dim>> &cracks,
                     const double                         margin,
                     std::vector<bool>                   &cell_is_pd)
    {
      unsigned int changed = 0;
      if (!(margin > 0.))
        return 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          const unsigned int i = cell->active_cell_index();
          if (cell_is_pd[i])
            continue;
          const Point<dim> center = cell->center();
          const double     reach  = margin_reach(cell, margin);
          for (const auto &crack : cracks)
            if (distance_to_crack(center, crack) <= reach)
              {
                cell_is_pd[i] = true;
                ++changed;
                break;
              }
        }
      return changed;
    }

#define INSTANTIATE(dim)                       \
  template class CrackGrowth<dim>;             \
  template unsigned int extend_pd_region<dim>( \
    const Triangulation<dim, dim> &,           \
    const std::vector<Mesh::Crack<dim>> &,     \
    double,                                    \
    std::vector<bool> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Fracture
} // namespace pdfem
