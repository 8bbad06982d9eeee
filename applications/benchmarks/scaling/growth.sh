#!/usr/bin/env bash
# Scaling benchmark (issue 21, item 2): the time of one quasi-static growth step against the problem
# size, 2D and 3D, 40 % of the cells PD, one rank, the solver chosen by cost (`Linear solver/Type =
# auto`; every growth step changes the matrix, so matrix-free GMRES with "amg fe" stays).
#   2D: plate_growth.prm, a centre crack grown by mcts (FC 1), one cell per tip and step, 6 steps.
#   3D: box_growth.prm, a through crack grown by the maximum principal stress (FC 2, 100 bonds per
#       step), 5 steps (the driver jumps to the critical load; the steps at that load grow).
# A growth step is a step that breaks bonds and solves again (history.csv: more broken bonds than
# the row before and linear iterations > 0); its time is the difference of wall_seconds from the
# row before: the criterion, the bonds' updates (refits, the matrix-free operator's data) and the
# solve. For each size: DoFs, bonds, set-up, the mean and largest growth-step time and its GMRES
# iterations, peak memory, the solver path; then the exponent of a least-squares fit of the mean
# growth-step time against DoFs over the sizes from 5 x 10^4 DoFs on (scaling_growth_fit.csv).
# Writes doc/benchmarks/scaling_growth.csv, scaling_growth_fit.csv and, with pdfem-plot, the chart
# scaling_growth.png.
#
# usage: applications/benchmarks/scaling/growth.sh [BUILD_DIR] [OUT_DIR]
#   SIZES_2D="100 200 400 720" SIZES_3D="20 40 60 80 96" (1/h: cells per metre).
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
source "$here/scene.sh"

csv="$out/scaling_growth.csv"
echo "dim,cells_per_m,dofs,bonds,setup_s,growth_steps,step_s,step_max_s,gmres_iterations,broken_bonds,process_wall_s,peak_mb,solver_path" > "$csv"

run() { # dim cells_per_metre
  local dim=$1 n=$2 name
  if [ "$dim" = 3 ]; then name=box; else name=plate; fi
  run_scene "$name" "$n" "${name}_growth.prm"
  local steps
  steps=$(python3 - "$dir/out/history.csv" << 'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
times, its = [], []
for before, r in zip(rows, rows[1:]):
    if int(r["n_broken_bonds"]) > int(before["n_broken_bonds"]) and int(r["linear_iterations"]) > 0:
        times.append(float(r["wall_seconds"]) - float(before["wall_seconds"]))
        its.append(int(r["linear_iterations"]))
if not times:
    sys.exit("no growth step in " + sys.argv[1])
print("%d,%.3f,%.3f,%.1f,%s" % (len(times), sum(times) / len(times), max(times), sum(its) / len(its),
                                rows[-1]["n_broken_bonds"]))
PY
  )
  printf '%s,%s,%s,%s,%.3f,%s,%s,%.0f,%s\n' "$dim" "$n" "$(v "$dir/out" problem.dofs)" \
    "$(v "$dir/out" problem.bonds)" "$(v "$dir/out" timings.setup)" "$steps" "$wall" \
    "$(v "$dir/out" peak_memory_mb_rank0)" "$(v "$dir/out" linear_solver.path | tr ',' ';')" | tee -a "$csv"
  rm -rf "$dir"
}

for n in ${SIZES_2D:-100 200 400 720}; do run 2 "$n"; done
for n in ${SIZES_3D:-20 40 60 80 96}; do run 3 "$n"; done

python3 - "$csv" "$out/scaling_growth_fit.csv" "$here" << 'PY'
import csv, sys
sys.path.insert(0, sys.argv[3])
from loglog import exponent, large
rows = list(csv.DictReader(open(sys.argv[1])))
with open(sys.argv[2], "w") as out:
    out.write("dim,quantity,exponent,sizes,smallest_dofs,largest_dofs\n")
    for dim in ("2", "3"):
        big = large(rows, dim)
        if len(big) < 2:
            continue
        for q in ("step_s", "gmres_iterations", "peak_mb"):
            line = "%s,%s,%.3f,%d,%s,%s" % (dim, q, exponent(big, q), len(big), big[0]["dofs"], big[-1]["dofs"])
            out.write(line + "\n")
            print(line)
PY

if have_plot; then
  split_by_dim "$csv" growth
  xvfb-run -a "$plot" chart "$work/growth_3.csv" --x dofs --y step_s --logx --logy --points \
    --csv2 "$work/growth_2.csv" --label "3D (FC 2),2D (FC 1)" --xlabel "DoFs" \
    --ylabel "time per growth step [s]" --title "One quasi-static growth step, 40 % PD, one rank" \
    --out "$out/scaling_growth.png"
  echo "chart: $out/scaling_growth.png"
else
  echo "pdfem-plot or xvfb-run missing: no chart (see doc/tools.md)"
fi
