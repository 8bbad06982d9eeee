#!/usr/bin/env python3
"""dog_bone_mesh.py -- the round dog-bone of lps_dog_bone as a uniform grid of equal cubes (gmsh .msh 2.2).

Usage: python3 dog_bone_mesh.py [--cells-per-mm F] [--layers] OUTPUT.msh

The specimen (lengths in mm, written in m; z is the axis, 0 <= z <= 117):
  * grips: cylinders of radius 30 over 0 <= z <= 30 and 87 <= z <= 117, each with a lateral
    through-hole of radius 5 along y, centred on the axis at z = 15 and z = 102;
  * gauge: a cylinder of radius 15 over 45 <= z <= 72;
  * fillets: quarter circles of radius 15 from each grip's inner edge (r = 30) to the gauge
    (r(z) = 30 - sqrt(15^2 - (z - 45)^2) over 30 <= z <= 45, mirrored over 72 <= z <= 87).
The FCBM paper's dog-bone (specs/002 §4.1) gives its dimensions only in a figure that our text does
not have; this shape keeps what the text says (lateral extent about 6 cm, height about 12-13 cm,
two lateral through-holes, delta = 3 mm small against the holes) and is stated as ours.

The grid: cubes of side h = 1 mm / F (F = --cells-per-mm, default 1; 3 F must be whole, e.g. 4/3 for
h = 0.75 mm), the lattice x = (i - (n - 1)/2) h over 60 F lattice points in x and y, z = k h. A cube is kept when its centre is inside the shape
(the staircase of the curved surfaces is the same for every model run on the mesh). The nodes are
the vertices of the kept cubes.

--layers adds the FCBM's fictitious Dirichlet layers Gamma_3: 3 mm (one horizon) of the grip's
cross-section below z = 0 and above z = 117 (volume "layers"), so that the body runs from -3 to
120 mm (124 F lattice planes at F = 1: with a gap of 4 planes the FFT box is 64 x 64 x 128 = 2^19).

Physical groups: volumes "specimen" (11) and "layers" (12); surfaces "bottom" (1) and "top" (2),
the lowest and highest faces of the body; with --layers the node sets "bottom_layer" (5) and
"top_layer" (6), every node with z <= 0 or z >= 117 mm (the layers and the specimen's end faces:
the nodes that the PD run's Dirichlet layer holds, for an FE run of the same problem); points
"pin_a" (3) and "pin_b" (4), two nodes in the
gauge's mid-plane 10 mm apart along x, which hold the rigid motions that the axial loading leaves
free (u_x = u_y = 0 at pin_a, u_y = 0 at pin_b: a minimal support, so its reactions are zero for a
self-equilibrated load).
"""
import math
import sys


def inside(x, y, z):
    """Is the point (mm) inside the specimen?"""
    if z < 0.0 or z > 117.0:
        return False
    r = math.hypot(x, y)
    zz = z if z <= 58.5 else 117.0 - z  # mirror the upper half onto the lower
    if zz <= 30.0:
        if x * x + (zz - 15.0) ** 2 <= 25.0:  # the through-hole along y
            return False
        return r <= 30.0
    if zz <= 45.0:
        return r <= 30.0 - math.sqrt(max(0.0, 225.0 - (zz - 45.0) ** 2))
    return r <= 15.0


def in_layer(x, y, z):
    return (-3.0 <= z < 0.0 or 117.0 < z <= 120.0) and math.hypot(x, y) <= 30.0


def add_cube(cells, node_id, tag, i, j, k):
    """Append the cube of lattice point (i, j, k) to cells as (tag, its 8 corners in gmsh's hexahedron
    order), numbering the corners not yet in node_id (1, 2, ...)."""
    corners = [(i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k),
               (i, j, k + 1), (i + 1, j, k + 1), (i + 1, j + 1, k + 1), (i, j + 1, k + 1)]
    for c in corners:
        if c not in node_id:
            node_id[c] = len(node_id) + 1
    cells.append((tag, corners))


def end_faces(c, k_lo, k_hi):
    """The faces of cube c (8 corners) on the planes k = k_lo ("bottom", 1) and k = k_hi ("top", 2),
    as (surface tag, 4 lattice points), oriented outwards."""
    faces = []
    if c[0][2] == k_lo:
        faces.append((1, [c[0], c[3], c[2], c[1]]))
    if c[4][2] == k_hi:
        faces.append((2, [c[4], c[5], c[6], c[7]]))
    return faces


def write_msh22(path, names, node_id, position_mm, points, faces, cells):
    """Writes a gmsh .msh 2.2 file: names [(dim, tag, name)], node_id {lattice point: id},
    position_mm(lattice point) in mm (written in m), and the elements as [(tag, item)] with a lattice
    point (points), 4 of them (quadrangle faces) or 8 (hexahedra)."""
    with open(path, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        out.write("$PhysicalNames\n%d\n" % len(names))
        for d, t, name in names:
            out.write('%d %d "%s"\n' % (d, t, name))
        out.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(node_id))
        for p, nid in sorted(node_id.items(), key=lambda item: item[1]):
            x, y, z = position_mm(p)
            out.write("%d %.12g %.12g %.12g\n" % (nid, x * 1e-3, y * 1e-3, z * 1e-3))
        out.write("$EndNodes\n$Elements\n%d\n" % (len(points) + len(faces) + len(cells)))
        e = 0
        for kind, items in ((15, points), (3, faces), (5, cells)):
            for tag, item in items:
                e += 1
                ids = [node_id[item]] if kind == 15 else [node_id[c] for c in item]
                out.write("%d %d 2 %d %d %s\n" % (e, kind, tag, tag, " ".join(map(str, ids))))
        out.write("$EndElements\n")


def main(argv):
    per_mm = 1
    layers = False
    args = []
    i = 0
    while i < len(argv):
        if argv[i] == "--cells-per-mm":
            per_mm = float(argv[i + 1])
            i += 2
        elif argv[i] == "--layers":
            layers = True
            i += 1
        elif argv[i].startswith("-"):
            args = []  # an unknown option (e.g. --help): the usage below
            break
        else:
            args.append(argv[i])
            i += 1
    # 3 mm (the layers) and 60 mm (the lattice) must be whole numbers of cubes.
    if len(args) != 1 or per_mm <= 0 or abs(3 * per_mm - round(3 * per_mm)) > 1e-9:
        sys.exit("usage: python3 dog_bone_mesh.py [--cells-per-mm F (3 F a whole number: 1, 4/3 = "
                 "1.3333333333333333, 2, ...)] [--layers] OUTPUT.msh")
    def whole(mm):
        return int(round(mm * per_mm))
    h = 1.0 / per_mm
    n = whole(60)  # lattice points in x and y
    k_lo = -whole(3) if layers else 0
    k_hi = whole(120 if layers else 117)  # last lattice plane

    def x_of(i):
        return (i - (n - 1) / 2.0) * h

    node_id = {}
    cells = []  # (volume tag, 8 lattice points)
    for k in range(k_lo, k_hi):
        zc = (k + 0.5) * h
        for j in range(n - 1):
            yc = x_of(j + 0.5)
            for i in range(n - 1):
                xc = x_of(i + 0.5)
                if inside(xc, yc, zc):
                    tag = 11
                elif layers and in_layer(xc, yc, zc):
                    tag = 12
                else:
                    continue
                add_cube(cells, node_id, tag, i, j, k)
    faces = []  # (surface tag, 4 lattice points)
    for _, c in cells:
        faces += end_faces(c, k_lo, k_hi)
    k_mid = whole(58.5)
    i_a = (n - 1) // 2
    pins = [(3, (i_a, i_a, k_mid)), (4, (i_a + whole(10), i_a, k_mid))]
    for _, p in pins:
        if p not in node_id:
            sys.exit("dog_bone_mesh.py: a pin is not a node of the mesh")
    if layers:
        for p in node_id:
            if p[2] <= 0:
                pins.append((5, p))
            elif p[2] >= whole(117):
                pins.append((6, p))

    names = [(3, 11, "specimen"), (2, 1, "bottom"), (2, 2, "top"), (0, 3, "pin_a"), (0, 4, "pin_b")]
    if layers:
        names += [(3, 12, "layers"), (0, 5, "bottom_layer"), (0, 6, "top_layer")]
    write_msh22(args[0], names, node_id, lambda p: (x_of(p[0]), x_of(p[1]), p[2] * h), pins, faces,
                cells)
    print("%s: %d cubes of %.4g mm, %d nodes%s" % (args[0], len(cells), h, len(node_id),
                                                  ", with the Dirichlet layers" if layers else ""))


if __name__ == "__main__":
    main(sys.argv[1:])
