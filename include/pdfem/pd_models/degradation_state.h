// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_MODELS_DEGRADATION_STATE_H
#define PDFEM_PD_MODELS_DEGRADATION_STATE_H

namespace pdfem
{
  namespace PDModels
  {
    /**
     * How far the smooth degradation of a PD model (bond based with
     * `Degradation = tanh`, specs/003 §1.4) has gone at a state, for drivers
     * that switch on it (`adaptive`; Layout::smooth_degradation says
     * whether a model has one, else all members are 0). Bonds are counted
     * in both directions (each family holds its own), over all ranks.
     */
    struct DegradationState
    {
      /// Bonds whose stretch (the largest of the accepted states with an
      /// irreversible history) passed the switch threshold, a fraction of
      /// the onset stretch s_m; failed bonds included.
      unsigned long n_beyond_threshold = 0;
      /// Bonds failed for good (stretch past s_c).
      unsigned long n_failed = 0;
      /// The degradation sum_bonds (1 - T(s)): 0 for an intact body; a
      /// failed bond counts 1.
      double degradation = 0.;
      /// max_bonds s / s_m over the intact bonds.
      double max_onset_ratio = 0.;
    };
  } // namespace PDModels
} // namespace pdfem

#endif
