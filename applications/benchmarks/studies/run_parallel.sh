#!/usr/bin/env bash
# The ranks-and-threads study of doc/benchmarks/studies.md, by pdfem-study: the 3D box of the scaling
# benchmark (static tension, a PD slab of 40 % of the cells between two FE blocks, m = 4, matrix-free
# GMRES with "amg fe"), base cell size 1/16 m refined 0, 1 and 2 times, run
#   - on 1 and 2 MPI ranks with one thread per rank (DEAL_II_NUM_THREADS=1), and
#   - on 1 rank with 2 threads (DEAL_II_NUM_THREADS=2),
# every run an mpirun process of its own (pdfem-study's --vary ranks), so that all three include the
# same process start-up. The error is that of the largest u_x against the exact sigma / E * 0.5 m.
# Writes studies_parallel_1thread.csv/.png and studies_parallel_2threads.csv/.png (pdfem-study's
# tables and charts) and studies_parallel.csv: one row per mesh with the three wall times, the
# parallel efficiencies t(1 rank, 1 thread) / (2 t), and rank 0's peak memory of each.
# The charts need pdfem-plot (VTK; a display or xvfb-run).
#
#   applications/benchmarks/studies/run_parallel.sh [BUILD_DIR] [OUT_DIR]
#   REFINEMENTS="0,1,2" selects the meshes.
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
refinements=${REFINEMENTS:-0,1,2}
sed "s/@H@/0.0625/" "$root/applications/benchmarks/scaling/box.geo.in" > "$work/box.geo"
cp "$root/applications/benchmarks/scaling/box.prm" "$work/box.prm"
exact=5e-5 # sigma / E * 0.5 m = 7e6 / 70e9 * 0.5

source "$here/study_common.sh"
box_study() { # NAME THREADS RANKS
  DEAL_II_NUM_THREADS=$2 study "$1" "$work/box.prm" --vary "Mesh/Global refinements=$refinements" \
    --vary "ranks=$3" --output final.max_displacement.x --reference "$exact"
}
box_study parallel_1thread 1 1,2
box_study parallel_2threads 2 1

# One row per mesh: columns of the two study tables looked up by their header names.
t1="$out/studies_parallel_1thread.csv"
t2="$out/studies_parallel_2threads.csv"
awk -F, -v r="$(column "$t1" "Mesh/Global refinements")" -v n="$(column "$t1" ranks)" \
  -v d="$(column "$t1" dofs)" -v w="$(column "$t1" wall_seconds)" \
  -v p="$(column "$t1" pdfem_total_seconds)" -v m="$(column "$t1" peak_memory_mb)" \
  -v w2="$(column "$t2" wall_seconds)" -v p2="$(column "$t2" pdfem_total_seconds)" \
  -v m2="$(column "$t2" peak_memory_mb)" -v r2="$(column "$t2" "Mesh/Global refinements")" '
  FNR == 1 { next }
  FILENAME == ARGV[1] { dofs[$r] = $d; wall[$r, $n] = $w; own[$r, $n] = $p; mem[$r, $n] = $m
                        if (!($r in seen)) { order[++count] = $r; seen[$r] = 1 } ; next }
  { wall[$r2, "t2"] = $w2; own[$r2, "t2"] = $p2; mem[$r2, "t2"] = $m2 }
  END {
    print "refinements,dofs,wall_1rank_1thread,wall_2ranks,wall_1rank_2threads," \
          "pdfem_1rank_1thread,pdfem_2ranks,pdfem_1rank_2threads," \
          "efficiency_2ranks,efficiency_2threads,pdfem_efficiency_2ranks,pdfem_efficiency_2threads," \
          "memory_mb_1rank_1thread,memory_mb_rank0_2ranks,memory_mb_1rank_2threads"
    for (i = 1; i <= count; ++i) {
      k = order[i]
      printf "%s,%s,%s,%s,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f,%s,%s,%s\n", k, dofs[k],
        wall[k, 1], wall[k, 2], wall[k, "t2"], own[k, 1], own[k, 2], own[k, "t2"],
        wall[k, 1] / (2 * wall[k, 2]), wall[k, 1] / (2 * wall[k, "t2"]),
        own[k, 1] / (2 * own[k, 2]), own[k, 1] / (2 * own[k, "t2"]),
        mem[k, 1], mem[k, 2], mem[k, "t2"]
    }
  }' "$t1" "$t2" > "$out/studies_parallel.csv"
cat "$out/studies_parallel.csv"
if have_plot; then
  xvfb-run -a "$plot" chart "$out/studies_parallel.csv" --x dofs \
    --y wall_1rank_1thread,wall_2ranks,wall_1rank_2threads --logx --logy --markers \
    --label "1 rank x 1 thread,2 ranks x 1 thread,1 rank x 2 threads" --xlabel "DoFs" \
    --ylabel "wall time of the run [s]" --title "3D box, static: ranks and threads" \
    --out "$out/studies_parallel_time.png"
fi
