#!/usr/bin/env python3
"""compare_fe.py -- the FCBM paper's difference measure (specs/002 eq. 98) between two runs of the dog-bone.

Usage: python3 compare_fe.py PD_OUTPUT FE_OUTPUT [--csv FILE] [--max-mean PERCENT]

Reads nodes.csv of both pdfem output folders and matches their nodes by position (to 1e-9 m):
the PD body's nodes that are nodes of the FE mesh (the specimen; the Dirichlet layers have no FE
counterpart). With h_FE = h_PD / n the FE nodes on the PD lattice are used (every n-th). For each
displacement component i it prints, over the matched nodes,

  E_i = |u_i^PD - u_i^FE| / max |u_i^FE|          (the paper's eq. 98, max over all FE nodes)

as its mean and its maximum, with where the maximum is, and the relative L2 difference of the
displacement vector. --csv writes one row per component; --max-mean exits 1 when a component's mean
E is above PERCENT. Pure Python 3.
"""
import csv
import math
import sys


def read(folder):
    with open(folder + "/nodes.csv") as f:
        rows = list(csv.DictReader(f))
    return rows


def key(row):
    return tuple(int(round(float(row[c]) * 1e9)) for c in ("x", "y", "z"))


def main(argv):
    options = {"--csv": None, "--max-mean": None}
    for name in options:
        if name in argv:
            i = argv.index(name)
            options[name] = argv[i + 1]
            argv = argv[:i] + argv[i + 2:]
    out_csv = options["--csv"]
    if len(argv) != 2:
        sys.exit("usage: python3 compare_fe.py PD_OUTPUT FE_OUTPUT [--csv FILE] [--max-mean PERCENT]")
    pd_rows, fe_rows = read(argv[0]), read(argv[1])
    fe = {key(r): r for r in fe_rows}
    pairs = [(r, fe[key(r)]) for r in pd_rows if key(r) in fe]
    if not pairs:
        sys.exit("compare_fe.py: no common nodes")
    names = ("ux", "uy", "uz")
    result = []
    l2_diff = l2_ref = 0.0
    for c in names:
        u_max = max(abs(float(r[c])) for r in fe_rows)
        diffs = [(abs(float(p[c]) - float(q[c])) / u_max, p) for p, q in pairs]
        mean = sum(d for d, _ in diffs) / len(diffs)
        worst, where = max(diffs, key=lambda item: item[0])
        result.append((c, u_max, mean, worst, where))
        for p, q in pairs:
            l2_diff += (float(p[c]) - float(q[c])) ** 2
            l2_ref += float(q[c]) ** 2
    print("%d common nodes (PD %d, FE %d)" % (len(pairs), len(pd_rows), len(fe_rows)))
    for c, u_max, mean, worst, where in result:
        print("%s: max |u_FE| = %.4e m, mean E = %.3f %%, max E = %.2f %% at (%.1f, %.1f, %.1f) mm"
              % (c, u_max, 100 * mean, 100 * worst, 1e3 * float(where["x"]), 1e3 * float(where["y"]),
                 1e3 * float(where["z"])))
    print("relative L2 difference of u: %.3f %%" % (100 * math.sqrt(l2_diff / l2_ref)))
    failed = False
    if options["--max-mean"] is not None:
        limit = float(options["--max-mean"]) / 100
        for c, _, mean, _, _ in result:
            if mean > limit:
                print("FAIL %s: mean E %.3f %% above %s %%" % (c, 100 * mean, options["--max-mean"]))
                failed = True
    if out_csv:
        with open(out_csv, "w") as f:
            f.write("component,max_abs_u_fe,mean_difference,max_difference,common_nodes\n")
            for c, u_max, mean, worst, _ in result:
                f.write("%s,%.6e,%.6e,%.6e,%d\n" % (c, u_max, mean, worst, len(pairs)))
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main(sys.argv[1:])
