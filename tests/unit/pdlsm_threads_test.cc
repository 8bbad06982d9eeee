// SPDX-License-Identifier: LGPL-2.1-or-later
// The PDLSM fits of the set-up run on two threads (fit_every_family()):
// the same weights, bit for bit, as one family at a time, and the same
// family named, with the same count, when some cannot carry the fit.
//
// Each test raises deal.II's thread limit (main.cc sets 1) before the
// process makes ThreadTeam::shared(): ctest runs every unit test in a
// process of its own. Run together with other tests, they are skipped
// when the team was already made with one thread.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/pdlsm.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>
#include <sstream>

#include "pd_models_test_tools.h"
#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using namespace pdfem;

  /// ThreadTeam::shared() with two members, if this process can still
  /// have them.
  bool
  two_threads()
  {
    MultithreadInfo::set_thread_limit(2);
    return ThreadTeam::shared().size() == 2;
  }

  /// The PD nodes of a jittered n^3 lattice of spacing h = 1 / n, all of
  /// them owners (in @p order, or node order), with horizon m h.
  struct Lattice
  {
    Lattice(const unsigned int n, const double m)
    {
      const double                           h = 1. / n;
      std::mt19937                           random(5);
      std::uniform_real_distribution<double> jitter(-0.1 * h, 0.1 * h);
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            x.emplace_back(i * h + jitter(random),
                           j * h + jitter(random),
                           k * h + jitter(random));
      volume.assign(x.size(), h * h * h);
      horizon.assign(x.size(), m * h);
      boundary_area.assign(x.size(), Tensor<1, 3>());
      has_fe_cells.assign(x.size(), 0);
      std::vector<unsigned int> owners(x.size());
      std::iota(owners.begin(), owners.end(), 0u);
      set_owners(owners);
      region.position      = &x;
      region.volume        = &volume;
      region.pd_volume     = &volume;
      region.horizon       = &horizon;
      region.spacing       = h;
      region.has_fe_cells  = &has_fe_cells;
      region.boundary_area = &boundary_area;
      region.families      = &families;
      region.lambda        = 1.5e3;
      region.mu            = 1e3;
      region.source_file   = "test.prm";
    }
    void
    set_owners(const std::vector<unsigned int> &owners)
    {
      families = PD::find_families(x,
                                   horizon,
                                   owners,
                                   std::vector<std::uint8_t>(x.size(), 1));
    }
    /// Whether each family can carry the second-order fit, one family at
    /// a time (PDLSM::compute_weights() with the region's inputs).
    std::vector<bool>
    fits(const double weight_factor) const
    {
      const PDModels::PDLSM<3>  pdlsm(region.lambda, region.mu, weight_factor);
      std::vector<bool>         result;
      std::vector<Tensor<1, 3>> xi, a;
      std::vector<double>       v;
      std::vector<SymmetricTensor<2, 3>> b;
      for (std::size_t o = 0; o < families.owners.size(); ++o)
        {
          const unsigned int k = families.owners[o];
          xi.clear();
          v.clear();
          for (std::size_t j = families.offsets[o]; j < families.offsets[o + 1];
               ++j)
            {
              xi.push_back(x[families.members[j]] - x[k]);
              v.push_back(volume[families.members[j]]);
            }
          result.push_back(pdlsm.compute_weights(xi, v, horizon[k], a, b));
        }
      return result;
    }
    std::vector<Point<3>>     x;
    std::vector<double>       volume, horizon;
    std::vector<Tensor<1, 3>> boundary_area;
    std::vector<std::uint8_t> has_fe_cells;
    PD::Families              families;
    PDModels::Region<3>       region;
  };

  /// Everything a model's rows give at a random u: forces and tangents
  /// (row models), or family forces and tangents (family-element models).
  std::vector<double>
  rows(const PDModels::Interface<3> &model, const Lattice &lattice)
  {
    Field<3>                   u(lattice.x.size());
    std::mt19937               random(3);
    std::normal_distribution<> normal;
    for (double &v : u.values)
      v = 1e-3 * normal(random);
    const std::size_t   n = lattice.families.owners.size();
    std::vector<double> out;
    const auto          append = [&](const auto &tensors) {
      for (const auto &t : tensors)
        for (unsigned int i = 0; i < t.n_independent_components; ++i)
          out.push_back(t[t.unrolled_to_component_indices(i)]);
    };
    if (model.layout().family_elements)
      for (std::size_t o = 0; o < n; ++o)
        {
          std::vector<Tensor<1, 3>> f;
          std::vector<Tensor<2, 3>> K;
          model.family_forces(o, u.field(), f);
          model.family_tangent(o, u.field(), K);
          append(f);
          append(K);
        }
    else
      {
        out.resize(3 * n);
        model.forces(0, n, u.field(), out.data());
        for (std::size_t o = 0; o < n; ++o)
          {
            std::vector<Tensor<2, 3>> blocks;
            model.tangent_row(o, u.field(), blocks);
            append(blocks);
          }
      }
    return out;
  }

  /// The model's rows after initialize() (the fits on the threads) and
  /// after every family is fitted again, one at a time (a cut of no bond:
  /// the same bonds), are equal bit for bit.
  void
  expect_fits_as_one_at_a_time(
    const std::string                                      &name,
    const std::vector<std::pair<std::string, std::string>> &entries)
  {
    Lattice lattice(9, 3.);
    auto    model = make_model<3>(name, entries);
    model->initialize(lattice.region);
    const std::vector<double> on_threads = rows(*model, lattice);
    std::vector<std::size_t>  all(lattice.families.owners.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    model->reference_bonds_cut(all, true);
    const std::vector<double> one_at_a_time = rows(*model, lattice);
    ASSERT_EQ(on_threads.size(), one_at_a_time.size());
    ASSERT_GT(on_threads.size(), 0u);
    std::size_t n_different = 0;
    for (std::size_t i = 0; i < on_threads.size(); ++i)
      n_different +=
        std::memcmp(&on_threads[i], &one_at_a_time[i], sizeof(double)) != 0;
    EXPECT_EQ(n_different, 0u) << name;
  }

  TEST(PDLSMThreads, CollocatedFitsAreThoseOfOneFamilyAtATime)
  {
    if (!two_threads())
      GTEST_SKIP() << "ThreadTeam::shared() was made with one thread";
    expect_fits_as_one_at_a_time("pdlsm", {});
  }

  TEST(PDLSMThreads, EnergyFitsAreThoseOfOneFamilyAtATime)
  {
    if (!two_threads())
      GTEST_SKIP() << "ThreadTeam::shared() was made with one thread";
    for (const std::string fit : {"quadratic", "linear"})
      expect_fits_as_one_at_a_time("pdlsm energy",
                                   {{"Energy form/Gradient fit", fit},
                                    {"Energy form/Integration correction",
                                     "false"},
                                    {"Energy form/Broken bonds", "refit"}});
  }

  TEST(PDLSMThreads, BadFamilyIsTheFirstInFamilyOrder)
  {
    if (!two_threads())
      GTEST_SKIP() << "ThreadTeam::shared() was made with one thread";
    // m = 1.5: the families on the lattice's edges and corners are too
    // small for the fit. The owners come in a shuffled order with the
    // good families first, so that the first bad family (in family
    // order) lies far into the owners, among bad families on either
    // thread.
    const double              weight_factor = 0.33;
    Lattice                   lattice(10, 1.5);
    const std::vector<bool>   fits = lattice.fits(weight_factor);
    std::vector<unsigned int> good, bad;
    for (std::size_t o = 0; o < fits.size(); ++o)
      (fits[o] ? good : bad).push_back(lattice.families.owners[o]);
    ASSERT_GE(bad.size(), 50u);
    ASSERT_GE(good.size(), 200u);
    std::mt19937 random(9);
    std::shuffle(good.begin(), good.end(), random);
    std::shuffle(bad.begin(), bad.end(), random);
    std::vector<unsigned int> owners = good;
    owners.insert(owners.end(), bad.begin(), bad.end());
    lattice.set_owners(owners);

    // One family at a time: the count and the first bad one.
    const std::vector<bool> serial = lattice.fits(weight_factor);
    const std::size_t       first =
      std::find(serial.begin(), serial.end(), false) - serial.begin();
    ASSERT_EQ(first, good.size());
    std::ostringstream expected;
    expected << bad.size() << " PD node(s) have too few effective family "
             << "members for the second-order PDLSM fit with a = 0.33 (e.g. "
             << "the node at (" << lattice.x[owners[first]] << ") with "
             << lattice.families.offsets[first + 1] -
                  lattice.families.offsets[first]
             << " members)";

    for (int run = 0; run < 5; ++run)
      {
        auto model = make_model<3>("pdlsm", {{"Weight factor", "0.33"}});
        try
          {
            model->initialize(lattice.region);
            ADD_FAILURE() << "no error";
          }
        catch (const InputError &e)
          {
            EXPECT_NE(std::string(e.what()).find(expected.str()),
                      std::string::npos)
              << e.what() << "\nexpected: " << expected.str();
          }
      }
  }
} // namespace
