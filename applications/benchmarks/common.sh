# Sourced by the benchmark scripts: the layout every one of them starts from.
#
#   source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"
#
# Arguments: [BUILD_DIR] [OUT_DIR] of the calling script (default: build/ and doc/benchmarks/ of
# the checkout). Sets: here (the calling script's folder), root, build, out (created), pdfem, pdfem-plot as plot, pdfem_check as get,
# work (a temporary folder removed on exit), peer (the PDLSM-FEM inputs beside the checkout), and
# v DIR KEY (a value of DIR/summary.json), have_plot (true when the charts can be drawn: pdfem-plot
# built and xvfb-run installed). Lets Open MPI run as root.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=${2:-$root/doc/benchmarks}
pdfem="$build/bin/pdfem"
plot="$build/bin/pdfem-plot"
get="$build/tests/pdfem_check"
[ -x "$get" ] || get="$(find "$build" -name pdfem_check -type f | head -n 1)"
peer="$root/../shared/peer-inputs/pdlsm-fem/plateCrack"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
v() { "$get" get "$1/summary.json" "$2"; }
have_plot() { [ -x "$plot" ] && command -v xvfb-run > /dev/null; }
