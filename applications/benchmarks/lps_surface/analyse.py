#!/usr/bin/env python3
"""analyse.py -- the tables of doc/benchmarks/lps_surface.md from run.py's CSV.

Usage: python3 analyse.py RESULTS.csv

For every bar (shape, W, L, h, nu) with the runs free/lps_fft, free/fe and all/lps_fft it splits
the PD / FE force ratio of the free bar into

  F_PD / F_FE = (A_n / A_c) x (M_n,PD / M_c,FE) x (eps_mid,PD / eps_mid,FE)

  A_n / A_c        the nodes' cross-section (node count x h^2) over the cubes' one
  M_n,PD = E_100 (1 + s_free)   the section's modulus per node area: E_100 the lattice's
                   homogeneous cube-axis Young's modulus (lattice_moduli.py), s_free the surface part
  eps_mid ratio    the strain of the middle third: how the ends share the prescribed displacement

(not for a bar with a hole: its middle third crosses the hole) and from the uniaxial-strain bar (all): s_all = M_n / C11 - 1 (the truncated families alone, exact
in section_energy.py) and the end compliance Delta = L (1 / eps_mid - 1) / 2 per end (mm; FE: 0).
k = s (A_n / (P_n delta)) is the surface part per unit of perimeter x horizon (P_n, A_n of the
nodes' section: W + h wide, or a disc of area A_n).
"""
import csv
import math
import sys

DELTA = 3.015


def lattice(nu, m, E=1.0):
    kappa = E / (3 * (1 - 2 * nu)); mu = E / (2 * (1 + nu)); lam = kappa - 2 * mu / 3
    A, B = 3 * kappa - 5 * mu, 15 * mu
    n = int(math.floor(m)); mm = szz = q4 = q22 = 0.0
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            for k in range(-n, n + 1):
                r2 = i * i + j * j + k * k
                if r2 == 0 or r2 > m * m:
                    continue
                r = math.sqrt(r2); w = 1 / r
                mm += w * r2; szz += w * k * k; q4 += w * k ** 4 / r2; q22 += w * i * i * k * k / r2
    s = 3 * szz / mm
    C11 = A / 3 * s * s + B / mm * q4
    C12 = A / 3 * s * s + B / mm * q22
    E100 = (C11 - C12) * (C11 + 2 * C12) / (C11 + C12)
    return E100 / E, C11 / (lam + 2 * mu)


def main(argv):
    if len(argv) != 1:
        sys.exit(__doc__)
    rows = list(csv.DictReader(open(argv[0])))
    runs = {}
    for r in rows:
        key = (r["shape"], float(r["W"]), float(r["L"]), float(r["h"]), float(r["nu"]), float(r.get("T", 3)),
               float(r.get("hole", 0) or 0))
        runs.setdefault(key, {})[(r["mode"], r["model"])] = r
    print("| bar | L | T | h | m | nu | F_PD | F_FE | **PD/FE** | A_n/A_c | E_100/E | s_free | "
          "eps_mid PD/FE | s_all | Delta end (mm) | k_free | k_all |")
    print("|" + "---|" * 17)
    for key in sorted(runs, key=lambda k: (k[0], k[4], k[1], -k[3])):
        shape, W, L, h, nu, T, hole = key
        g = runs[key]
        if ("free", "lps_fft") not in g or ("free", "fe") not in g:
            continue
        p, f = g[("free", "lps_fft")], g[("free", "fe")]
        m = DELTA / h
        E100, C11 = lattice(nu, m)
        A_c, A_n = float(p["A_c"]), float(p["A_n"])
        if shape == "square":
            per = 4 * (W + h)
        else:
            per = 2 * math.sqrt(math.pi * A_n)
        geo = A_n / (per * DELTA)
        s_free = float(p["M_n"]) / E100 - 1
        end = float(p["eps_mid"]) / float(f["eps_mid"])
        cells = ["%s %g%s" % (shape, W, " + hole R %g" % hole if hole else ""), "%g" % L, "%g" % T, "%g" % h, "%.3f" % m, "%g" % nu,
                 "%.0f" % float(p["F"]), "%.0f" % float(f["F"]),
                 "**%+.1f %%**" % (100 * (float(p["F"]) / float(f["F"]) - 1)),
                 "%.4f" % (A_n / A_c), "%.4f" % E100, "%+.1f %%" % (100 * s_free), "%.4f" % end]
        if hole:  # the middle third crosses the hole: only the forces mean something
            cells[-3:] = ["–", "–", "–"]
            cells += ["–", "–", "–", "–"]
        elif ("all", "lps_fft") in g:
            a = g[("all", "lps_fft")]
            s_all = float(a["M_n"]) / C11 - 1
            delta_end = L * (1 / float(a["eps_mid"]) - 1) / 2
            cells += ["%+.1f %%" % (100 * s_all), "%.2f" % delta_end, "%.3f" % (s_free * geo),
                      "%.3f" % (s_all * geo)]
        else:
            cells += ["–", "–", "%.3f" % (s_free * geo), "–"]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
