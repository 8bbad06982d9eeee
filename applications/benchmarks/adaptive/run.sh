#!/usr/bin/env bash
# Adaptive explicit-implicit benchmark (issue 17): the adaptive driver against pure adaptive
# dynamic relaxation (ADR) and Newton-only load stepping on the fracture cases of Hu et al.
# (applications/examples/adaptive_fracture), one rank, runs alternated (adaptive, ADR, adaptive,
# ADR) so that both see the same machine load:
#   - speed-up of the adaptive scheme over ADR relaxed in increments as long as the adaptive
#     run's explicit ones (the same load path), its accuracy (relative L2 of u, largest damage
#     difference against that ADR run);
#   - Newton-only with 10 and 40 load steps: where it stops (exit state, load factor reached),
#     its time, its error against ADR where it completes.
# Writes doc/benchmarks/adaptive.csv and, when pdfem-plot is built, adaptive_accuracy.png
# (error against time). Whole-process time (wall) beside pdfem's own ("total" in summary.json).
#
# usage: applications/benchmarks/adaptive/run.sh [BUILD_DIR] [OUT_DIR]
# environment: CASES, the scenes (default "square_hole": a name of a scene of adaptive_fracture,
# or the path of a scene file, e.g. a coarser lattice of one), NEWTON_STEPS (default "10 40";
# empty: no Newton-only rows).
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
examples="$root/applications/examples/adaptive_fracture"
csv="$out/adaptive.csv"
echo "case,method,setting,exit_state,load_factor,wall_s,pdfem_s,relaxation_iterations,newton_iterations,switches,broken_bonds,l2_u_vs_adr,max_damage_diff_vs_adr" > "$csv"

run() { # dir scene [--set ...]: runs, prints its wall seconds
  local d=$1 scene=$2
  shift 2
  local t0 t1
  t0=$(date +%s.%N)
  "$pdfem" "$scene" --output "$d" --quiet --set "Output/Write vtu=false" --set "Output/Write nodes csv=true" "$@" \
    > /dev/null 2>&1 || true
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }'
}
row() { # case method setting dir wall reference_dir
  local d=$4 l2="" dd=""
  if [ -n "$6" ] && [ "$(v "$d" exit_state)" = completed ]; then
    l2=$("$get" fields "$d/nodes.csv" "$6/nodes.csv" l2 ux,uy 1e300 | sed -e 's/.*: \([^ ]*\) (tol.*/\1/')
    dd=$("$get" fields "$d/nodes.csv" "$6/nodes.csv" max damage 1e300 | sed -e 's/.*: \([^ ]*\) (tol.*/\1/')
  fi
  printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$1" "$2" "$3" "$(v "$d" exit_state)" \
    "$("$get" get "$d/summary.json" final.load_factor 2> /dev/null || echo)" "$5" "$(v "$d" timings.total)" \
    "$("$get" get "$d/summary.json" final.relaxation_iterations 2> /dev/null || echo)" \
    "$("$get" get "$d/summary.json" final.newton_iterations 2> /dev/null || echo)" \
    "$("$get" get "$d/summary.json" final.switches 2> /dev/null || echo)" \
    "$(v "$d" problem.broken_bonds)" "$l2" "$dd" | tee -a "$csv"
}

for case in ${CASES:-square_hole}; do
  scene="$examples/$case.prm"
  if [ -f "$case" ]; then
    scene=$(realpath "$case")
    case=$(basename "$case" .prm)
  fi
  # the adaptive run first: its explicit increment sets the ADR reference's load steps
  w_ad1=$(run "$work/$case-adaptive-1" "$scene")
  t_n=$(v "$work/$case-adaptive-1" final.first_switch_load_factor)
  n_e=$(sed -n 's/^ *set Explicit steps *= *\([0-9]*\).*/\1/p' "$scene")
  steps=$(awk -v t="$t_n" -v n="$n_e" 'BEGIN { printf "%d", n / (1 - t) + 0.5 }')
  w_adr1=$(run "$work/$case-adr-1" "$scene" --set "Driver/Type=dynamic relaxation" --set "Driver/Load steps=$steps")
  w_ad2=$(run "$work/$case-adaptive-2" "$scene")
  w_adr2=$(run "$work/$case-adr-2" "$scene" --set "Driver/Type=dynamic relaxation" --set "Driver/Load steps=$steps")
  ref="$work/$case-adr-1"
  row "$case" adr "$steps load steps" "$ref" "$w_adr1" ""
  row "$case" adaptive "run 1" "$work/$case-adaptive-1" "$w_ad1" "$ref"
  row "$case" adr "$steps load steps (run 2)" "$work/$case-adr-2" "$w_adr2" "$ref"
  row "$case" adaptive "run 2" "$work/$case-adaptive-2" "$w_ad2" "$ref"
  for n in ${NEWTON_STEPS-10 40}; do
    w=$(run "$work/$case-newton-$n" "$scene" --set "Driver/Type=newton" --set "Driver/Load steps=$n")
    row "$case" newton "$n load steps" "$work/$case-newton-$n" "$w" "$ref"
  done
done

if have_plot; then
  awk -F, 'NR > 1 && $12 != "" && $12 > 0 { print $2 "," $7 "," $12 }' "$csv" |
    sed '1i method,pdfem_s,l2_u_vs_adr' > "$work/accuracy.csv"
  xvfb-run -a "$plot" chart "$work/accuracy.csv" --x pdfem_s --y l2_u_vs_adr --points --logy \
    --out "$out/adaptive_accuracy.png" 2> /dev/null || true
fi
echo "wrote $csv"
