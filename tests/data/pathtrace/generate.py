#!/usr/bin/env python3
"""Generate the path tracer's test scenes (tests/test_path_tracer.cpp) into this directory.

Run from anywhere:  python3 tests/data/pathtrace/generate.py
Reuses scenes/gltf_encoder.py and geometry.py; standard library only; deterministic output.

  coloured-furnace.gltf  the closed unit cube of tests/data/solve/white-furnace.gltf, every
                         face single-sided (facing in), rho = (0.6, 0.3, 0.1), Le = 1/pi in
                         every channel: L = Le / (1 - rho) per channel.
  two-sided-lamp.gltf    `lamp`: unit square x, z in [0, 1], y = 0, normal +Y, doubleSided,
                         rho = 0.5, Le = (1, 0.5, 0.25); `sky`: unit square y = 1 facing -Y
                         (towards the lamp), single-sided, rho = 0, Le = 1. Nothing below.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.dont_write_bytecode = True  # leave no __pycache__ in scenes/
sys.path.insert(0, os.path.join(ROOT, "scenes"))

from geometry import quads_to_mesh, square  # noqa: E402
from gltf_encoder import GltfBuilder, write_gltf  # noqa: E402

GENERATOR = "radiosity tests/data/pathtrace/generate.py"


def builder():
    b = GltfBuilder()
    b.doc["asset"]["generator"] = GENERATOR
    return b


def coloured_furnace():
    b = builder()
    glow = b.material("coloured_glow", (0.6, 0.3, 0.1), emissive=(1.0 / math.pi,) * 3)
    faces = [  # (name, axis, level, inward sign), as scenes/bundled_scenes.py's closed_cube
        ("floor", 1, 0, +1), ("ceiling", 1, 1, -1),
        ("left", 0, 0, +1), ("right", 0, 1, -1),
        ("front", 2, 1, -1), ("back", 2, 0, +1),
    ]
    nodes = []
    for name, axis, level, sign in faces:
        positions, indices = quads_to_mesh([square(axis, level, sign)])
        nodes.append(b.surface(name, positions, indices, glow))
    b.add_scene("coloured_furnace", nodes)
    return b


def two_sided_lamp():
    b = builder()
    lamp = b.material("two_sided_lamp", (0.5, 0.5, 0.5), emissive=(1.0, 0.5, 0.25), double_sided=True)
    sky = b.material("sky", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    nodes = []
    for name, level, sign, mat in (("lamp", 0, +1, lamp), ("sky", 1, -1, sky)):
        positions, indices = quads_to_mesh([square(1, level, sign)])
        nodes.append(b.surface(name, positions, indices, mat))
    b.add_scene("two_sided_lamp", nodes)
    return b


def main():
    for name, scene in (("coloured-furnace.gltf", coloured_furnace()), ("two-sided-lamp.gltf", two_sided_lamp())):
        print(write_gltf(HERE, name, scene))


if __name__ == "__main__":
    main()
