#!/usr/bin/env bash
# Parallel benchmark (issue 21, item 3): the 3D box of run.sh (40 % PD, m = 4) on 1, 2 and 4 MPI
# ranks (4 on this 2-core machine is oversubscribed: noted as such in the CSV), one thread per rank
# (DEAL_II_NUM_THREADS=1; by default a rank takes the cores it shares with the others),
# static (matrix-free GMRES, "amg fe") and explicit (20 central-difference steps, collocated pdlsm).
# Per run: the phases of summary.json, rank 0's peak memory, the whole-process wall time, and the
# parallel efficiency t(1) / (n t(n)) of setup (and of two of its parts: the matrices, i.e. the
# set-up phases fe_matrix + pd_model, and ML's hierarchy, phase preconditioner: nan for explicit,
# which builds none), of the work after it (assembly + solve for static, the time steps for
# explicit: total - mesh - setup - output) and of the whole run (total - mesh). Runs alternate over
# the rank counts (ROUNDS rounds) and the median is kept.
# Writes doc/benchmarks/scaling_parallel.csv (medians) and scaling_parallel_runs.csv (every run).
#
# usage: applications/benchmarks/scaling/parallel.sh [BUILD_DIR] [OUT_DIR]
#   SIZE=40 (cells per metre: 105 903 DoFs) RANKS="1 2 4" ROUNDS=3
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"

n=${SIZE:-40}
ranks=${RANKS:-1 2 4}
rounds=${ROUNDS:-3}
cores=$(nproc)
sed "s/@H@/1 \/ $n/" "$here/box.geo.in" > "$work/box.geo"
cp "$here/box.prm" "$work/"
raw="$work/raw.csv"
: > "$raw"

run() { # kind ranks round
  local kind=$1 np=$2 round=$3 dir="$work/$1-$2-$3" extra=()
  if [ "$kind" = explicit ]; then
    extra=(--set "Material/Density=2700" --set "Peridynamics/Model=pdlsm" --set "Driver/Type=explicit"
      --set "Driver/Time step=1e-8" --set "Driver/End time=2e-7")
  fi
  local start; start=$(date +%s.%N)
  DEAL_II_NUM_THREADS=1 mpirun -np "$np" --bind-to none "$pdfem" "$work/box.prm" --output "$dir" --quiet \
    "${extra[@]}" > /dev/null
  local wall; wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", e - s }')
  echo "$kind,$np,$round,$(v "$dir" problem.dofs),$(v "$dir" threads),$(v "$dir" timings.mesh),$(v "$dir" timings.setup),$(v "$dir" timings.assembly),$(v "$dir" timings.solve),$(v "$dir" timings.output),$(v "$dir" timings.total),$wall,$(v "$dir" peak_memory_mb_rank0),$(v "$dir" steps),$(v "$dir" timings.setup_phases.fe_matrix),$(v "$dir" timings.setup_phases.pd_model),$(v "$dir" timings.setup_phases.preconditioner)" >> "$raw"
  rm -rf "$dir"
}

for round in $(seq 1 "$rounds"); do
  for kind in static explicit; do
    for np in $ranks; do run "$kind" "$np" "$round"; done
  done
done

# the columns of run()'s lines
cols=kind,ranks,round,dofs,threads,mesh_s,setup_s,assembly_s,solve_s,output_s,total_s,process_wall_s
cols+=,peak_mb_rank0,steps,fe_matrix_s,pd_model_s,preconditioner_s
(echo "$cols" && cat "$raw") > "$out/scaling_parallel_runs.csv"
python3 - "$out/scaling_parallel_runs.csv" "$out/scaling_parallel.csv" "$cores" << 'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
cores = int(sys.argv[3])
med = {}
for r in rows:
    med.setdefault((r["kind"], int(r["ranks"])), []).append(r)
with open(sys.argv[2], "w") as out:
    out.write("kind,ranks,oversubscribed,dofs,rounds,setup_s,work_s,output_s,total_s,process_wall_s,peak_mb_rank0,"
              "efficiency_setup,efficiency_work,efficiency_total,matrices_s,amg_s,efficiency_matrices,efficiency_amg\n")
    for kind in ("static", "explicit"):
        base = None
        for np in sorted(n for k, n in med if k == kind):
            rs = med[(kind, np)]
            m = lambda key: statistics.median(float(r[key]) for r in rs)
            setup = m("setup_s")
            # the work after set-up: assembly + solve (static), the time steps (explicit)
            work = statistics.median(
                float(r["assembly_s"]) + float(r["solve_s"]) if kind == "static" else
                float(r["total_s"]) - float(r["mesh_s"]) - float(r["setup_s"]) - float(r["output_s"])
                for r in rs)
            total = statistics.median(float(r["total_s"]) - float(r["mesh_s"]) for r in rs)
            # the set-up's assembly of the operator: the FE matrices (patterns and cells' stiffness,
            # phase fe_matrix) and the PD model's data (pd_model); and ML's hierarchy apart
            matrices = statistics.median(float(r["fe_matrix_s"]) + float(r["pd_model_s"]) for r in rs)
            amg = m("preconditioner_s")
            if base is None:
                base = (np, setup, work, total, matrices, amg)
            eff = lambda t1, tn: base[0] * t1 / (np * tn) if tn > 0 else float("nan")
            line = "%s,%d,%s,%s,%d,%.3f,%.3f,%.3f,%.3f,%.2f,%.0f,%.2f,%.2f,%.2f,%.3f,%.3f,%.2f,%.2f" % (
                kind, np, "yes" if np > cores else "no", rs[0]["dofs"], len(rs), setup, work, m("output_s"),
                total, m("process_wall_s"), m("peak_mb_rank0"), eff(base[1], setup), eff(base[2], work),
                eff(base[3], total), matrices, amg, eff(base[4], matrices),
                eff(base[5], amg) if kind == "static" else float("nan"))
            out.write(line + "\n")
            print(line)
PY
