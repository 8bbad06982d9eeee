#!/usr/bin/env bash
# The plate-with-hole studies of doc/benchmarks/studies.md, by pdfem-study:
#  1. the peak stress sigma_xx at the hole against Heywood's 2.198e7 Pa over the mesh size factor
#     and the horizon factor (studies_plate_hole.csv/.png), and over the mesh size factor with and
#     without the PD band (Mesh/PD regions = pd, none: studies_plate_hole_fe.csv/.png);
#  2. the peak reaction of quasi-static growth from the hole with the hand-chosen band, the band
#     plus Fracture/Automatic region, all FE with no region and all FE with Automatic region, against
#     the all-PD run (studies_plate_hole_growth.csv/.png).
# The charts need pdfem-plot, i.e. VTK (and a display or xvfb-run).
#
#   applications/benchmarks/studies/run_plate_hole.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
source "$here/study_common.sh"
study plate_hole "$here/plate_with_hole.prm" \
  --vary "Mesh/Mesh size factor=1,0.7,0.5,0.35,0.25" --vary "Peridynamics/Horizon factor=3,4" \
  --output final.max_stress.xx --reference 2.198e7
study plate_hole_fe "$here/plate_with_hole.prm" \
  --vary "Mesh/Mesh size factor=1,0.7,0.5,0.35,0.25" --vary "Mesh/PD regions=pd,none" \
  --output final.max_stress.xx --reference 2.198e7
# "PD regions=none; Automatic region=0" has no PD, so nothing cracks: it runs all 80 steps and
# ends "completed" with the linear elastic reaction at the last step as its peak.
study plate_hole_growth "$here/plate_hole_growth.prm" \
  --vary "Mesh/PD regions=pd,none" --vary "Fracture/Automatic region=0,0.8" \
  --output peak_reaction.right.x --output final.pd_nodes --reference run:"Mesh/PD regions=all"
