#!/usr/bin/env bash
# Tests of pdfem-study (ctest study.*) on the tiny patch scene (tests/scenes/patch_2d_quad.prm,
# 0.1 s a run). Timings are never printed or compared, only their consistency with the pareto column.
#
# usage: study_test.sh CASE STUDY PDFEM CHECKER SCENE WORK
#   two_point         a two-point study (Young's modulus 70e9, 140e9; --set horizon factor 4):
#                     study.csv has a header and 2 rows, the varied values, outputs equal to plain
#                     pdfem runs of the same settings (1e-10), errors against the given reference,
#                     a consistent pareto column, the overrides in each run's parameters.prm
#   reference_run     --reference run:"...": the errors against the reference run's summary.json
#   failed_run        a run that diverges stays in study.csv with its state and no error; exit 3
#   ranks             --vary ranks=1,2: mpirun pdfem runs (in_process 0), outputs as pdfem's (1e-10),
#                     the 1-rank run unbound (as many threads as a plain run)
#   chart             study.png is a PNG, study_pareto.csv holds the runs marked pareto = 1
#   chart_series      with two --vary, study_chart.csv has one series per value of the first
#   bad_vary, unknown_parameter, unknown_output, unknown_option
#                     exit status 2, one line on stderr naming the option, no study.csv
set -u
case=$1 study=$(readlink -f "$2") pdfem=$(readlink -f "$3") checker=$(readlink -f "$4")
scene=$(readlink -f "$5") work=$6
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail() { echo "FAIL: $*"; exit 1; }

# csv FILE ROW COLUMN: the cell of data row ROW (1-based) in the column named COLUMN.
csv() {
  awk -F, -v row="$2" -v name="$3" '
    NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
    NR == row + 1 { if (c) print $c; else print "NO-COLUMN" }' "$1"
}
# close A B TOL: |A - B| <= TOL |B| (TOL absolute when B = 0).
close() {
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN {
    d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; if (m == 0) m = 1; exit !(a != "" && d <= t * m) }'
}
# error_case RC STDERR_FILE TEXT...: exit status 2, one line on stderr holding every TEXT, no study.csv.
error_case() {
  local rc=$1 err=$2; shift 2
  cat "$err"
  [ "$rc" -eq 2 ] || fail "exit status $rc, expected 2"
  [ "$(wc -l < "$err")" -eq 1 ] || fail "stderr has $(wc -l < "$err") lines, expected 1"
  grep -q '^pdfem-study: error: ' "$err" || fail "stderr does not start with 'pdfem-study: error: '"
  for text in "$@"; do
    grep -qF -- "$text" "$err" || fail "stderr does not name '$text'"
  done
  [ ! -e study/study.csv ] || fail "study.csv written despite bad input"
}

E="Material/Young's modulus"
case $case in
two_point)
  "$study" "$scene" --vary "$E=70e9,140e9" --set "Peridynamics/Horizon factor=4" \
    --output final.max_displacement.x --output final.min_displacement.y \
    --reference 1.1e-4 --reference -3.3e-5 -o study --no-chart > study.log 2>&1
  rc=$?
  [ $rc -eq 0 ] || { cat study.log; fail "exit status $rc, expected 0"; }
  [ "$(wc -l < study/study.csv)" -eq 3 ] || fail "study.csv: $(wc -l < study/study.csv) lines, expected 3"
  header="run,folder,$E,in_process,exit_state,final.max_displacement.x,final.min_displacement.y"
  header+=",final.max_displacement.x.reference,final.min_displacement.y.reference"
  header+=",final.max_displacement.x.error,final.min_displacement.y.error"
  header+=",wall_seconds,pdfem_total_seconds,peak_memory_mb,dofs,bonds,pareto"
  [ "$(head -n 1 study/study.csv)" = "$header" ] || fail "study.csv header: $(head -n 1 study/study.csv)"
  k=0
  for modulus in 70e9 140e9; do
    k=$((k + 1))
    [ "$(csv study/study.csv $k "$E")" = $modulus ] || fail "row $k: $E is not $modulus"
    [ "$(csv study/study.csv $k in_process)" = 1 ] || fail "row $k: not run in process"
    [ "$(csv study/study.csv $k exit_state)" = completed ] || fail "row $k: not completed"
    folder=study/$(csv study/study.csv $k folder)
    grep -q "Young's modulus *= $modulus\$" "$folder/parameters.prm" || fail "row $k: $folder/parameters.prm has not E = $modulus"
    grep -q "Horizon factor *= 4\$" "$folder/parameters.prm" || fail "row $k: the --set horizon factor is not in $folder/parameters.prm"
    # the same setting run by pdfem itself
    "$pdfem" "$scene" --set "$E=$modulus" --set "Peridynamics/Horizon factor=4" --output plain_$k \
      --quiet > plain_$k.log 2>&1 || fail "plain pdfem run $k failed"
    for key in final.max_displacement.x final.min_displacement.y problem.dofs problem.bonds; do
      column=$key
      [ $key = problem.dofs ] && column=dofs
      [ $key = problem.bonds ] && column=bonds
      v=$(csv study/study.csv $k $column) p=$("$checker" get plain_$k/summary.json $key)
      close "$v" "$p" 1e-10 || fail "row $k: $column = $v, pdfem gives $p"
    done
    # errors: |v - ref| / |ref|, against the values given and the analytic displacements
    for key in final.max_displacement.x final.min_displacement.y; do
      v=$(csv study/study.csv $k $key) r=$(csv study/study.csv $k $key.reference)
      e=$(csv study/study.csv $k $key.error)
      want=$(awk -v v="$v" -v r="$r" 'BEGIN { d = v - r; if (d < 0) d = -d; printf "%.17g", d / (r < 0 ? -r : r) }')
      close "$e" "$want" 1e-12 || fail "row $k: $key.error = $e, expected $want"
    done
  done
  close "$(csv study/study.csv 1 final.max_displacement.x.reference)" 1.1e-4 1e-15 || fail "reference of x"
  close "$(csv study/study.csv 1 final.max_displacement.x.error)" 0.090909090909090909 1e-9 || fail "row 1: error of x"
  close "$(csv study/study.csv 2 final.max_displacement.x.error)" 0.54545454545454545 1e-9 || fail "row 2: error of x"
  close "$(csv study/study.csv 2 final.min_displacement.y.error)" 0.5 1e-9 || fail "row 2: error of y"
  # pareto = 1 exactly for the rows that no other row beats in both wall time and first error
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { t[NR] = $c["wall_seconds"]; e[NR] = $c["final.max_displacement.x.error"]; p[NR] = $c["pareto"]; n = NR }
    END {
      for (a = 2; a <= n; ++a) {
        if (t[a] <= 0 || e[a] == "") { print "row " a - 1 ": no time or error"; exit 1 }
        front = 1
        for (b = 2; b <= n; ++b)
          if (b != a && t[b] <= t[a] && e[b] <= e[a] && (t[b] < t[a] || e[b] < e[a])) front = 0
        if (p[a] != front) { print "row " a - 1 ": pareto " p[a] ", expected " front; exit 1 }
      }
    }' study/study.csv || fail "pareto column"
  for k in 1 2; do
    m=$(csv study/study.csv $k peak_memory_mb)
    [ "$m" = n/a ] || awk -v m="$m" 'BEGIN { exit !(m > 10) }' || fail "row $k: peak memory $m MB"
    awk -v t="$(csv study/study.csv $k pdfem_total_seconds)" 'BEGIN { exit !(t > 0) }' || fail "row $k: no timings.total"
  done
  ;;
reference_run)
  "$study" "$scene" --vary "$E=70e9,140e9" --output final.max_displacement.x \
    --reference "run:$E=35e9" -o study --no-chart > study.log 2>&1
  rc=$?
  [ $rc -eq 0 ] || { cat study.log; fail "exit status $rc, expected 0"; }
  ref=$("$checker" get study/reference/summary.json final.max_displacement.x)
  close "$ref" 2e-4 1e-10 || fail "the reference run (E = 35e9) gives $ref, expected 2e-4"
  for k in 1 2; do
    close "$(csv study/study.csv $k final.max_displacement.x.reference)" "$ref" 1e-15 || fail "row $k: reference"
  done
  close "$(csv study/study.csv 1 final.max_displacement.x.error)" 0.5 1e-9 || fail "row 1: error"
  close "$(csv study/study.csv 2 final.max_displacement.x.error)" 0.75 1e-9 || fail "row 2: error"
  ;;
failed_run)
  "$study" "$scene" --vary "Driver/Residual tolerance=1e-30,1e-9" --set "Driver/Max iterations=2" \
    --output final.max_displacement.x --reference 1e-4 -o study --no-chart > study.log 2>&1
  rc=$?
  [ $rc -eq 3 ] || { cat study.log; fail "exit status $rc, expected 3"; }
  [ "$(wc -l < study/study.csv)" -eq 3 ] || fail "study.csv: $(wc -l < study/study.csv) lines, expected 3"
  [ "$(csv study/study.csv 1 exit_state)" = diverged ] || fail "row 1: exit state $(csv study/study.csv 1 exit_state)"
  [ -z "$(csv study/study.csv 1 final.max_displacement.x.error)" ] || fail "row 1: an error for a failed run"
  [ -z "$(csv study/study.csv 1 pareto)" ] || fail "row 1: ranked on the Pareto front"
  [ "$(csv study/study.csv 2 exit_state)" = completed ] || fail "row 2: the study did not go on"
  [ "$(csv study/study.csv 2 pareto)" = 1 ] || fail "row 2: the only ranked run is not on the front"
  close "$(csv study/study.csv 2 final.max_displacement.x.error)" 0 1e-12 || fail "row 2: error"
  ;;
ranks)
  "$study" "$scene" --vary "ranks=1,2" --output final.max_displacement.x --reference 1e-4 \
    -o study --no-chart > study.log 2>&1
  rc=$?
  [ $rc -eq 0 ] || { cat study.log; cat study/run_00*/run.log; fail "exit status $rc, expected 0"; }
  "$pdfem" "$scene" --output plain --quiet > plain.log 2>&1 || fail "plain pdfem run failed"
  p=$("$checker" get plain/summary.json final.max_displacement.x)
  for k in 1 2; do
    [ "$(csv study/study.csv $k ranks)" = $k ] || fail "row $k: ranks"
    [ "$(csv study/study.csv $k in_process)" = 0 ] || fail "row $k: in_process is not 0"
    [ "$("$checker" get study/run_00$k/summary.json ranks)" = $k ] || fail "row $k: summary.json ranks"
    close "$(csv study/study.csv $k final.max_displacement.x)" "$p" 1e-10 || fail "row $k: not pdfem's value"
  done
  # The 1-rank run is not bound to one core by mpirun: it has the threads a plain run has.
  [ "$("$checker" get study/run_001/summary.json threads)" = "$("$checker" get plain/summary.json threads)" ] ||
    { cat study/run_001/run.log; fail "the 1-rank run has $("$checker" get study/run_001/summary.json threads) thread(s), a plain run $("$checker" get plain/summary.json threads)"; }
  ;;
chart)
  "$study" "$scene" --vary "$E=70e9,140e9" --output final.max_displacement.x --reference 1.1e-4 \
    -o study > study.log 2>&1
  rc=$?
  [ $rc -eq 0 ] || { cat study.log; fail "exit status $rc, expected 0"; }
  [ "$(head -c 8 study/study.png | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { cat study.log; cat study/chart.log; fail "study.png is not a PNG"; }
  front=$(awk -F, 'NR > 1 && $NF == 1' study/study.csv | wc -l)
  [ "$(($(wc -l < study/study_pareto.csv) - 1))" -eq "$front" ] || fail "study_pareto.csv does not hold the $front pareto row(s)"
  ;;
chart_series)
  # Two --vary: one series per value of the first (a line with markers through the second's
  # values), not one per run.
  H="Peridynamics/Horizon factor"
  "$study" "$scene" --vary "$E=70e9,140e9" --vary "$H=3,4" --output final.max_displacement.x \
    --reference 1.1e-4 -o study > study.log 2>&1
  rc=$?
  [ $rc -eq 0 ] || { cat study.log; fail "exit status $rc, expected 0"; }
  [ "$(head -c 8 study/study.png | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { cat study/chart.log; fail "study.png is not a PNG"; }
  [ "$(head -n 1 study/study_chart.csv)" = "wall_seconds,series_1,series_2" ] ||
    fail "study_chart.csv header: $(head -n 1 study/study_chart.csv), expected two series"
  # Runs 1 and 2 (E = 70e9) in series 1, runs 3 and 4 in series 2.
  [ "$(awk -F, 'NR > 1 { print ($2 != "") ($3 != "") }' study/study_chart.csv | tr '\n' ' ')" = "10 10 01 01 " ] ||
    fail "runs not grouped by the first --vary: $(cat study/study_chart.csv)"
  ;;
bad_vary)
  "$study" "$scene" --vary "Peridynamics/Horizon factor" --output final.max_displacement.x -o study > out.log 2> err.log
  error_case $? err.log "--vary" "Section/Entry=value"
  "$study" "$scene" --vary "Peridynamics/Horizon factor=3,,4" --output final.max_displacement.x -o study > out.log 2> err.log
  error_case $? err.log "--vary" "empty value"
  [ ! -e study ] || fail "the study folder was made"
  ;;
unknown_parameter)
  "$study" "$scene" --vary "Peridynamics/Horizon factr=3,4" --output final.max_displacement.x -o study > out.log 2> err.log
  error_case $? err.log "--vary" "Horizon factr" "did you mean 'Peridynamics/Horizon factor'"
  [ ! -e study ] || fail "the study folder was made: something ran"
  [ ! -s out.log ] || fail "stdout not empty: $(cat out.log)"
  ;;
unknown_output)
  "$study" "$scene" --vary "Peridynamics/Horizon factor=3,4" --output final.max_stres.xx -o study --no-chart > out.log 2> err.log
  error_case $? err.log "--output final.max_stres.xx" "final.max_stress.xx"
  [ ! -e study/run_002 ] || fail "the study went on after the unknown key"
  ;;
unknown_option)
  "$study" "$scene" --varry "Peridynamics/Horizon factor=3,4" --output final.max_displacement.x -o study > out.log 2> err.log
  error_case $? err.log "unknown option '--varry'" "--vary"
  ;;
*)
  fail "unknown case $case"
  ;;
esac
echo "study test $case: passed"
