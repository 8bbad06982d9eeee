// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/fracture/interaction_integral.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>

#include "williams_fields.h"

namespace pdfem
{
  namespace Fracture
  {
    using namespace dealii;
    using namespace internal;

    namespace
    {
      /// Even-odd test of @p p against the polygon @p v.
      bool
      inside_polygon(const std::vector<Point<2>> &v, const Point<2> &p)
      {
        bool in = false;
        for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
          if ((v[i][1] > p[1]) != (v[j][1] > p[1]) &&
              p[0] <
                (v[j][0] - v[i][0]) * (p[1] - v[i][1]) / (v[j][1] - v[i][1]) +
                  v[i][0])
            in = !in;
        return in;
      }
    } // namespace

    template <int dim>
    struct InteractionIntegral<dim>::Impl
    {
      const Coupling::CoupledSystem<dim> &system;
      FE::ElasticMaterial                 material;
      hp::FECollection<dim>               fe;
      hp::QCollection<dim>                quadrature;
      hp::QCollection<dim - 1>            face_quadrature;
      std::vector<Point<dim>>             center;
      std::vector<double>                 radius, size;
      std::vector<bool>                   pd;
      std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;

      /// The cell whose outline contains @p p, or -1.
      int
      find_cell(const Point<dim> &p) const
      {
        for (std::size_t c = 0; c < cells.size(); ++c)
          {
            if (p.distance(center[c]) > radius[c] * (1. + 1e-12))
              continue;
            if constexpr (dim == 2)
              {
                const auto            &cell = cells[c];
                std::vector<Point<2>>  outline;
                const std::vector<int> quad = {0, 1, 3, 2};
                const unsigned int     n    = cell->n_vertices();
                for (unsigned int i = 0; i < n; ++i)
                  outline.push_back(cell->vertex(n == 4 ? quad[i] : i));
                if (inside_polygon(outline, p))
                  return c;
              }
            else
              {
                // Tolerant: a point on a face between two cells may fall
                // outside both by round-off (deal.II's point_inside()).
                const ReferenceCell reference = cells[c]->reference_cell();
                if (!reference.is_hyper_cube())
                  {
                    if (p.distance(center[c]) <= 0.5 * radius[c])
                      return c;
                    continue;
                  }
                try
                  {
                    const Point<dim> unit =
                      reference.template get_default_linear_mapping<dim>()
                        .transform_real_to_unit_cell(cells[c], p);
                    if (reference.contains_point(unit, 1e-10))
                      return c;
                  }
                catch (...)
                  {
                    // the inverse map failed: p is far outside this cell
                  }
              }
          }
        return -1;
      }
    };

    template <int dim>
    InteractionIntegral<dim>::InteractionIntegral(
      const Coupling::CoupledSystem<dim> &system,
      const FE::ElasticMaterial          &material)
      : impl(std::make_unique<Impl>(
          Impl{system, material, {}, {}, {}, {}, {}, {}, {}, {}}))
    {
      Impl &s = *impl;
      // In the order of the system's collections (its mapping's): one
      // element per kind of cell its mesh has.
      for (const auto &element : system.node_dof_handler().get_fe_collection())
        if (element.reference_cell().is_hyper_cube())
          {
            s.fe.push_back(FE_Q<dim>(1));
            s.quadrature.push_back(QGauss<dim>(4));
            s.face_quadrature.push_back(QGauss<dim - 1>(4));
          }
        else
          {
            s.fe.push_back(FE_SimplexP<dim>(1));
            s.quadrature.push_back(QGaussSimplex<dim>(3));
            s.face_quadrature.push_back(QGaussSimplex<dim - 1>(3));
          }
      for (const auto &cell : system.node_dof_handler().active_cell_iterators())
        {
          s.cells.push_back(cell);
          s.center.push_back(cell->center());
          double r = 0.;
          for (const unsigned int v : cell->vertex_indices())
            r = std::max(r, cell->vertex(v).distance(cell->center()));
          s.radius.push_back(r);
          s.size.push_back(std::pow(cell->measure(), 1. / dim));
          s.pd.push_back(system.cell_is_pd()[cell->active_cell_index()]);
        }
    }

    template <int dim>
    InteractionIntegral<dim>::~InteractionIntegral() = default;

    template <int dim>
    double
    InteractionIntegral<dim>::element_size(const Point<dim> &p) const
    {
      const Impl &s    = *impl;
      std::size_t best = 0;
      for (std::size_t c = 1; c < s.cells.size(); ++c)
        if (p.distance(s.center[c]) < p.distance(s.center[best]))
          best = c;
      return s.size[best];
    }

    template <int dim>
    bool
    InteractionIntegral<dim>::inside(const Point<dim> &p) const
    {
      return impl->find_cell(p) >= 0;
    }

    template <int dim>
    bool
    InteractionIntegral<dim>::inside_pd_region(const Point<dim> &p) const
    {
      const int c = impl->find_cell(p);
      return c >= 0 && impl->pd[c];
    }

    namespace
    {
      /// Distance from @p p to a crack (segment; triangle: its vertices and
      /// edges as segments, enough to keep the cracks near a domain).
      template <int dim>
      double
      rough_distance(const Point<dim> &p, const Mesh::Crack<dim> &crack)
      {
        double d = std::numeric_limits<double>::max();
        for (unsigned int i = 0; i < dim; ++i)
          {
            const Point<dim>    &a  = crack.points[i];
            const Point<dim>    &b  = crack.points[(i + 1) % dim];
            const Tensor<1, dim> ab = b - a;
            const double         L2 = ab.norm_square();
            const double         t =
              L2 > 0. ? std::clamp((p - a) * ab / L2, 0., 1.) : 0.;
            d = std::min(d, p.distance(a + t * ab));
          }
        return d;
      }

      /// Whether the bounding box of @p crack meets that of the ball
      /// (@p center, @p radius): false only if the crack misses the ball.
      template <int dim>
      bool
      meets_ball(const Mesh::Crack<dim> &crack,
                 const Point<dim>       &center,
                 const double            radius)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            double lo = crack.points[0][d], hi = lo;
            for (unsigned int i = 1; i < dim; ++i)
              {
                lo = std::min(lo, crack.points[i][d]);
                hi = std::max(hi, crack.points[i][d]);
              }
            if (lo > center[d] + radius || hi < center[d] - radius)
              return false;
          }
        return true;
      }

      /// The bump q_s(d) = cos^2(pi d / 2w) for |d| < w (eq. 9.4) and its
      /// derivative.
      std::pair<double, double>
      bump(const double d, const double w)
      {
        if (std::abs(d) >= w)
          return {0., 0.};
        const double a = 0.5 * M_PI / w;
        return {std::cos(a * d) * std::cos(a * d), -a * std::sin(2. * a * d)};
      }

      /// int_lo^hi q_s(d) dd, the virtual crack advance area (eq. 9.5).
      double
      bump_integral(double lo, double hi, const double w)
      {
        lo = std::max(lo, -w);
        hi = std::min(hi, w);
        if (!(hi > lo))
          return 0.;
        const auto F = [w](const double d) {
          return 0.5 * d + w / (2. * M_PI) * std::sin(M_PI * d / w);
        };
        return F(hi) - F(lo);
      }
    } // namespace

    template <int dim>
    Tensor<1, dim>
    Front<dim>::tangent() const
    {
      const Tensor<1, dim> t = end - begin;
      return t.norm() > 0. ? t / t.norm() : Tensor<1, dim>();
    }

    template <int dim>
    double
    Front<dim>::length() const
    {
      return begin.distance(end);
    }

    template <int dim>
    StressIntensity
    InteractionIntegral<dim>::compute(
      const Coupling::NodalResults<dim>   &results,
      const Point<dim>                    &tip,
      const Tensor<1, dim>                &direction,
      const double                         r_in,
      const double                         r_out,
      const std::vector<Mesh::Crack<dim>> &cracks) const
    {
      if constexpr (dim != 2)
        {
          (void)results;
          (void)tip;
          (void)direction;
          (void)r_in;
          (void)r_out;
          (void)cracks;
          throw RunFailure("unsupported",
                           "3D crack fronts: use compute_front()");
        }
      else
        return compute_front(results,
                             Front<dim>{tip, tip, direction},
                             0.,
                             r_in,
                             r_out,
                             0.,
                             cracks);
    }

    template <int dim>
    StressIntensity
    InteractionIntegral<dim>::compute_front(
      const Coupling::NodalResults<dim>   &results,
      const Front<dim>                    &front,
      const double                         s_k,
      const double                         r_in,
      const double                         r_out,
      const double                         w,
      const std::vector<Mesh::Crack<dim>> &cracks) const
    {
      const Impl  &s  = *impl;
      const double E  = s.material.youngs_modulus;
      const double nu = s.material.poissons_ratio;
      const double mu = s.material.mu();
      // 2D: the law in use (lambda* in plane stress); 3D: plane-strain
      // auxiliary fields with the 3D law (eq. 9.7).
      const double lambda =
        dim == 2 ? s.material.lambda() : E * nu / ((1. + nu) * (1. - 2. * nu));
      const bool   pstress = dim == 2 && s.material.plane_stress;
      const double kappa   = pstress ? (3. - nu) / (1. + nu) : 3. - 4. * nu;
      const double E_prime = pstress ? E : E / (1. - nu * nu);

      // Front axes: row 0 = e1 (ahead of the crack), row 1 = e2, [row 2 =
      // e3 along the front].
      const Tensor<1, dim> e1 = front.direction / front.direction.norm();
      Tensor<2, dim>       R;
      Point<dim>           origin = front.begin;
      if constexpr (dim == 2)
        {
          R[0][0] = e1[0];
          R[0][1] = e1[1];
          R[1][0] = -e1[1];
          R[1][1] = e1[0];
        }
      else
        {
          Tensor<1, 3> e3 = front.tangent();
          e3 -= (e3 * e1) * e1; // exactly normal to e1
          e3 /= e3.norm();
          const Tensor<1, 3> e2 = cross_product_3d(e3, e1);
          for (unsigned int j = 0; j < 3; ++j)
            {
              R[0][j] = e1[j];
              R[1][j] = e2[j];
              R[2][j] = e3[j];
            }
          origin = front.begin + s_k * front.tangent();
        }
      // The front's ends in x3 from s_k, and the virtual crack advance area
      // int q_s ds over the front (eq. 9.5; 1 in 2D).
      const double s_lo = -s_k, s_hi = front.length() - s_k;
      const double advance = dim == 2 ? 1. : bump_integral(s_lo, s_hi, w);
      const double reach   = dim == 2 ? r_out : std::hypot(r_out, w);

      const auto hooke = [&](const Tensor<2, dim> &g) {
        const SymmetricTensor<2, dim> eps = symmetrize(g);
        return SymmetricTensor<2, dim>(
          lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2. * mu * eps);
      };

      // Only the crack pieces near the domain can hide a vertex; per cell,
      // those near the cell (near_cell).
      std::vector<Mesh::Crack<dim>> near;
      for (const auto &crack : cracks)
        if (rough_distance(origin, crack) <= 2. * reach)
          near.push_back(crack);

      // grad u^M (in front axes) at a point xl in front axes, mode M = 0, 1
      // (plane Williams fields), 2 (mode III: u_3 = 2/mu sqrt(r/2pi)
      // sin(theta/2), eq. 9.7).
      const auto auxiliary = [&](const Tensor<1, dim> &xl,
                                 const unsigned int    mode) {
        Tensor<2, dim> Ga;
        if (mode < 2)
          {
            const Tensor<2, 2> g =
              williams_gradient(Point<2>(xl[0], xl[1]), mode, kappa, mu);
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                Ga[i][j] = g[i][j];
          }
        else if constexpr (dim == 3)
          {
            const Tensor<1, 2> g =
              mode_iii_gradient(Point<2>(xl[0], xl[1]), mu);
            for (unsigned int j = 0; j < 2; ++j)
              Ga[2][j] = g[j];
          }
        return Ga;
      };
      constexpr unsigned int n_modes = dim == 2 ? 2 : 3;

      const std::vector<unsigned int> &node_of_dof =
        s.system.node_of_scalar_dof();
      /// A thread's FEValues, its cell's DoFs and crack pieces.
      struct Workspace
      {
        hp::FEValues<dim>                    fe_values;
        hp::FEFaceValues<dim>                face_values;
        std::vector<types::global_dof_index> dofs;
        std::vector<Mesh::Crack<dim>>        near_cell;
      };
      /// A cell's share of I^(M), M = 0, 1, 2, and of J.
      using Share = std::array<double, 4>;

      // Adds P_j v_j dx at the point q of fv (cell c): P_j the integrand of
      // J and I^(M) (eq. 9.1, 9.2, 9.6, 9.7), v (front axes) = grad q in the
      // volume, -q n on the body's surface.
      const auto add = [&](const Workspace         &ws,
                           Share                   &share,
                           const FEValuesBase<dim> &fv,
                           const unsigned int       q,
                           const std::size_t        c,
                           const Tensor<1, dim>    &xl,
                           const Tensor<1, dim>    &v,
                           const double             dx) {
        const auto       &dofs = ws.dofs;
        const Point<dim> &xq   = fv.quadrature_point(q);
        // grad u at the point, in global axes
        Tensor<2, dim> G;
        if (!s.pd[c])
          for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
            G += outer_product(results.displacement[node_of_dof[dofs[i]]],
                               fv.shape_grad(i, q));
        else
          {
            double weight = 0.;
            for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
              {
                const unsigned int k = node_of_dof[dofs[i]];
                if (Mesh::cut_by_any(ws.near_cell, xq, results.position[k]))
                  continue;
                weight += fv.shape_value(i, q);
                G += fv.shape_value(i, q) * results.displacement_gradient[k];
              }
            if (!(weight > 1e-3))
              return; // a point no vertex sees: no field
            G /= weight;
          }
        const Tensor<2, dim>          Gl    = R * G * transpose(R);
        const SymmetricTensor<2, dim> sigma = hooke(Gl);

        // J: (sigma_ij u_i,1 - W delta_1j) v_j
        const double W = 0.5 * (sigma * symmetrize(Gl));
        for (unsigned int j = 0; j < dim; ++j)
          {
            double a = 0.;
            for (unsigned int i = 0; i < dim; ++i)
              a += sigma[i][j] * Gl[i][0];
            share[3] += (a - (j == 0 ? W : 0.)) * v[j] * dx;
          }
        // I^(M)
        for (unsigned int mode = 0; mode < n_modes; ++mode)
          {
            const Tensor<2, dim>          Ga      = auxiliary(xl, mode);
            const SymmetricTensor<2, dim> sigma_a = hooke(Ga);
            const double                  W12     = sigma * symmetrize(Ga);
            for (unsigned int j = 0; j < dim; ++j)
              {
                double a = 0.;
                for (unsigned int i = 0; i < dim; ++i)
                  a += sigma[i][j] * Ga[i][0] + sigma_a[i][j] * Gl[i][0];
                share[mode] += (a - (j == 0 ? W12 : 0.)) * v[j] * dx;
              }
          }
      };

      // The cells that reach into the domain r_in < r < r_out, |x3| < w.
      std::vector<std::size_t> domain;
      for (std::size_t c = 0; c < s.cells.size(); ++c)
        {
          const Tensor<1, dim> xc = R * (s.center[c] - origin);
          const double         rc = std::hypot(xc[0], xc[1]);
          if (rc - s.radius[c] >= r_out || rc + s.radius[c] <= r_in)
            continue;
          if (dim == 3 && std::abs(xc[dim - 1]) - s.radius[c] >= w)
            continue;
          domain.push_back(c);
        }

      // Adds cell c's share (volume and, in 3D, surface terms).
      const auto integrate_cell =
        [&](Workspace &ws, const std::size_t c, Share &share) {
          const auto &cell = s.cells[c];
          // A crack piece that hides a vertex from a point of the cell
          // meets the cell's ball.
          ws.near_cell.clear();
          if (s.pd[c])
            for (const auto &crack : near)
              if (meets_ball(crack, s.center[c], s.radius[c]))
                ws.near_cell.push_back(crack);
          ws.fe_values.reinit(cell);
          const FEValues<dim> &fv = ws.fe_values.get_present_fe_values();
          ws.dofs.resize(fv.dofs_per_cell);
          cell->get_dof_indices(ws.dofs);
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            {
              const Tensor<1, dim> xl = R * (fv.quadrature_point(q) - origin);
              const double         r  = std::hypot(xl[0], xl[1]);
              if (r <= r_in || r >= r_out)
                continue;
              // q = q_r(r) q_s(x3): q_r = 1 - smoothstep((r - r_in) /
              // (r_out - r_in)) (eq. 9.3), q_s the bump (eq. 9.4).
              double qs = 1., dqs = 0.;
              if constexpr (dim == 3)
                {
                  std::tie(qs, dqs) = bump(xl[2], w);
                  if (qs == 0. && dqs == 0.)
                    continue;
                }
              const double   t   = std::max(0., (r - r_in) / (r_out - r_in));
              const double   qr  = 1. - t * t * (3. - 2. * t);
              const double   dqr = -6. * t * (1. - t) / (r_out - r_in);
              Tensor<1, dim> dq; // front axes
              dq[0] = dqr * xl[0] / r * qs;
              dq[1] = dqr * xl[1] / r * qs;
              if constexpr (dim == 3)
                dq[2] = qr * dqs;
              add(ws, share, fv, q, c, xl, dq, fv.JxW(q));
            }

          // 3D: where q does not vanish on the body's surface (the faces
          // that the front ends on), the surface term -int P_j n_j q dS of
          // the divergence theorem (eq. 9.6), for r_in < r < r_out like the
          // volume term: inside r_in both are left out (their sum is
          // -int P_3,3 q_s dV, zero for fields that do not vary along the
          // front, and the nonlocal fields there are smeared). 2D domains
          // are kept off the surface.
          if constexpr (dim == 3)
            for (const unsigned int f : cell->face_indices())
              {
                if (!cell->face(f)->at_boundary())
                  continue;
                ws.face_values.reinit(cell, f);
                const FEFaceValues<dim> &ffv =
                  ws.face_values.get_present_fe_values();
                for (unsigned int q = 0; q < ffv.n_quadrature_points; ++q)
                  {
                    const Tensor<1, dim> xl =
                      R * (ffv.quadrature_point(q) - origin);
                    const double r = std::hypot(xl[0], xl[1]);
                    if (r <= r_in || r >= r_out)
                      continue;
                    const double t = (r - r_in) / (r_out - r_in);
                    const double qv =
                      (1. - t * t * (3. - 2. * t)) * bump(xl[2], w).first;
                    if (qv == 0.)
                      continue;
                    add(ws,
                        share,
                        ffv,
                        q,
                        c,
                        xl,
                        -qv * (R * ffv.normal_vector(q)),
                        ffv.JxW(q));
                  }
              }
        };

      // The cells on the threads, each cell's share summed in a fixed order
      // below: the same K on any number of threads. The mixed-mode scenes
      // of fracture.md (two tips, ~300 cells each) spent 0.12 s of their
      // 1.6 s here on one thread; with two threads (and the duals' one
      // evaluation per point) their criterion took 0.11-0.13 s instead of
      // 0.16-0.20 s.
      std::vector<Share>                      shares(domain.size(), Share{});
      ThreadTeam                             &team = ThreadTeam::shared();
      std::vector<std::unique_ptr<Workspace>> workspaces(team.size());
      std::atomic<std::size_t>                next{0};
      team.run([&](const unsigned int member) {
        for (std::size_t i; (i = next++) < domain.size();)
          {
            if (!workspaces[member])
              workspaces[member] = std::make_unique<Workspace>(
                Workspace{hp::FEValues<dim>(s.system.mapping(),
                                            s.fe,
                                            s.quadrature,
                                            update_values | update_gradients |
                                              update_quadrature_points |
                                              update_JxW_values),
                          hp::FEFaceValues<dim>(s.system.mapping(),
                                                s.fe,
                                                s.face_quadrature,
                                                update_values |
                                                  update_gradients |
                                                  update_quadrature_points |
                                                  update_normal_vectors |
                                                  update_JxW_values),
                          {},
                          {}});
            integrate_cell(*workspaces[member], domain[i], shares[i]);
          }
      });
      double I[3] = {0., 0., 0.}, J = 0.;
      for (const Share &share : shares)
        {
          for (unsigned int m = 0; m < 3; ++m)
            I[m] += share[m];
          J += share[3];
        }
      StressIntensity k;
      if (!(advance > 0.))
        return k;
      k.K_I  = 0.5 * E_prime * I[0] / advance;
      k.K_II = 0.5 * E_prime * I[1] / advance;
      if (dim == 3)
        k.K_III = mu * I[2] / advance;
      k.J = J / advance;
      return k;
    }

    template <int dim>
    std::vector<Front<dim>>
    InteractionIntegral<dim>::straight_fronts(
      const std::vector<Mesh::Crack<dim>> &cracks) const
    {
      std::vector<Front<dim>> fronts;
      if constexpr (dim == 3)
        {
          // Vertices merged within a tolerance of the crack size.
          double size = 0.;
          for (const auto &c : cracks)
            for (unsigned int i = 0; i < 3; ++i)
              size =
                std::max(size, c.points[i].distance(c.points[(i + 1) % 3]));
          const double          tol = 1e-9 * size;
          std::vector<Point<3>> vertex;
          const auto            id = [&](const Point<3> &p) {
            for (unsigned int v = 0; v < vertex.size(); ++v)
              if (vertex[v].distance(p) <= tol)
                return v;
            vertex.push_back(p);
            return static_cast<unsigned int>(vertex.size() - 1);
          };
          // Edges (a < b) with their triangles.
          struct Edge
          {
            unsigned int a, b, triangle, count;
          };
          std::vector<Edge> edges;
          for (unsigned int t = 0; t < cracks.size(); ++t)
            for (unsigned int i = 0; i < 3; ++i)
              {
                unsigned int a = id(cracks[t].points[i]),
                             b = id(cracks[t].points[(i + 1) % 3]);
                if (a > b)
                  std::swap(a, b);
                auto e = std::find_if(edges.begin(), edges.end(), [&](auto &x) {
                  return x.a == a && x.b == b;
                });
                if (e == edges.end())
                  edges.push_back({a, b, t, 1});
                else
                  ++e->count;
              }
          // Boundary edges whose outside is inside the body: front pieces.
          std::vector<Front<3>> pieces;
          for (const Edge &e : edges)
            {
              if (e.count != 1)
                continue;
              const auto    &tri = cracks[e.triangle].points;
              const Point<3> A = vertex[e.a], B = vertex[e.b];
              const Point<3> mid = 0.5 * (A + B);
              const Point<3> centroid((tri[0] + tri[1] + tri[2]) / 3.);
              Tensor<1, 3>   t = (B - A) / A.distance(B);
              Tensor<1, 3>   n = mid - centroid;
              n -= (n * t) * t; // in the plane, normal to the edge, outwards
              if (!(n.norm() > 0.))
                continue;
              n /= n.norm();
              if (!inside(mid + 1e-6 * size * n) ||
                  !inside(mid - 1e-6 * size * n))
                continue;
              // Orient x3 by its largest component (deterministic).
              unsigned int big = 0;
              for (unsigned int j = 1; j < 3; ++j)
                if (std::abs(t[j]) > std::abs(t[big]) * (1. + 1e-12))
                  big = j;
              pieces.push_back(t[big] > 0. ? Front<3>{A, B, n} :
                                             Front<3>{B, A, n});
            }
          // Join pieces that continue each other on a line (same x1).
          std::vector<bool> used(pieces.size(), false);
          for (std::size_t p = 0; p < pieces.size(); ++p)
            {
              if (used[p])
                continue;
              used[p]          = true;
              Front<3>   f     = pieces[p];
              const auto along = [&](const Front<3> &o) {
                const Tensor<1, 3> t   = f.tangent();
                const auto         off = [&](const Point<3> &x) {
                  const Tensor<1, 3> d = x - f.begin;
                  return (d - (d * t) * t).norm();
                };
                return (o.direction - f.direction).norm() <= 1e-6 &&
                       off(o.begin) <= tol && off(o.end) <= tol;
              };
              for (bool grew = true; grew;)
                {
                  grew = false;
                  for (std::size_t o = 0; o < pieces.size(); ++o)
                    if (!used[o] && along(pieces[o]))
                      {
                        if (pieces[o].begin.distance(f.end) <= tol)
                          f.end = pieces[o].end;
                        else if (pieces[o].end.distance(f.begin) <= tol)
                          f.begin = pieces[o].begin;
                        else
                          continue;
                        used[o] = true;
                        grew    = true;
                      }
                }
              // Clip the front to the body (triangles may reach beyond
              // it): bisection from the midpoint, which is inside.
              const Point<3> mid = 0.5 * (f.begin + f.end);
              for (Point<3> *e : {&f.begin, &f.end})
                if (!inside(*e))
                  {
                    Point<3> in = mid, out = *e;
                    for (unsigned int i = 0; i < 60; ++i)
                      {
                        const Point<3> m       = 0.5 * (in + out);
                        (inside(m) ? in : out) = m;
                      }
                    *e = in;
                  }
              fronts.push_back(f);
            }
        }
      else
        (void)cracks;
      return fronts;
    }

#define INSTANTIATE(dim)      \
  template struct Front<dim>; \
  template class InteractionIntegral<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Fracture
} // namespace pdfem
