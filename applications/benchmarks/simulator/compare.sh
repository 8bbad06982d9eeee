#!/usr/bin/env bash
# Speed of one build against another on the peer's inputs (read in place from ../shared): the 3D box
# static, plateCrack quasi-static FC1 and FC2, and the explicit plateCrack FC2 input as given.
# The two builds run alternately, PAIRS times per input, so that both see the same drift of the
# machine's speed (±25 % within minutes); each run records the whole-process wall time
# (/usr/bin/time) and pdfem's own total (summary.json timings.total). The inputs run as given
# (field output included).
#
# usage: [PAIRS=3] [INPUTS="box fc1 fc2 explicit"] compare.sh OLD_BUILD NEW_BUILD [OUT_DIR]
# writes OUT_DIR/simulator_speed.csv (default doc/benchmarks) and prints the paired ratios.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
out=${3:-$root/doc/benchmarks}
peer="$root/../shared/peer-inputs/pdlsm-fem"
[ -d "$peer" ] || { echo "compare.sh: $peer not found" >&2; exit 1; }
get="$(find "$new" -name pdfem_check -type f | head -n 1)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
declare -A input=(
  [box]="$peer/box/boxVpd4_static.in"
  [fc1]="$peer/plateCrack/platCrack_quasiStatic_FC1.in"
  [fc2]="$peer/plateCrack/platCrack_quasiStatic_FC2.in"
  [explicit]="$peer/plateCrack/platCrack_NewMarkOFF_FC2.in")
mkdir -p "$out"
csv="$out/simulator_speed.csv"
echo "input,pair,build,wall_seconds,pdfem_total_seconds,steps,exit_state" > "$csv"
run() { # build label input pair
  local dir="$work/$2-$4-$1"
  /usr/bin/time -f "%e" -o "$dir.time" "$3/bin/pdfem" "${input[$1]}" --quiet --output "$dir" \
    > /dev/null 2>&1 || true
  echo "$1,$4,$2,$(cat "$dir.time"),$("$get" get "$dir/summary.json" timings.total),$("$get" get "$dir/summary.json" steps),$("$get" get "$dir/summary.json" exit_state)" >> "$csv"
}
for name in ${INPUTS:-box fc1 fc2 explicit}; do
  for pair in $(seq 1 "${PAIRS:-3}"); do
    if (( pair % 2 )); then run "$name" old "$old" "$pair"; run "$name" new "$new" "$pair"
    else run "$name" new "$new" "$pair"; run "$name" old "$old" "$pair"; fi
  done
  # paired ratios new / old of the wall time, and their median
  ratios=$(awk -F, -v n="$name" '$1 == n { t[$2 "," $3] = $4; p[$2] = 1 }
    END { for (k in p) printf "%.3f\n", t[k ",new"] / t[k ",old"] }' "$csv" | sort -n)
  count=$(echo "$ratios" | wc -l)
  median=$(echo "$ratios" | awk -v c="$count" '{ r[NR] = $1 }
    END { printf "%.3f", (c % 2 ? r[(c + 1) / 2] : (r[c / 2] + r[c / 2 + 1]) / 2) }')
  echo "$name new/old wall time: median $median ($(echo $ratios))"
done
echo "compare.sh: $csv"
