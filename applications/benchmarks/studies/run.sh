#!/usr/bin/env bash
# The study of doc/benchmarks/studies.md: K_I of the centre crack in a strip against the handbook
# value, over the mesh size factor and the horizon factor, by pdfem-study. Writes
# doc/benchmarks/studies_center_crack.csv and .png (the chart needs pdfem-plot, i.e. VTK).
#
#   applications/benchmarks/studies/run.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
"$build/bin/pdfem-study" "$here/center_crack_strip.prm" \
  --vary "Mesh/Mesh size factor=1,0.5,0.4" --vary "Peridynamics/Horizon factor=3,5" \
  --output final.crack_tips.tip0.K_I --output final.crack_tips.tip1.K_I \
  --reference 9.1372e5 --reference 9.1372e5 -o "$work/study"
cp "$work/study/study.csv" "$out/studies_center_crack.csv"
if [ -f "$work/study/study.png" ]; then
  cp "$work/study/study.png" "$out/studies_center_crack.png"
fi
