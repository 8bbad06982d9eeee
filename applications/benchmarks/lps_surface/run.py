#!/usr/bin/env python3
"""run.py -- the runs of the LPS surface-effect study (doc/benchmarks/lps_surface.md, issue 18).

Usage: python3 run.py [--pdfem PATH] [--work DIR] [--csv FILE] CASE [CASE ...]

A CASE is comma-separated key=value pairs, e.g.
  shape=square,W=12,L=36,h=1,nu=0.4,mode=free,model=lps_fft
  shape: square | round (W the side or the diameter, mm); centred=1: a round bar on the lattice of
  the dog-bone (bar_mesh.py --cube-centred);  L: gauge length (mm);  h: cube side (mm);
  hole: the radius of a lateral through-hole at mid-length (mm, bar_mesh.py --hole; default none);
  T: the Dirichlet layers' thickness (mm, default 3: every layer node is held, z <= 0 and z >= L);
  nu: Poisson's ratio;  mode: free (lateral displacements free, the dog-bone's pins) | faces (the
  lateral faces held in their normal direction: xfaces: x = 0, yfaces: y = 0; a delta-thick layer
  in PD) | all (u_x = u_y = 0 at every node: uniaxial strain);  model: lps_fft | lps | fe.
The horizon is delta = 3.015 mm (m = delta / h), E = 60 GPa, the end displacement 1e-3 L (nominal
strain eps = 1e-3). Each run's mesh and output go to DIR (default /tmp/lps_surface); a run whose
summary.json exists is not repeated. Prints and (--csv) writes one row per case:

  F          the axial reaction (top_layer, z) [N]
  A_c, A_n   the cubes' cross-section and the nodes' (node count x h^2) [mm^2]
  F_ref      the analytic force: E A_c eps (free) or (lambda + 2 mu) A_c eps (faces, all)
  eps_mid    the mean strain of the middle third: (mean u_z at z = 2L/3 - at z = L/3) / (L/3)
  M_c, M_n   F / (A eps_mid) / (E or lambda + 2 mu): the section's modulus over the continuum's,
             with A_c or A_n
  nu_mid     -(slope of u_x over x on the mid-plane) / eps_mid (free mode)
  iterations the CG iterations (history.csv), seconds pdfem's total time (summary.json)
"""
import csv
import json
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DELTA = 3.015
E = 60e9


def parse(case):
    c = dict(kv.split("=") for kv in case.split(","))
    c.setdefault("shape", "square")
    c.setdefault("nu", "0.4")
    c.setdefault("mode", "free")
    c.setdefault("model", "lps_fft")
    c.setdefault("centred", "0")
    c.setdefault("T", "3")
    c.setdefault("hole", "0")
    c.setdefault("L", str(3 * float(c["W"])))
    return c


def name_of(c):
    return "%s%s_W%s_L%s_h%s%s" % (c["shape"], "c" if c["centred"] == "1" else "", c["W"], c["L"], c["h"],
                                   ("" if float(c["T"]) == 3 else "_T" + c["T"]) +
                                   ("" if float(c["hole"]) == 0 else "_hole" + c["hole"]))


def linear_iterations(out):
    """The linear (CG) iterations of the last step, from history.csv."""
    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows[-1].get("linear_iterations", "") if rows else ""


def run(c, pdfem, work):
    mesh = os.path.join(work, name_of(c) + ".msh")
    if not os.path.exists(mesh):
        cmd = [sys.executable, os.path.join(HERE, "bar_mesh.py"), "--h", c["h"], "--width", c["W"],
               "--length", c["L"], "--layer", c["T"], "--hole", c["hole"], mesh]
        if c["shape"] == "round":
            cmd.insert(2, "--round")
            if c["centred"] == "1":
                cmd.insert(3, "--cube-centred")
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    out = os.path.join(work, "%s_nu%s_%s_%s" % (name_of(c), c["nu"], c["mode"], c["model"]))
    U = 1e-3 * float(c["L"]) * 1e-3
    lateral = {"free": "pin_a: x = 0; pin_a: y = 0; pin_b: y = 0",
               "faces": "xfaces: x = 0; yfaces: y = 0",
               "all": "all: x = 0; all: y = 0"}[c["mode"]]
    dirichlet = "bottom_layer: z = 0; top_layer: z = %.12g; %s" % (U, lateral)
    prm = "bar_fe.prm" if c["model"] == "fe" else "bar_pd.prm"
    sets = ["Mesh/Input file=" + mesh, "Material/Poisson's ratio=" + c["nu"],
            "Boundary conditions/Dirichlet=" + dirichlet]
    m = DELTA / float(c["h"])
    if c["model"] != "fe":
        sets.append("Peridynamics/Horizon factor=%.10g" % m)
    if c["model"] == "lps":
        sets.append("Peridynamics/Model=lps")
    seconds = None
    if not os.path.exists(os.path.join(out, "summary.json")):
        cmd = ["nice", "-n", "10", pdfem, os.path.join(HERE, prm), "--output", out]
        for s in sets:
            cmd += ["--set", s]
        t0 = time.time()
        with open(out + ".log", "w") as log:
            subprocess.run(cmd, check=True, stdout=log, stderr=subprocess.STDOUT)
        seconds = time.time() - t0
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    F = summary["final"]["reaction"]["top_layer"]["z"]
    nodes = []
    with open(os.path.join(out, "nodes.csv")) as f:
        for r in csv.DictReader(f):
            nodes.append((float(r["x"]) * 1e3, float(r["y"]) * 1e3, float(r["z"]) * 1e3,
                          float(r["ux"]), float(r["uz"])))
    h, L, W = float(c["h"]), float(c["L"]), float(c["W"])
    n_a = sum(1 for p in nodes if abs(p[2]) < 1e-6)
    # cubes of the cross-section (from the mesh's cell count: the gauge has L/h layers of cubes)
    # the cubes of the full cross-section (bar_mesh.py's rule; a hole takes cubes from some layers only)
    n = round(W / h) + (1 if c["centred"] == "1" else 0)
    x0 = (-(n // 2) - (0.5 if c["centred"] == "1" else 0.0) + 0.5) * h  # the first cube's centre
    A_c = h * h * sum(1 for j in range(n) for i in range(n)
                      if c["shape"] == "square" or math.hypot(x0 + i * h, x0 + j * h) <= 0.5 * W)
    A_n = n_a * h * h
    nu = float(c["nu"])
    M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    ref = E if c["mode"] == "free" else M
    eps = 1e-3
    F_ref = ref * A_c * 1e-6 * eps

    def plane(z):
        k = round(z / h) * h
        return k, [p for p in nodes if abs(p[2] - k) < 1e-6]

    z1, p1 = plane(L / 3)
    z2, p2 = plane(2 * L / 3)
    eps_mid = (sum(p[4] for p in p2) / len(p2) - sum(p[4] for p in p1) / len(p1)) / ((z2 - z1) * 1e-3)
    zm, pm = plane(L / 2)
    sx = sum(p[0] for p in pm) / len(pm)
    sxx = sum((p[0] - sx) ** 2 for p in pm)
    slope = sum((p[0] - sx) * p[3] for p in pm) / sxx / 1e-3 if sxx > 0 else 0.0
    row = dict(shape=c["shape"], W=W, L=L, T=float(c["T"]), hole=float(c["hole"]), h=h, m=round(m, 3), nu=nu, mode=c["mode"], model=c["model"],
               nodes=summary["problem"]["nodes"], F=F, A_c=A_c, A_n=A_n, F_ref=F_ref,
               F_over_ref=F / F_ref, eps_mid=eps_mid / eps,
               M_c=F / (A_c * 1e-6 * eps_mid) / ref, M_n=F / (A_n * 1e-6 * eps_mid) / ref,
               nu_mid=-slope / eps_mid, iterations=linear_iterations(out),
               seconds=summary["timings"]["total"])
    return row


def main(argv):
    pdfem, work, out_csv = "/work/main/build/bin/pdfem", "/tmp/lps_surface", None
    cases = []
    i = 0
    while i < len(argv):
        if argv[i] == "--pdfem":
            pdfem = argv[i + 1]; i += 2
        elif argv[i] == "--work":
            work = argv[i + 1]; i += 2
        elif argv[i] == "--csv":
            out_csv = argv[i + 1]; i += 2
        else:
            cases.append(argv[i]); i += 1
    if not cases:
        sys.exit(__doc__)
    os.makedirs(work, exist_ok=True)
    rows = []
    for case in cases:
        row = run(parse(case), pdfem, work)
        rows.append(row)
        print("%-6s W=%-4g L=%-4g h=%-5g m=%-6g nu=%-4g %-5s %-7s F=%10.1f N  F/F_ref=%.4f  A_n/A_c=%.4f  "
              "eps_mid=%.4f  M_c=%.4f  M_n=%.4f  nu_mid=%.4f  %.1f s"
              % (row["shape"], row["W"], row["L"], row["h"], row["m"], row["nu"], row["mode"], row["model"],
                 row["F"], row["F_over_ref"], row["A_n"] / row["A_c"], row["eps_mid"], row["M_c"],
                 row["M_n"], row["nu_mid"], row["seconds"]), flush=True)
    if out_csv:
        new = not os.path.exists(out_csv)
        with open(out_csv, "a") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            if new:
                w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main(sys.argv[1:])
