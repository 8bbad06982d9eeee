#!/usr/bin/env bash
# The explicit step on plateCrack FC2 (the peer's platCrack_NewMarkOFF_FC2.in as given: 1 100 steps
# of 5e-7 s, the max principal stress criterion after every step) against the memory-bandwidth
# bound of its operator (issue 21):
#   1. PAIRS runs (default 5), alternating with a previous build when OLD_BUILD=<build dir> is given
#      (the machine's speed drifts: ratios only within one run of this script); per run the time per
#      step, the internal force and the criterion per step, pdfem's own time and the process's;
#   2. the bytes one internal force must stream: per bond the PDLSM block -V_k G_m (3 doubles in 2D,
#      6 in 3D) and the member index (4 B); per family its owner, offsets and boundary area (28 B in
#      2D) and its force (16 B); the FE cells' matrix (8 B value + 4 B column per entry,
#      summary.json problem.fe_matrix_entries); four vectors of DoFs (u, its ghosted copy, the FE
#      product, f_int);
#   3. triad bandwidths (a[i] = b[i] + 3 c[i]), one and two threads: DRAM-sized arrays (480 MB), and
#      arrays of the operator's own size, which stay in the 32 MB L3 cache between steps as the
#      operator's data do (the whole step touches about 12 MB);
#   4. the bound = bytes / bandwidth, and the measured internal force over it.
# Writes doc/benchmarks/dynamics_explicit_step.csv (runs) and dynamics_explicit_bound.csv.
#
# usage: [OLD_BUILD=dir] [PAIRS=5] applications/benchmarks/dynamics/explicit_step.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
input="$peer/platCrack_NewMarkOFF_FC2.in"
if [ ! -f "$input" ]; then
  echo "explicit_step.sh: $input not found (the peer's inputs beside the checkout)" >&2
  exit 1
fi
cp "$peer/platCrack.lis" "$input" "$work/"
pairs=${PAIRS:-5}

runs="$out/dynamics_explicit_step.csv"
echo "build,run,seconds_per_step,internal_force_per_step,criterion_per_step,pdfem_total_s,process_wall_s" > "$runs"
run_one() { # LABEL PDFEM RUN
  local d="$work/$1-$3"
  local start end
  start=$(date +%s.%N)
  "$2" "$work/platCrack_NewMarkOFF_FC2.in" --output "$d" --quiet --set "Output/Write vtu=false" > /dev/null
  end=$(date +%s.%N)
  awk -v b="$1" -v r="$3" -v s="$(v "$d" timings.seconds_per_step)" \
    -v f="$(v "$d" timings.internal_force_per_step)" -v c="$(v "$d" timings.criterion)" \
    -v n="$(v "$d" steps)" -v t="$(v "$d" timings.total)" -v w="$(awk -v a="$start" -v e="$end" 'BEGIN { print e - a }')" \
    'BEGIN { printf "%s,%s,%.4e,%.4e,%.4e,%.3f,%.3f\n", b, r, s, f, c / n, t, w }' | tee -a "$runs"
}
for r in $(seq 1 "$pairs"); do
  if [ -n "${OLD_BUILD:-}" ]; then
    run_one previous "$OLD_BUILD/bin/pdfem" "$r"
  fi
  run_one current "$pdfem" "$r"
done
d="$work/current-1"

# ---- triad bandwidths: DRAM-sized and operator-sized arrays, one and two threads
cat > "$work/triad.c" << 'EOF'
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
/* usage: triad BYTES REPEATS -> GB/s of a[i] = b[i] + 3 c[i] over three arrays of BYTES / 3 */
int main(int argc, char **argv) {
  const long n = atol(argv[1]) / 24; const int repeats = atoi(argv[2]);
  double *a = malloc(n * 8), *b = malloc(n * 8), *c = malloc(n * 8);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) { a[i] = 0; b[i] = i; c[i] = 2 * i; }
  double best = 1e30;
  for (int r = 0; r < 5; ++r) {
    const double t0 = omp_get_wtime();
    for (int k = 0; k < repeats; ++k) {
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
    }
    const double s = (omp_get_wtime() - t0) / repeats; if (s < best) best = s;
  }
  printf("%.2f\n", 24.0 * n / best / 1e9 + 0 * a[n / 2]);
  return 0;
}
EOF
cc -O2 -fopenmp "$work/triad.c" -o "$work/triad"

bonds=$(v "$d" problem.bonds)
pd_nodes=$(v "$d" problem.pd_nodes)
dofs=$(v "$d" problem.dofs)
fe_entries=$(v "$d" problem.fe_matrix_entries)
bytes=$(awk -v b="$bonds" -v o="$pd_nodes" -v e="$fe_entries" -v n="$dofs" \
  'BEGIN { printf "%.0f", b * (3 * 8 + 4) + o * (28 + 16) + e * 12 + (n + 1) * 4 + 4 * n * 8 }')
dram1=$(OMP_NUM_THREADS=1 "$work/triad" 480000000 1)
dram2=$(OMP_NUM_THREADS=2 "$work/triad" 480000000 1)
cache1=$(OMP_NUM_THREADS=1 "$work/triad" "$bytes" 200)
cache2=$(OMP_NUM_THREADS=2 "$work/triad" "$bytes" 200)
bound="$out/dynamics_explicit_bound.csv"
echo "bonds,pd_nodes,fe_matrix_entries,dofs,operator_bytes,triad_dram_1thread_gb_s,triad_dram_2threads_gb_s,triad_operator_size_1thread_gb_s,triad_operator_size_2threads_gb_s,bound_dram_2threads_s,bound_cache_2threads_s,internal_force_median_s,over_bound_dram,over_bound_cache" > "$bound"
median=$(awk -F, '$1 == "current" { print $4 }' "$runs" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }')
awk -v b="$bonds" -v o="$pd_nodes" -v e="$fe_entries" -v n="$dofs" -v B="$bytes" -v d1="$dram1" -v d2="$dram2" \
  -v c1="$cache1" -v c2="$cache2" -v m="$median" 'BEGIN {
    bd = B / (d2 * 1e9); bc = B / (c2 * 1e9)
    printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%.4e,%.4e,%.4e,%.2f,%.2f\n", b, o, e, n, B, d1, d2, c1, c2, bd, bc, m, m / bd, m / bc
  }' | tee -a "$bound"
