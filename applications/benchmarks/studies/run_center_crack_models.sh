#!/usr/bin/env bash
# The centre crack of doc/benchmarks/studies.md with every kind of model, by pdfem-study: K_I against
# the handbook value 9.1372e5 Pa sqrt(m) of
#   - FE only, the crack as a real slit (applications/benchmarks/operator/centre_crack_slit.geo, P1,
#     1 mm x the factor at the tips; interaction integral over 20-60 element sizes), mesh size factor
#     2, 1, 0.5                                                         (studies_cc_fe.csv/.png);
#   - FE with a PD band chosen by the crack: PD regions = none and Fracture/Adaptive margin = 2, 4, 8
#     element sizes around it, mesh size factor 1 and 0.5             (studies_cc_band.csv/.png);
#   - all PD, mesh size factor 1 and 0.5                                (studies_cc_all_pd.csv/.png);
# all at the default horizon m = 4 (the hand-drawn band |y| <= 0.15 m over m = 3, 5 is run.sh's study).
# Then one chart of the error against the run time for all of them (studies_cc_models.png, data
# studies_cc_models.csv). The charts need pdfem-plot (VTK; a display or xvfb-run).
#
#   applications/benchmarks/studies/run_center_crack_models.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
scene="$here/center_crack_strip.prm"
slit="$root/applications/benchmarks/operator/centre_crack_slit.geo"
reference=(--output final.crack_tips.tip0.K_I --reference 9.1372e5)

source "$here/study_common.sh"
study cc_fe "$scene" "${reference[@]}" --set "Mesh/Input file=$slit" --set "Mesh/PD regions=none" \
  --set "Fracture/Domain inner radius=20" --set "Fracture/Domain outer radius=60" \
  --vary "Mesh/Mesh size factor=2,1,0.5"
study cc_band "$scene" "${reference[@]}" --set "Mesh/PD regions=none" --vary "Mesh/Mesh size factor=1,0.5" \
  --vary "Fracture/Adaptive margin=2,4,8"
study cc_all_pd "$scene" "${reference[@]}" --set "Mesh/PD regions=all" --vary "Mesh/Mesh size factor=1,0.5"

# One table for one chart: a row per run, its error in the column of its model.
merged="$out/studies_cc_models.csv"
echo "wall_seconds,fe_slit,band_margin_2,band_margin_4,band_margin_8,all_pd,mesh_size_factor,dofs" > "$merged"
for name in cc_fe cc_band cc_all_pd; do
  f="$out/studies_$name.csv"
  awk -F, -v name="$name" -v w="$(column "$f" wall_seconds)" -v e="$(column "$f" final.crack_tips.tip0.K_I.error)" \
    -v s="$(column "$f" "Mesh/Mesh size factor")" -v m="$(column "$f" "Fracture/Adaptive margin")" \
    -v d="$(column "$f" dofs)" 'NR > 1 && $e != "" {
      c = name == "cc_fe" ? 1 : name == "cc_all_pd" ? 5 : ($m == 2 ? 2 : $m == 4 ? 3 : 4)
      row = $w
      for (i = 1; i <= 5; ++i) row = row "," (i == c ? ($e < 0 ? -$e : $e) : "")
      print row "," $s "," $d
    }' "$f" >> "$merged"
done
cat "$merged"
if have_plot; then
  xvfb-run -a "$plot" chart "$merged" --x wall_seconds \
    --y fe_slit,band_margin_2,band_margin_4,band_margin_8,all_pd --logx --logy --markers \
    --label "FE only (slit),PD band of 2 cells,PD band of 4 cells,PD band of 8 cells,all PD" \
    --xlabel "wall time of the run [s]" --ylabel "|relative error of K_I|" \
    --title "Centre crack: K_I error against run time, by model" --out "$out/studies_cc_models.png"
fi
