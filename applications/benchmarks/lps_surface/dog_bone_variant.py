#!/usr/bin/env python3
"""dog_bone_variant.py -- the dog-bone of applications/examples/lps_dog_bone without its through-holes
(doc/benchmarks/lps_surface.md): runs that example's dog_bone_mesh.py with its shape test replaced.

Usage: python3 dog_bone_variant.py --no-holes [dog_bone_mesh.py options] OUTPUT.msh
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "examples", "lps_dog_bone"))
import dog_bone_mesh  # noqa: E402


def inside_no_holes(x, y, z):
    """dog_bone_mesh.inside without the lateral through-holes."""
    if z < 0.0 or z > 117.0:
        return False
    r = math.hypot(x, y)
    zz = z if z <= 58.5 else 117.0 - z
    if zz <= 30.0:
        return r <= 30.0
    if zz <= 45.0:
        return r <= 30.0 - math.sqrt(max(0.0, 225.0 - (zz - 45.0) ** 2))
    return r <= 15.0


if __name__ == "__main__":
    argv = sys.argv[1:]
    if "--no-holes" not in argv:
        sys.exit(__doc__)
    argv.remove("--no-holes")
    dog_bone_mesh.inside = inside_no_holes
    dog_bone_mesh.main(argv)
