#!/usr/bin/env bash
# RNP plate in uniaxial tension against the classical solution, refined with the horizon factor
# fixed (m = 5), so that the horizon halves with the grid (tests/scenes/rnp_plate_tension.prm,
# specs/000 §4.2 / §7.10). The classical end displacement is u_x(0) = -0.01; the PD error is the
# O(horizon) surface effect of the loaded free edge plus the O(1/m) lattice error, so it halves
# with h, and the Richardson extrapolation of the last two grids removes its first-order part.
# Writes doc/benchmarks/rnp_plate_tension.csv and, with pdfem-plot, rnp_plate_tension.png.
#
# usage: applications/benchmarks/rnp/plate_tension.sh [BUILD_DIR] [OUT_DIR]
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"

csv="$out/rnp_plate_tension.csv"
echo "refinements,h,nodes,min_u_x,classical,relative_error,richardson,richardson_error" > "$csv"
previous=""
for r in 0 1 2; do
  dir="$work/r$r"
  "$pdfem" "$root/tests/scenes/rnp_plate_tension.prm" --quiet --output "$dir" \
    --set "Mesh/Global refinements=$r"
  u=$("$get" get "$dir/summary.json" final.min_displacement.x)
  n=$("$get" get "$dir/summary.json" problem.nodes)
  awk -v r="$r" -v u="$u" -v n="$n" -v p="$previous" 'BEGIN {
    h = 0.1 / 2^r; e = (-u - 0.01) / 0.01; # relative error of |u_x(0)|
    if (p == "") { x = ""; xe = "" } else { x = 2 * u - p; xe = sprintf("%.5f", (-x - 0.01) / 0.01); x = sprintf("%.6g", x) }
    printf "%d,%.4g,%d,%.6g,-0.01,%.5f,%s,%s\n", r, h, n, u, e, x, xe }' >> "$csv"
  previous=$u
done
cat "$csv"
plot="$build/bin/pdfem-plot"
if [ -x "$plot" ]; then
  run() { if command -v xvfb-run > /dev/null; then xvfb-run -a "$@"; else "$@"; fi; }
  run "$plot" chart "$csv" --x h --y relative_error --logx --logy --points \
    --xlabel "grid spacing h (horizon 5h)" --ylabel "|u_x(0)| error vs classical" \
    --title "RNP plate in tension: error halves with h" --out "$out/rnp_plate_tension.png"
fi
