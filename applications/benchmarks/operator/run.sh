#!/usr/bin/env bash
# Operator benchmark (issue 16, item 4): accuracy against cost of the two PDLSM operators and of
# plain finite elements with the crack as a real slit (no PD at all), at three mesh sizes each:
#
#   a. K_I of a centre crack in a strip against the handbook (Tada/Feddersen)  -> operator_centre_crack.csv
#   b. K_I of an edge crack in a strip against the handbook (Brown & Srawley)  -> operator_edge_crack.csv
#      (also every variant with matrix-free GMRES besides MUMPS                -> operator_solver.csv)
#   c. K_I, K_II of an inclined centre crack (beta = 30 deg) in a large plate  -> operator_inclined.csv
#   d. the peak stress at a hole in a long strip against Heywood's value       -> operator_hole.csv
#   e. quasi-static MCTS growth from the inclined crack of (c): peak load and
#      crack path against LEFM (initiation load, kink angle)                   -> operator_growth.csv,
#                                                                                 operator_growth_paths.csv
#
# Operators ("model" column): "pdlsm" (collocated, the peer's; crack faces = cut bonds, the default),
# "pdlsm free faces" (the same with Crack faces = free surface, fracture.md §2), "pdlsm energy" (the
# energy form, theory.md §12; its fit and stabilisation in the "fit" and "stabilisation" columns; the
# defaults are linear and 1), and "fe" (PD regions = none; for the cracks a mesh with the crack as a slit
# of width 2e-5). The energy form's Gradient fit (linear, quadratic) x Stabilisation (0.1, 1, 10) is
# swept on (a), (b) and (d). Wall times: "total_s" is pdfem's own (summary.json timings.total: reading
# the mesh, set-up, solve, criterion, output), "process_s" the whole process (date before and after;
# it adds the start-up of the shared libraries). Every mesh is made by gmsh before the runs, so
# meshing is in neither. One run at a time. Static cases (a)-(d) use pdfem's default linear solver
# for 2D (direct, MUMPS); the growth case (e) uses matrix-free GMRES with "amg fe" for every model,
# because the direct solver factorises again at every growth step (4x slower for the energy form).
# A run that fails is recorded with its exit code, exit state and the first error line ("note").
# Writes the CSV files and, when pdfem-plot and xvfb-run are there, PNG charts into OUT_DIR
# (default doc/benchmarks/operator_*).
#
# usage: [SECTIONS=abcde] applications/benchmarks/operator/run.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
# here, root, build, out, pdfem, plot, get, work (removed on exit); Open MPI as root.
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
# A build folder that holds libpdfem.so beside bin/ (an installed snapshot) needs it on the path.
if [ -f "$build/libpdfem.so" ]; then export LD_LIBRARY_PATH="$build${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"; fi
out=$(cd "$out" && pwd)
sections=${SECTIONS:-abcde}
scenes="$root/tests/scenes"
script_start=$(date +%s.%N)
load_before=$(cut -d ' ' -f 1 /proc/loadavg)

# ---- helpers

# val SUMMARY KEY: a value of summary.json, empty when the key (or the file) is missing.
val() { "$get" get "$1" "$2" 2> /dev/null || true; }
# kval SUMMARY KEY: a result, only from a run that completed (rc = 0): a stopped run's K is not one.
kval() { if [ "$rc" = 0 ]; then val "$1" "$2"; fi; }

# run DIR SCENE [pdfem options]: one pdfem run; sets rc (exit code) and process_s (whole-process wall
# time). Output and errors go to DIR.log.
run() {
  local dir=$1 scene=$2
  shift 2
  local start
  start=$(date +%s.%N)
  rc=0
  "$pdfem" "$scene" --quiet --output "$dir" --set "Output/Write vtu=false" "$@" > "$dir.log" 2>&1 || rc=$?
  process_s=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.3f", e - s }')
}

# The columns every CSV ends with.
common_header="linear_solver,exit_code,exit_state,dofs,pd_nodes,total_s,setup_s,solve_s,process_s,linear_iterations,peak_mb,force_imbalance,constraint_residual,correction_iterations,note"
# common DIR SOLVER: those columns for the run just made in DIR (rc and process_s from run()).
common() {
  local dir=$1 solver=$2 s="$1/summary.json" state="no summary.json" its="" note=""
  [ -f "$s" ] && state=$(val "$s" exit_state)
  [ -f "$dir/history.csv" ] && its=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "linear_iterations") c = i }
                                              NR > 1 && c { n += $c } END { if (c) print n }' "$dir/history.csv")
  if [ "$rc" != 0 ]; then
    note=$(val "$s" message)
    [ -n "$note" ] || note=$(grep -m 1 -i "error" "$dir.log" || head -n 1 "$dir.log" || true)
    note=$(printf '%s' "$note" | tr ',"\n' ';  ')
  fi
  printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,"%s"' "$solver" "$rc" "$state" "$(val "$s" problem.dofs)" \
    "$(val "$s" problem.pd_nodes)" "$(val "$s" timings.total)" "$(val "$s" timings.setup)" \
    "$(val "$s" timings.solve)" "$process_s" "$its" "$(val "$s" peak_memory_mb_rank0)" \
    "$(val "$s" force_balance.max_imbalance)" "$(val "$s" "pd_model.integration constraint residual")" \
    "$(val "$s" "pd_model.integration correction iterations")" "$note"
}

# set_variant NAME: the model options (array vopts) and the CSV labels model, fit, stab of a variant:
# pdlsm | pdlsm-free | energy:FIT:STABILISATION[:BROKEN_BONDS] | fe (BROKEN_BONDS: refit; model
# "pdlsm energy refit"; the default condense is "pdlsm energy").
set_variant() {
  fit="" stab=""
  case $1 in
    pdlsm) model="pdlsm"; vopts=(--set "Peridynamics/Model=pdlsm") ;;
    pdlsm-free) model="pdlsm free faces"
      vopts=(--set "Peridynamics/Model=pdlsm" --set "Peridynamics/Crack faces=free surface") ;;
    energy:*) IFS=: read -r _ fit stab broken <<< "$1"; model="pdlsm energy${broken:+ $broken}"
      vopts=(--set "Peridynamics/Model=pdlsm energy" --set "Peridynamics/Energy form/Gradient fit=$fit"
             --set "Peridynamics/Energy form/Stabilisation=$stab"
             --set "Peridynamics/Energy form/Broken bonds=${broken:-condense}") ;;
    fe) model="fe"; vopts=(--set "Mesh/PD regions=none") ;;
  esac
}

msh() { # GEO MSH [gmsh options]: mesh a .geo once (format 2.2), so that no run pays for meshing
  local geo=$1 msh=$2
  shift 2
  gmsh -2 "$geo" -format msh22 -o "$msh" -v 0 "$@"
}

# wide LONG_CSV X Y SCALE AWK_PROGRAM > a CSV for pdfem-plot chart: column x and one column per series,
# empty where a row belongs to another series. The awk program sees the row's fields by name in f[]
# and selects the row by setting s to its series' name; Y is multiplied by SCALE (100: per cent).
wide() {
  awk -F, -v X="$2" -v Y="$3" -v scale="$4" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    { for (k in col) f[k] = $col[k]; s = ""; '"$5"'
      if (s != "" && f[X] != "" && f[Y] != "") { if (!(s in seen)) { seen[s] = ++ns; name[ns] = s }
                                                 row[++nr] = seen[s]; xs[nr] = f[X]; ys[nr] = scale * f[Y] } }
    END { printf "x"; for (j = 1; j <= ns; ++j) printf ",%s", name[j]; print ""
          for (r = 1; r <= nr; ++r) { printf "%s", xs[r]; for (j = 1; j <= ns; ++j) printf ",%s", (j == row[r] ? ys[r] : ""); print "" } }' "$1"
}
columns() { head -n 1 "$1" | cut -d, -f2-; } # the series of a wide CSV
by_x() { awk 'NR == 1 { print; fflush(); next } { print | "sort -t, -k1,1g" }'; } # rows of a wide CSV in the order of x
time_label="pdfem wall time (summary.json timings.total) [s]"
# chart WIDE_CSV OUT_PNG [pdfem-plot options]: every series of a wide CSV against x, log x axis.
chart() {
  local csv=$1 png=$2; shift 2
  xvfb-run -a "$plot" chart "$csv" --x x --y "$(columns "$csv")" --logx "$@" --out "$png"
}
# pair_chart SOLID.csv DASHED.csv OUT_PNG [options]: two wide CSVs in one chart, log x axis.
pair_chart() {
  local a=$1 b=$2 png=$3; shift 3
  xvfb-run -a "$plot" chart "$a" --x x --y "$(columns "$a")" --csv2 "$b" --y2 "$(columns "$b")" --logx \
    --label "$(columns "$a"),$(columns "$b")" "$@" --out "$png"
}
# error_charts CSV NAME TITLE Y YLABEL SWEEP_SERIES: error Y against time (the energy form at its defaults)
# -> operator_NAME.png, and against the energy form's stabilisation, one series per fit and mesh named
# by the awk expression SWEEP_SERIES -> operator_NAME_sweep.png.
error_charts() {
  local csv=$1 name=$2 title=$3 y=$4 ylabel=$5 series=$6
  have_plot || return 0
  wide "$csv" total_s "$y" 100 'if (f["model"] != "pdlsm energy" || (f["fit"] == "linear" && f["stabilisation"] == 1)) {
      s = f["model"]; if (s == "pdlsm energy") s = "pdlsm energy (linear; 1)" }' > "$work/$name.csv"
  chart "$work/$name.csv" "$out/operator_$name.png" --xlabel "$time_label" --ylabel "$ylabel" \
    --title "$title: error against time"
  wide "$csv" stabilisation "$y" 100 'if (f["model"] == "pdlsm energy") s = f["fit"] " fit; " '"$series" | by_x \
    > "$work/${name}_sweep.csv"
  chart "$work/${name}_sweep.csv" "$out/operator_${name}_sweep.png" \
    --xlabel "Energy form/Stabilisation [x shear modulus]" --ylabel "$ylabel" \
    --title "$title: pdlsm energy, fit and stabilisation"
}

# ---- meshes

# Strip meshes (meshes/cracked_strip.geo): h = 0.02, 0.01, 0.005 (the band keeps an odd number of
# cells across, so that y = 0 is a row of cell centres and no node lies on the cracks).
declare -A strip_cells=([0.02]="50 15 34" [0.01]="100 31 68" [0.005]="200 61 136")
strip_sizes="0.02 0.01 0.005"
if [[ $sections == *a* || $sections == *b* ]]; then
  for h in $strip_sizes; do
    read -r nx ny nb <<< "${strip_cells[$h]}"
    sed -e "s/^nx = 50;/nx = $nx;/" -e "s/^ny = 15;/ny = $ny;/" -e "s/^nb = 34;/nb = $nb;/" \
      "$root/meshes/cracked_strip.geo" > "$work/strip_$h.geo"
    msh "$work/strip_$h.geo" "$work/strip_$h.msh"
  done
  # FE slits: 2, 1 and 0.5 mm at the tips (gmsh -clscale 2, 1, 0.5 of 1 mm).
  for f in 2 1 0.5; do
    msh "$here/centre_crack_slit.geo" "$work/centre_slit_$f.msh" -clscale "$f"
    msh "$root/applications/benchmarks/fracture/edge_crack_slit.geo" "$work/edge_slit_$f.msh" -clscale "$f"
  done
fi

energy_variants="energy:linear:1 energy:linear:0.1 energy:linear:10 energy:quadratic:0.1 energy:quadratic:1 energy:quadratic:10"

# ---- a, b: centre and edge cracks in the strip (tests/scenes/sif_*_strip.prm), m = 4, annulus 4-10 h.
# The handbook values hold to 0.1 % (centre) and 0.5 % (edge). The FE slits take the annulus
# 20-60 mm at every mesh size (20/f to 60/f tip elements).
strip_case() { # CASE SCENE REFERENCE CSV SLIT_PREFIX
  local case=$1 scene=$2 reference=$3 csv=$4 slit=$5 h f v dir K
  echo "case,model,fit,stabilisation,mesh,h,K_I,K_I_ref,K_I_error,K_II,$common_header" > "$csv"
  for h in $strip_sizes; do
    for v in pdlsm pdlsm-free $energy_variants; do
      set_variant "$v"
      dir="$work/${case}_${v//:/_}_$h"
      run "$dir" "$scene" "${vopts[@]}" --set "Mesh/Input file=$work/strip_$h.msh"
      K=$(kval "$dir/summary.json" final.crack_tips.tip0.K_I)
      printf '%s,%s,%s,%s,strip h=%s,%s,%s,%s,%s,%s,%s\n' "$case" "$model" "$fit" "$stab" "$h" "$h" "$K" "$reference" \
        "$(awk -v k="$K" -v r="$reference" 'BEGIN { if (k != "") printf "%.6f", (k - r) / r }')" \
        "$(kval "$dir/summary.json" final.crack_tips.tip0.K_II)" "$(common "$dir" direct)" >> "$csv"
    done
  done
  for f in 2 1 0.5; do
    set_variant fe
    dir="$work/${case}_fe_$f"
    run "$dir" "$scene" "${vopts[@]}" --set "Mesh/Input file=$work/${slit}_$f.msh" \
      --set "Fracture/Domain inner radius=$(awk -v f="$f" 'BEGIN { print 20 / f }')" \
      --set "Fracture/Domain outer radius=$(awk -v f="$f" 'BEGIN { print 60 / f }')"
    K=$(kval "$dir/summary.json" final.crack_tips.tip0.K_I)
    printf '%s,fe slit,,,slit clscale %s,%s,%s,%s,%s,%s,%s\n' "$case" "$f" "$(awk -v f="$f" 'BEGIN { print f / 1000 }')" \
      "$K" "$reference" "$(awk -v k="$K" -v r="$reference" 'BEGIN { if (k != "") printf "%.6f", (k - r) / r }')" \
      "$(kval "$dir/summary.json" final.crack_tips.tip0.K_II)" "$(common "$dir" direct)" >> "$csv"
  done
}

# Error against pdfem's wall time for the default variants, and the sweep of the energy form.
strip_charts() { # CSV NAME TITLE
  error_charts "$1" "$2" "$3" K_I_error "K_I / handbook - 1 [%]" '"h = " f["h"]'
}

if [[ $sections == *a* ]]; then
  strip_case centre "$scenes/sif_center_crack_strip.prm" 9.1372e5 "$out/operator_centre_crack.csv" centre_slit
  strip_charts "$out/operator_centre_crack.csv" centre_crack "Centre crack"
fi
if [[ $sections == *b* ]]; then
  strip_case edge "$scenes/sif_edge_crack_strip.prm" 1.67799e6 "$out/operator_edge_crack.csv" edge_slit
  strip_charts "$out/operator_edge_crack.csv" edge_crack "Edge crack"
  # The same runs with matrix-free GMRES + "amg fe" (the solver for large 2D and 3D), iteration limit
  # 500 (the converging runs take 60-120): how each variant suits the FE-built preconditioner.
  csv="$out/operator_solver.csv"
  echo "case,model,fit,stabilisation,mesh,h,K_I,K_I_error,$common_header" > "$csv"
  for h in $strip_sizes; do
    for v in pdlsm pdlsm-free $energy_variants; do
      set_variant "$v"
      dir="$work/solver_${v//:/_}_$h"
      run "$dir" "$scenes/sif_edge_crack_strip.prm" "${vopts[@]}" --set "Mesh/Input file=$work/strip_$h.msh" \
        --set "Linear solver/Type=gmres" --set "Linear solver/Max iterations=500"
      K=$(kval "$dir/summary.json" final.crack_tips.tip0.K_I)
      printf 'edge,%s,%s,%s,strip h=%s,%s,%s,%s,%s\n' "$model" "$fit" "$stab" "$h" "$h" "$K" \
        "$(awk -v k="$K" 'BEGIN { if (k != "" && k != 0) printf "%.6f", (k - 1.67799e6) / 1.67799e6 }')" \
        "$(common "$dir" "gmres amg fe")" >> "$csv"
    done
  done
fi

# ---- c: inclined central crack, beta = 30 deg, 2a = 40 mm, W = 1 m, sigma = 70 MPa
# (applications/examples/inclined_crack, specs/004 §6.1): K_I = K0 cos^2(beta),
# K_II = K0 cos(beta) sin(beta), K0 = sigma sqrt(pi a), infinite plate (the finite width adds +0.10 %).
# Errors in units of K0 (fracture.md's measure), of the mean of the two tips; tip_spread is their
# largest difference. PD box of n x n cells, n = 39 (the paper's mesh), 79, 159; m = 4, annulus 4-10 h.
# FE slit: 0.5, 0.25, 0.125 mm at the tips, annulus 5-12 mm.
beta=30
crack=$(awk -v b="$beta" 'BEGIN { r = b * atan2(0, -1) / 180; c = 0.02 * cos(r); s = 0.02 * sin(r);
                                  printf "(%.17g, %.17g) -- (%.17g, %.17g)", -c, -s, c, s }')
incl_prm="$root/applications/examples/inclined_crack/inclined_crack.prm"
incl_mesh() { # N: the PD box of meshes/inclined_crack.geo with N x N cells
  [ -f "$work/inclined_$1.msh" ] && return 0
  sed "s/^n  = 39;/n  = $1;/" "$root/meshes/inclined_crack.geo" > "$work/inclined_$1.geo"
  msh "$work/inclined_$1.geo" "$work/inclined_$1.msh"
}
inclined_row() { # MODEL FIT STAB MESH H DIR SOLVER: one row of operator_inclined.csv
  local s="$6/summary.json"
  printf '%s,%s,%s,%s,%s,%s,%s\n' "$1" "$2" "$3" "$4" "$5" \
    "$(awk -v a="$(kval "$s" final.crack_tips.tip0.K_I)" -v b="$(kval "$s" final.crack_tips.tip1.K_I)" \
           -v c="$(kval "$s" final.crack_tips.tip0.K_II)" -v d="$(kval "$s" final.crack_tips.tip1.K_II)" -v beta="$beta" 'BEGIN {
       r = beta * atan2(0, -1) / 180; K0 = 70e6 * sqrt(atan2(0, -1) * 0.02); eI = K0 * cos(r)^2; eII = K0 * cos(r) * sin(r)
       if (a == "" || b == "") { printf ",,%.6e,%.6e,,,", eI, eII; exit }
       KI = (a + b) / 2; KII = (c + d) / 2; sp = (a > b ? a - b : b - a); t = (c > d ? c - d : d - c); if (t > sp) sp = t
       printf "%.6e,%.6e,%.6e,%.6e,%.6f,%.6f,%.2e", KI, KII, eI, eII, (KI - eI) / K0, (KII - eII) / K0, sp / K0 }')" \
    "$(common "$6" "$7")"
}
if [[ $sections == *c* || $sections == *e* ]]; then
  for f in 2 1 0.5; do
    sed "s/^beta = 30;/beta = $beta;/" "$here/inclined_crack_slit.geo" > "$work/inclined_slit.geo"
    msh "$work/inclined_slit.geo" "$work/inclined_slit_$f.msh" -clscale "$f"
  done
  csv="$out/operator_inclined.csv"
  echo "model,fit,stabilisation,mesh,h,K_I,K_II,K_I_exact,K_II_exact,K_I_error_of_K0,K_II_error_of_K0,tip_spread_of_K0,$common_header" > "$csv"
  for n in 39 79 159; do
    incl_mesh $n
    for v in pdlsm pdlsm-free energy:linear:1; do
      set_variant "$v"
      dir="$work/inclined_${v//:/_}_$n"
      run "$dir" "$incl_prm" "${vopts[@]}" --set "Mesh/Input file=$work/inclined_$n.msh" \
        --set "Peridynamics/Pre-existing cracks=$crack"
      inclined_row "$model" "$fit" "$stab" "box n=$n" "$(awk -v n="$n" 'BEGIN { printf "%.6g", 0.1 / n }')" "$dir" direct >> "$csv"
    done
  done
  for f in 2 1 0.5; do
    set_variant fe
    dir="$work/inclined_fe_$f"
    run "$dir" "$incl_prm" "${vopts[@]}" --set "Mesh/Input file=$work/inclined_slit_$f.msh" \
      --set "Peridynamics/Pre-existing cracks=$crack" \
      --set "Fracture/Domain inner radius=$(awk -v f="$f" 'BEGIN { print 5 / (0.25 * f) }')" \
      --set "Fracture/Domain outer radius=$(awk -v f="$f" 'BEGIN { print 12 / (0.25 * f) }')"
    inclined_row "fe slit" "" "" "slit clscale $f" "$(awk -v f="$f" 'BEGIN { print 0.00025 * f }')" "$dir" direct >> "$csv"
  done
  if have_plot; then
    wide "$csv" total_s K_I_error_of_K0 100 's = f["model"] " K_I"' > "$work/incl_I.csv"
    wide "$csv" total_s K_II_error_of_K0 100 's = f["model"] " K_II"' > "$work/incl_II.csv"
    pair_chart "$work/incl_I.csv" "$work/incl_II.csv" "$out/operator_inclined.png" \
      --xlabel "$time_label" --ylabel "(K - exact) / K0 [%]" \
      --title "Inclined crack, 30 deg: K_I (solid), K_II (dashed)"
  fi
fi

# ---- d: plate with a hole (applications/examples/plate_with_hole: d/W = 0.2, m = 3, PD band
# |x| <= 0.2 inside FE), gmsh sizes x 1, 0.5, 0.25. Peak sigma_xx against Heywood's finite-width value
# sigma (2 + (1 - d/W)^3) / (1 - d/W) = 2.198e7 Pa (Howland's series via Peterson's fit: 2.195e7).
# FE: the same mesh with PD regions = none (nodal stresses extrapolated from the Gauss points and
# averaged, theory.md §6).
if [[ $sections == *d* ]]; then
  csv="$out/operator_hole.csv"
  echo "model,fit,stabilisation,mesh,h_hole,sigma_max,reference,error,$common_header" > "$csv"
  hole_prm="$root/applications/examples/plate_with_hole/plate_with_hole.prm"
  for f in 1 0.5 0.25; do
    msh "$root/meshes/plate_with_hole.geo" "$work/hole_$f.msh" -clscale "$f"
    for v in pdlsm $energy_variants fe; do
      set_variant "$v"
      dir="$work/hole_${v//:/_}_$f"
      run "$dir" "$hole_prm" "${vopts[@]}" --set "Mesh/Input file=$work/hole_$f.msh"
      S=$(kval "$dir/summary.json" final.max_stress.xx)
      printf '%s,%s,%s,size x %s,%s,%s,2.198e7,%s,%s\n' "$model" "$fit" "$stab" "$f" \
        "$(awk -v f="$f" 'BEGIN { print 0.01 * f }')" "$S" \
        "$(awk -v k="$S" 'BEGIN { if (k != "") printf "%.6f", (k - 2.198e7) / 2.198e7 }')" "$(common "$dir" direct)" >> "$csv"
    done
  done
  error_charts "$csv" hole "Plate with a hole" error "peak sigma_xx / Heywood - 1 [%]" '"sizes x " f["h_hole"] / 0.01'
fi

# ---- e: quasi-static growth from the inclined crack of (c). Traction 70 MPa x t on top and bottom,
# K_Ic = 1.5e7 Pa sqrt(m), MCTS (theory.md §10), growth length 1 cell, load increment 0.25: three
# steps below the critical load, then the driver's jump to 1.001 x its extrapolated critical load,
# where the crack grows at constant load (unstable under a traction). PD box n = 39, 59, 79; the runs
# stop after N = round(0.256 n) growth steps (about 25.6 mm per tip, which stays inside the box).
# LEFM (MCTS with the exact K of (c)): kink theta_c = 2 atan((K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)),
# K_eq = K_I cos^3(theta_c/2) - 1.5 K_II cos(theta_c/2) sin(theta_c); peak load 1.001 K_Ic / K_eq per unit
# load factor (the driver's jump factor included, so that the error is the model's; under a traction
# LEFM's peak is its initiation load, the model's peak is the largest load factor of the run, its
# initiation that of the first step that breaks bonds); first segment at
# beta + theta_c to the x axis. The FE slit cannot grow a crack: its rows are the same LEFM formulas
# with the K of the slit models of (c). Path: the tip at +a (the other is its point image: "symmetry"
# is |tip0 + tip1| at the end). Matrix-free GMRES + amg fe for every model.
if [[ $sections == *e* ]]; then
  csv="$out/operator_growth.csv"
  paths="$out/operator_growth_paths.csv"
  echo "model,mesh,h,growth_steps,initiation_load_factor,initiation_error,peak_load_factor,peak_stress,peak_ref,peak_error,kink_deg,kink_ref_deg,kink_error_deg,chord_deg,last_segments_deg,tip_x,tip_y,symmetry_m,$common_header" > "$csv"
  echo "model,mesh,point,x,y" > "$paths"
  read -r ref_t ref_kink <<< "$(awk -v beta="$beta" -v kic=1.5e7 'BEGIN { pi = atan2(0, -1); r = beta * pi / 180
    K0 = 70e6 * sqrt(pi * 0.02); KI = K0 * cos(r)^2; KII = K0 * cos(r) * sin(r)
    th = 2 * atan2(KI - sqrt(KI^2 + 8 * KII^2), 4 * KII); Keq = KI * cos(th / 2)^3 - 1.5 * KII * cos(th / 2) * sin(th)
    printf "%.9g %.6f", 1.001 * kic / Keq, beta + th * 180 / pi }')"
  grow=(--set "Driver/Type=quasi-static" --set "Driver/Load increment=0.25" --set "Fracture/Fracture toughness=1.5e7"
        --set "Boundary conditions/Traction=top: normal = 70e6 * t; bottom: normal = 70e6 * t"
        --set "Linear solver/Type=gmres" --set "Peridynamics/Pre-existing cracks=$crack")
  tip1=$(awk -v b="$beta" 'BEGIN { r = b * atan2(0, -1) / 180; printf "%.17g %.17g", 0.02 * cos(r), 0.02 * sin(r) }')
  for n in 39 59 79; do
    incl_mesh $n
    N=$(awk -v n="$n" 'BEGIN { printf "%d", 0.256 * n + 0.5 }')
    for v in pdlsm pdlsm-free energy:linear:1 energy:linear:1:refit; do
      set_variant "$v"
      dir="$work/growth_${v//:/_}_$n"
      run "$dir" "$incl_prm" "${vopts[@]}" "${grow[@]}" --set "Mesh/Input file=$work/inclined_$n.msh" \
        --set "Driver/Load steps=$((3 + N))"
      # Initiation: the load factor of the first step that broke bonds. Peak: the largest load factor
      # of the run (a kinked tip may need a little more load before it runs on).
      read -r t0 t <<< "$( [ -f "$dir/history.csv" ] && awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "load_factor") l = i; if ($i == "n_broken_bonds") b = i }; next }
                   NR == 2 { b0 = $b } NR > 2 && $b > b0 && !t { t = $l } $l > m { m = $l } END { if (t) print t, m }' "$dir/history.csv" || true)"
      # Path of the tip at +a: the points after the initial tip in crack_paths.csv (crack 0 runs from
      # the end of tip 0 to the end of tip 1).
      geo=""
      if [ -f "$dir/crack_paths.csv" ]; then
        geo=$(awk -F, -v t="$tip1" -v ref="$ref_kink" -v model="$model" -v mesh="box n=$n" -v paths="$paths" '
          BEGIN { split(t, p, " ") } NR > 1 && $1 == 0 { k++; X[k] = $3; Y[k] = $4 }
          END { for (j = 1; j <= k; ++j) if ((X[j] - p[1])^2 + (Y[j] - p[2])^2 < 1e-16) i = j
                if (!i || k == i) { print ",,,,,,,,"; exit }
                d = 180 / atan2(0, -1); for (j = i; j <= k; ++j) printf "%s,%s,%d,%s,%s\n", model, mesh, j - i, X[j], Y[j] >> paths
                kink = atan2(Y[i + 1] - Y[i], X[i + 1] - X[i]) * d; m = (k - 3 > i ? k - 3 : i)
                printf "%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.6g,%.6g,%.3g", k - i, kink, ref, kink - ref,
                  atan2(Y[k] - Y[i], X[k] - X[i]) * d, atan2(Y[k] - Y[m], X[k] - X[m]) * d, X[k], Y[k], sqrt((X[1] + X[k])^2 + (Y[1] + Y[k])^2) }' "$dir/crack_paths.csv")
      fi
      [ -n "$geo" ] || geo=",,,,,,,,"
      IFS=, read -r steps kink kref kerr chord last tx ty sym <<< "$geo"
      printf '%s,box n=%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$model" "$n" \
        "$(awk -v n="$n" 'BEGIN { printf "%.6g", 0.1 / n }')" "$steps" "$t0" \
        "$(awk -v t="$t0" -v r="$ref_t" 'BEGIN { if (t != "") printf "%.6f", t / r - 1 }')" "$t" \
        "$(awk -v t="$t" 'BEGIN { if (t != "") printf "%.6e", 70e6 * t }')" "$(awk -v t="$ref_t" 'BEGIN { printf "%.6e", 70e6 * t }')" \
        "$(awk -v t="$t" -v r="$ref_t" 'BEGIN { if (t != "") printf "%.6f", t / r - 1 }')" \
        "$kink" "$kref" "$kerr" "$chord" "$last" "$tx" "$ty" "$sym" "$(common "$dir" "gmres amg fe")" >> "$csv"
    done
  done
  # The FE slit rows: LEFM with the K of the slit models of (c) (timings are those runs').
  for f in 2 1 0.5; do
    dir="$work/inclined_fe_$f"
    s="$dir/summary.json"
    rc=$(awk -F, -v m="slit clscale $f" '$4 == m { print $(NF - 13) }' "$out/operator_inclined.csv")
    process_s=$(awk -F, -v m="slit clscale $f" '$4 == m { print $(NF - 6) }' "$out/operator_inclined.csv")
    fe=$(awk -v a="$(kval "$s" final.crack_tips.tip1.K_I)" -v b="$(kval "$s" final.crack_tips.tip1.K_II)" -v ref="$ref_kink" \
           -v rt="$ref_t" -v kic=1.5e7 -v beta="$beta" 'BEGIN { if (a == "") { print ",,,,,,,,"; exit }
      pi = atan2(0, -1); th = 2 * atan2(a - sqrt(a^2 + 8 * b^2), 4 * b); Keq = a * cos(th / 2)^3 - 1.5 * b * cos(th / 2) * sin(th)
      t = 1.001 * kic / Keq; k = beta + th * 180 / pi
      printf "%.9g,%.6f,%.9g,%.6e,%.6e,%.6f,%.3f,%.3f,%.3f", t, t / rt - 1, t, 70e6 * t, 70e6 * rt, t / rt - 1, k, ref, k - ref }')
    printf 'fe slit (LEFM from K),slit clscale %s,%s,,%s,,,,,,%s\n' "$f" "$(awk -v f="$f" 'BEGIN { print 0.00025 * f }')" \
      "$fe" "$(common "$dir" direct)" >> "$csv"
  done
  if have_plot; then
    wide "$csv" total_s initiation_error 100 's = f["model"] " initiation"' > "$work/growth_i.csv"
    wide "$csv" total_s peak_error 100 's = f["model"] " peak"' > "$work/growth_p.csv"
    pair_chart "$work/growth_i.csv" "$work/growth_p.csv" "$out/operator_growth.png" \
      --xlabel "$time_label" --ylabel "load / LEFM initiation load - 1 [%]" \
      --title "Growth: initiation (solid) and peak (dashed) load"
    # Paths on the finest mesh, the LEFM kink over the first 3 mm and the initial crack.
    wide "$paths" x y 1 'if (f["mesh"] == "box n=79") s = f["model"] " (n = 79)"; if (f["mesh"] == "box n=39") s = f["model"] " (n = 39)"' \
      > "$work/paths.csv"
    awk -v t="$tip1" -v k="$ref_kink" -v beta="$beta" 'BEGIN { split(t, p, " "); r = k * atan2(0, -1) / 180
      print "x,initial crack,LEFM kink"; printf "%.9g,%.9g,\n%.9g,%.9g,%.9g\n", p[1] - 0.003 * cos(beta * atan2(0, -1) / 180),
        p[2] - 0.003 * sin(beta * atan2(0, -1) / 180), p[1], p[2], p[2]; printf "%.9g,,%.9g\n", p[1] + 0.003 * cos(r), p[2] + 0.003 * sin(r) }' \
      > "$work/paths_ref.csv"
    xvfb-run -a "$plot" chart "$work/paths.csv" --x x --y "$(columns "$work/paths.csv")" \
      --csv2 "$work/paths_ref.csv" --y2 "initial crack,LEFM kink" \
      --label "$(columns "$work/paths.csv"),initial crack (end),LEFM kink (first 3 mm)" \
      --xlabel "x [m]" --ylabel "y [m]" --title "Growth from the inclined crack: path of the tip at +a" \
      --out "$out/operator_growth_path.png"
  fi
fi

# ---- the run's setting
{
  echo "date,pdfem_version,cpu,cores,load_before,load_after,script_s"
  printf '%s,%s,"%s",%s,%s,%s,%s\n' "$(date +%F)" "$("$pdfem" --version | tr ',' ';')" \
    "$(grep -m 1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')" "$(nproc)" "$load_before" \
    "$(cut -d ' ' -f 1 /proc/loadavg)" "$(awk -v s="$script_start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.0f", e - s }')"
} > "$out/operator_setup.csv"
echo "Results in $out/operator_*.csv"
