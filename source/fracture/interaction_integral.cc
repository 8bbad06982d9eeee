// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/fracture/interaction_integral.h>

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

#include <algorithm>
#include <cmath>

namespace pdfem
{
  namespace Fracture
  {
    using namespace dealii;

    namespace
    {
      /// A forward-mode dual number: value and one derivative.
      struct Dual
      {
        double v = 0., d = 0.;
      };
      Dual
      operator+(Dual a, Dual b)
      {
        return {a.v + b.v, a.d + b.d};
      }
      Dual
      operator-(Dual a, Dual b)
      {
        return {a.v - b.v, a.d - b.d};
      }
      Dual
      operator*(Dual a, Dual b)
      {
        return {a.v * b.v, a.d * b.v + a.v * b.d};
      }
      Dual
      operator*(double s, Dual a)
      {
        return {s * a.v, s * a.d};
      }
      Dual
      operator+(double s, Dual a)
      {
        return {s + a.v, a.d};
      }
      Dual
      sqrt(Dual a)
      {
        const double r = std::sqrt(a.v);
        return {r, a.d / (2. * r)};
      }
      Dual
      sin(Dual a)
      {
        return {std::sin(a.v), std::cos(a.v) * a.d};
      }
      Dual
      cos(Dual a)
      {
        return {std::cos(a.v), -std::sin(a.v) * a.d};
      }
      Dual
      atan2(Dual y, Dual x)
      {
        const double r2 = x.v * x.v + y.v * y.v;
        return {std::atan2(y.v, x.v), (x.v * y.d - y.v * x.d) / r2};
      }

      /**
       * Williams near-tip displacement of unit K_I (mode 0) or K_II (mode 1)
       * at (x1, x2) in tip axes (Anderson, Fracture Mechanics, Table 2.2).
       */
      std::array<Dual, 2>
      williams_displacement(const Dual         x1,
                            const Dual         x2,
                            const unsigned int mode,
                            const double       kappa,
                            const double       mu)
      {
        const Dual r     = sqrt(x1 * x1 + x2 * x2);
        const Dual theta = atan2(x2, x1);
        const Dual f     = (1. / (2. * mu * std::sqrt(2. * M_PI))) * sqrt(r);
        const Dual s = sin(0.5 * theta), c = cos(0.5 * theta);
        if (mode == 0)
          return {{f * c * ((kappa - 1.) + 2. * s * s),
                   f * s * ((kappa + 1.) + (-2.) * c * c)}};
        return {{f * s * ((kappa + 1.) + 2. * c * c),
                 (-1.) * f * c * ((kappa - 1.) + (-2.) * s * s)}};
      }

      /// grad u^aux (component i, direction j) in tip axes.
      Tensor<2, 2>
      williams_gradient(const Point<2>    &x,
                        const unsigned int mode,
                        const double       kappa,
                        const double       mu)
      {
        Tensor<2, 2> g;
        for (unsigned int j = 0; j < 2; ++j)
          {
            const Dual x1{x[0], j == 0 ? 1. : 0.};
            const Dual x2{x[1], j == 1 ? 1. : 0.};
            const auto u = williams_displacement(x1, x2, mode, kappa, mu);
            g[0][j]      = u[0].d;
            g[1][j]      = u[1].d;
          }
        return g;
      }

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
      const Coupling::CoupledSystem<dim>                         &system;
      FE::ElasticMaterial                                         material;
      hp::FECollection<dim>                                       fe;
      hp::QCollection<dim>                                        quadrature;
      std::vector<Point<dim>>                                     center;
      std::vector<double>                                         radius, size;
      std::vector<bool>                                           pd;
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
                if (cells[c]->reference_cell().is_hyper_cube() ?
                      cells[c]->point_inside(p) :
                      p.distance(center[c]) <= 0.5 * radius[c])
                  return c;
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
          Impl{system, material, {}, {}, {}, {}, {}, {}, {}}))
    {
      Impl &s = *impl;
      s.fe.push_back(FE_Q<dim>(1));
      s.fe.push_back(FE_SimplexP<dim>(1));
      s.quadrature.push_back(QGauss<dim>(4));
      s.quadrature.push_back(QGaussSimplex<dim>(3));
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
                           "stress-intensity factors are computed in 2D only");
        }
      else
        {
          const Impl  &s       = *impl;
          const double E       = s.material.youngs_modulus;
          const double nu      = s.material.poissons_ratio;
          const double mu      = s.material.mu();
          const double lambda  = s.material.lambda();
          const bool   pstress = s.material.plane_stress;
          const double kappa   = pstress ? (3. - nu) / (1. + nu) : 3. - 4. * nu;
          const double E_prime = pstress ? E : E / (1. - nu * nu);

          // Tip axes: row 0 = e1 (along the crack), row 1 = e2.
          const Tensor<1, 2> e1 = direction / direction.norm();
          Tensor<2, 2>       R;
          R[0][0]          = e1[0];
          R[0][1]          = e1[1];
          R[1][0]          = -e1[1];
          R[1][1]          = e1[0];
          const auto hooke = [&](const Tensor<2, 2> &g) {
            const SymmetricTensor<2, 2> eps = symmetrize(g);
            return SymmetricTensor<2, 2>(
              lambda * trace(eps) * unit_symmetric_tensor<2>() + 2. * mu * eps);
          };

          // Only the crack segments near the domain can hide a vertex.
          std::vector<Mesh::Crack<dim>> near;
          for (const auto &crack : cracks)
            {
              const Tensor<1, 2> ab = crack.points[1] - crack.points[0];
              const double       L2 = ab.norm_square();
              const double       t =
                L2 > 0. ?
                        std::clamp((tip - crack.points[0]) * ab / L2, 0., 1.) :
                        0.;
              if (tip.distance(crack.points[0] + t * ab) <= 2. * r_out)
                near.push_back(crack);
            }

          hp::FEValues<dim>                fe_values(s.system.mapping(),
                                      s.fe,
                                      s.quadrature,
                                      update_values | update_gradients |
                                        update_quadrature_points |
                                        update_JxW_values);
          const std::vector<unsigned int> &node_of_dof =
            s.system.node_of_scalar_dof();
          std::vector<types::global_dof_index> dofs;
          double                               I[2] = {0., 0.}, J = 0.;
          for (std::size_t c = 0; c < s.cells.size(); ++c)
            {
              // Only cells that reach into the annulus r_in < r < r_out.
              const double d = tip.distance(s.center[c]);
              if (d - s.radius[c] >= r_out || d + s.radius[c] <= r_in)
                continue;
              const auto &cell = s.cells[c];
              fe_values.reinit(cell);
              const FEValues<dim> &fv = fe_values.get_present_fe_values();
              dofs.resize(fv.dofs_per_cell);
              cell->get_dof_indices(dofs);
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  const Point<2> &xq = fv.quadrature_point(q);
                  const double    r  = xq.distance(tip);
                  if (r <= r_in || r >= r_out)
                    continue;
                  // q(r) = 1 - smoothstep((r - r_in) / (r_out - r_in))
                  const double       t   = (r - r_in) / (r_out - r_in);
                  const double       dqr = -6. * t * (1. - t) / (r_out - r_in);
                  const Tensor<1, 2> xl  = R * (xq - tip);
                  const Tensor<1, 2> dq  = dqr * xl / r; // tip axes

                  // grad u at the point, in global axes
                  Tensor<2, 2> G;
                  if (!s.pd[c])
                    for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
                      G += outer_product(
                        results.displacement[node_of_dof[dofs[i]]],
                        fv.shape_grad(i, q));
                  else
                    {
                      double weight = 0.;
                      for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
                        {
                          const unsigned int k = node_of_dof[dofs[i]];
                          if (Mesh::cut_by_any(near, xq, results.position[k]))
                            continue;
                          weight += fv.shape_value(i, q);
                          G += fv.shape_value(i, q) *
                               results.displacement_gradient[k];
                        }
                      if (!(weight > 1e-3))
                        continue; // a point no vertex sees: no field
                      G /= weight;
                    }
                  const Tensor<2, 2>          Gl    = R * G * transpose(R);
                  const SymmetricTensor<2, 2> sigma = hooke(Gl);
                  const double                JxW   = fv.JxW(q);

                  // J: (sigma_ij u_i,1 - W delta_1j) q_,j
                  const double W = 0.5 * (sigma * symmetrize(Gl));
                  for (unsigned int j = 0; j < 2; ++j)
                    {
                      double a = 0.;
                      for (unsigned int i = 0; i < 2; ++i)
                        a += sigma[i][j] * Gl[i][0];
                      J += (a - (j == 0 ? W : 0.)) * dq[j] * JxW;
                    }
                  for (unsigned int mode = 0; mode < 2; ++mode)
                    {
                      const Tensor<2, 2> Ga =
                        williams_gradient(Point<2>(xl), mode, kappa, mu);
                      const SymmetricTensor<2, 2> sigma_a = hooke(Ga);
                      const double                W12 = sigma * symmetrize(Ga);
                      for (unsigned int j = 0; j < 2; ++j)
                        {
                          double a = 0.;
                          for (unsigned int i = 0; i < 2; ++i)
                            a +=
                              sigma[i][j] * Ga[i][0] + sigma_a[i][j] * Gl[i][0];
                          I[mode] += (a - (j == 0 ? W12 : 0.)) * dq[j] * JxW;
                        }
                    }
                }
            }
          return {0.5 * E_prime * I[0], 0.5 * E_prime * I[1], J};
        }
    }

#define INSTANTIATE(dim) template class InteractionIntegral<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Fracture
} // namespace pdfem
