#!/usr/bin/env bash
# Kill-and-restart test (issue 19, doc/reliability.md): a run that writes a
# checkpoint every EVERY steps is killed (SIGKILL, no clean-up) at the step
# boundary or inside a checkpoint write given by KILL (PDFEM_TEST_KILL:
# step:N or checkpoint:N), then continued with --restart; its history.csv
# (all but wall_seconds) and nodes.csv must be those of the same run left
# alone, byte for byte (TOL = exact), or to the relative tolerance TOL where
# the run left alone does not repeat itself to the bit (MUMPS on several
# ranks schedules its work dynamically; the relative residual, noise at
# 1e-15, is not compared then, nor the linear iterations: a solve with
# reused factors may take one more or fewer at that noise).
# usage: restart_test.sh PDFEM CHECKER MPIEXEC NP SCENE WORK EVERY KILL TOL [--set ...]
set -u
pdfem=$(readlink -f "$1") checker=$(readlink -f "$2") mpiexec=$3 np=$4 scene=$(readlink -f "$5")
work=$6 every=$7 kill=$8 tol=$9
shift 9
rm -rf "$work" && mkdir -p "$work"
fail() {
  echo "FAIL: $*"
  exit 1
}
run() {
  if [ "$np" -gt 1 ]; then
    "$mpiexec" -n "$np" -x PDFEM_TEST_KILL "$pdfem" "$@"
  else
    "$pdfem" "$@"
  fi
}
common=(--quiet --set "Output/Checkpoint steps=$every" --set "Output/Write nodes csv=true" "$@")

export PDFEM_TEST_KILL=""
run "$scene" --output "$work/alone" "${common[@]}" > "$work/alone.log" 2>&1 \
  || { cat "$work/alone.log"; fail "the run left alone did not end with status 0"; }

export PDFEM_TEST_KILL="$kill"
run "$scene" --output "$work/killed" "${common[@]}" > "$work/killed.log" 2>&1 \
  && fail "the run was not killed at $kill"
grep -q '"exit_state": "running"' "$work/killed/summary.json" \
  || fail "the killed run's summary.json does not say 'running'"
killed_rows=$(($(wc -l < "$work/killed/history.csv") - 1))
[ -d "$work/killed/checkpoint" ] || fail "no checkpoint folder after the kill at $kill"

export PDFEM_TEST_KILL=""
run "$scene" --output "$work/killed" --restart "$work/killed" "${common[@]}" \
  > "$work/restart.log" 2>&1 || { cat "$work/restart.log"; fail "the restarted run did not end with status 0"; }

rows=$(($(wc -l < "$work/alone/history.csv") - 1))
if [ "$tol" = exact ]; then
  # wall_seconds is the last column
  strip() { awk 'BEGIN { FS = OFS = "," } { NF--; print }' "$1"; }
  diff <(strip "$work/alone/history.csv") <(strip "$work/killed/history.csv") > "$work/history.diff" \
    || { head -n 20 "$work/history.diff"; fail "history.csv differs from the run left alone"; }
  cmp "$work/alone/nodes.csv" "$work/killed/nodes.csv" || fail "nodes.csv differs from the run left alone"
  echo "killed at $kill with $killed_rows history rows written; restarted: $rows rows and nodes.csv identical"
else
  "$checker" csv "$work/alone/history.csv" "$work/killed/history.csv" "$tol" wall_seconds,residual,linear_iterations \
    || fail "history.csv differs from the run left alone by more than $tol"
  "$checker" csv "$work/alone/nodes.csv" "$work/killed/nodes.csv" "$tol" \
    || fail "nodes.csv differs from the run left alone by more than $tol"
  echo "killed at $kill with $killed_rows history rows written; restarted: $rows rows and nodes.csv within $tol"
fi
