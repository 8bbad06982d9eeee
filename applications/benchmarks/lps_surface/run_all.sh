#!/bin/sh
# run_all.sh -- every run of doc/benchmarks/lps_surface.md (about 12 min of pdfem on 2 cores; a
# run whose output exists in WORK is read, not repeated). Writes results.csv here and prints the
# decomposition table (analyse.py).
# Usage: sh run_all.sh [WORK (default /tmp/lps_surface)]
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=${1:-/tmp/lps_surface}
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
C=""
# square bars 4 and 8 horizons wide (L = 3 W), m = 2.01 ... 5.025, nu = 0.4
for W in 12 24; do for h in 1.5 1 0.75 0.6; do
  C="$C W=$W,h=$h,mode=free,model=lps_fft W=$W,h=$h,mode=all,model=lps_fft W=$W,h=$h,mode=free,model=fe"
done; done
# 16 horizons wide (L = 2 W)
for h in 1.5 1; do
  C="$C W=48,L=96,h=$h,mode=free,model=lps_fft W=48,L=96,h=$h,mode=all,model=lps_fft W=48,L=96,h=$h,mode=free,model=fe"
done
# the dog-bone's gauge section: a disc of diameter 30 mm on its lattice
for h in 1 0.75 0.6; do
  B=shape=round,centred=1,W=30,L=60,h=$h
  C="$C $B,mode=free,model=lps_fft $B,mode=all,model=lps_fft $B,mode=free,model=fe"
done
# the dog-bone's grip section (diameter 60 mm), without and with its lateral through-hole (R = 5 mm)
B=shape=round,centred=1,W=60,L=60,h=1
C="$C $B,mode=free,model=lps_fft $B,mode=free,model=fe $B,hole=5,mode=free,model=lps_fft $B,hole=5,mode=free,model=fe"
# nu = 0.25 (A = 3 kappa - 5 mu = 0: no dilatation term)
for W in 12 24; do for h in 1 0.75; do
  C="$C W=$W,h=$h,nu=0.25,mode=free,model=lps_fft W=$W,h=$h,nu=0.25,mode=all,model=lps_fft W=$W,h=$h,nu=0.25,mode=free,model=fe"
done; done
# lateral faces held in their normal direction; FE in uniaxial strain
C="$C W=12,h=1,mode=faces,model=lps_fft W=12,h=1,mode=faces,model=fe W=12,h=1,mode=all,model=fe"
# the direct bond loop (lps) against lps fft
for mo in free all; do for mod in lps lps_fft; do
  C="$C W=12,h=1.5,mode=$mo,model=$mod W=6,L=12,h=1,mode=$mo,model=$mod"
done; done
# the Dirichlet layers' thickness: 2 horizons and a third of one
C="$C W=12,h=1,T=6,mode=free,model=lps_fft W=12,h=1,T=6,mode=all,model=lps_fft W=12,h=1,T=6,mode=free,model=fe"
C="$C W=12,h=0.75,T=6,mode=all,model=lps_fft"
C="$C W=12,h=1,T=1,mode=free,model=lps_fft W=12,h=1,T=1,mode=all,model=lps_fft W=12,h=1,T=1,mode=free,model=fe"
rm -f "$HERE/results.csv"
# shellcheck disable=SC2086
python3 "$HERE/run.py" --work "$WORK" --csv "$HERE/results.csv" $C
python3 "$HERE/analyse.py" "$HERE/results.csv"
