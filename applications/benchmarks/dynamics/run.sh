#!/usr/bin/env bash
# Dynamics benchmark (issue 5): cost and stability of the explicit central difference and of
# Newmark on
#   - plateCrack, the peer's explicit and Newmark inputs read unchanged (14 280 DoFs, 147 140
#     bonds; needs ../shared/peer-inputs beside the project): time per explicit step, cost per
#     bond against the memory-bandwidth limit, Newmark with the factorisation reused against
#     refactorised every step (as the peer does);
#   - the stability chart: dt/dt_crit from 0.5 to 1.5 with the central difference on the FE bar
#     of tests/scenes/dynamics_wave_bar_1d.prm and on plateCrack, and Newmark at 0.5-50 dt_crit
#     on the bar (exit state, steps done, largest energy error, wave-speed error) and at 0.24-20
#     dt_crit on plateCrack (energy error).
# Writes doc/benchmarks/dynamics_cost.csv, dynamics_stability.csv, dynamics_newmark.csv and, when
# pdfem-plot is built, PNG charts beside them. Tests never time anything; this script does.
#
# usage: applications/benchmarks/dynamics/run.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
bar="$root/tests/scenes/dynamics_wave_bar_1d.prm"

# ---- memory bandwidth (STREAM-like triad, one core): the limit for the bond loop
cat > "$work/triad.c" << 'EOF'
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
int main(void) {
  const long n = 20000000; double *a = malloc(n * 8), *b = malloc(n * 8), *c = malloc(n * 8);
  for (long i = 0; i < n; ++i) { a[i] = 0; b[i] = i; c[i] = 2 * i; }
  double best = 1e30;
  for (int r = 0; r < 5; ++r) {
    struct timespec t0, t1; clock_gettime(CLOCK_MONOTONIC, &t0);
    for (long i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double s = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec); if (s < best) best = s;
  }
  printf("%.2f\n", 3.0 * 8 * n / best / 1e9 + 0 * a[n / 2]);
  return 0;
}
EOF
bandwidth=$(cc -O2 "$work/triad.c" -o "$work/triad" && "$work/triad" || echo 0)
echo "triad bandwidth, one core: $bandwidth GB/s"

# ---- cost: explicit step and Newmark reuse on plateCrack
cost="$out/dynamics_cost.csv"
echo "case,variant,dofs,bonds,steps,dt,dt_over_dt_crit,seconds_per_step,steady_seconds_per_step,internal_force_per_step,update_per_step,solve_per_step,factorize_s,factorizations,bonds_per_s,bandwidth_gb_s,bandwidth_bound_bonds_per_s,peak_mb" > "$cost"
cost_row() { # case variant dir
  local d=$3 bonds fi bps bound steady
  bonds=$(v "$d" problem.bonds); fi=$(v "$d" timings.internal_force_per_step)
  bps=$(awk -v b="$bonds" -v t="$fi" 'BEGIN { printf "%.3e", b / t }')
  # per intact bond the PD kernel streams weight_b (3 doubles in 2D), the member index (4 B) and
  # the intact flag (1 B): 29 B; the member's displacement (16 B) mostly comes from cache.
  bound=$(awk -v g="$bandwidth" 'BEGIN { printf "%.3e", g * 1e9 / 29 }')
  # steady: the per-step phases (forces, updates, solve) without any factorisation
  steady=$(awk -v a="$fi" -v b="$(v "$d" timings.external_force_per_step)" -v c="$(v "$d" timings.update_per_step)" \
    -v e="$(v "$d" timings.solve_per_step)" 'BEGIN { printf "%.4e", a + b + c + e }')
  printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.0f\n' "$1" "$2" "$(v "$d" problem.dofs)" "$bonds" \
    "$(v "$d" steps)" "$(v "$d" dynamics.time_step)" "$("$get" get "$d/summary.json" dynamics.time_step_ratio 2> /dev/null || echo)" \
    "$(v "$d" timings.seconds_per_step)" "$steady" "$fi" "$(v "$d" timings.update_per_step)" \
    "$(v "$d" timings.solve_per_step)" "$(v "$d" timings.factorize)" \
    "$("$get" get "$d/summary.json" dynamics.factorizations 2> /dev/null || echo)" "$bps" "$bandwidth" "$bound" \
    "$(v "$d" peak_memory_mb_rank0)" | tee -a "$cost"
}
if [ -f "$peer/platCrack_NewMarkOFF_FC2.in" ]; then
  cp "$peer"/platCrack.lis "$peer"/platCrack_NewMark*.in "$work/"
  "$pdfem" "$work/platCrack_NewMarkOFF_FC2.in" --output "$work/pc-explicit" --quiet --set "Output/Write vtu=false"
  cost_row plateCrack "explicit peer dt 5e-7 (1100 steps)" "$work/pc-explicit"
  "$pdfem" "$work/platCrack_NewMarkOFF_FC2.in" --output "$work/pc-explicit-auto" --quiet \
    --set "Output/Write vtu=false" --set "Driver/Time step=auto"
  cost_row plateCrack "explicit automatic dt 0.9 dt_crit" "$work/pc-explicit-auto"
  # Newmark: the peer's 1100 steps with the factorisation reused; refactorised every step (as the
  # peer) for 40 steps only, which is long enough for a per-step time.
  "$pdfem" "$work/platCrack_NewMarkON_FC2.in" --output "$work/pc-newmark-reuse" --quiet \
    --set "Output/Write vtu=false"
  cost_row plateCrack "newmark reuse (1100 steps)" "$work/pc-newmark-reuse"
  # The machine is shared: three interleaved pairs of 40-step runs, reused and refactorised, so
  # that both see the same load. Per step: time_loop / steps (the reused run includes its one
  # factorisation, 1/40 of it per step).
  for rep in 1 2 3; do
    for reuse in true false; do
      "$pdfem" "$work/platCrack_NewMarkON_FC2.in" --output "$work/pc-newmark-$reuse-$rep" --quiet \
        --set "Output/Write vtu=false" --set "Driver/End time=2e-5" --set "Driver/Reuse factorization=$reuse"
      cost_row plateCrack "newmark 40 steps reuse=$reuse run $rep" "$work/pc-newmark-$reuse-$rep"
    done
  done
fi

# ---- stability chart: explicit dt/dt_crit 0.5-1.5
stab="$out/dynamics_stability.csv"
echo "case,integrator,dt_over_dt_crit,dt,dt_crit,exit_state,steps,steps_planned,max_abs_energy_error,late_max_abs_energy_error,final_energy_error,time_step_reduction" > "$stab"
stab_row() { # case integrator ratio dir
  local d=$4 dt crit planned end late
  dt=$(v "$d" dynamics.time_step); end=$(v "$d" dynamics.end_time)
  crit=$("$get" get "$d/summary.json" dynamics.critical_time_step 2> /dev/null || echo)
  planned=$(awk -v e="$end" -v t="$dt" 'BEGIN { n = e / t - 1e-9; print (n == int(n)) ? n : int(n) + 1 }')
  # late: the largest |energy_error| in the history rows from step 100 on (rows every 100 steps
  # and the last one), without the start-up mismatch of the first steps of a step load
  late=$(awk -F, -v c="$(head -n 1 "$d/history.csv" | tr ',' '\n' | grep -n '^energy_error$' | cut -d: -f1)" \
    'NR > 1 && ($1 >= 100 || last) { e = $c < 0 ? -$c : $c; if (e > m) m = e } { row = $0 }
     END { n = split(row, f, ","); e = f[c] < 0 ? -f[c] : f[c]; if (e > m) m = e; printf "%.3e", m }' "$d/history.csv")
  printf '%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$1" "$2" "$3" "$dt" "$crit" "$(v "$d" exit_state)" \
    "$(v "$d" steps)" "$planned" "$(v "$d" dynamics.max_abs_energy_error)" "$late" \
    "$(v "$d" dynamics.energy_error)" \
    "$("$get" get "$d/summary.json" dynamics.time_step_reduction 2> /dev/null || echo 1)" | tee -a "$stab"
}
for r in 0.5 0.6 0.7 0.8 0.9 0.95 1.0 1.05 1.1 1.2 1.3 1.4 1.5; do
  "$pdfem" "$bar" --output "$work/bar-$r" --quiet --set "Driver/Time step safety factor=$r" \
    --set "Driver/End time=1e-3" --set "Driver/History interval=100" 2> /dev/null || true
  stab_row bar "central difference" "$r" "$work/bar-$r"
  if [ -f "$work/platCrack_NewMarkOFF_FC2.in" ]; then
    "$pdfem" "$work/platCrack_NewMarkOFF_FC2.in" --output "$work/pc-$r" --quiet --set "Output/Write vtu=false" \
      --set "Driver/Time step=auto" --set "Driver/Time step safety factor=$r" \
      --set "Driver/History interval=100" 2> /dev/null || true
    stab_row plateCrack "central difference" "$r" "$work/pc-$r"
  fi
done

# ---- Newmark at large steps on the bar: energy (conserved) and accuracy (wave speed)
nm="$out/dynamics_newmark.csv"
echo "case,dt_over_dt_crit,dt,steps,exit_state,max_abs_energy_error,wave_speed,wave_speed_error" > "$nm"
crit=$(v "$work/bar-0.9" dynamics.critical_time_step)
for r in 0.5 1 2 5 10 20 50; do
  dt=$(awk -v c="$crit" -v r="$r" 'BEGIN { printf "%.6e", c * r }')
  d="$work/nm-$r"
  "$pdfem" "$bar" --output "$d" --quiet --set "Driver/Type=newmark" --set "Driver/Time step=$dt" \
    --set "Driver/End time=2.2e-4" 2> /dev/null || true
  line=$("$get" wave-speed "$d/history.csv" u_a_x 0.2 u_b_x 0.8 1e-6 5000 1 || true)
  speed=$(echo "$line" | awk '{ print $4 }')
  printf '%s,%s,%s,%s,%s,%s,%s,%s\n' bar "$r" "$dt" "$(v "$d" steps)" "$(v "$d" exit_state)" \
    "$(v "$d" dynamics.max_abs_energy_error)" "$speed" \
    "$(awk -v c="$speed" 'BEGIN { printf "%.3e", (c - 5000) / 5000 }')" | tee -a "$nm"
done

# ---- Newmark at large steps on plateCrack (the peer's Newmark input): energy and cost
if [ -f "$work/platCrack_NewMarkON_FC2.in" ]; then
  crit=$(v "$work/pc-0.9" dynamics.critical_time_step)
  for r in 0.24 1 5 20; do
    dt=$(awk -v c="$crit" -v r="$r" 'BEGIN { printf "%.6e", c * r }')
    d="$work/pc-nm-$r"
    "$pdfem" "$work/platCrack_NewMarkON_FC2.in" --output "$d" --quiet --set "Output/Write vtu=false" \
      --set "Driver/Time step=$dt" 2> /dev/null || true
    printf '%s,%s,%s,%s,%s,%s,%s,%s\n' plateCrack "$r" "$dt" "$(v "$d" steps)" "$(v "$d" exit_state)" \
      "$(v "$d" dynamics.max_abs_energy_error)" "" "" | tee -a "$nm"
  done
fi

# ---- charts
if have_plot; then
  grep -E "^case|^bar," "$stab" > "$work/stab-bar.csv"
  if grep -q "^plateCrack," "$stab"; then
    grep -E "^case|^plateCrack," "$stab" > "$work/stab-pc.csv"
    xvfb-run -a "$plot" chart "$work/stab-bar.csv" --x dt_over_dt_crit --y late_max_abs_energy_error \
      --csv2 "$work/stab-pc.csv" --label "FE bar (1212 DoFs),plateCrack (14 280 DoFs)" --logy --points \
      --xlabel "dt / dt_crit (power iteration)" --ylabel "largest |energy error| after step 100, or at the stop" \
      --title "Central difference: energy error against the time step" --out "$out/dynamics_stability.png"
  else
    xvfb-run -a "$plot" chart "$work/stab-bar.csv" --x dt_over_dt_crit --y late_max_abs_energy_error --logy --points \
      --xlabel "dt / dt_crit (power iteration)" --ylabel "largest |energy error| after step 100, or at the stop" \
      --title "Central difference: energy error against the time step" --out "$out/dynamics_stability.png"
  fi
  awk -F, 'NR == 1 { print "dt_over_dt_crit,abs_wave_speed_error_percent,max_abs_energy_error" }
           NR > 1 && $1 == "bar" { e = $8 < 0 ? -$8 : $8; print $2 "," 100 * e "," $6 }' "$nm" > "$work/nm.csv"
  xvfb-run -a "$plot" chart "$work/nm.csv" --x dt_over_dt_crit --y abs_wave_speed_error_percent --logx --points \
    --xlabel "dt / dt_crit (explicit limit)" --ylabel "|wave speed error| [%]" \
    --title "Newmark (average acceleration) on the bar: accuracy at large steps" \
    --out "$out/dynamics_newmark.png"
fi
echo "results in $out"
