// SPDX-License-Identifier: LGPL-2.1-or-later
// The linearised LPS model in the direct form ("lps", pd_models/lps.h,
// doc/theory.md §15) in the coupled system:
// - each family's tangent is the central differences of its forces, and
//   f = K u (the energy is quadratic), with and without broken bonds, 2D
//   (plane stress, plane strain; jittered quads, all PD and coupled) and
//   3D;
// - rigid translations and (linearised) rotations give no force, with
//   broken bonds;
// - a homogeneous deformation on a uniform grid: theta = tr(grad u) at
//   every node whose family is whole, theta = dim eps for an expansion at
//   every node (surfaces, jitter and broken bonds included), and no force
//   at the nodes two horizons inside;
// - the forces, theta and m equal those of the FFT module's LPS operator
//   (FFT::DirectOperator and FFT::FftOperator) on the same grid, at every
//   node with Nodal volumes = uniform (the grid's Delta V), with dead
//   nodes (integrity 0 = all their bonds broken), and two horizons inside
//   with the cells' volumes (half a cell at a surface).
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/fft/direct_operator.h>
#include <pdfem/fft/fft_operator.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/lps.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <random>

#include "pd_models_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;

  /// A unit square/cube of n^dim cells (jittered by @p jitter of a cell),
  /// the cells with @p is_pd(centre) PD, E = 1e3, Poisson's ratio @p nu,
  /// the model lps with @p entries, horizon factor @p m.
  template <int dim>
  struct LpsBody
  {
    LpsBody(const unsigned int                                      n,
            const double                                            jitter,
            const std::function<bool(const Point<dim> &)>          &is_pd,
            const double                                            nu,
            const std::vector<std::pair<std::string, std::string>> &entries,
            const double                                            m = 3.015,
            const bool plane_strain                                   = false)
      : tria(MPI_COMM_WORLD)
    {
      GridGenerator::subdivided_hyper_cube(tria, n);
      if (jitter > 0.)
        GridTools::distort_random(jitter, tria, false, 5);
      std::vector<bool> pd(tria.n_active_cells());
      for (const auto &cell : tria.active_cell_iterators())
        pd[cell->active_cell_index()] = is_pd(cell->center());
      const Coupling::Settings<dim> settings = body_settings<dim>(
        nu, m, make_model<dim>("lps", entries), plane_strain);
      system =
        std::make_unique<Coupling::CoupledSystem<dim>>(tria, pd, settings);
      spacing = 1. / n;
    }

    const PDModels::LPS<dim> &
    model() const
    {
      return dynamic_cast<const PDModels::LPS<dim> &>(system->pd_model());
    }

    unsigned int
    n_nodes() const
    {
      return system->size().n_nodes;
    }

    /// u(x) at every node.
    Field<dim>
    field(const std::function<Tensor<1, dim>(const Point<dim> &)> &u) const
    {
      Field<dim> f(n_nodes());
      for (unsigned int k = 0; k < n_nodes(); ++k)
        {
          const Tensor<1, dim> v = u(system->node_position(k));
          for (unsigned int c = 0; c < dim; ++c)
            f.values[dim * k + c] = v[c];
        }
      return f;
    }

    /// The internal force at every node: the family forces scattered to
    /// the owners and members.
    std::vector<Tensor<1, dim>>
    nodal_forces(const Field<dim> &u) const
    {
      const PD::Families         &f = system->families();
      std::vector<Tensor<1, dim>> F(n_nodes()), family;
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        {
          model().family_forces(o, u.field(), family);
          F[f.owners[o]] += family[0];
          std::size_t i = 0;
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            if (f.intact[j])
              F[f.members[j]] += family[++i];
          EXPECT_EQ(i + 1, family.size());
        }
      return F;
    }

    /// The distance of node @p k from the cube's surface.
    double
    depth(const unsigned int k) const
    {
      const Point<dim> p = system->node_position(k);
      double           d = 1.;
      for (unsigned int c = 0; c < dim; ++c)
        d = std::min({d, p[c], 1. - p[c]});
      return d;
    }

    parallel::shared::Triangulation<dim>          tria;
    std::unique_ptr<Coupling::CoupledSystem<dim>> system;
    double                                        spacing = 0.;
  };

  template <int dim>
  bool
  all_pd(const Point<dim> &)
  {
    return true;
  }

  /// PD cells in the middle band 0.3 < x < 0.7, FE around.
  template <int dim>
  bool
  middle_band(const Point<dim> &p)
  {
    return std::abs(p[0] - 0.5) < 0.2;
  }

  template <int dim>
  double
  max_norm(const std::vector<Tensor<1, dim>> &F)
  {
    double s = 0.;
    for (const auto &f : F)
      s = std::max(s, f.norm());
    return s;
  }

  /// max |family tangent - central differences of the family forces| and
  /// max |K u - f(u)|, relative to the largest tangent entry and the
  /// largest force, over every family, at a random u.
  template <int dim>
  std::pair<double, double>
  family_tangent_error(const LpsBody<dim> &body)
  {
    const auto                            &model = body.model();
    const PD::Families                    &f     = body.system->families();
    Field<dim>                             u(body.n_nodes());
    std::mt19937                           random(17);
    std::uniform_real_distribution<double> value(-1e-3, 1e-3);
    for (double &v : u.values)
      v = value(random);
    std::vector<Tensor<1, dim>> fp, fm, f0;
    std::vector<Tensor<2, dim>> K;
    double       error = 0., scale = 0., linear = 0., force_scale = 0.;
    const double h = 1e-6;
    for (std::size_t o = 0; o < f.owners.size(); ++o)
      {
        model.family_tangent(o, u.field(), K);
        model.family_forces(o, u.field(), f0);
        std::vector<unsigned int> nodes{f.owners[o]};
        for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
          if (f.intact[j])
            nodes.push_back(f.members[j]);
        const std::size_t n = nodes.size();
        EXPECT_EQ(K.size(), n * n);
        EXPECT_EQ(f0.size(), n);
        for (std::size_t a = 0; a < n; ++a)
          {
            Tensor<1, dim> Ku;
            for (std::size_t b = 0; b < n; ++b)
              Ku += K[a * n + b] * u.field()[nodes[b]];
            linear      = std::max(linear, (Ku - f0[a]).norm());
            force_scale = std::max(force_scale, f0[a].norm());
          }
        for (std::size_t b = 0; b < n; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            {
              double &x = u.values[dim * nodes[b] + c];
              x += h;
              model.family_forces(o, u.field(), fp);
              x -= 2. * h;
              model.family_forces(o, u.field(), fm);
              x += h;
              for (std::size_t a = 0; a < n; ++a)
                for (unsigned int r = 0; r < dim; ++r)
                  {
                    const double fd = (fp[a][r] - fm[a][r]) / (2. * h);
                    error = std::max(error, std::abs(fd - K[a * n + b][r][c]));
                    scale = std::max(scale, std::abs(K[a * n + b][r][c]));
                  }
            }
      }
    EXPECT_GT(scale, 0.);
    EXPECT_GT(force_scale, 0.);
    return {error / scale, linear / force_scale};
  }

  /// Break every bond (k, m) with (k + m) % 5 == 0, both directions.
  template <int dim>
  void
  break_some(LpsBody<dim> &body)
  {
    body.system->break_bonds_if([](const unsigned int k, const unsigned int m) {
      return (k + m) % 5 == 0;
    });
    EXPECT_GT(body.system->families().n_broken(), 0u);
  }

  template <int dim>
  void
  check_tangent(LpsBody<dim> &body, const char *what)
  {
    for (const bool broken : {false, true})
      {
        if (broken)
          break_some(body);
        const auto [fd, linear] = family_tangent_error(body);
        EXPECT_LT(fd, 1e-6) << what << (broken ? ", broken bonds" : "");
        EXPECT_LT(linear, 1e-12) << what << (broken ? ", broken bonds" : "");
      }
  }

  TEST(Lps, FamilyTangentIsCentralDifferencesOfFamilyForces2D)
  {
    LpsBody<2> stress(8, 0.2, all_pd<2>, 0.3, {});
    check_tangent(stress, "2D plane stress, nu = 0.3, all PD");
    LpsBody<2> strain(8, 0.2, all_pd<2>, 0.45, {}, 3.015, true);
    check_tangent(strain, "2D plane strain, nu = 0.45, all PD");
    LpsBody<2> coupled(
      8, 0.2, middle_band<2>, 0.2, {{"LPS/Influence function", "1"}});
    check_tangent(coupled, "2D plane stress, nu = 0.2, omega = 1, coupled");
  }

  TEST(Lps, FamilyTangentIsCentralDifferencesOfFamilyForces3D)
  {
    LpsBody<3> all(4, 0.2, all_pd<3>, 0.3, {}, 2.015);
    check_tangent(all, "3D, nu = 0.3, all PD");
    LpsBody<3> coupled(
      4, 0.2, middle_band<3>, 0.1, {{"LPS/Nodal volumes", "uniform"}}, 2.015);
    check_tangent(coupled, "3D, nu = 0.1, uniform volumes, coupled");
  }

  /// The largest family force at @p u over the largest at @p reference.
  template <int dim>
  double
  relative_force(const LpsBody<dim> &body,
                 const Field<dim>   &u,
                 const Field<dim>   &reference)
  {
    return max_norm(body.nodal_forces(u)) /
           max_norm(body.nodal_forces(reference));
  }

  template <int dim>
  void
  check_rigid_motions(LpsBody<dim> &body)
  {
    Tensor<1, dim> t;
    Tensor<2, dim> W, E;
    for (unsigned int c = 0; c < dim; ++c)
      {
        t[c]    = 0.3 + 0.1 * c;
        E[c][c] = 1e-3 * (1. + c);
      }
    W[0][1] = 0.02;
    W[1][0] = -0.02;
    if (dim == 3)
      {
        W[1][2] = -0.01;
        W[2][1] = 0.01;
      }
    const Field<dim> stretch =
      body.field([&](const Point<dim> &p) { return E * p; });
    for (const bool broken : {false, true})
      {
        if (broken)
          break_some(body);
        const auto translation =
          body.field([&](const Point<dim> &) { return t; });
        const auto rotation =
          body.field([&](const Point<dim> &p) { return W * p; });
        EXPECT_LT(relative_force(body, translation, stretch), 1e-12);
        EXPECT_LT(relative_force(body, rotation, stretch), 1e-12);
      }
  }

  TEST(Lps, RigidMotionsGiveNoForce)
  {
    LpsBody<2> plate(8, 0.2, all_pd<2>, 0.3, {});
    check_rigid_motions(plate);
    LpsBody<3> cube(4, 0.2, all_pd<3>, 0.3, {}, 2.015);
    check_rigid_motions(cube);
  }

  template <int dim>
  void
  check_homogeneous(LpsBody<dim> &body)
  {
    // u = H x with a general H: theta = tr H where the family is whole,
    // no force two horizons inside. u = eps x: theta = dim eps at every
    // node, surfaces included.
    Tensor<2, dim> H;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        H[i][j] = 1e-3 * (1. + i + 2. * j) * (i == j ? 1. : -0.3);
    const auto   u     = body.field([&](const Point<dim> &p) { return H * p; });
    const double delta = body.model().constants()[0].second;
    const auto  &f     = body.system->families();
    const auto   F     = body.nodal_forces(u);
    double       inside = 0.;
    unsigned int n_deep = 0, n_whole = 0;
    for (unsigned int k = 0; k < body.n_nodes(); ++k)
      if (body.depth(k) > 2. * delta + 1e-9)
        {
          inside = std::max(inside, F[k].norm());
          ++n_deep;
        }
    EXPECT_GT(n_deep, 0u);
    EXPECT_LT(inside / max_norm(F), 1e-12);
    for (std::size_t o = 0; o < f.owners.size(); ++o)
      if (body.depth(f.owners[o]) > delta + 1e-9)
        {
          EXPECT_NEAR(body.model().dilatation(o, u.field()), trace(H), 1e-15);
          ++n_whole;
        }
    EXPECT_GT(n_whole, n_deep);

    const double eps = 2e-3;
    const auto   expansion =
      body.field([&](const Point<dim> &p) { return eps * Tensor<1, dim>(p); });
    for (const bool broken : {false, true})
      {
        if (broken)
          break_some(body);
        for (std::size_t o = 0; o < f.owners.size(); ++o)
          EXPECT_NEAR(body.model().dilatation(o, expansion.field()),
                      dim * eps,
                      1e-15);
      }
  }

  TEST(Lps, HomogeneousDeformation)
  {
    LpsBody<2> plate(16, 0., all_pd<2>, 0.3, {});
    check_homogeneous(plate);
    LpsBody<3> cube(14, 0., all_pd<3>, 0.25, {}, 2.015);
    check_homogeneous(cube);
    // Expansion on a jittered mesh: theta = dim eps still.
    LpsBody<2> jittered(8, 0.2, all_pd<2>, 0.3, {});
    const auto u =
      jittered.field([](const Point<2> &p) { return 1e-3 * Tensor<1, 2>(p); });
    const auto &f = jittered.system->families();
    for (std::size_t o = 0; o < f.owners.size(); ++o)
      EXPECT_NEAR(jittered.model().dilatation(o, u.field()), 2e-3, 1e-15);
  }

  /// max |a - b| / max |b| over the nodes with @p use(k).
  template <int dim>
  double
  relative_difference(const std::vector<Tensor<1, dim>>       &a,
                      const std::vector<Tensor<1, dim>>       &b,
                      const std::function<bool(unsigned int)> &use)
  {
    double d = 0., s = 0.;
    for (unsigned int k = 0; k < a.size(); ++k)
      if (use(k))
        {
          d = std::max(d, (a[k] - b[k]).norm());
          s = std::max(s, b[k].norm());
        }
    EXPECT_GT(s, 0.);
    return d / s;
  }

  /// The body's nodes on an FFT grid with a gap of more than a horizon:
  /// L of FFT::DirectOperator and FftOperator (random u, dead nodes)
  /// against the family forces, -L Delta V, at every node (uniform
  /// volumes) or two horizons inside (cells).
  template <int dim>
  void
  check_fft(const unsigned int n, const double m, const double nu)
  {
    for (const bool uniform : {true, false})
      {
        LpsBody<dim>       body(n,
                          0.,
                          all_pd<dim>,
                          nu,
                          {{"LPS/Nodal volumes",
                            uniform ? "uniform" : "cells"}},
                          m);
        const double       h     = body.spacing;
        const double       delta = m * h;
        FFT::Grid<dim>     grid;
        const unsigned int gap = std::ceil(m) + 1;
        for (unsigned int c = 0; c < dim; ++c)
          {
            grid.n[c]       = n + 1 + gap;
            grid.spacing[c] = h;
          }
        FFT::Material material;
        material.model         = FFT::Model::lps;
        material.horizon       = delta;
        material.bulk_modulus  = body.model().constants()[2].second;
        material.shear_modulus = body.model().constants()[3].second;

        // Node k at grid node round(x / h); 10 % dead nodes.
        const std::size_t                      N = grid.n_nodes();
        std::vector<std::size_t>               at(body.n_nodes());
        std::vector<double>                    mask(N, 0.), integrity(N, 1.);
        std::vector<std::uint8_t>              dead(body.n_nodes(), 0);
        std::mt19937                           random(23);
        std::uniform_real_distribution<double> value(-1e-3, 1e-3);
        for (unsigned int k = 0; k < body.n_nodes(); ++k)
          {
            const Point<dim>              p = body.system->node_position(k);
            std::array<unsigned int, dim> i;
            for (unsigned int c = 0; c < dim; ++c)
              i[c] = std::lround(p[c] / h);
            at[k]            = grid.node(i);
            mask[at[k]]      = 1.;
            dead[k]          = random() % 10 == 0;
            integrity[at[k]] = dead[k] ? 0. : 1.;
          }
        body.system->break_bonds_if(
          [&](unsigned int k, unsigned int j) { return dead[k] || dead[j]; });
        Field<dim>          u(body.n_nodes());
        std::vector<double> u_grid(dim * N, 0.);
        for (unsigned int k = 0; k < body.n_nodes(); ++k)
          for (unsigned int c = 0; c < dim; ++c)
            {
              u.values[dim * k + c] = value(random);
              u_grid[c * N + at[k]] = u.values[dim * k + c];
            }
        const auto F = body.nodal_forces(u);

        FFT::DirectOperator<dim> direct(grid, material);
        FFT::FftOperator<dim>    fft(grid, material);
        for (FFT::Operator<dim> *op :
             std::initializer_list<FFT::Operator<dim> *>{&direct, &fft})
          {
            op->set_masks(mask, integrity);
            std::vector<double> L, theta;
            op->apply(u_grid, L);
            op->dilatation(u_grid, theta);
            const auto                 &m_grid = op->weighted_volume();
            std::vector<Tensor<1, dim>> F_grid(body.n_nodes());
            for (unsigned int k = 0; k < body.n_nodes(); ++k)
              for (unsigned int c = 0; c < dim; ++c)
                F_grid[k][c] = -L[c * N + at[k]] * grid.node_volume();
            const auto use = [&](const unsigned int k) {
              return uniform || body.depth(k) > 2. * delta + 1e-9;
            };
            EXPECT_LT(relative_difference<dim>(F, F_grid, use), 1e-12)
              << dim << "D, " << (uniform ? "uniform" : "cells");
            const auto &f           = body.system->families();
            double      theta_scale = 0., m_scale = 0.;
            for (std::size_t o = 0; o < f.owners.size(); ++o)
              {
                theta_scale =
                  std::max(theta_scale, std::abs(theta[at[f.owners[o]]]));
                m_scale = std::max(m_scale, m_grid[at[f.owners[o]]]);
              }
            for (std::size_t o = 0; o < f.owners.size(); ++o)
              if (use(f.owners[o]) && !dead[f.owners[o]])
                {
                  const std::size_t g = at[f.owners[o]];
                  EXPECT_NEAR(body.model().dilatation(o, u.field()),
                              theta[g],
                              1e-12 * theta_scale);
                  EXPECT_NEAR(body.model().weighted_volume(o),
                              m_grid[g],
                              1e-12 * m_scale);
                }
          }
      }
  }

  TEST(Lps, EqualsFftOperator)
  {
    check_fft<2>(20, 3.015, 0.3);
    check_fft<3>(12, 2.015, 0.2);
  }
} // namespace
