#!/usr/bin/env bash
# check.sh -- the dog-bone pipeline end to end on a coarse grid, for the test suite
# (example.lps_dog_bone): the mesher, the PD scene (lps fft, static, CG with the FFT
# preconditioner), the FE reference of the same problem and the paper's difference measure.
#
# usage: check.sh --pdfem PDFEM --work DIR [--cells-per-mm F] [--horizon-factor M] [--max-mean P]
#   defaults: F = 2/3 (1.5 mm cubes, 76 136 nodes), M = 2.01 (delta = 3.015 mm), P = 3 (percent)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
pdfem="" work="" per_mm=0.6666666666666666 m=2.01 max_mean=3
while (($#)); do
  case "$1" in
    --pdfem) pdfem="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --cells-per-mm) per_mm="$2"; shift 2 ;;
    --horizon-factor) m="$2"; shift 2 ;;
    --max-mean) max_mean="$2"; shift 2 ;;
    *) echo "check.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -n "$pdfem" && -n "$work" ]] || { echo "usage: check.sh --pdfem PDFEM --work DIR [...]" >&2; exit 2; }
command -v python3 > /dev/null || { echo "check.sh: no python3: skipped"; exit 77; }
mkdir -p "$work"
python3 "$here/dog_bone_mesh.py" --cells-per-mm "$per_mm" --layers "$work/body.msh"
"$pdfem" "$here/lps_dog_bone.prm" --output "$work/pd" --quiet \
  --set "Mesh/Input file=$work/body.msh" --set "Peridynamics/Horizon factor=$m"
"$pdfem" "$here/dog_bone_fe_layers.prm" --output "$work/fe" --quiet --set "Mesh/Input file=$work/body.msh"
python3 "$here/compare_fe.py" "$work/pd" "$work/fe" --max-mean "$max_mean"
