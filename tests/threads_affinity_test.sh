#!/usr/bin/env bash
# A run never has more threads than cores it may run on (fit_threads_to_cores(), thread_team.h):
# - bound to one core (taskset, as mpirun binds a rank) with DEAL_II_NUM_THREADS=2, it runs with
#   1 thread (summary.json 'threads') and says why on stderr;
# - with two cores allowed it keeps its 2 threads and says nothing (skipped on a 1-core machine).
# usage: threads_affinity_test.sh PDFEM CHECKER SCENE WORK
set -u
pdfem=$(readlink -f "$1") checker=$(readlink -f "$2") scene=$(readlink -f "$3") work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }

DEAL_II_NUM_THREADS=2 taskset -c 0 "$pdfem" "$scene" --output bound --quiet > bound.log 2>&1 ||
  { cat bound.log; fail "the bound run failed"; }
[ "$("$checker" get bound/summary.json threads)" = 1 ] ||
  fail "bound to one core: threads = $("$checker" get bound/summary.json threads), expected 1"
grep -q "^pdfem: note: this process may run on 1 core only .* so it uses 1 thread instead of 2; 'mpirun --bind-to none' lets it use 2$" bound.log ||
  { cat bound.log; fail "no note on stderr about the core binding"; }

if [ "$(nproc)" -lt 2 ]; then
  echo "only $(nproc) core allowed here: the unbound case is skipped"
  exit 0
fi
DEAL_II_NUM_THREADS=2 taskset -c 0,1 "$pdfem" "$scene" --output free --quiet > free.log 2>&1 ||
  { cat free.log; fail "the unbound run failed"; }
[ "$("$checker" get free/summary.json threads)" = 2 ] ||
  fail "two cores allowed: threads = $("$checker" get free/summary.json threads), expected 2"
! grep -q "may run on" free.log || fail "a note about binding without one: $(cat free.log)"
echo "threads fit the cores: 1 bound, 2 free"
