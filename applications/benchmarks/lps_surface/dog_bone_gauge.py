#!/usr/bin/env python3
"""dog_bone_gauge.py -- split the dog-bone's PD / FE force ratio into the gauge section's modulus
and the gauge's strain (doc/benchmarks/lps_surface.md).

Usage: python3 dog_bone_gauge.py PD_OUTPUT FE_OUTPUT [--z1 52] [--z2 65]

Reads summary.json (the reaction of top_layer or top, z) and nodes.csv of both runs of
applications/examples/lps_dog_bone, and over the lattice planes nearest z1 and z2 (mm, inside the
gauge 45 <= z <= 72) takes the mean u_z of each plane's nodes: the gauge strain
eps_g = (mean u_z(z2) - mean u_z(z1)) / (z2 - z1). Prints F, eps_g, the section modulus
F / (A eps_g) with A = the nodes' count x h^2 (PD) or the cubes' area (FE, from the plane's node
count is not exact, so the FE one uses F / eps_g only as a ratio), and the ratios PD / FE of F,
of eps_g, and of F / eps_g (the gauge section's stiffness).
"""
import csv
import json
import sys


def load(folder, z1, z2):
    with open(folder + "/summary.json") as f:
        s = json.load(f)
    r = s["final"]["reaction"]
    F = (r["top_layer"] if "top_layer" in r else r["top"])["z"]
    zs = {}
    with open(folder + "/nodes.csv") as f:
        for row in csv.DictReader(f):
            z = float(row["z"]) * 1e3
            zs.setdefault(round(z, 6), []).append(float(row["uz"]))
    planes = sorted(zs)

    def mean_at(z):
        k = min(planes, key=lambda p: abs(p - z))
        return k, sum(zs[k]) / len(zs[k]), len(zs[k])

    k1, u1, n1 = mean_at(z1)
    k2, u2, n2 = mean_at(z2)
    return F, (u2 - u1) / ((k2 - k1) * 1e-3), (k1, k2, n1, n2)


def main(argv):
    z1, z2 = 52.0, 65.0
    if "--z1" in argv:
        i = argv.index("--z1"); z1 = float(argv[i + 1]); argv = argv[:i] + argv[i + 2:]
    if "--z2" in argv:
        i = argv.index("--z2"); z2 = float(argv[i + 1]); argv = argv[:i] + argv[i + 2:]
    if len(argv) != 2:
        sys.exit(__doc__)
    Fp, ep, wp = load(argv[0], z1, z2)
    Ff, ef, wf = load(argv[1], z1, z2)
    print("planes z = %.3f and %.3f mm (PD %d / %d nodes each)" % (wp[0], wp[1], wp[2], wp[3]))
    print("PD: F = %.1f N, gauge strain = %.6e" % (Fp, ep))
    print("FE: F = %.1f N, gauge strain = %.6e" % (Ff, ef))
    print("PD / FE: F %.4f = gauge stiffness F/eps_g %.4f x gauge strain %.4f"
          % (Fp / Ff, (Fp / ep) / (Ff / ef), ep / ef))


if __name__ == "__main__":
    main(sys.argv[1:])
