#!/usr/bin/env bash
# Convergence of the 1D bar (specs/003 §5.1 case A, §7 item 7): bar_1d.prm at several lattice
# spacings dx = 0.01 m x FACTOR (Mesh/Mesh size factor, read by bar_1d.geo), the relative L2 error
#
#   e = sqrt( sum_k (u_k - u^a(x_k))^2 dV_k / sum_k u^a(x_k)^2 dV_k ),   u^a(x) = F x / (E A),
#
# over the bar's nodes 0 <= x <= L (both lines of nodes; dV_k = dx, dx/2 at x = L, the nodes' share
# of the bar), u(L), and the least-squares slope of log e against log dx. F / (E A) = 1e-3 is
# bar_1d.prm's: 2e8 Pa / 2e11 Pa.
#
# usage: convergence.sh [options] [-- extra pdfem arguments, e.g. --set "Section/Entry=value"]
#   --pdfem PATH        the pdfem executable (default: build/bin/pdfem of the checkout)
#   --factors "F ..."   mesh size factors (default: the paper's dx = 1/10 ... 1/20000 m)
#   --work DIR          run folders (default: a temporary folder, removed at the end)
#   --csv FILE          write the table as CSV
#   --chart FILE.png    draw e against dx, log-log, beside a line of slope 1 through the finest
#                       point (pdfem-plot beside pdfem, under xvfb-run)
#   --slope S TOL       exit 1 unless |slope - S| <= TOL (and every run completed)
#   --max-tip-error E   exit 1 unless |u(L) - 1e-3| / 1e-3 <= E at the finest dx
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
pdfem="$here/../../../build/bin/pdfem"
factors="10 1 0.2 0.1 0.02 0.01 0.005"
work="" csv="" chart="" slope="" slope_tol="" tip_tol=""
while [ $# -gt 0 ]; do
  case "$1" in
    --pdfem) pdfem=$2; shift 2 ;;
    --factors) factors=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --csv) csv=$2; shift 2 ;;
    --chart) chart=$2; shift 2 ;;
    --slope) slope=$2; slope_tol=$3; shift 3 ;;
    --max-tip-error) tip_tol=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "convergence.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
if [ -z "$work" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

table="$work/convergence.csv"
echo "dx,nodes,u_L,u_L_error,l2_error,pdfem_s" > "$table"
for f in $factors; do
  d="$work/factor_$f"
  "$pdfem" "$here/bar_1d.prm" --quiet --output "$d" --set "Mesh/Mesh size factor=$f" \
    --set "Output/Write nodes csv=true" "$@" > "$d.log" 2>&1 || {
    echo "convergence.sh: the run with factor $f failed:" >&2
    cat "$d.log" >&2
    exit 1
  }
  seconds=$(sed -n 's/.*"total": *\([0-9.eE+-]*\).*/\1/p' "$d/summary.json" | head -n 1)
  # nodes.csv: x,y,ux,uy,...; the bar's nodes are those with x >= 0
  awk -F, -v dx="$(awk -v f="$f" 'BEGIN { printf "%.10g", 0.01 * f }')" -v s="$seconds" '
    NR > 1 && $1 >= -1e-9 * dx {
      w = ($1 > 1 - 1e-6 * dx) ? 0.5 : 1; ua = 1e-3 * $1
      num += w * ($3 - ua)^2; den += w * ua^2; n++
      if ($1 > 1 - 1e-6 * dx) uL = $3
    }
    END { printf "%.10g,%d,%.10e,%.6e,%.6e,%s\n", dx, n, uL, (uL - 1e-3) / 1e-3, sqrt(num / den), s }
  ' "$d/nodes.csv" >> "$table"
done

# the table, the local slopes and the least-squares slope of log e against log dx
status=0
awk -F, -v want="$slope" -v tol="$slope_tol" -v tip="$tip_tol" '
  NR == 1 { printf "%10s %7s %14s %11s %11s %9s %7s\n", "dx [m]", "nodes", "u(L) [m]", "u(L) rel.", "L2 error", "pdfem s", "slope"; next }
  {
    x = log($1); y = log($5); m++
    sx += x; sy += y; sxx += x * x; sxy += x * y
    local = m > 1 ? sprintf("%.3f", (y - py) / (x - px)) : "-"
    printf "%10.4g %7d %14.8e %11.3e %11.4e %9.2f %7s\n", $1, $2, $3, $4, $5, $6, local
    px = x; py = y; last_tip = $4
  }
  END {
    s = (m * sxy - sx * sy) / (m * sxx - sx * sx)
    printf "least-squares slope of log(L2 error) against log(dx) over %d spacings: %.4f\n", m, s
    bad = 0
    if (want != "" && (s - want > tol || want - s > tol)) {
      printf "FAIL: slope %.4f is not %s +- %s\n", s, want, tol; bad = 1
    }
    if (tip != "" && (last_tip > tip || -last_tip > tip)) {
      printf "FAIL: u(L) at the finest dx is %.3e from 1e-3 m relative, more than %s\n", last_tip, tip; bad = 1
    }
    exit bad
  }' "$table" || status=$?
[ -n "$csv" ] && cp "$table" "$csv"
if [ -n "$chart" ]; then
  awk -F, 'NR == 1 { print "dx,l2_error,first_order"; next } { dx[NR] = $1; e[NR] = $5; n = NR }
    END { for (i = 2; i <= n; i++) printf "%s,%s,%.6e\n", dx[i], e[i], e[n] * dx[i] / dx[n] }' \
    "$table" > "$work/chart.csv"
  xvfb-run -a "$(dirname "$pdfem")/pdfem-plot" chart "$work/chart.csv" --x dx --y l2_error,first_order \
    --logx --logy --markers --label "relative L2 error of u,first order (slope 1)" --xlabel "dx [m]" \
    --ylabel "relative L2 error" --size 900 600 \
    --title "1D bar, bond-based, delta = 3.015 dx: first-order convergence" --out "$chart"
fi
exit $status
