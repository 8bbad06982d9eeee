#!/usr/bin/env bash
# The explicit-against-Newmark studies of doc/benchmarks/studies.md, by pdfem-study, on the peer's
# dynamic plateCrack input (platCrack_NewMarkOFF_FC2.in, converted by pdfem-convert: 14 280 DoFs,
# grips pulled apart at 1 m/s for 0.55 ms, lumped mass):
#  1. with dynamic fracture (max principal stress, the input as given): the peak reaction of the
#     right grip, the load factor (time / end time) of that peak, and the broken bonds, against
#     central differences at dt = 1.25e-7 s (0.06 dt_crit) (studies_dynamics_fracture.csv/.png);
#  2. the same without fracture (Fracture/Criterion = none): the elastic response of the cracked
#     plate (studies_dynamics_elastic.csv/.png).
# Both vary the driver (explicit = central differences, newmark = average acceleration, both with the
# lumped mass) and the time step from 0.12 to 13 times the explicit critical step 2.08e-6 s. An
# explicit step above the critical one is refused before the first step ('time step too large'),
# which the study keeps as a failed run (pdfem-study then exits 3: expected here).
# Needs ../shared (the peer's inputs); the charts need pdfem-plot (VTK; a display or xvfb-run).
#
#   applications/benchmarks/studies/run_dynamics.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
input="$peer/platCrack_NewMarkOFF_FC2.in"
if [ ! -f "$input" ]; then
  echo "run_dynamics.sh: $input not found (the peer's inputs beside the checkout)" >&2
  exit 1
fi
"$build/bin/pdfem-convert" "$input" --output "$work/plate" > /dev/null
scene="$work/plate/platCrack_NewMarkOFF_FC2.prm"

source "$here/study_common.sh"
grid=(--vary "Driver/Type=explicit,newmark"
  --vary "Driver/Time step=2.5e-7,5e-7,1e-6,1.87e-6,4e-6,1e-5,2.75e-5")
reference='run:Driver/Type=explicit;Driver/Time step=1.25e-7'
study dynamics_fracture "$scene" "${grid[@]}" \
  --output peak_reaction.RF.x --output peak_reaction.RF.x_load_factor --output problem.broken_bonds \
  --reference "$reference"
study dynamics_elastic "$scene" --set "Fracture/Criterion=none" "${grid[@]}" \
  --output peak_reaction.RF.x --output final.max_displacement.y --reference "$reference"
