#!/usr/bin/env python3
"""history.csv of rnp_plate_hard.prm -> U, wedge force, softened nodes, crack tip, stable.

Usage: rnp_plate_hard_csv.py HISTORY.csv OUT.csv U_MAX
U = U_MAX * load_factor; F = the reaction of the upper wedge (y), in MN per unit thickness;
crack_tip_x = tip1_x: the pre-crack tip (7.5) advanced to the farthest softened node near its line.
"""
import csv
import sys

history, out, u_max = sys.argv[1], sys.argv[2], float(sys.argv[3])
with open(history) as f:
    rows = list(csv.DictReader(f))
force = [c for c in rows[0] if c.startswith("reaction_") and c.endswith("_y")][0]
with open(out, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["step", "U", "F_MN", "max_damage", "softened_nodes", "crack_tip_x", "stable"])
    for r in rows:
        w.writerow([r["step"], "%.6g" % (u_max * float(r["load_factor"])),
                    "%.6g" % (float(r[force]) / 1e6), "%.6g" % float(r["max_damage"]),
                    r["softened_nodes"], "%.6g" % float(r["tip1_x"]), r["stable"]])
