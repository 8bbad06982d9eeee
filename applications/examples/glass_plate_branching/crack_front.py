#!/usr/bin/env python3
"""crack_front.py -- the crack front and branching of glass_plate_branching runs.

Usage: python3 crack_front.py OUTPUT_DIR [OUTPUT_DIR ...]

For each pdfem output folder (a run of glass_plate_branching.prm):

* from history.csv (the columns of the postprocessor `lps fft damage`): the leading crack tip
  x_tip(t) = failed_max_x, the rightmost failed node (lambda = 0), and its speed
  v(t) = (x_tip(t + T) - x_tip(t - T)) / 2T over T = 1 us (the tip moves in whole grid spacings,
  0.25 mm, so that a shorter window gives steps of 1000 m/s);
* from nodes.csv (the final state): the failed nodes (damage > 0.999) of every grid column
  x > 50 mm grouped into clusters along y (a gap of more than 1 mm = one horizon between two
  clusters); the crack has branched where a column holds two or more clusters over at least
  1 mm of x (4 consecutive columns). Prints the first such x, or "no branching".

Writes crack_front.csv (time_us and, per run, tip_mm_<run> and speed_<run> in m/s) in the
current folder. Pure Python 3, no packages needed.
"""
import csv
import os
import sys

NOTCH_TIP = 0.05  # m, the pre-crack's tip
GAP = 1e-3  # m, a gap between clusters of failed nodes (one horizon)
MIN_RUN = 4  # consecutive grid columns with two clusters: a branch
WINDOW = 1e-6  # s, half the window of the speed


def history(folder):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time"]) for r in rows]
    n = [float(r["failed_nodes"]) for r in rows]
    x = [float(r["failed_max_x"]) if float(r["failed_nodes"]) > 0 else NOTCH_TIP for r in rows]
    return t, n, x


def speed(t, x):
    v = []
    for i, ti in enumerate(t):
        lo = max(j for j in range(len(t)) if t[j] <= max(ti - WINDOW, t[0]) + 1e-12)
        hi = min(j for j in range(len(t)) if t[j] >= min(ti + WINDOW, t[-1]) - 1e-12)
        v.append((x[hi] - x[lo]) / (t[hi] - t[lo]) if t[hi] > t[lo] else 0.0)
    return v


def branching(folder):
    columns = {}
    with open(os.path.join(folder, "nodes.csv")) as f:
        for r in csv.DictReader(f):
            x, y = float(r["x"]), float(r["y"])
            if float(r["damage"]) > 0.999 and x > NOTCH_TIP + 1e-9:
                columns.setdefault(round(x, 9), []).append(y)
    run, first = 0, None
    for x in sorted(columns):
        ys = sorted(columns[x])
        clusters = 1 + sum(1 for a, b in zip(ys, ys[1:]) if b - a > GAP)
        run = run + 1 if clusters >= 2 else 0
        if run == MIN_RUN:
            first = x - (MIN_RUN - 1) * (sorted(columns)[1] - sorted(columns)[0])
            break
    return first, max(columns) if columns else None


def main(folders):
    table = {}
    for folder in folders:
        name = os.path.basename(os.path.normpath(folder)).replace("output-", "")
        t, n, x = history(folder)
        v = speed(t, x)
        table[name] = (t, x, v)
        first, last = branching(folder)
        moved = [ti for ti, xi in zip(t, x) if xi > NOTCH_TIP + 1e-9]
        print("%s: %d failed nodes at t = %.1f us" % (name, n[-1], t[-1] * 1e6))
        if moved:
            print("  crack tip leaves the pre-crack at t = %.2f us; at the end x_tip = %.2f mm"
                  % (moved[0] * 1e6, x[-1] * 1e3))
            # the time the tip reached its final place (the right edge, or where it stopped)
            t_end = next(ti for ti, xi in zip(t, x) if xi >= x[-1] - 1e-12)
            grow = [vi for ti, vi in zip(t, v) if ti >= moved[0]]
            print("  tip speed: mean %.0f m/s from %.2f us to %.2f us (x_tip from 50 to %.2f mm), "
                  "largest %.0f m/s" % ((x[-1] - NOTCH_TIP) / max(t_end - moved[0], 1e-300),
                                         moved[0] * 1e6, t_end * 1e6, x[-1] * 1e3, max(grow)))
        else:
            print("  the crack did not grow")
        print("  branching: " + ("first at x = %.2f mm" % (first * 1e3) if first
                                 else "no branching"))
    names = list(table)
    t = table[names[0]][0]
    with open("crack_front.csv", "w") as f:
        f.write(",".join(["time_us"] + ["tip_mm_%s,speed_%s" % (k, k) for k in names]) + "\n")
        for i, ti in enumerate(t):
            cells = ["%.4f" % (ti * 1e6)]
            for k in names:
                tk, xk, vk = table[k]
                cells += ["%.4f" % (xk[i] * 1e3), "%.1f" % vk[i]] if i < len(tk) else ["", ""]
            f.write(",".join(cells) + "\n")
    print("wrote crack_front.csv")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: crack_front.py OUTPUT_DIR [OUTPUT_DIR ...]")
    main(sys.argv[1:])
