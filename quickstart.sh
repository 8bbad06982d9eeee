#!/usr/bin/env bash
# pdfem quickstart on Debian 12:
#   ./quickstart.sh run    install what is missing, build (Release), run the default scene
#   ./quickstart.sh test   install what is missing, build, run the whole test suite
# Environment: PDFEM_BUILD_DIR (default ./build), PDFEM_JOBS (default 2).
set -euo pipefail

command=${1:-run}
case "$command" in
  run | test | build) ;;
  -h | --help)
    sed -n '2,5p' "$0"
    exit 0
    ;;
  *)
    echo "quickstart.sh: unknown command '$command' (allowed: run, test, build)" >&2
    exit 2
    ;;
esac

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${PDFEM_BUILD_DIR:-$here/build}
jobs=${PDFEM_JOBS:-2}

# ---- 1. Debian packages (only those that are missing)
# libopenblas0-serial replaces Debian's reference BLAS under MUMPS (its dense kernels): a MUMPS
# factorisation of plateCrack's coupled matrix took 2.4x less time with it (doc/benchmarks/fracture.md).
# libvtk9-dev, xvfb, xauth, fonts-dejavu-core: pdfem-plot and pdfem-render (PNG pictures, drawn
# through a virtual X server; doc/tools.md). libfftw3-dev (with pkgconf to find it): the fft module
# (FFT evaluation of PD operators, doc/benchmarks/fft.md); libfftw3-mpi-dev for its MPI form (slabs over the ranks).
packages=(cmake ninja-build g++ libdeal.ii-dev libmumps-dev gmsh openmpi-bin libgtest-dev ccache libopenblas0-serial
  libvtk9-dev xvfb xauth fonts-dejavu-core libfftw3-dev libfftw3-mpi-dev pkgconf)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "quickstart: installing ${missing[*]}"
  if [ "$(id -u)" -eq 0 ]; then
    sudo=""
  elif command -v sudo >/dev/null; then
    sudo="sudo"
  else
    echo "quickstart: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Open MPI refuses to start as root unless told otherwise (containers, CI).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

# ---- 2. configure and build (Release, ccache when present)
# ccache: paths relative to the project (hits across clones in other folders), and the settings
# that let it cache compilations using the precompiled header.
export CCACHE_BASEDIR="$here"
export CCACHE_SLOPPINESS="pch_defines,time_macros,include_file_mtime,include_file_ctime"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
elif ! grep -q "pdfem-render" "$build/build.ninja"; then
  cmake "$build" # configured before VTK was installed: look for it again
fi
cmake --build "$build" -j "$jobs"

# ---- 3. run or test
case "$command" in
  run)
    scene="$here/applications/examples/plate_with_hole/plate_with_hole.prm"
    out="$build/output/plate_with_hole"
    "$build/bin/pdfem" "$scene" --output "$out"
    echo
    echo "quickstart: results of $(basename "$scene") are in $out"
    echo "  summary.json  sizes, peak values, timings, exit state"
    echo "  history.csv   one row per load step"
    echo "  solution.pvd  open in ParaView (displacement, stress, damage, PD region)"
    # A picture of the result (pdfem-render; doc/tools.md). Not having one does not fail the run.
    picture="$out/picture.png"
    render=("$build/bin/pdfem-render" "$out/solution.pvd" --field stress_xx -o "$picture")
    if [ ! -x "$build/bin/pdfem-render" ]; then
      echo "quickstart: no picture: pdfem-render was not built (VTK 9 not found: apt-get install libvtk9-dev)"
    else
      if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
        render=(xvfb-run -a "${render[@]}")
      fi
      if "${render[@]}" >"$out/picture.log" 2>&1; then
        echo "  picture.png   stress_xx on the deformed shape (pdfem-render): $picture"
      else
        echo "quickstart: no picture: $(tail -n 1 "$out/picture.log")"
      fi
    fi
    ;;
  test)
    ctest --test-dir "$build" -j "$jobs" --output-on-failure
    ;;
esac
