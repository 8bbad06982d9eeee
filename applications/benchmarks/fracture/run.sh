#!/usr/bin/env bash
# Fracture benchmark: accuracy of the stress-intensity factors and cost of crack growth.
#
#   1. inclined central crack in a large plate (specs/004 §6.1), beta = 0..90 degrees, annuli
#      4-10, 5-12 and 6-14 element sizes, on the
#      paper's mesh (39 x 39 PD cells) and on a finer one (79 x 79): K_I, K_II against
#      sigma sqrt(pi a) cos^2(beta), sigma sqrt(pi a) cos(beta) sin(beta) -> sif_inclined.csv;
#   2. centre and edge cracks in a strip against the handbook, and FE models with a real slit
#      (plateCrack, edge crack) as references for what the integral gives on an exact
#      discontinuity -> sif_references.csv;
#   3. PDLSM-FEM's plateCrack quasi-static FC1 and FC2 inputs (read in place from ../shared):
#      peak reaction, its displacement and wall time against the peer's baseline, the
#      load-displacement chart and a picture of the crack path -> growth_peer.csv, PNGs;
#   4. the adaptive PD region against an all-PD and a band model of the same growth scene
#      -> growth_adaptive.csv;
#   5. mixed-mode growth on mostly-PD meshes (mixed_mode_plate.prm: 62.7 and 81.3 % PD cells,
#      cracks at 30 and 45 degrees; the peer's operator, and once the energy form that
#      Model = auto picks), meshed in the run and read from the mesh file it wrote: pdfem's own
#      and the whole process's time, the solver's share and iterations -> growth_mixed_mode.csv,
#      a picture of one crack path.
# Writes CSV and PNG files into doc/benchmarks/ (PNG only when pdfem-plot is built).
#
# usage: [SECTIONS=1234] applications/benchmarks/fracture/run.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
sections=${SECTIONS:-12345} # e.g. SECTIONS=3 runs only the peer inputs

# ---- 1. inclined crack
if [[ $sections == *1* ]]; then
csv="$out/fracture_sif_inclined.csv"
echo "mesh,annulus,beta_deg,tip,K_I,K_II,K_I_exact,K_II_exact,K_I_error_of_K0,K_II_error_of_K0" > "$csv"
for n in 39 79; do
  sed "s/^n  = 39;/n  = $n;/" "$root/meshes/inclined_crack.geo" > "$work/inclined_$n.geo"
  for annulus in "4 10" "5 12" "6 14"; do
    read -r r_in r_out <<< "$annulus"
    for beta in 0 15 30 45 60 75 90; do
      crack=$(awk -v b="$beta" 'BEGIN { r = b * atan2(0, -1) / 180; c = 0.02 * cos(r); s = 0.02 * sin(r);
                                        printf "(%.17g, %.17g) -- (%.17g, %.17g)", -c, -s, c, s }')
      dir="$work/inclined_${n}_${r_in}_$beta"
      "$pdfem" "$root/applications/examples/inclined_crack/inclined_crack.prm" --quiet --output "$dir" \
        --set "Mesh/Input file=$work/inclined_$n.geo" --set "Peridynamics/Pre-existing cracks=$crack" \
        --set "Output/Write vtu=false" --set "Fracture/Domain inner radius=$r_in" \
        --set "Fracture/Domain outer radius=$r_out"
      for tip in tip0 tip1; do
        KI=$("$get" get "$dir/summary.json" final.crack_tips.$tip.K_I)
        KII=$("$get" get "$dir/summary.json" final.crack_tips.$tip.K_II)
        awk -v n="$n" -v a="$r_in-$r_out" -v b="$beta" -v t="$tip" -v KI="$KI" -v KII="$KII" 'BEGIN {
          r = b * atan2(0, -1) / 180; K0 = 70e6 * sqrt(atan2(0, -1) * 0.02);
          eI = K0 * cos(r)^2; eII = K0 * cos(r) * sin(r);
          printf "%s,%s,%s,%s,%.6e,%.6e,%.6e,%.6e,%.5f,%.5f\n", n, a, b, t, KI, KII, eI, eII, (KI - eI) / K0, (KII - eII) / K0 }' >> "$csv"
      done
    done
  done
done
fi

# ---- 2. handbook strips and slit references
if [[ $sections == *2* ]]; then
csv="$out/fracture_sif_references.csv"
echo "case,model,dofs,K_I,reference,relative_error" > "$csv"
strip() { # name scene reference [--set ...]
  local name=$1 scene=$2 reference=$3; shift 3
  local dir="$work/$name"
  "$pdfem" "$scene" --quiet --output "$dir" --set "Output/Write vtu=false" "$@" 2> /dev/null
  local K; K=$("$get" get "$dir/summary.json" final.crack_tips.tip0.K_I)
  printf '%s,%s,%s,%.6e,%.6e,%s\n' "${name%%:*}" "${name#*:}" "$("$get" get "$dir/summary.json" problem.dofs)" \
    "$K" "$reference" "$(awk -v k="$K" -v r="$reference" 'BEGIN { printf "%.4f", (k - r) / r }')" >> "$csv"
}
scenes="$root/tests/scenes"
fine=(--set "Mesh/Input file=$root/tests/meshes/cracked_strip_fine.geo" --set "Linear solver/Type=gmres")
free=(--set "Peridynamics/Crack faces=free surface")
for faces in cut free; do
  [ $faces = cut ] && opt=() || opt=("${free[@]}")
  strip "centre strip:$faces h=0.02" "$scenes/sif_center_crack_strip.prm" 9.1372e5 ${opt[@]+"${opt[@]}"}
  strip "centre strip:$faces h=0.01" "$scenes/sif_center_crack_strip.prm" 9.1372e5 "${fine[@]}" ${opt[@]+"${opt[@]}"}
  for nu in 0; do
    strip "centre strip:$faces h=0.02 nu=$nu" "$scenes/sif_center_crack_strip.prm" 9.1372e5 \
      --set "Material/Poisson's ratio=$nu" ${opt[@]+"${opt[@]}"}
  done
  strip "centre strip:$faces h=0.02 plane strain" "$scenes/sif_center_crack_strip.prm" 9.1372e5 \
    --set "Material/Plane model=plane strain" ${opt[@]+"${opt[@]}"}
  strip "edge strip:$faces h=0.02" "$scenes/sif_edge_crack_strip.prm" 1.67799e6 ${opt[@]+"${opt[@]}"}
  strip "edge strip:$faces h=0.01" "$scenes/sif_edge_crack_strip.prm" 1.67799e6 "${fine[@]}" ${opt[@]+"${opt[@]}"}
  strip "edge strip:$faces all pd h=0.02" "$scenes/sif_edge_crack_strip.prm" 1.67799e6 \
    --set "Mesh/PD regions=all" --set "Linear solver/Type=gmres" ${opt[@]+"${opt[@]}"}
done
gmsh -2 "$here/edge_crack_slit.geo" -format msh22 -o "$work/edge_slit.msh" -v 0
sed -e "s|../../meshes/cracked_strip.geo|$work/edge_slit.msh|" -e 's/  set PD regions = pd/  set PD regions = none/' \
  "$scenes/sif_edge_crack_strip.prm" > "$work/edge_slit.prm"
strip "edge strip:fe slit 1 mm" "$work/edge_slit.prm" 1.67799e6 \
  --set "Fracture/Domain inner radius=20" --set "Fracture/Domain outer radius=60"
for f in 1 0.5; do
  gmsh -2 "$here/plate_crack_slit.geo" -clscale $f -format msh22 -o "$work/slit_$f.msh" -v 0
  sed "s|plate_crack_slit.geo|$work/slit_$f.msh|" "$here/plate_crack_slit.prm" > "$work/slit_$f.prm"
  strip "plateCrack:fe slit clscale $f" "$work/slit_$f.prm" 3.7329e6
done
if [ -d "$peer" ]; then
  strip "plateCrack:pdlsm-fem (peer mesh)" "$root/tests/scenes/peer_plate_crack_static.in" 3.7329e6
fi

fi

# ---- 3. the peer's quasi-static inputs
if [[ $sections == *3* ]]; then
if [ -d "$peer" ]; then
  csv="$out/fracture_growth_peer.csv"
  echo "input,steps,exit_state,peak_RF,peak_step,peak_U,peer_peak_RF,peer_peak_U,wall_s,peer_wall_s,speedup,solve_s,criterion_s,linear_iterations" > "$csv"
  for fc in 1 2; do
    input="$peer/platCrack_quasiStatic_FC$fc.in"
    dir="$work/peer_fc$fc"
    start=$(date +%s.%N)
    "$pdfem" "$input" --quiet --output "$dir" 2> /dev/null || true
    wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", e - s }')
    s="$dir/summary.json"
    if [ $fc = 1 ]; then ppeak=3.8787e7; pu=2.9497e-4; pwall=55.5; else ppeak=4.0170e7; pu=3.1533e-4; pwall=69.3; fi
    its=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "linear_iterations") c = i } NR > 1 { s += $c } END { print s }' "$dir/history.csv")
    printf 'FC%s,%s,%s,%.5e,%s,%.5e,%s,%s,%s,%s,%.1f,%.2f,%.2f,%s\n' "$fc" "$("$get" get "$s" steps)" \
      "$("$get" get "$s" exit_state)" "$("$get" get "$s" peak_reaction.RF.x)" "$("$get" get "$s" peak_reaction.RF.x_step)" \
      "$(awk -v t="$("$get" get "$s" peak_reaction.RF.x_load_factor)" 'BEGIN { print t * 4.79e-5 }')" \
      "$ppeak" "$pu" "$wall" "$pwall" "$(awk -v w="$wall" -v p="$pwall" 'BEGIN { print p / w }')" \
      "$("$get" get "$s" timings.solve)" "$("$get" get "$s" timings.criterion)" "$its" >> "$csv"
    # load-displacement: U = 4.79e-5 t
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "load_factor") t = i; if ($i == "reaction_RF_x") r = i }
                       print "U,reaction_RF_x"; next }
             { printf "%.6e,%.6e\n", $t * 4.79e-5, $r }' "$dir/history.csv" > "$out/fracture_peer_fc${fc}_curve.csv"
    printf 'U,peer_peak\n%s,%s\n' "$pu" "$ppeak" > "$work/peer_fc$fc.csv"
    if have_plot; then
      xvfb-run -a "$plot" chart "$out/fracture_peer_fc${fc}_curve.csv" --x U --y reaction_RF_x \
        --csv2 "$work/peer_fc$fc.csv" --y2 peer_peak --points --label "pdfem,PDLSM-FEM peak (baseline)" \
        --xlabel "prescribed displacement U [m]" --ylabel "reaction RF [N/m]" \
        --title "plateCrack quasi-static FC$fc: reaction against displacement" \
        --out "$out/fracture_peer_fc${fc}_curve.png"
      last=$(ls "$dir"/solution_*.pvtu | sort | tail -n 1)
      xvfb-run -a "$plot" field "$last" --field damage --lines "$dir/crack_paths.vtk" --edges \
        --zoom -0.55 0.55 -0.55 0.55 --title "plateCrack FC$fc: damage and crack path (last step)" \
        --out "$out/fracture_peer_fc${fc}_path.png"
    fi
  done
fi

fi

# ---- 4. adaptive PD region
if [[ $sections == *4* ]]; then
csv="$out/fracture_growth_adaptive.csv"
echo "model,pd_cells_start,pd_cells_end,cells,peak_reaction,peak_step,steps,exit_state,solve_s,total_s" > "$csv"
for scene in growth_mcts_all_pd growth_mcts_center_crack growth_mcts_adaptive; do
  dir="$work/$scene"
  "$pdfem" "$scenes/$scene.prm" --quiet --output "$dir" --set "Linear solver/Type=gmres" 2> /dev/null || true
  s="$dir/summary.json"
  printf '%s,%s,%s,%s,%.6e,%s,%s,%s,%.2f,%.2f\n' "$scene" "$("$get" get "$s" problem.pd_cells)" \
    "$("$get" get "$s" final.pd_cells)" "$("$get" get "$s" problem.cells)" "$("$get" get "$s" peak_reaction.top.y)" \
    "$("$get" get "$s" peak_reaction.top.y_step)" "$("$get" get "$s" steps)" "$("$get" get "$s" exit_state)" \
    "$("$get" get "$s" timings.solve)" "$("$get" get "$s" timings.total)" >> "$csv"
  if [ "$scene" = growth_mcts_adaptive ] && have_plot; then
    "$pdfem" "$scenes/$scene.prm" --quiet --output "$dir-vtu" --set "Linear solver/Type=gmres" \
      --set "Output/Write vtu=true" 2> /dev/null || true
    xvfb-run -a "$plot" field "$dir-vtu/solution_00000.pvtu" --field pd_region --lines "$dir-vtu/crack_paths.vtk" \
      --edges --zoom -0.55 0.55 -0.3 0.3 --title "Adaptive PD region (yellow) after the crack cut the strip" \
      --out "$out/fracture_adaptive_region.png"
  fi
done
fi

# ---- 5. mixed-mode growth on mostly-PD meshes
if [[ $sections == *5* ]]; then
csv="$out/fracture_growth_mixed_mode.csv"
echo "model,n_pd,theta_deg,mesh_input,dofs,pd_cell_share,steps,exit_state,peak_RF,solves,linear_iterations,solve_s,criterion_s,pdfem_s,process_wall_s,peak_memory_mb" > "$csv"
# mixed MODEL N_PD THETA INPUT: INPUT "geo" meshes mixed_mode_plate.geo in the run (pdfem calls gmsh);
# "msh" reads the mesh the geo run wrote, as the peer reads its mesh file (the same cells and
# numbering: history.csv is the same bit for bit), so that the time compares like with like.
mixed() {
  local model=$1 n_pd=$2 theta=$3 input=$4 crack dir mesh write_vtu=false start wall its
  sed "s/^n_pd = 47;/n_pd = $n_pd;/" "$here/mixed_mode_plate.geo" > "$work/mixed_mode_plate_$n_pd.geo"
  crack=$(awk -v t="$theta" 'BEGIN { r = t * atan2(0, -1) / 180; x = 0.098 * sin(r); y = 0.098 * cos(r);
                                     printf "(0, 0) -- (%.17g, %.17g); (0, 0) -- (%.17g, %.17g)", x, y, -x, -y }')
  dir="$work/mixed_${model// /_}_${n_pd}_$theta"
  mesh="$work/mixed_mode_plate_$n_pd.geo"
  if [ "$input" = msh ]; then
    mesh="$dir/mixed_mode_plate_$n_pd.msh"
    dir="$dir-msh"
  fi
  [ "$model$n_pd$theta$input" = pdlsm4745geo ] && write_vtu=true
  start=$(date +%s.%N)
  "$pdfem" "$here/mixed_mode_plate.prm" --quiet --output "$dir" --set "Mesh/Input file=$mesh" \
    --set "Peridynamics/Pre-existing cracks=$crack" --set "Peridynamics/Model=$model" \
    --set "Output/Write vtu=$write_vtu" --set "Output/Write every=1000" 2> /dev/null || true
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", e - s }')
  its=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "linear_iterations") c = i } NR > 1 { s += $c } END { print s }' "$dir/history.csv")
  printf '%s,%s,%s,%s,%s,%.3f,%s,%s,%.5e,%s,%s,%.2f,%.2f,%.2f,%s,%.0f\n' "$(v "$dir" pd_model.name)" "$n_pd" "$theta" "$input" \
    "$(v "$dir" problem.dofs)" "$(awk -v p="$(v "$dir" problem.pd_cells)" -v c="$(v "$dir" problem.cells)" 'BEGIN { print p / c }')" \
    "$(v "$dir" steps)" "$(v "$dir" exit_state)" "$(v "$dir" peak_reaction.RF.x)" \
    "$(v "$dir" linear_solver.choice.solves)" "$its" "$(v "$dir" timings.solve)" "$(v "$dir" timings.criterion)" \
    "$(v "$dir" timings.total)" "$wall" "$(v "$dir" peak_memory_mb_rank0)" >> "$csv"
}
for n_pd in 47 61; do
  for theta in 30 45; do
    mixed pdlsm "$n_pd" "$theta" geo
    mixed pdlsm "$n_pd" "$theta" msh
  done
done
# The operator pdfem chooses for cracked scenes (Model = auto): the energy form.
mixed auto 47 45 geo
if have_plot; then
  last=$(ls "$work"/mixed_pdlsm_47_45/solution_*.pvtu | sort | tail -n 1)
  xvfb-run -a "$plot" field "$last" --field damage --lines "$work/mixed_pdlsm_47_45/crack_paths.vtk" --edges \
    --zoom -0.55 0.55 -0.55 0.55 --title "Mixed-mode growth: 62.7 % PD, crack at 45 degrees" \
    --out "$out/fracture_mixed_mode_path.png"
fi
fi
echo "Results in $out/fracture_*.csv"
