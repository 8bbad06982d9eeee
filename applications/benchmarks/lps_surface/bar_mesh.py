#!/usr/bin/env python3
"""bar_mesh.py -- a straight bar as a uniform grid of equal cubes (gmsh .msh 2.2), for the LPS
surface-effect study (doc/benchmarks/lps_surface.md; issue 18).

Usage: python3 bar_mesh.py [--h H] [--width W] [--length L] [--layer T] [--round [--cube-centred]]
                          [--hole R] OUTPUT.msh

Lengths in mm, written in m. z is the axis. The specimen (the gauge) is 0 <= z <= L; Dirichlet
layers of thickness T (default 3, one horizon of the dog-bone) are added below z = 0 and above
z = L with the bar's cross-section, as applications/examples/lps_dog_bone/dog_bone_mesh.py --layers
does. The cross-section is a square W x W (default), or with --round a disc of diameter W
(a cube is kept when its centre is inside, as in dog_bone_mesh.py). The cubes have side H; W/H,
L/H and T/H must be whole (W/H even). The nodes are the cubes' vertices. By default a node is on
the axis; --cube-centred puts a cube's centre there instead (the lattice of dog_bone_mesh.py, whose
cube centres are at whole multiples of H: the same staircase as the dog-bone's gauge for W = 30),
and pin_a is then the node (-H/2, -H/2) next to the axis. --hole R removes the cubes whose centres
are within R of the line x = 0, z = L/2 (a lateral through-hole along y, as the dog-bone's grips
have); the pins are then at z = L/4.

Physical groups (the names of dog_bone_mesh.py, plus the lateral sets):
  volumes  "specimen" (11), "layers" (12); surfaces "bottom" (1), "top" (2) (the body's lowest and
  highest faces); node sets "bottom_layer" (5) (every node with z <= 0), "top_layer" (6)
  (z >= L), "pin_a" (3) (the node on the axis at z = L/2), "pin_b" (4) (the node W/4 from it along
  x, rounded to the lattice), and "all" (7) (every node: u_x = u_y = 0 everywhere holds the bar in
  uniaxial strain). Square bars also have the surfaces "xfaces" (8) (x = -W/2 and x = W/2) and
  "yfaces" (9) (y = +-W/2), over the whole body, layers included.
"""
import math
import os
import sys

# The .msh 2.2 writer of the dog-bone example's mesher.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                                "lps_dog_bone"))
from dog_bone_mesh import add_cube, end_faces, write_msh22  # noqa: E402


def main(argv):
    h, width, length, layer, round_bar, centred, hole = 1.0, 12.0, 36.0, 3.0, False, False, 0.0
    args = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("--h", "--width", "--length", "--layer", "--hole"):
            v = float(argv[i + 1])
            if a == "--hole":
                hole = v
            elif a == "--h":
                h = v
            elif a == "--width":
                width = v
            elif a == "--length":
                length = v
            else:
                layer = v
            i += 2
        elif a == "--round":
            round_bar = True
            i += 1
        elif a == "--cube-centred":
            centred = True
            i += 1
        elif a.startswith("-"):
            args = []
            break
        else:
            args.append(a)
            i += 1

    def whole(mm):
        q = mm / h
        if abs(q - round(q)) > 1e-9:
            sys.exit("bar_mesh.py: %g mm is not a whole number of cubes of %g mm" % (mm, h))
        return int(round(q))

    if len(args) != 1:
        sys.exit(__doc__)
    n = whole(width)
    if n % 2:
        sys.exit("bar_mesh.py: W/H must be even (a node on the axis)")
    nl, nt = whole(length), whole(layer)
    if nl % 2:
        sys.exit("bar_mesh.py: L/H must be even (a node at mid-length)")
    k_lo, k_hi = -nt, nl + nt
    shift = 0.0
    if centred:
        n += 1  # an odd number of cubes: the middle one is centred on the axis
        shift = 0.5

    def x_of(i):
        return (i - n // 2 - shift) * h

    def kept(i, j):  # the cube (i, j) of the cross-section
        if not round_bar:
            return True
        return math.hypot(x_of(i) + 0.5 * h, x_of(j) + 0.5 * h) <= 0.5 * width

    node_id = {}
    cells = []
    for k in range(k_lo, k_hi):
        tag = 11 if 0 <= k < nl else 12
        for j in range(n):
            for i in range(n):
                if not kept(i, j):
                    continue
                if hole > 0 and (x_of(i) + 0.5 * h) ** 2 + ((k + 0.5) * h - 0.5 * length) ** 2 <= hole * hole:
                    continue
                add_cube(cells, node_id, tag, i, j, k)
    faces = []
    for _, c in cells:
        faces += end_faces(c, k_lo, k_hi)
        if not round_bar:
            i0, j0 = c[0][0], c[0][1]
            if i0 == 0:
                faces.append((8, [c[0], c[4], c[7], c[3]]))
            if i0 == n - 1:
                faces.append((8, [c[1], c[2], c[6], c[5]]))
            if j0 == 0:
                faces.append((9, [c[0], c[1], c[5], c[4]]))
            if j0 == n - 1:
                faces.append((9, [c[3], c[7], c[6], c[2]]))
    k_pin = nl // 4 if hole > 0 else nl // 2
    pin_a = (n // 2, n // 2, k_pin)  # (0, 0) or, --cube-centred, (-h/2, -h/2)
    pin_b = (n // 2 + max(1, int(round(0.25 * width / h))), n // 2, k_pin)
    points = [(3, pin_a), (4, pin_b)]
    for p in (pin_a, pin_b):
        if p not in node_id:
            sys.exit("bar_mesh.py: a pin is not a node")
    for p in node_id:
        if p[2] <= 0:
            points.append((5, p))
        elif p[2] >= nl:
            points.append((6, p))
    for p in node_id:
        points.append((7, p))

    names = [(3, 11, "specimen"), (3, 12, "layers"), (2, 1, "bottom"), (2, 2, "top"),
             (0, 3, "pin_a"), (0, 4, "pin_b"), (0, 5, "bottom_layer"), (0, 6, "top_layer"),
             (0, 7, "all")]
    if not round_bar:
        names += [(2, 8, "xfaces"), (2, 9, "yfaces")]
    write_msh22(args[0], names, node_id, lambda p: (x_of(p[0]), x_of(p[1]), p[2] * h), points,
                faces, cells)
    n_section = sum(1 for p in node_id if p[2] == 0)
    cubes_section = sum(1 for j in range(n) for i in range(n) if kept(i, j))
    print("%s: %d cubes of %g mm, %d nodes; cross-section: %d cubes (%.6g mm^2), %d nodes "
          "(%.6g mm^2 at h^2 each)" % (args[0], len(cells), h, len(node_id), cubes_section,
                                       cubes_section * h * h, n_section, n_section * h * h))


if __name__ == "__main__":
    main(sys.argv[1:])
