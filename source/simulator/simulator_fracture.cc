// SPDX-License-Identifier: LGPL-2.1-or-later
// What the Simulator does about bonds breaking besides the crack criterion:
// the PD model's own history (bonds degraded for good), fragments cut loose,
// and whether the body still carries the load.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/fracture/automatic_region.h>
#include <pdfem/fracture/crack_growth.h>

#include <deal.II/base/mpi.h>

#include "simulator_impl.h"

namespace pdfem
{
  using namespace dealii;

  template <int dim>
  unsigned long
  Simulator<dim>::Impl::accept_model_state(
    const Drivers::SystemInterface::Vector &u_now)
  {
    const unsigned long failed = coupled->accept_state(u_now);
    if (failed > 0)
      hold_fragments();
    return failed;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::hold_fragments()
  {
    // Fragments cut loose (a few PD nodes bonded only to each other) are
    // held where they are: unheld, they make the next solve singular.
    const unsigned long held = coupled->hold_fragments(
      Fracture::CrackGrowth<dim>::smallest_piece(coupled->size().n_nodes));
    if (held > 0 && progress)
      *progress << "  " << held
                << " PD nodes of fragments cut loose are held where they are\n";
  }

  template <int dim>
  void
  Simulator<dim>::Impl::separated_by_model(
    const Drivers::StepRecord &record) const
  {
    const unsigned int pieces = coupled->count_pieces(
      Fracture::CrackGrowth<dim>::smallest_piece(coupled->size().n_nodes));
    if (pieces > 1)
      throw RunFailure("separated",
                       "the bonds the PD model failed cut the body into " +
                         std::to_string(pieces) + " pieces at step " +
                         std::to_string(record.step) + " (load factor " +
                         number(record.load_factor) + ")");
  }

  template <int dim>
  void
  Simulator<dim>::Impl::separated_by_load(const double          t,
                                          Drivers::GrowthCheck &check)
  {
    // The grips' secant stiffness: the reactions over the largest
    // prescribed displacement (none: load control, where a cut body has no
    // equilibrium instead). Below 1e-3 of its peak the body no longer
    // carries load, even if a few bonds still link its pieces (a strip
    // cut across by the max principal stress criterion kept 3e-5 of its
    // peak through a handful of bonds; issue 19).
    Drivers::SystemInterface::Vector prescribed;
    coupled->initialize_vector(prescribed);
    coupled->apply_dirichlet(prescribed, t);
    const double displacement = prescribed.linfty_norm();
    if (!(displacement > 0.))
      return;
    double reaction = 0.;
    for (const auto &r : coupled->reactions())
      reaction += r.norm();
    const double stiffness = reaction / displacement;
    peak_grip_stiffness    = std::max(peak_grip_stiffness, stiffness);
    if (stiffness < 1e-3 * peak_grip_stiffness)
      {
        check.separated = true;
        check.separation =
          "the grips carry " + number(100. * stiffness / peak_grip_stiffness) +
          " % of the load per displacement they carried at the peak";
      }
  }

  template <int dim>
  bool
  Simulator<dim>::Impl::grow_region_by_stress(double &load_ratio)
  {
    const auto &f = setup.fracture;
    if (!results)
      update_results(u);
    const Fracture::RegionGrowth growth =
      Fracture::extend_pd_region_by_stress(*coupled,
                                           *results,
                                           f.automatic_region *
                                             f.tensile_strength,
                                           f.adaptive_margin,
                                           setup.cell_is_pd);
    load_ratio = growth.load_ratio;
    if (growth.new_pd_cells == 0)
      return false;
    rebuild_coupled();
    results.reset();
    if (progress)
      *progress << "  PD region: " << growth.new_pd_cells
                << " FE cells reached " << f.automatic_region
                << " x the tensile strength (with their margin) and became "
                   "PD; the step is solved again\n";
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::rebuild_coupled()
  {
    // The fracture history (cuts, bonds broken one by one, fragments held)
    // replayed on the new families, as a restart does.
    StateArchive history;
    coupled->save_fracture_state(history);
    coupled.reset();
    coupled = std::make_unique<Coupling::CoupledSystem<dim>>(*setup.tria,
                                                             setup.cell_is_pd,
                                                             setup.settings);
    coupled->restore_fracture_state(history);
    if (cracks)
      cracks->attach(*coupled);
  }

#define INSTANTIATE(dim)                                                        \
  template bool          Simulator<dim>::Impl::grow_region_by_stress(double &); \
  template void          Simulator<dim>::Impl::rebuild_coupled();               \
  template unsigned long Simulator<dim>::Impl::accept_model_state(              \
    const Drivers::SystemInterface::Vector &);                                  \
  template void Simulator<dim>::Impl::hold_fragments();                         \
  template void Simulator<dim>::Impl::separated_by_model(                       \
    const Drivers::StepRecord &) const;                                         \
  template void Simulator<dim>::Impl::separated_by_load(                        \
    double, Drivers::GrowthCheck &);
  PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace pdfem
