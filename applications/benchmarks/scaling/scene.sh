# Sourced by run.sh and growth.sh (after ../common.sh): one scaling scene at one size.
#
#   run_scene NAME CELLS_PER_METRE PRM [pdfem options...]
#
# writes $work/NAME-N/NAME.geo from NAME.geo.in (h = 1 / N), copies PRM beside it and runs pdfem on
# it (output in $dir/out, --quiet). Sets dir (the run's folder; the caller removes it) and wall (the
# whole process's wall time in seconds).
run_scene() {
  local name=$1 n=$2 prm=$3
  shift 3
  dir="$work/$name-$n"
  mkdir -p "$dir"
  sed "s/@H@/1 \/ $n/" "$here/$name.geo.in" > "$dir/$name.geo"
  cp "$here/$prm" "$dir/"
  local start
  start=$(date +%s.%N)
  "$pdfem" "$dir/$prm" --output "$dir/out" --quiet "$@"
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", e - s }')
}

#   split_by_dim CSV PREFIX
#
# writes the rows of CSV whose first column is 2 and 3, each with the header, to
# $work/PREFIX_2.csv and $work/PREFIX_3.csv (one curve each in the charts).
split_by_dim() {
  local dim
  for dim in 2 3; do
    awk -F, -v d=$dim 'NR == 1 || $1 == d' "$1" > "$work/$2_$dim.csv"
  done
}
