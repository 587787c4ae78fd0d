"""The solver's test scenes (tests/data/solve/): white furnaces and reflective cubes whose
radiosity has a closed form, near reflectance 1 and at extreme light levels, and a shadow for
adaptive refinement."""

import math
import os

from bench_scenes import reflective_cube
from bundled_scenes import closed_cube
from geometry import facing, quads_to_mesh
from gltf_encoder import GltfBuilder, write_gltf


def occluder_scene():
    """A square occluder over a floor under a square area light: the shadow test of adaptive
    refinement. Floor 2 x 2 m at y = 0 (x, z in [-1, 1]) facing up; light 0.4 x 0.4 m at
    y = 2 facing down (Le = 10); occluder 0.6 x 0.6 m at y = 0.8, double-sided grey. Its shadow
    on the floor is a square of about 0.8 m, centred; the floor's corners are lit smoothly.
    A camera looks at the floor from below the occluder's height."""
    b = GltfBuilder()
    grey = b.grey()
    light = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), strength=10.0)
    two_sided = b.material("two_sided", (0.5, 0.5, 0.5), double_sided=True)

    def centred(size, y, sign):
        h = size / 2.0
        quad = [(-h, y, -h), (h, y, -h), (h, y, h), (-h, y, h)]
        return facing(quad, (0.0, float(sign), 0.0))

    nodes = []
    for name, quad, mat in (("floor", centred(2.0, 0.0, +1), grey), ("light", centred(0.4, 2.0, -1), light),
                            ("occluder", centred(0.6, 0.8, +1), two_sided)):
        positions, indices = quads_to_mesh([quad])
        nodes.append(b.surface(name, positions, indices, mat))
    b.doc.setdefault("cameras", []).append(
        {"name": "low", "type": "perspective",
         "perspective": {"yfov": 1.0, "aspectRatio": 1.0, "znear": 0.01}})
    # From (0, 0.6, 2.4), under the occluder's height, pitched down to look at the floor's
    # centre: the whole shadow is in view.
    pitch = -math.atan2(0.6, 2.4)
    nodes.append(b.add_node("camera", camera=0, translation=(0.0, 0.6, 2.4),
                            rotation=(math.sin(pitch / 2.0), 0.0, 0.0, math.cos(pitch / 2.0))))
    # Straight down from just under the occluder with a wide field: the whole shadow and its
    # penumbra in plan view, for looking at the refined mesh (--debug-mesh).
    b.doc["cameras"].append(
        {"name": "plan", "type": "perspective",
         "perspective": {"yfov": 2.0, "aspectRatio": 1.0, "znear": 0.01}})
    down = -math.pi / 4.0
    nodes.append(b.add_node("plan_camera", camera=1, translation=(0.0, 0.75, 0.0),
                            rotation=(math.sin(down), 0.0, 0.0, math.cos(down))))
    b.add_scene("occluder", nodes)
    return b


def write_solve_scenes(root):
    """tests/data/solve/ under `root`: scenes the solver's tests run."""
    directory = os.path.join(root, "tests", "data", "solve")
    write_gltf(directory, "white-furnace.gltf", closed_cube(furnace=True))
    # The same cubes with every face cut into 16 x 16 quads: small patches that shoot in clusters.
    write_gltf(directory, "white-furnace-cut.gltf", closed_cube(furnace=True, cut=16))
    write_gltf(directory, "closed-cube-cut.gltf", closed_cube(cut=16))
    # Near rho = 1: overshooting and the power per ray (solver/amplification.h).
    write_gltf(directory, "white-furnace-0.99.gltf", closed_cube(furnace=True, rho=0.99))
    write_gltf(directory, "reflective-cube-0.95.gltf", reflective_cube(0.95))
    write_gltf(directory, "two-reflectance-cube.gltf", reflective_cube(0.98, floor_rho=0.5))
    write_gltf(directory, "occluder.gltf", occluder_scene())
    # The same furnace at 1e-30 and 1e30 times the light: only the units may change.
    write_gltf(directory, "faint-furnace.gltf", closed_cube(furnace=True, strength=1e-30))
    write_gltf(directory, "bright-furnace.gltf", closed_cube(furnace=True, strength=1e30))
