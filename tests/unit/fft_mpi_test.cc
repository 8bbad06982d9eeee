// SPDX-License-Identifier: LGPL-2.1-or-later
// FftOperator over MPI ranks (fft/fft_operator.h, FftOptions::communicator):
// on every rank the one-rank operator (MPI_COMM_SELF) on the whole box is
// the reference, and the operator on MPI_COMM_WORLD, given the rank's slab
// of the same random fields and masks, must return the reference's slab:
// apply(), dilatation(), energy_density(), damage() (both normalisations),
// weighted_volume() and apply_periodic_inverse(), for the linear and
// nonlinear bond-based models and LPS, 2D and 3D, with a body inside the
// box and 15 % dead nodes. Relative difference max |a - b| (over all ranks)
// / max |b| at most 1e-12. Grids: odd slowest sizes (uneven slabs), a 2D
// grid whose two Fourier rows k_1 = 0, 1 fall on different ranks (the
// periodic inverse's s then crosses ranks), and a grid of 3 planes (with 4
// ranks a rank holds none). Also: the slabs tile the box in rank order,
// local_slab() = slab(), and the memory per rank falls with the ranks.
// SlabExchange: every box node owned by one rank in a scattered order
// (node % ranks, reversed) reaches its slab and comes back, 2 and 3
// components, with an empty slab on 4 ranks.
// Run on 1, 2 and 4 ranks (tests/CMakeLists.txt: unit.FftMpi.*,
// unit.np2.FftMpi, unit.np4.FftMpi).
#include <pdfem/fft/fft_operator.h>
#include <pdfem/fft/slab_exchange.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fft_test_tools.h"
#include <gtest/gtest.h>
#include <mpi.h>

namespace
{
  using namespace pdfem::FFT;
  using test_tools::material;
  using test_tools::random_field;

  int
  n_ranks()
  {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
  }

  double
  max_over_ranks(double x)
  {
    MPI_Allreduce(MPI_IN_PLACE, &x, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return x;
  }

  /// The slab's part of a field of @p components blocks of N values.
  std::vector<double>
  local(const std::vector<double> &whole,
        const Slab                &slab,
        const std::size_t          N,
        const unsigned int         components = 1)
  {
    std::vector<double> part;
    for (unsigned int c = 0; c < components; ++c)
      part.insert(part.end(),
                  whole.begin() + c * N + slab.begin,
                  whole.begin() + c * N + slab.end);
    return part;
  }

  /// max over ranks of max |a - b| on the slab / max |reference|, with
  /// @p a the rank's slab and @p reference the whole field.
  double
  difference(const std::vector<double> &a,
             const std::vector<double> &reference,
             const Slab                &slab,
             const std::size_t          N,
             const unsigned int         components = 1)
  {
    const std::vector<double> b = local(reference, slab, N, components);
    EXPECT_EQ(a.size(), b.size());
    double d = 0., s = 0.;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
      d = std::max(d, std::abs(a[k] - b[k]));
    for (const double v : reference)
      s = std::max(s, std::abs(v));
    EXPECT_GT(s, 0.);
    return max_over_ranks(d) / s;
  }

  /// An ellipsoidal body a spacing inside the box faces and a random
  /// integrity with 15 % dead nodes (the same on every rank).
  template <int dim>
  void
  masks(const Grid<dim>     &g,
        std::vector<double> &body,
        std::vector<double> &integrity)
  {
    std::array<double, dim> inset;
    for (unsigned int d = 0; d < dim; ++d)
      inset[d] = 0.9 * g.spacing[d];
    test_tools::ellipsoid_masks<dim>(g, inset, false, 11, body, integrity);
  }

  template <int dim>
  Grid<dim>
  grid(const std::array<unsigned int, dim> &n,
       const std::array<double, dim>       &spacing)
  {
    Grid<dim> g;
    g.n       = n;
    g.spacing = spacing;
    return g;
  }

  /// Every operation of the distributed operator against the one-rank
  /// reference on the same fields; with @p check_memory, each rank holds at
  /// most 1.6 / ranks of the reference's bytes (tiny grids excepted: there
  /// FFTW's blocks of Fourier rows are too coarse).
  template <int dim>
  void
  compare(const Grid<dim>   &g,
          const Material    &mat,
          const unsigned int threads,
          const bool         check_memory,
          const bool         keep_mask_fields = true,
          const bool         intact           = false)
  {
    const double tol  = 1e-12;
    const auto   name = std::to_string(dim) + "D " + model_name(mat.model) +
                      " on " + std::to_string(n_ranks()) + " ranks";
    SCOPED_TRACE(name);
    FftOptions distributed;
    distributed.communicator     = MPI_COMM_WORLD;
    distributed.threads          = threads;
    distributed.keep_mask_fields = keep_mask_fields;
    FftOperator<dim>  reference(g, mat), op(g, mat, distributed);
    const Slab        slab = op.slab();
    const std::size_t N    = g.n_nodes();

    std::vector<double> body, integrity;
    masks(g, body, integrity);
    if (intact)
      std::fill(integrity.begin(), integrity.end(), 1.);
    reference.set_masks(body, integrity);
    op.set_masks(local(body, slab, N), local(integrity, slab, N));
    // the layer of the kept fields, found by correlations across the slabs
    unsigned long layer = op.n_layer_nodes();
    MPI_Allreduce(
      MPI_IN_PLACE, &layer, 1, MPI_UNSIGNED_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(layer, keep_mask_fields ? reference.n_layer_nodes() : 0u);
    if (intact)
      EXPECT_LT(reference.n_layer_nodes(),
                std::size_t(std::count(body.begin(), body.end(), 1.)));
    const bool   lps            = mat.model == Model::lps;
    const bool   nonlinear      = mat.model == Model::nonlinear_bond_based;
    const double amplitude      = nonlinear ? 0.05 : 1.;
    const std::vector<double> u = random_field(dim * N, amplitude, 5);
    const std::vector<double> u_local = local(u, slab, N, dim);

    std::vector<double> a, b;
    reference.apply(u, b);
    op.apply(u_local, a);
    EXPECT_LE(difference(a, b, slab, N, dim), tol) << "apply";
    if (lps)
      {
        reference.dilatation(u, b);
        op.dilatation(u_local, a);
        EXPECT_LE(difference(a, b, slab, N), tol) << "dilatation";
        EXPECT_LE(difference(
                    op.weighted_volume(), reference.weighted_volume(), slab, N),
                  tol)
          << "weighted volume";
      }
    if (!nonlinear)
      {
        reference.energy_density(u, b);
        op.energy_density(u_local, a);
        EXPECT_LE(difference(a, b, slab, N), tol) << "energy density";
      }
    for (const auto n :
         {DamageNormalisation::full_horizon, DamageNormalisation::body})
      if (!intact) // (an intact body has no damage to compare)
        {
          reference.damage(b, n);
          op.damage(a, n);
          EXPECT_LE(difference(a, b, slab, N), tol) << "damage";
        }
    if (!nonlinear)
      {
        // twice: the symbol is made at the first call and kept
        for (const unsigned int seed : {8u, 9u})
          {
            const std::vector<double> r = random_field(dim * N, 1., seed);
            reference.apply_periodic_inverse(r, b);
            op.apply_periodic_inverse(local(r, slab, N, dim), a);
            EXPECT_LE(difference(a, b, slab, N, dim), tol)
              << "periodic inverse";
          }
        // the masks are those set before the symbol was made
        reference.apply(u, b);
        op.apply(u_local, a);
        EXPECT_LE(difference(a, b, slab, N, dim), tol) << "apply after";
      }
    const double share = max_over_ranks(op.bytes() / reference.bytes());
    if (check_memory)
      {
        EXPECT_LE(share, n_ranks() == 1 ? 1. : 1.6 / n_ranks());
      }
  }

  template <int dim>
  void
  compare_models(const Grid<dim> &g,
                 const double     horizon,
                 const bool       check_memory)
  {
    for (const Model model :
         {Model::linear_bond_based, Model::nonlinear_bond_based, Model::lps})
      compare(g, material(model, horizon), 1, check_memory);
  }
} // namespace

TEST(FftMpi, Slabs)
{
  const auto g    = grid<3>({{13, 10, 14}}, {{1., 0.9, 0.8}});
  const int  size = n_ranks();
  int        rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  FftOptions options;
  options.communicator = MPI_COMM_WORLD;
  FftOperator<3> op(g, material(Model::lps, 2.55), options);
  const Slab     s = op.slab(), t = local_slab(g, MPI_COMM_WORLD);
  EXPECT_EQ(s.begin, t.begin);
  EXPECT_EQ(s.end, t.end);
  EXPECT_EQ(s.n_nodes(), std::size_t(s.n_planes) * 10 * 14);
  EXPECT_EQ(s.begin, std::size_t(s.first_plane) * 10 * 14);
  EXPECT_EQ(op.weighted_volume().size(), s.n_nodes());
  // the slabs tile the box in rank order
  std::vector<unsigned long> ranges(2 * size);
  const unsigned long        mine[2] = {s.begin, s.end};
  MPI_Allgather(mine,
                2,
                MPI_UNSIGNED_LONG,
                ranges.data(),
                2,
                MPI_UNSIGNED_LONG,
                MPI_COMM_WORLD);
  EXPECT_EQ(ranges.front(), 0u);
  EXPECT_EQ(ranges.back(), g.n_nodes());
  for (int r = 1; r < size; ++r)
    EXPECT_EQ(ranges[2 * r], ranges[2 * r - 1]);
  // MPI_COMM_SELF: the whole box
  const Slab w = local_slab(g, MPI_COMM_SELF);
  EXPECT_EQ(w.begin, 0u);
  EXPECT_EQ(w.end, g.n_nodes());
  EXPECT_EQ(w.n_planes, 13u);
  // wrong sizes and no communicator are refused
  std::vector<double> f;
  EXPECT_THROW(op.apply(std::vector<double>(3 * s.n_nodes() + 3, 0.), f),
               std::invalid_argument);
  options.communicator = MPI_COMM_NULL;
  EXPECT_THROW(FftOperator<3>(g, material(Model::lps, 2.55), options),
               std::invalid_argument);
}

// 25 x 20: slabs of 13 and 12 planes on 2 ranks.
TEST(FftMpi, Models2D)
{
  compare_models(grid<2>({{25, 20}}, {{1., 0.8}}), 3.05, true);
}

// 15 x 3: the Fourier rows k_1 = 0 (the rigid translations) and k_1 = 1 (the
// mode giving the periodic inverse's s) on different ranks; with 4 ranks
// two ranks hold no mode.
TEST(FftMpi, TwoFourierRows2D)
{
  compare_models(grid<2>({{15, 3}}, {{0.5, 1.}}), 1.2, false);
}

// 13 x 10 x 14: slabs of 7 and 6 planes on 2 ranks.
TEST(FftMpi, Models3D)
{
  compare_models(grid<3>({{13, 10, 14}}, {{1., 0.9, 0.8}}), 2.55, true);
}

// Two threads per rank.
TEST(FftMpi, Threads3D)
{
  compare(grid<3>({{13, 10, 14}}, {{1., 0.9, 0.8}}),
          material(Model::lps, 2.55),
          2,
          true);
}

// The lean setting (the mask fields recomputed in each evaluation) against
// the one-rank operator that keeps them, on the grids above: ranks without
// planes or modes take the same transforms.
TEST(FftMpi, RecomputedMaskFields)
{
  for (const Model model :
       {Model::linear_bond_based, Model::nonlinear_bond_based, Model::lps})
    {
      compare(grid<3>({{13, 10, 14}}, {{1., 0.9, 0.8}}),
              material(model, 2.55),
              2,
              false,
              false);
      compare(
        grid<2>({{15, 3}}, {{0.5, 1.}}), material(model, 1.2), 1, false, false);
      compare(grid<3>({{3, 10, 12}}, {{1., 0.9, 0.8}}),
              material(model, 1.3),
              1,
              false,
              false);
    }
}

// An intact body on grids with an interior: the kept fields' layer (the
// nodes within the fields' reach of the gap) crosses the slab boundaries.
TEST(FftMpi, LayerOfTheKeptFieldsAcrossSlabs)
{
  for (const Model model :
       {Model::linear_bond_based, Model::nonlinear_bond_based, Model::lps})
    {
      compare(grid<2>({{40, 32}}, {{1., 0.8}}),
              material(model, 3.05),
              1,
              false,
              true,
              true);
      compare(grid<3>({{20, 18, 16}}, {{1., 0.9, 0.8}}),
              material(model, 2.55),
              1,
              false,
              true,
              true);
    }
}

// 3 x 10 x 12 planes: with 4 ranks the last holds no plane (FFTW's blocks
// of ceil(3 / 4) = 1 plane), and its fields are empty.
TEST(FftMpi, MoreRanksThanPlanes)
{
  const auto g    = grid<3>({{3, 10, 12}}, {{1., 0.9, 0.8}});
  const Slab s    = local_slab(g, MPI_COMM_WORLD);
  int        rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (n_ranks() >= 4 && rank == 3)
    {
      EXPECT_EQ(s.n_nodes(), 0u);
    }
  compare_models(g, 1.3, false);
}

TEST(FftMpi, SlabExchangeMovesValuesBothWays)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  for (const std::array<unsigned int, 3> n :
       {std::array<unsigned int, 3>{{7, 4, 3}},
        std::array<unsigned int, 3>{{3, 5, 2}}}) // 4 ranks: one holds none
    {
      Grid<3> grid;
      grid.n          = n;
      grid.spacing    = {{1., 1., 1.}};
      const Slab slab = local_slab(grid, MPI_COMM_WORLD);
      // This rank's points: every ranks-th box node, in reverse order.
      std::vector<std::size_t> points;
      for (std::size_t k = grid.n_nodes(); k-- > 0;)
        if (int(k % n_ranks()) == rank)
          points.push_back(k);
      const SlabExchange exchange(points, slab, MPI_COMM_WORLD);
      EXPECT_EQ(exchange.n_points(), points.size());
      const auto value = [](const std::size_t k, const unsigned int c) {
        return 1000. * double(c) + double(k) + 0.5;
      };
      for (const unsigned int nc : {2u, 3u})
        {
          std::vector<double> at_points(nc * points.size());
          for (std::size_t p = 0; p < points.size(); ++p)
            for (unsigned int c = 0; c < nc; ++c)
              at_points[nc * p + c] = value(points[p], c);
          std::vector<double> field;
          exchange.push(at_points.data(), nc, field);
          ASSERT_EQ(field.size(), nc * slab.n_nodes());
          double error = 0.;
          for (std::size_t k = 0; k < slab.n_nodes(); ++k)
            for (unsigned int c = 0; c < nc; ++c)
              error = std::max(error,
                               std::abs(field[c * slab.n_nodes() + k] -
                                        value(slab.begin + k, c)));
          EXPECT_EQ(max_over_ranks(error), 0.);
          // Back: the slab's field, doubled, at the points.
          for (double &v : field)
            v *= 2.;
          std::vector<double> back(nc * points.size(), 0.);
          exchange.pull(field, nc, back.data());
          error = 0.;
          for (std::size_t p = 0; p < points.size(); ++p)
            for (unsigned int c = 0; c < nc; ++c)
              error =
                std::max(error,
                         std::abs(back[nc * p + c] - 2. * value(points[p], c)));
          EXPECT_EQ(max_over_ranks(error), 0.);
        }
    }
}

TEST(FftMpi, SlabExchangeSkipsEmptySlabsWhereverTheyReport)
{
  // Slabs made by hand: one rank (the second of 3 or more, the last of 2)
  // holds nothing and reports the range [0, 0) (FFTW leaves local_0_start
  // undefined where local_n0 = 0), so that the reported ends are not in
  // order; the others split 6 planes of 4 nodes. Every box node is a point
  // of the rank node % ranks.
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const int  n       = n_ranks();
  const int  empty   = n == 1 ? -1 : 1;
  const int  holders = n == 1 ? 1 : n - 1;
  const int  index   = rank < empty || empty < 0 ? rank : rank - 1;
  Slab       slab;
  const auto plane_of = [&](const int r) { return 6 * r / holders; };
  if (rank != empty)
    {
      slab.first_plane = plane_of(index);
      slab.n_planes    = plane_of(index + 1) - plane_of(index);
      slab.begin       = 4 * slab.first_plane;
      slab.end         = slab.begin + 4 * slab.n_planes;
    }
  std::vector<std::size_t> points;
  for (std::size_t k = 0; k < 24; ++k)
    if (int(k % n) == rank)
      points.push_back(k);
  const SlabExchange  exchange(points, slab, MPI_COMM_WORLD);
  std::vector<double> values(points.begin(), points.end()), field;
  exchange.push(values.data(), 1, field);
  double error = 0.;
  for (std::size_t k = 0; k < slab.n_nodes(); ++k)
    error = std::max(error, std::abs(field[k] - double(slab.begin + k)));
  EXPECT_EQ(max_over_ranks(error), 0.);
  std::vector<double> back(points.size(), -1.);
  exchange.pull(field, 1, back.data());
  EXPECT_EQ(back, values);
}
