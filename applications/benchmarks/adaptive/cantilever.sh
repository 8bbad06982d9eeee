#!/usr/bin/env bash
# Case 1 of Hu et al. (specs/003 §5.1, §5.3): the 3D cantilever
# (applications/examples/bond_based_cantilever/cantilever_3d.prm), 5000 N on the free end, no bond
# degrades. The adaptive driver, Newton and pure adaptive dynamic relaxation (ADR) on the same
# scene, run after one another PAIRS times (adaptive, Newton, ADR, adaptive, Newton, ADR, ...) so
# that each sees the same machine load. Every run has the same model: bond based with the tanh
# degradation at s_m = 0.01, s_c = 0.02 (the adaptive driver needs an onset; the largest stretch of
# this case is ~1e-4, so no bond reaches it and the adaptive run stays implicit, as in the paper),
# the same relative residual tolerance TOL, one rank.
#
# Writes OUT_DIR/adaptive_cantilever.csv: method, run, pdfem's own time (summary.json
# timings.total), the whole process's wall time, Newton and relaxation iterations, tip deflection
# (final.min_displacement.z) and its difference from Euler-Bernoulli's 1.0e-3 m.
#
# usage: applications/benchmarks/adaptive/cantilever.sh [BUILD_DIR] [OUT_DIR]
#   environment: FACTOR (Mesh/Mesh size factor, default 1: dx = 2 cm; 0.5 is the paper's 1 cm),
#                PAIRS (default 2), TOL (default 1e-8), SOLVER (direct, the scene's, or cg: every
#                run with matrix-free CG preconditioned by 'amg fe'; the relaxation then bounds
#                the tangent's rows without assembling it; or auto: Linear solver/Type = auto,
#                which takes that CG for the bond-based model)
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
scene="$root/applications/examples/bond_based_cantilever/cantilever_3d.prm"
factor=${FACTOR:-1} pairs=${PAIRS:-2} tol=${TOL:-1e-8}
csv="$out/adaptive_cantilever.csv"
echo "mesh_size_factor,solver,method,run,exit_state,pdfem_s,wall_s,newton_iterations,relaxation_iterations,tip_z,tip_vs_euler_bernoulli" > "$csv"
common=(--quiet --set "Mesh/Mesh size factor=$factor" --set "Driver/Residual tolerance=$tol"
  --set "Peridynamics/Bond based/Degradation=tanh" --set "Peridynamics/Bond based/Onset stretch=0.01"
  --set "Peridynamics/Bond based/Critical stretch=0.02")
solver=${SOLVER:-direct}
if [ "$solver" = cg ]; then
  common+=(--set "Linear solver/Type=cg" --set "Linear solver/Preconditioner=amg fe")
elif [ "$solver" = auto ]; then
  common+=(--set "Linear solver/Type=auto")
fi
declare -A args
args[adaptive]="Driver/Type=adaptive;Driver/Adaptive/Implicit steps=1;Driver/Adaptive/Explicit steps=1;Driver/Adaptive/Quiet steps=1;Driver/Adaptive/Damage tolerance=1e-3"
args[newton]="Driver/Type=newton;Driver/Load steps=1"
args[adr]="Driver/Type=dynamic relaxation;Driver/Load steps=1"
for run in $(seq 1 "$pairs"); do
  for method in adaptive newton adr; do
    d="$work/$method-$run"
    sets=()
    IFS=';' read -ra list <<< "${args[$method]}"
    for s in "${list[@]}"; do sets+=(--set "$s"); done
    t0=$(date +%s.%N)
    "$pdfem" "$scene" --output "$d" "${common[@]}" "${sets[@]}" > "$d.log" 2>&1 || true
    t1=$(date +%s.%N)
    wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')
    # the newton driver counts its iterations in history.csv only; the relaxation driver's
    # newton_iterations column holds its relaxation iterations
    case $method in
      adaptive) newton=$(v "$d" final.newton_iterations) ;;
      newton) newton=$(awk -F, 'NR > 1 { n += $4 } END { print n }' "$d/history.csv") ;;
      adr) newton=0 ;;
    esac
    relax=$("$get" get "$d/summary.json" final.relaxation_iterations 2> /dev/null || echo 0)
    tip=$(v "$d" final.min_displacement.z)
    printf '%s,%s,%s,%s,%s,%.2f,%s,%s,%s,%s,%s\n' "$factor" "$solver" "$method" "$run" "$(v "$d" exit_state)" \
      "$(v "$d" timings.total)" "$wall" "$newton" "$relax" "$tip" \
      "$(awk -v t="$tip" 'BEGIN { printf "%+.2f %%", (-t - 1e-3) / 1e-3 * 100 }')" | tee -a "$csv"
  done
done
echo "wrote $csv"
