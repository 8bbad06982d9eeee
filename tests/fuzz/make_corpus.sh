#!/bin/bash
# Makes the seed corpora of the fuzz targets (tests/fuzz/corpus/<reader>/) from the test inputs:
#   prm       every scene of tests/scenes;
#   msh       the test geometries meshed coarsely by gmsh, in formats 4.1 and 2.2;
#   pdlsm_fem every PDLSM-FEM command file of the tests with its .lis mesh after a line `#@ mesh`
#             (readers.h), MSHFILE renamed to mesh.lis.
# Files over 64 KiB are left out.
# Usage: tests/fuzz/make_corpus.sh (from anywhere; needs gmsh). Rewrites the three folders.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tests=$(dirname "$here")
corpus=$here/corpus
rm -rf "$corpus"
mkdir -p "$corpus"/{prm,msh,pdlsm_fem}

cp "$tests"/scenes/*.prm "$corpus/prm/"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for geo in patch_2d_quad patch_2d_quad_pins patch_2d_tri through_crack_2d patch_3d_hex patch_3d_tet; do
  dim=2
  [[ $geo == *3d* ]] && dim=3
  for format in msh41 msh22; do
    gmsh -$dim -format $format -clscale 4 -v 0 "$tests/meshes/$geo.geo" -o "$work/$geo-$format.msh" > /dev/null
    cp "$work/$geo-$format.msh" "$corpus/msh/"
  done
done

for in in "$tests"/data/pdlsm_fem/*.in "$tests"/scenes/*.in; do
  lis=$(awk '$1 == "MSHFILE" { print $2; exit }' "$in")
  out=$corpus/pdlsm_fem/$(basename "$in")
  sed 's/^\(MSHFILE[[:space:]]\+\).*/\1mesh.lis/' "$in" > "$out"
  lis_path=$(dirname "$in")/$lis
  if [[ -n $lis && -f $lis_path ]]; then
    printf '\n#@ mesh\n' >> "$out"
    cat "$lis_path" >> "$out"
  fi
done
# The meshes alone, each with a minimal command file.
for lis in "$tests"/data/pdlsm_fem/*.lis; do
  out=$corpus/pdlsm_fem/$(basename "$lis" .lis)-mesh.in
  printf 'MSHFILE mesh.lis\nSOLVER STATIC\n\n#@ mesh\n' > "$out"
  cat "$lis" >> "$out"
done
# Small inputs only: libFuzzer's speed falls with the input's length.
find "$corpus" -type f -size +64k -delete
echo "corpus: $(ls "$corpus/prm" | wc -l) prm, $(ls "$corpus/msh" | wc -l) msh, $(ls "$corpus/pdlsm_fem" | wc -l) pdlsm_fem"
