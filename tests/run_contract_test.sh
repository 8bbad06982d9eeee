#!/usr/bin/env bash
# The run contract of design.md that scene tests do not see:
# - while a run is going, summary.json says 'running' (a killed run is never taken for a finished one);
# - SIGTERM and SIGINT end a run after the current step with exit status 3, summary.json says
#   'interrupted' and names the signal, and history.csv ends with the step the run stopped at;
#   a driver that can resume writes a checkpoint first (restart_test.sh restarts from one);
# - parameters.prm in the output folder (every --set applied) repeats the run: the same nodes.csv;
# - a run removes the outputs an earlier run left in its folder, and no other file;
# - an output that cannot be written (the folder removed mid-run) ends the run with 'io error';
# - solution.pvd's times are the steps' times, increasing; the .vtu mark cracked cells.
# usage: run_contract_test.sh PDFEM CHECKER SCENES_DIR WORK
set -u
pdfem=$(readlink -f "$1") checker=$(readlink -f "$2") scenes=$(readlink -f "$3") work=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# name, signal, scene, overrides (long runs: stopped well before their end)
run_case() {
  local name=$1 sig=$2 scene=$3; shift 3
  local out="$work/$name"
  "$pdfem" "$scenes/$scene" --output "$out" --quiet "$@" > "$work/$name.log" 2>&1 &
  local pid=$!
  for _ in $(seq 1 1200); do
    if [ -f "$out/history.csv" ] && [ "$(wc -l < "$out/history.csv")" -ge 3 ]; then break; fi
    kill -0 $pid 2> /dev/null || break
    sleep 0.1
  done
  "$checker" string "$out/summary.json" exit_state running || fail "$name: no 'running' summary.json"
  kill "-$sig" $pid 2> /dev/null
  wait $pid
  local rc=$?
  cat "$work/$name.log"
  [ $rc -eq 3 ] || fail "$name: exit status $rc, expected 3"
  "$checker" string "$out/summary.json" exit_state interrupted || fail "$name: exit state"
  grep -q "SIG$sig received" "$out/summary.json" || fail "$name: the message does not name SIG$sig"
  grep -q "SIG$sig received: stopped after step" "$work/$name.log" || fail "$name: no message on stderr"
  # the last history row is the step the run stopped at
  local last_step steps
  last_step=$(tail -n 1 "$out/history.csv" | cut -d, -f1)
  steps=$("$checker" get "$out/summary.json" steps)
  [ "${last_step%.*}" = "$steps" ] || fail "$name: history ends at step $last_step, summary says $steps"
  echo "$name: stopped by SIG$sig at step $steps"
}

# explicit dynamics, 100 times its usual end time
run_case explicit TERM dynamics_wave_plate_plane_stress.prm --set "Driver/End time=2.2e-2"
# a resumable driver writes a checkpoint on the signal and says how to go on
[ -f "$work/explicit/checkpoint/rank-0.state" ] || fail "explicit: no checkpoint after SIGTERM"
grep -q "go on with --restart" "$work/explicit.log" || fail "explicit: the message does not say how to go on"
# Newton with stability checks, many load steps
run_case newton INT rnp_cracked_plate_hard.prm --set "Driver/Load steps=2000"
[ -f "$work/newton/checkpoint/rank-0.state" ] || fail "newton: no checkpoint after SIGINT"

# --print-parameters with a scene: its resolved parameters (every --set applied), nothing run
"$pdfem" "$scenes/bond_based_softening.prm" --set "Driver/Load steps=7" --print-parameters \
  --output "$work/printed" > "$work/printed.prm" 2> "$work/printed.err" || fail "--print-parameters: exit status"
grep -Eq '^ *set Load steps *= 7$' "$work/printed.prm" || fail "--print-parameters: the --set value is not printed"
grep -Eq '^ *set Onset stretch *= 0.002$' "$work/printed.prm" || fail "--print-parameters: the scene's value is not printed"
[ ! -e "$work/printed" ] || fail "--print-parameters: the scene was run"
"$pdfem" "$work/printed.prm" --quiet --output "$work/printed_run" > /dev/null 2>&1 \
  || fail "--print-parameters: its output is not a scene that runs"
"$pdfem" "$scenes/bond_based_softening.prm" --set "Driver/Type=newtn" --print-parameters > /dev/null 2>&1
[ $? -eq 2 ] || fail "--print-parameters: a bad choice was not refused"

# progress lines (user_guide.md, "Progress lines"): every step line names the largest reaction and
# the time left (by load; a bound where cracks grow), and with Progress interval = 0 every Newton
# iteration inside a step has a line
"$pdfem" "$scenes/bond_based_softening.prm" --output "$work/progress" \
  --set "Output/Progress interval=0" > "$work/progress.log" 2>&1 || fail "progress: the run failed"
grep -Eq '^Step +3/10 .* reaction (left|right) = \(.*\) N  left ~[0-9.]+ s$' "$work/progress.log" \
  || fail "progress: no reaction or time left in the step line"
grep -Eq '^  load factor [0-9.e-]+: Newton iteration [0-9]+, \|r\|/\|f\| = ' "$work/progress.log" \
  || fail "progress: no line from inside a step"
"$pdfem" "$scenes/growth_load_control_separated.prm" --output "$work/progress_growth" \
  > "$work/progress_growth.log" 2>&1
grep -Eq '^Step +2/100 .* left <= [0-9.]+ s$' "$work/progress_growth.log" \
  || fail "progress: a growth run's time left is not a bound"

# solution.pvd lists each output at its step's time (the load factor here), strictly increasing:
# growth steps at a held load 1e-9 (relative) after the one before; every .vtu has the cell array
# 'cracked': the cells the pre-existing crack cuts, more once it has grown
out="$work/pvd"
"$pdfem" "$scenes/growth_mcts_center_crack.prm" --output "$out" --quiet --set "Output/Write vtu=true" \
  --set "Output/Write every=1" > /dev/null 2>&1
[ -f "$out/solution.pvd" ] || fail "pvd: no solution.pvd"
python3 - "$out" << 'PY' || fail "pvd: times or cracked cells"
import base64, re, struct, sys
out = sys.argv[1]
pvd = [float(t) for t in re.findall(r'timestep="([^"]+)"', open(out + "/solution.pvd").read())]
rows = [l.split(",") for l in open(out + "/history.csv").read().split()[1:]]
times = [float(r[1]) for r in rows]
assert len(pvd) == len(times) + 1, (len(pvd), len(times))  # every step, then the final state
assert all(b > a for a, b in zip(pvd, pvd[1:])), "not increasing"
for t, h in zip(pvd, times + times[-1:]):
    assert abs(t - h) <= 1e-7 * max(1., abs(h)), (t, h)
assert len(set(times)) < len(times), "the scene has no growth steps at a held load"
def cracked(vtu):
    m = re.search(r'Name="cracked"[^>]*>\s*([^<\s]*)', open(vtu, encoding="latin-1").read())
    raw = base64.b64decode(m.group(1))
    return sum(struct.unpack("<%df" % ((len(raw) - 4) // 4), raw[4:]))
first, last = cracked(out + "/solution_00000.0.vtu"), cracked(out + "/solution_%05d.0.vtu" % (len(pvd) - 1))
assert 0 < first < last, (first, last)  # the pre-existing crack, then the grown one
print("pvd: %d records from %g to %g, increasing; cracked cells %d, then %d" % (len(pvd), pvd[0], pvd[-1], first, last))
PY

# the output folder removed during a run: the next field output fails, the run ends 'io error'
# (exit status 3, one message naming the file), no crash
out="$work/removed"
"$pdfem" "$scenes/rnp_cracked_plate_hard.prm" --output "$out" --quiet --set "Driver/Load steps=2000" \
  --set "Output/Write vtu=true" --set "Output/Write every=1" > "$work/removed.log" 2>&1 &
pid=$!
for _ in $(seq 1 1200); do
  if [ -f "$out/history.csv" ] && [ "$(wc -l < "$out/history.csv")" -ge 3 ]; then break; fi
  kill -0 $pid 2> /dev/null || break
  sleep 0.1
done
# (a file the run creates while rm -rf empties the folder keeps the folder: remove until it is gone)
for _ in $(seq 1 100); do
  rm -rf "$out" 2> /dev/null
  [ -e "$out" ] || break
done
wait $pid
rc=$?
cat "$work/removed.log"
[ $rc -eq 3 ] || fail "removed folder: exit status $rc, expected 3"
grep -q "io error" "$work/removed.log" || fail "removed folder: no 'io error' message"
! grep -qi "terminate\|Stacktrace\|Aborted" "$work/removed.log" || fail "removed folder: a crash"
echo "removed folder: io error"

# --restart without a checkpoint there: one line, status 2, no folder made
"$pdfem" "$scenes/patch_2d_quad.prm" --restart "$work/none" > "$work/none.log" 2>&1
[ $? -eq 2 ] || fail "--restart without a checkpoint: status not 2"
grep -q "no checkpoint there" "$work/none.log" || fail "--restart without a checkpoint: message"
[ ! -e "$work/none" ] || fail "--restart without a checkpoint made its folder"

# parameters.prm repeats the run, from another folder
"$pdfem" "$scenes/patch_2d_quad.prm" --output "$work/first" --quiet --set "Output/Write nodes csv=true" \
  || fail "patch_2d_quad did not complete"
grep -q "Write nodes csv *= true" "$work/first/parameters.prm" || fail "parameters.prm lacks the --set value"
# ... into a folder with an earlier run's outputs: those go, other files stay
mkdir -p "$work/again" && touch "$work/again/solution_00099.vtu" "$work/again/crack_paths.csv" \
  "$work/again/notes.txt"
(cd "$work" && "$pdfem" first/parameters.prm --output "$work/again" --quiet) || fail "parameters.prm did not run"
cmp -s "$work/first/nodes.csv" "$work/again/nodes.csv" || fail "parameters.prm gave another nodes.csv"
[ ! -e "$work/again/solution_00099.vtu" ] && [ ! -e "$work/again/crack_paths.csv" ] \
  || fail "an earlier run's outputs stayed in the folder"
[ -e "$work/again/notes.txt" ] || fail "a file pdfem does not write was removed"
# a read-only output folder: refused before any work, one line, nothing written. Root writes
# anyway, so as root the run is made as 'nobody' where that user can run pdfem (else skipped).
ro="$work/readonly"
mkdir -p "$ro" && chmod 555 "$ro"
as_user=()
if [ "$(id -u)" = 0 ]; then
  chmod -R a+rX "$work"
  if command -v runuser > /dev/null && runuser -u nobody -- test -x "$pdfem" \
    && runuser -u nobody -- test -r "$scenes/patch_2d_quad.prm"; then
    as_user=(runuser -u nobody -- env HOME=/tmp)
  else
    ro=""
    echo "read-only folder: skipped (root, and 'nobody' cannot run pdfem here)"
  fi
fi
if [ -n "$ro" ]; then
  "${as_user[@]}" "$pdfem" "$scenes/patch_2d_quad.prm" --output "$ro" --quiet > "$work/ro.out" 2> "$work/ro.err"
  [ $? -eq 2 ] || fail "read-only folder: status not 2"
  [ "$(wc -l < "$work/ro.err")" -eq 1 ] || fail "read-only folder: not one line: $(cat "$work/ro.err")"
  grep -q "cannot write into the output folder '$ro': Permission denied" "$work/ro.err" \
    || fail "read-only folder: message $(cat "$work/ro.err")"
  [ -z "$(ls -A "$ro")" ] || fail "read-only folder: something was written"
  echo "read-only folder: $(cat "$work/ro.err")"
fi
echo "run contract test passed"
