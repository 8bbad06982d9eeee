// SPDX-License-Identifier: LGPL-2.1-or-later
// Time per evaluation of a PD operator on a uniform periodic grid: the FFT
// form (FFT::FftOperator, specs/002) against the direct neighbour sum
// (FFT::DirectOperator), for grid sizes N = 2^k and horizon factors
// m = delta / spacing. Writes one CSV row per (k, m) to stdout (run.sh
// collects them into doc/benchmarks/fft.csv).
//
// The direct sum costs the same per node on any grid large enough for its
// horizon (no neighbour lists: the bonds are grid offsets), so it is timed
// on min(N, 2^direct_log2) nodes and scaled to N; the columns say on how
// many nodes it ran. Times are the best of the repetitions made within
// --seconds (at least one), after one untimed evaluation for the FFT.
// --lean: the FFT operator recomputes its mask fields in every evaluation
// (FftOptions::keep_mask_fields = false; column mask_fields).
// --body block: the body is a block with a gap of one horizon to the box
// faces instead of the whole box (column body), for both operators; the
// direct sum then runs on the full grid only (--direct-log2 at least
// --log2n), and layer_nodes is the FFT operator's n_layer_nodes() (rank 0's).
//
// Under mpirun the FFT operator is distributed over the ranks (slabs of
// whole planes, FftOptions::communicator = MPI_COMM_WORLD): each rank holds
// its slab of u and L, the time is rank 0's for an evaluation followed by a
// barrier, fft_bytes_per_rank is the largest rank's bytes(), and the direct
// sum is left out (--no-direct implied). Rank 0 writes the rows.
#include <pdfem/fft/direct_operator.h>
#include <pdfem/fft/fft_operator.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <mpi.h>

namespace
{
  using namespace pdfem::FFT;

  struct Options
  {
    int                       dim   = 3;
    Model                     model = Model::linear_bond_based;
    std::vector<unsigned int> log2n{15};
    std::vector<double>       m{5.};
    unsigned int              threads     = 1;
    unsigned int              direct_log2 = 15;
    double                    seconds     = 1.;
    Planning                  planning    = Planning::measure;
    bool                      header      = false;
    bool                      skip_direct = false;
    bool                      lean        = false;
    bool                      block       = false;
    int                       ranks       = 1;
    int                       rank        = 0;
  };

  template <typename T>
  std::vector<T>
  list(const std::string &text)
  {
    std::vector<T>    values;
    std::stringstream s(text);
    std::string       item;
    while (std::getline(s, item, ','))
      values.push_back(static_cast<T>(std::stod(item)));
    return values;
  }

  [[noreturn]] void
  usage(const std::string &problem)
  {
    std::cerr
      << "pdfem_fft_benchmark: " << problem << "\n"
      << "usage: pdfem_fft_benchmark --dim 2|3 --model linear|nonlinear|lps\n"
      << "         --log2n K1,K2,... --m M1,M2,... [--threads T]\n"
      << "         [--direct-log2 K] [--no-direct] [--seconds S]\n"
      << "         [--planning measure|estimate] [--lean] [--header]\n"
      << "         [--body box|block]\n"
      << "       (under mpirun -np P: the FFT operator on P ranks)\n";
    std::exit(2);
  }

  Options
  parse(int argc, char **argv)
  {
    Options o;
    for (int a = 1; a < argc; ++a)
      {
        const std::string key   = argv[a];
        const auto        value = [&]() -> std::string {
          if (a + 1 >= argc)
            usage(key + " needs a value");
          return argv[++a];
        };
        if (key == "--dim")
          o.dim = std::stoi(value());
        else if (key == "--model")
          {
            const std::string v = value();
            if (v == "linear")
              o.model = Model::linear_bond_based;
            else if (v == "nonlinear")
              o.model = Model::nonlinear_bond_based;
            else if (v == "lps")
              o.model = Model::lps;
            else
              usage("unknown model " + v);
          }
        else if (key == "--log2n")
          o.log2n = list<unsigned int>(value());
        else if (key == "--m")
          o.m = list<double>(value());
        else if (key == "--threads")
          o.threads = std::stoi(value());
        else if (key == "--direct-log2")
          o.direct_log2 = std::stoi(value());
        else if (key == "--no-direct")
          o.skip_direct = true;
        else if (key == "--seconds")
          o.seconds = std::stod(value());
        else if (key == "--planning")
          o.planning =
            value() == "estimate" ? Planning::estimate : Planning::measure;
        else if (key == "--header")
          o.header = true;
        else if (key == "--lean")
          o.lean = true;
        else if (key == "--body")
          {
            const std::string v = value();
            if (v != "box" && v != "block")
              usage("--body must be box or block, not " + v);
            o.block = v == "block";
          }
        else
          usage("unknown option " + key);
      }
    if (o.dim != 2 && o.dim != 3)
      usage("--dim must be 2 or 3");
    if (o.block && !o.skip_direct &&
        o.direct_log2 < *std::max_element(o.log2n.begin(), o.log2n.end()))
      usage("--body block times the direct sum on the full grid only: give "
            "--direct-log2 at least the largest --log2n, or --no-direct");
    MPI_Comm_size(MPI_COMM_WORLD, &o.ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &o.rank);
    if (o.ranks > 1)
      o.skip_direct = true;
    return o;
  }

  /// 2^k nodes, as equal as powers of two allow (the first directions
  /// larger), spacing 1.
  template <int dim>
  Grid<dim>
  grid(const unsigned int k)
  {
    Grid<dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      {
        g.n[d]       = 1u << (k / dim + (d < k % dim ? 1 : 0));
        g.spacing[d] = 1.;
      }
    return g;
  }

  /// chi_B at the box nodes [begin, end) of @p g: with @p block the nodes
  /// at least ceil(m) spacings from every box face (the body in its
  /// periodic box with a gap of one horizon, specs/002 §3), else empty (the
  /// body fills the box).
  template <int dim>
  std::vector<double>
  body_mask(const Grid<dim>  &g,
            const double      m,
            const std::size_t begin,
            const std::size_t end,
            const bool        block)
  {
    std::vector<double> body;
    if (!block)
      return body;
    const unsigned int gap = static_cast<unsigned int>(std::ceil(m));
    for (std::size_t k = begin; k < end; ++k)
      {
        const auto i      = g.indices(k);
        bool       inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          inside = inside && i[d] >= gap && i[d] + gap < g.n[d];
        body.push_back(inside ? 1. : 0.);
      }
    return body;
  }

  template <int dim>
  std::string
  shape(const Grid<dim> &g)
  {
    std::string s;
    for (unsigned int d = 0; d < dim; ++d)
      s += (d ? "x" : "") + std::to_string(g.n[d]);
    return s;
  }

  Material
  material(const Model model, const double horizon, const int dim)
  {
    Material m;
    m.model   = model;
    m.horizon = horizon;
    m.micromodulus =
      (dim == 3 ? 12. / M_PI : 9. / M_PI) / std::pow(horizon, dim + 1);
    m.bulk_modulus  = 1.;
    m.shear_modulus = 0.6;
    return m;
  }

  double
  now()
  {
    return std::chrono::duration<double>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
  }

  /// The best time of f() within @p seconds (at least @p at_least runs);
  /// rank 0 decides when to stop (all ranks run f() as often).
  template <typename F>
  double
  best_time(const F &f, const double seconds, const unsigned int at_least)
  {
    double       best  = 1e300;
    const double start = now();
    for (unsigned int r = 0;; ++r)
      {
        int more = r < at_least || now() - start < seconds;
        MPI_Bcast(&more, 1, MPI_INT, 0, MPI_COMM_WORLD);
        if (!more)
          break;
        const double t = now();
        f();
        best = std::min(best, now() - t);
      }
    return best;
  }

  template <int dim>
  void
  run(const Options &o)
  {
    // (m, nodes, seconds per node, bonds) of the direct sums timed so far
    std::vector<std::array<double, 4>> direct_times;
    for (const unsigned int k : o.log2n)
      for (const double m : o.m)
        {
          const Grid<dim>   g    = grid<dim>(k);
          const Material    mat  = material(o.model, m, dim);
          const std::size_t N    = g.n_nodes();
          const Slab        slab = local_slab(g, MPI_COMM_WORLD);
          std::mt19937      generator(1 + o.rank);
          std::uniform_real_distribution<double> value(-1e-3, 1e-3);
          std::vector<double> u(dim * slab.n_nodes()), L, body, integrity;
          for (auto &v : u)
            v = value(generator);
          // The body fills the periodic box (no gap): the direct sum then
          // visits every node's every bond, as the FFT form does in any
          // case (with a body mask the direct sum skips the gap nodes, and
          // its cost shrinks by the body's share of the box). --body block:
          // a block with a gap of one horizon (both operators).
          body = body_mask(g, m, slab.begin, slab.end, o.block);
          integrity.clear();

          FftOptions options;
          options.threads          = o.threads;
          options.planning         = o.planning;
          options.communicator     = MPI_COMM_WORLD;
          options.keep_mask_fields = !o.lean;
          MPI_Barrier(MPI_COMM_WORLD);
          double           t0 = now();
          FftOperator<dim> fft(g, mat, options);
          fft.set_masks(body, integrity);
          MPI_Barrier(MPI_COMM_WORLD);
          const double setup = now() - t0;
          fft.apply(u, L); // untimed: first touch of the work space
          const std::size_t before = fft.n_transforms();
          fft.apply(u, L);
          const std::size_t transforms = fft.n_transforms() - before;
          const double      t_fft      = best_time(
            [&]() {
              fft.apply(u, L);
              MPI_Barrier(MPI_COMM_WORLD);
            },
            o.seconds,
            2);
          const double bytes          = fft.bytes_per_node();
          double       bytes_per_rank = fft.bytes();
          MPI_Allreduce(MPI_IN_PLACE,
                        &bytes_per_rank,
                        1,
                        MPI_DOUBLE,
                        MPI_MAX,
                        MPI_COMM_WORLD);
          // the fields a run needs at least: u and L (dim each), beta, and
          // for LPS m and theta
          const double minimum =
            8. * (2 * dim + 1 + (o.model == Model::lps ? 2 : 0));

          double      t_direct = 0.;
          std::size_t nd       = 0;
          std::size_t bonds    = 0;
          if (!o.skip_direct)
            {
              const Grid<dim> gd = grid<dim>(std::min(k, o.direct_log2));
              nd                 = gd.n_nodes();
              // the same (m, grid) was timed for a smaller N already
              const auto known =
                std::find_if(direct_times.begin(),
                             direct_times.end(),
                             [&](const auto &t) {
                               return t[0] == m && t[1] == double(nd);
                             });
              if (known != direct_times.end())
                {
                  t_direct = (*known)[2] * double(N);
                  bonds    = static_cast<std::size_t>((*known)[3]);
                }
              else
                {
                  DirectOperator<dim> direct(gd, mat, o.threads);
                  direct.set_masks(body_mask(gd, m, 0, nd, o.block), {});
                  std::vector<double> ud(dim * nd), Ld;
                  for (auto &v : ud)
                    v = value(generator);
                  bonds = direct.n_bonds_per_node();
                  const double per_node =
                    best_time([&]() { direct.apply(ud, Ld); }, o.seconds, 1) /
                    double(nd);
                  direct_times.push_back(
                    {{m, double(nd), per_node, double(bonds)}});
                  t_direct = per_node * double(N);
                }
            }
          if (o.rank != 0)
            continue;
          std::printf("%d,%s,%g,%u,%zu,%s,%zu,%.6e,%.3f,%zu,%.6e,%zu,%.3f,%.1f,"
                      "%.0f,%u,%d,%.0f,%s,%s,%zu\n",
                      dim,
                      model_name(o.model).c_str(),
                      m,
                      k,
                      N,
                      shape(g).c_str(),
                      bonds,
                      t_fft,
                      setup,
                      transforms,
                      t_direct,
                      nd,
                      t_direct > 0. ? t_direct / t_fft : 0.,
                      bytes,
                      minimum,
                      o.threads,
                      o.ranks,
                      bytes_per_rank,
                      o.lean ? "recomputed" : "kept",
                      o.block ? "block" : "box",
                      fft.n_layer_nodes());
          std::fflush(stdout);
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  const Options o = parse(argc, argv);
  if (o.header && o.rank == 0)
    std::printf("dim,model,m,log2n,nodes,grid,bonds,fft_seconds,fft_setup_"
                "seconds,transforms,direct_seconds,direct_nodes,speedup,fft_"
                "bytes_per_node,min_bytes_per_node,threads,ranks,fft_bytes_"
                "per_rank,mask_fields,body,layer_nodes\n");
  if (o.dim == 2)
    run<2>(o);
  else
    run<3>(o);
  MPI_Finalize();
  return 0;
}
