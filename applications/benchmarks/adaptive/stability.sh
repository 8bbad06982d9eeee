#!/usr/bin/env bash
# Where each method stops (issue 17): the three drivers of the bond-based fracture scenes pushed
# over their parameters, on the square plate with a hole of tests/scenes/adaptive_square_hole.prm
# (dx = 2.5 mm, 1 124 DoFs) pulled 0.275 mm, where the crack crosses the plate:
#   - Newton: load steps 2 ... 200 -> the load factor reached (it stops 'unstable' at the limit
#     point where the crack runs), step cuts;
#   - dynamic relaxation: fixed damping c = 0.05 ... 1.9 and the adaptive one, density factor
#     0.25 ... 4 -> iterations, or where it diverges;
#   - adaptive: N_i = 1 ... 10 and N_e = 10 ... 160 -> switches, relaxation iterations.
# Writes doc/benchmarks/adaptive_stability.csv and, when pdfem-plot is built,
# adaptive_stability_newton.png, _relaxation.png, _density.png, _switches.png (CHARTS_ONLY=1:
# redraw them from the CSV without running).
#
# Other cases: SCENE (a scene file), PULL (its `Boundary conditions/Dirichlet=...` override, empty
# for none) and PREFIX (the names of the CSV and charts, default adaptive_stability), e.g. case 3 on
# a 4 mm lattice: SCENE=applications/benchmarks/adaptive/three_point_bending_coarse.prm PULL=
# PREFIX=adaptive_stability_case3; case 4 on 5 mm: SCENE=tests/scenes/adaptive_multi_hole.prm
# PULL= PREFIX=adaptive_stability_case4.
#
# usage: applications/benchmarks/adaptive/stability.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
scene=$(realpath "${SCENE:-$root/tests/scenes/adaptive_square_hole.prm}")
pull=${PULL-"Boundary conditions/Dirichlet=bottom: x = 0; bottom: y = -0.000275*t; top: x = 0; top: y = 0.000275*t"}
prefix=${PREFIX:-adaptive_stability}
pull_args=()
[ -z "$pull" ] || pull_args=(--set "$pull")
csv="$out/$prefix.csv"
if [ -z "${CHARTS_ONLY:-}" ]; then # CHARTS_ONLY=1: redraw the charts of the existing CSV
echo "method,parameter,value,exit_state,load_reached,pdfem_s,relaxation_iterations,newton_iterations,step_cuts,switches,broken_bonds" > "$csv"

one() { # method parameter value [--set ...]
  local m=$1 p=$2 x=$3 d="$work/run"
  shift 3
  rm -rf "$d"
  "$pdfem" "$scene" --output "$d" --quiet "${pull_args[@]}" --set "Output/Write vtu=false" --set "Driver/Residual tolerance=1e-8" "$@" > /dev/null 2>&1 || true
  local reached
  reached=$(tail -n 1 "$d/history.csv" 2> /dev/null | cut -d, -f3)
  [ -n "$reached" ] && [ "$reached" != load_factor ] || reached=0
  opt() { "$get" get "$d/summary.json" "$1" 2> /dev/null || echo; }
  printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$m" "$p" "$x" "$(v "$d" exit_state)" "$reached" \
    "$(v "$d" timings.total)" "$(opt final.relaxation_iterations)" "$(opt final.newton_iterations)" \
    "$(opt stability.step_cuts)$(opt final.step_cuts)" "$(opt final.switches)" "$(v "$d" problem.broken_bonds)" |
    tee -a "$csv"
}

for n in 2 5 10 20 50 100 200; do
  one newton load_steps "$n" --set "Driver/Type=newton" --set "Driver/Load steps=$n"
done
for c in adaptive 0.05 0.2 0.5 1.0 1.5 1.9; do
  one relaxation damping "$c" --set "Driver/Type=dynamic relaxation" --set "Driver/Load steps=60" \
    --set "Driver/Dynamic relaxation/Damping=$c" --set "Driver/Dynamic relaxation/Max iterations=20000"
done
for f in 0.25 0.5 0.75 1 2 4; do
  one relaxation density_factor "$f" --set "Driver/Type=dynamic relaxation" --set "Driver/Load steps=60" \
    --set "Driver/Dynamic relaxation/Density factor=$f" --set "Driver/Dynamic relaxation/Max iterations=20000"
done
for ni in 1 2 3 5 10; do
  one adaptive implicit_steps "$ni" --set "Driver/Adaptive/Implicit steps=$ni"
done
for ne in 10 20 40 80 160; do
  one adaptive explicit_steps "$ne" --set "Driver/Adaptive/Explicit steps=$ne"
done
fi

if have_plot; then
  chart() { # method parameter y out [options]
    local y=$3 o=$4
    awk -F, -v m="$1" -v p="$2" -v col="$y" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; print $3 "," col }
      NR > 1 && $1 == m && $2 == p && $3 != "adaptive" { print $3 "," $(c[col]) }' "$csv" > "$work/$o.csv"
    shift 4
    xvfb-run -a "$plot" chart "$work/$o.csv" --x value --y "$y" --points "$@" --out "$out/$o.png" 2> /dev/null || true
  }
  # the facts the labels name, from the CSV: the adaptive damping's iterations and the runs that
  # did not complete
  adaptive_its=$(awk -F, '$1 == "relaxation" && $2 == "damping" && $3 == "adaptive" { print $7 }' "$csv")
  failed() { # method parameter -> "stopped: v1 (t = ...), v2 (t = ...)" or "all complete"
    awk -F, -v m="$1" -v p="$2" '$1 == m && $2 == p && $4 != "completed" { l = l (l ? ", " : "") $3 sprintf(" (t = %.2g)", $5) }
      END { print (l ? "stopped: " l : "all complete") }' "$csv"
  }
  chart newton load_steps load_reached "${prefix}_newton" --logx --xlabel "load steps" \
    --ylabel "load factor reached (Newton stops 'unstable')" --legend none \
    --title "Newton: where it stops, against the load steps"
  chart relaxation damping relaxation_iterations "${prefix}_relaxation" --logy \
    --xlabel "fixed damping c (adaptive: $adaptive_its iterations; $(failed relaxation damping))" --ylabel "relaxation iterations, all steps" \
    --legend none --title "Dynamic relaxation: iterations against the damping"
  chart relaxation density_factor relaxation_iterations "${prefix}_density" --logx \
    --xlabel "density factor ($(failed relaxation density_factor))" --ylabel "relaxation iterations, all steps" \
    --legend none --title "Dynamic relaxation: iterations against the fictitious density"
  chart adaptive explicit_steps switches "${prefix}_switches" --logx --xlabel "explicit steps N_e" \
    --ylabel "switches" --legend none --title "Adaptive: switches against N_e ($(failed adaptive explicit_steps))"
fi
echo "wrote $csv"
