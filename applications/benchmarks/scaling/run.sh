#!/usr/bin/env bash
# Scaling benchmark (issue 21, item 2): time and memory of one static coupled solve against the
# problem size, 2D and 3D, 40 % of the cells PD (a PD strip or slab between two FE blocks, m = 4),
# matrix-free GMRES with "amg fe", one rank. For each size: DoFs, bonds, the phases of
# summary.json (setup = nodes, families, weights; solve = GMRES), the process's peak memory, GMRES
# iterations, the error of u_x at x = 0.5 against sigma / E (the exact solution), and the
# whole-process wall time. Then the exponent b of a least-squares fit t = a N^b (log-log) over the
# sizes from 5 x 10^4 DoFs on, and bytes per DoF and per bond.
# Then one explicit (central-difference) step on the same 3D boxes with the same operator (collocated
# pdlsm; a dynamic driver's default is the energy form, which couples two horizons and costs more):
# 20 steps of 1e-8 s with a lumped mass (density 2700), the time per step from summary.json
# (total - mesh - setup) / steps.
# Writes doc/benchmarks/scaling.csv, scaling_explicit.csv and scaling_fit.csv and, when pdfem-plot
# is built, the charts scaling_time.png and scaling_memory.png.
#
# usage: applications/benchmarks/scaling/run.sh [BUILD_DIR] [OUT_DIR]
#   SIZES_3D="20 40 60 80 96" SIZES_2D="100 200 400 720" SIZES_EXPLICIT="20 40 60 80" (1/h: cells
#   per metre) select the sizes.
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
source "$here/scene.sh"

sizes_3d=${SIZES_3D:-20 40 60 80 96}
sizes_2d=${SIZES_2D:-100 200 400 720}
csv="$out/scaling.csv"
echo "dim,cells_per_m,dofs,pd_nodes,bonds,mesh_s,setup_s,assembly_s,solve_s,total_s,compute_s,process_wall_s,peak_mb,gmres_iterations,max_ux,ux_error" > "$csv"

run() { # dim cells_per_metre
  local dim=$1 n=$2 name
  if [ "$dim" = 3 ]; then name=box; else name=plate; fi
  run_scene "$name" "$n" "$name.prm"
  local mesh total ux
  mesh=$(v "$dir/out" timings.mesh); total=$(v "$dir/out" timings.total)
  ux=$(v "$dir/out" final.max_displacement.x)
  printf '%s,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%s,%.0f,%s,%s,%.2e\n' "$dim" "$n" \
    "$(v "$dir/out" problem.dofs)" "$(v "$dir/out" problem.pd_nodes)" "$(v "$dir/out" problem.bonds)" \
    "$mesh" "$(v "$dir/out" timings.setup)" "$(v "$dir/out" timings.assembly)" \
    "$(v "$dir/out" timings.solve)" "$total" "$(awk -v t="$total" -v m="$mesh" 'BEGIN { print t - m }')" \
    "$wall" "$(v "$dir/out" peak_memory_mb_rank0)" "$(tail -n 1 "$dir/out/history.csv" | cut -d, -f5)" \
    "$ux" "$(awk -v u="$ux" 'BEGIN { printf "%.3e", u / (7e6 / 70e9 * 0.5) - 1 }')" | tee -a "$csv"
  rm -rf "$dir"
}

explicit_csv="$out/scaling_explicit.csv"
echo "dim,cells_per_m,dofs,bonds,steps,setup_s,seconds_per_step,process_wall_s,peak_mb" > "$explicit_csv"
run_explicit() { # cells_per_metre
  local n=$1
  run_scene box "$n" box.prm --set "Material/Density=2700" --set "Peridynamics/Model=pdlsm" \
    --set "Driver/Type=explicit" --set "Driver/Time step=1e-8" --set "Driver/End time=2e-7"
  local steps total mesh setup
  steps=$(v "$dir/out" steps); total=$(v "$dir/out" timings.total)
  mesh=$(v "$dir/out" timings.mesh); setup=$(v "$dir/out" timings.setup)
  printf '3,%s,%s,%s,%s,%.3f,%.5f,%s,%.0f\n' "$n" "$(v "$dir/out" problem.dofs)" "$(v "$dir/out" problem.bonds)" \
    "$steps" "$setup" "$(awk -v t="$total" -v m="$mesh" -v s="$setup" -v n="$steps" 'BEGIN { print (t - m - s) / n }')" \
    "$wall" "$(v "$dir/out" peak_memory_mb_rank0)" | tee -a "$explicit_csv"
  rm -rf "$dir"
}

for n in $sizes_2d; do run 2 "$n"; done
for n in $sizes_3d; do run 3 "$n"; done
for n in ${SIZES_EXPLICIT:-20 40 60 80}; do run_explicit "$n"; done

# Least-squares exponents over the sizes from 5e4 DoFs on (loglog.py).
python3 - "$csv" "$out/scaling_fit.csv" "$explicit_csv" "$here" << 'PY'
import csv, sys
sys.path.insert(0, sys.argv[4])
from loglog import exponent, large
rows = list(csv.DictReader(open(sys.argv[1])))
for r in csv.DictReader(open(sys.argv[3])):  # explicit steps: dim "3x"
    rows.append({"dim": "3x", "dofs": r["dofs"], "bonds": r["bonds"], "setup_s": r["setup_s"],
                 "solve_s": r["seconds_per_step"], "compute_s": r["seconds_per_step"],
                 "peak_mb": r["peak_mb"], "gmres_iterations": "1"})
with open(sys.argv[2], "w") as out:
    # dim 3x: the explicit steps on the 3D box
    out.write("dim,quantity,exponent,sizes,smallest_dofs,largest_dofs,bytes_per_dof_largest,bytes_per_bond_largest\n")
    for dim in ("2", "3", "3x"):
        big = large(rows, dim)
        if len(big) < 2:
            continue
        quantities = ("setup_s", "solve_s", "compute_s", "peak_mb", "gmres_iterations")
        if dim == "3x":
            quantities = ("solve_s", "peak_mb")  # solve_s: seconds per explicit step
        for q in quantities:
            last = big[-1]
            mb = float(last["peak_mb"]) * 2**20
            name = "seconds_per_step" if dim == "3x" and q == "solve_s" else q
            line = "%s,%s,%.3f,%d,%s,%s,%.0f,%.0f" % (dim, name, exponent(big, q), len(big), big[0]["dofs"],
                                                    last["dofs"], mb / float(last["dofs"]),
                                                    mb / float(last["bonds"]))
            out.write(line + "\n")
            print(line)
PY

if have_plot; then
  split_by_dim "$csv" scaling
  xvfb-run -a "$plot" chart "$work/scaling_3.csv" --x dofs --y compute_s,solve_s,setup_s --logx --logy --points \
    --csv2 "$work/scaling_2.csv" --label "3D total,3D solve,3D setup,2D total,2D solve,2D setup" \
    --xlabel "DoFs" --ylabel "time [s]" --title "Static coupled solve, 40 % PD, one rank" \
    --out "$out/scaling_time.png"
  xvfb-run -a "$plot" chart "$work/scaling_3.csv" --x dofs --y peak_mb --logx --logy --points \
    --csv2 "$work/scaling_2.csv" --label "3D,2D" --xlabel "DoFs" --ylabel "peak memory [MB]" \
    --title "Peak memory, one rank" --out "$out/scaling_memory.png"
  echo "charts: $out/scaling_time.png, $out/scaling_memory.png"
else
  echo "pdfem-plot or xvfb-run missing: no charts (see doc/tools.md)"
fi
