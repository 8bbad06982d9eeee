#!/bin/sh
# run_loads.sh -- the glass plate at the paper's three loads (sigma = 0.2, 2, 4 MPa), each into
# its own output folder output-<sigma>MPa, with a damage picture of each run (pdfem-render); then
# the crack-front table crack_front.csv (crack_front.py) and its two charts (pdfem-plot). About
# 1.5 min on a 2-core machine. Pictures need VTK and xvfb-run (doc/tools.md).
#
# Usage (from this folder): ./run_loads.sh [BUILD]   BUILD: pdfem's build folder (../../../build)
set -e
BUILD=${1:-../../../build}
for s in 0.2 2 4; do
  "$BUILD/bin/pdfem" glass_plate_branching.prm --output "output-${s}MPa" \
    --set "Boundary conditions/Traction=top: normal = ${s}e6; bottom: normal = ${s}e6"
  xvfb-run -a "$BUILD/bin/pdfem-render" "output-${s}MPa/solution.pvd" --field damage --warp 0 \
    --title "Glass plate, sigma = $s MPa: damage at t = 46 us" -o "damage_${s}MPa.png"
done
python3 crack_front.py output-0.2MPa output-2MPa output-4MPa
xvfb-run -a "$BUILD/bin/pdfem-plot" chart crack_front.csv --x time_us \
  --y tip_mm_0.2MPa,tip_mm_2MPa,tip_mm_4MPa --label "0.2 MPa,2 MPa,4 MPa" --xlabel "t [us]" \
  --ylabel "crack tip x [mm] (rightmost failed node)" --title "Glass plate: leading crack tip" \
  --legend top-left --out crack_tip.png
xvfb-run -a "$BUILD/bin/pdfem-plot" chart crack_front.csv --x time_us \
  --y speed_2MPa,speed_4MPa --label "2 MPa,4 MPa" --xlabel "t [us]" \
  --ylabel "tip speed [m/s] (2 us window)" --title "Glass plate: crack-tip speed" \
  --legend top-right --out crack_speed.png
