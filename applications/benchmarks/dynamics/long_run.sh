#!/usr/bin/env bash
# Long explicit runs on a cracked coupled plate (issue 16): 10^5 central-difference steps with the
# energy-form PD operator (Peridynamics/Model = pdlsm energy) against the collocated pdlsm.
#
# The plate of tests/scenes/dynamics_energy_form_crack.prm: [-0.5, 0.5]^2, a PD slab |x| <= 0.2
# between two FE blocks, a crack across the slab at x = 0.025, |y| <= 0.2625 (off the nodes of
# every mesh below), held on the left (x) and bottom (y), a step traction of 7 MPa on the right.
# Meshes: structured quads h = 0.1 and h = 0.05 (tests/meshes/patch_2d_quad.geo) and irregular
# triangles h = 0.1 (patch_2d_tri.geo). The time step is 0.9 of the power-iteration limit of the
# energy-form mesh (a short run measures it), the same for both operators; End time = 10^5 steps.
#
# energy_drift (history.csv, summary.json) is the central difference's own conserved energy,
# balanced against the work (Drivers::DynamicRecord): round-off for a symmetric operator.
# Writes doc/benchmarks/dynamics_long_run.csv and, with pdfem-plot, dynamics_long_run.png (|drift|
# against the step, h = 0.1 quads, both operators).
#
# usage: applications/benchmarks/dynamics/long_run.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
scene="$root/tests/scenes/dynamics_energy_form_crack.prm"
steps=${STEPS:-100000}

csv="$out/dynamics_long_run.csv"
echo "mesh,model,dofs,dt,dt_over_dt_crit,steps_planned,steps,exit_state,max_abs_energy_drift,final_energy_drift,external_work,max_abs_energy_error,pdfem_seconds,process_seconds" > "$csv"
for mesh in "quad 0.1" "quad 0.05" "tri 0.1"; do
  read -r kind h <<< "$mesh"
  sed "s/^h = 0.1;/h = $h;/" "$root/tests/meshes/patch_2d_$kind.geo" > "$work/${kind}_$h.geo"
  common=(--quiet --set "Mesh/Input file=$work/${kind}_$h.geo"
          --set "Peridynamics/Pre-existing cracks=(0.025, -0.2625) -- (0.025, 0.2625)"
          --set "Driver/Time step safety factor=0.9")
  # The stable step of the energy-form mesh, then 10^5 steps of it for both operators.
  "$pdfem" "$scene" "${common[@]}" --output "$work/probe" --set "Driver/End time=1e-5"
  dt=$(v "$work/probe" dynamics.time_step)
  end=$(awk -v dt="$dt" -v n="$steps" 'BEGIN { printf "%.17g", dt * n }')
  for model in "pdlsm energy" "pdlsm"; do
    d="$work/${kind}_${h}_${model// /_}"
    start=$(date +%s.%N)
    "$pdfem" "$scene" "${common[@]}" --output "$d" --set "Peridynamics/Model=$model" \
      --set "Driver/Time step=$dt" --set "Driver/End time=$end" --set "Driver/History interval=100" \
      2> "$d.err" || true
    finish=$(date +%s.%N)
    echo "$kind h=$h $model: $(v "$d" exit_state) after $(v "$d" steps) steps, drift $(v "$d" dynamics.max_abs_energy_drift)"
    printf "%s %s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.2f\n" "$kind" "$h" "$model" "$(v "$d" problem.dofs)" "$dt" \
      "$(v "$d" dynamics.time_step_ratio)" "$steps" "$(v "$d" steps)" "$(v "$d" exit_state)" \
      "$(v "$d" dynamics.max_abs_energy_drift)" "$(v "$d" dynamics.energy_drift)" \
      "$(v "$d" dynamics.external_work)" "$(v "$d" dynamics.max_abs_energy_error)" \
      "$(v "$d" timings.total)" "$(awk -v a="$start" -v b="$finish" 'BEGIN { print b - a }')" >> "$csv"
  done
done
cat "$csv"

# |energy_drift| against the step, h = 0.1 quads: both operators in one chart.
if have_plot; then
  for model in pdlsm_energy pdlsm; do
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "step") t = i; if ($i == "energy_drift") e = i }
                       print "step,abs_energy_drift"; next }
             { a = $e < 0 ? -$e : $e; if (a > 0) printf "%d,%.6g\n", $t, a }' \
      "$work/quad_0.1_$model/history.csv" > "$work/drift_$model.csv"
  done
  xvfb-run -a "$plot" chart "$work/drift_pdlsm_energy.csv" --x step --y abs_energy_drift --logx --logy \
    --csv2 "$work/drift_pdlsm.csv" --label "pdlsm energy,pdlsm (collocated)" \
    --title "Central difference, cracked coupled plate (h = 0.1): |energy drift|" \
    --xlabel "time step" --ylabel "|drift| / energy supplied" --out "$out/dynamics_long_run.png"
fi
