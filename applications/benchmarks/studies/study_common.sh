# Sourced by the study scripts of this folder, after ../common.sh.
#
# study NAME SCENE ARGS...  runs pdfem-study on SCENE with ARGS into $work/NAME and copies its
#                           study.csv and study.png to $out/studies_NAME.*; exit status 3 (some
#                           runs failed, kept in the table) is a result, any other failure stops.
# column FILE NAME          the 1-based index of column NAME in the header of FILE.
study() {
  local name=$1 status=0
  shift
  "$build/bin/pdfem-study" "$@" -o "$work/$name" || status=$?
  if [ "$status" -ne 0 ] && [ "$status" -ne 3 ]; then
    exit "$status"
  fi
  cp "$work/$name/study.csv" "$out/studies_$name.csv"
  if [ -f "$work/$name/study.png" ]; then
    cp "$work/$name/study.png" "$out/studies_$name.png"
  fi
}
column() {
  head -n 1 "$1" | tr ',' '\n' | grep -n -x -F "$2" | cut -d: -f1
}
