#!/usr/bin/env bash
# Static benchmark: wall time per phase and peak memory of pdfem on
#   - the 3D box of PDLSM-FEM's "box" example (105 903 DoFs, 40 % PD), matrix-free GMRES with
#     "amg fe" and, for comparison, the assembled coupled matrix with ML AMG;
#   - plate_with_hole at three gmsh mesh sizes (factor 1, 1/2, 1/4), with the direct solver
#     (MUMPS) and with matrix-free GMRES, against Heywood's finite-width value 2.198e7 Pa.
# Writes doc/benchmarks/static.csv and, when pdfem-plot is built, PNG charts beside it. Times are
# wall seconds from summary.json; compute_s = total - mesh (gmsh meshing of the .geo excluded).
#
# usage: applications/benchmarks/static/run.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"

csv="$out/static.csv"
echo "case,variant,mesh_size_factor,dofs,bonds,mesh_s,setup_s,assembly_s,solve_s,total_s,compute_s,peak_mb,linear_iterations,result,reference,relative_error" > "$csv"

run() { # case variant factor reference key prm [--set ...]
  local case=$1 variant=$2 factor=$3 reference=$4 key=$5 prm=$6
  shift 6
  local dir="$work/$case-$variant-$factor"
  "$pdfem" "$prm" --output "$dir" --quiet --set "Output/Write vtu=false" "$@"
  local s="$dir/summary.json"
  local result; result=$("$get" get "$s" "$key")
  local iterations; iterations=$(tail -n 1 "$dir/history.csv" | cut -d, -f5)
  local error; error=$(awk -v r="$result" -v e="$reference" 'BEGIN { printf "%.3e", (r - e) / e }')
  local mesh total; mesh=$("$get" get "$s" timings.mesh); total=$("$get" get "$s" timings.total)
  printf '%s,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.0f,%s,%s,%s,%s\n' "$case" "$variant" "$factor" \
    "$("$get" get "$s" problem.dofs)" "$("$get" get "$s" problem.bonds)" "$mesh" \
    "$("$get" get "$s" timings.setup)" "$("$get" get "$s" timings.assembly)" \
    "$("$get" get "$s" timings.solve)" "$total" "$(awk -v t="$total" -v m="$mesh" 'BEGIN { print t - m }')" \
    "$("$get" get "$s" peak_memory_mb_rank0)" "$iterations" "$result" "$reference" "$error" | tee -a "$csv"
}

# The peer's own box input, read unchanged (when ../shared is beside the project).
peer_box="$root/../shared/peer-inputs/pdlsm-fem/box/boxVpd4_static.in"
if [ -f "$peer_box" ]; then
  start=$(date +%s.%N)
  "$pdfem" "$peer_box" --output "$work/peer-box" --quiet
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", e - s }')
  s="$work/peer-box/summary.json"
  echo "peer box input (boxVpd4_static.in): process wall $wall s, total $("$get" get "$s" timings.total) s," \
    "peak $("$get" get "$s" peak_memory_mb_rank0) MB, max u_x $("$get" get "$s" final.max_displacement.x)," \
    "GMRES its $(tail -n 1 "$work/peer-box/history.csv" | cut -d, -f5); peer: 194.2 s, 9028 MB" | tee "$out/static_peer_box.txt"
fi

box="$here/box_3d.prm"
run box_3d "gmres amg-fe matrix-free" 1 5e-5 final.max_displacement.x "$box"
run box_3d "gmres amg assembled" 1 5e-5 final.max_displacement.x "$box" \
  --set "Linear solver/Preconditioner=amg"

hole="$root/applications/examples/plate_with_hole/plate_with_hole.prm"
for factor in 1 0.5 0.25; do
  run plate_with_hole "direct mumps" "$factor" 2.198e7 final.max_stress.xx "$hole" \
    --set "Mesh/Mesh size factor=$factor"
  run plate_with_hole "gmres amg-fe matrix-free" "$factor" 2.198e7 final.max_stress.xx "$hole" \
    --set "Mesh/Mesh size factor=$factor" --set "Linear solver/Type=gmres"
done

if have_plot; then
  grep -E "^case|^plate_with_hole,direct" "$csv" > "$work/direct.csv"
  grep -E "^case|^plate_with_hole,gmres" "$csv" > "$work/gmres.csv"
  xvfb-run -a "$plot" chart "$work/direct.csv" --x dofs --y compute_s --csv2 "$work/gmres.csv" --y2 compute_s \
    --label "direct (MUMPS),matrix-free GMRES + amg fe" --logx --logy --points \
    --xlabel "DoFs" --ylabel "wall time without meshing [s]" --title "plate_with_hole: time against size" \
    --out "$out/static_plate_time.png"
  awk -F, 'NR == 1 { print "dofs,abs_error_percent" } NR > 1 { e = $16 < 0 ? -$16 : $16; print $4 "," 100 * e }' \
    "$work/direct.csv" > "$work/error.csv"
  xvfb-run -a "$plot" chart "$work/error.csv" --x dofs --y abs_error_percent --logx --points \
    --xlabel "DoFs" --ylabel "|peak sigma_xx / Heywood - 1| [%]" \
    --title "plate_with_hole: accuracy against size" --out "$out/static_plate_error.png"
  echo "charts: $out/static_plate_time.png, $out/static_plate_error.png"
else
  echo "pdfem-plot or xvfb-run missing: no charts (see doc/tools.md)"
fi
echo "results: $csv"
