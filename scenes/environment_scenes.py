"""Environment maps (OpenEXR) and the scenes they light (tests/data/environment/)."""

import os

from geometry import rect
from gltf_encoder import GltfBuilder, write, write_gltf
from image_encoders import exr_bytes, rgb_exr
from scene_parts import add_quads, grey_plane


def sun_and_sky(x, y):
    """The 64 x 32 test map: a sky of 0.1 W/m^2/sr over the upper half (the lower half, the
    ground, is black) and a sun of 2000 W/m^2/sr in the 2 x 2 texels 47..48, 8..9: centred on
    u = 0.75, t = 0.28125, that is glTF +Z turned up by 39.375 degrees toward +Y."""
    if 47 <= x <= 48 and 8 <= y <= 9:
        return (2000.0, 2000.0, 2000.0)
    return (0.1, 0.1, 0.1) if y < 16 else (0.0, 0.0, 0.0)


def facing_quads():
    """Two grey unit quads in the plane z = 0, 3 m apart, one facing +Z and one facing -Z:
    single-sided, coplanar, so each sees only what lies outside."""
    b = GltfBuilder()
    toward = add_quads(b, "toward_plus_z", [rect(2, 0.0, (-2.0, -1.0), (0.0, 1.0), (0.0, 0.0, 1.0))], b.grey())
    away = add_quads(b, "toward_minus_z", [rect(2, 0.0, (1.0, 2.0), (0.0, 1.0), (0.0, 0.0, -1.0))], b.grey())
    b.add_scene("facing_quads", [toward, away])
    return b


def write_environment_scenes(root):
    """tests/data/environment/ under `root`: the maps and scenes; the maps the program must
    refuse are bad_fixtures.py's."""
    directory = os.path.join(root, "tests", "data", "environment")
    write(directory, "uniform.exr", rgb_exr(8, 4, lambda x, y: (1.0, 1.0, 1.0)))
    write(directory, "sun.exr", rgb_exr(64, 32, sun_and_sky))
    write(directory, "grey-y.exr", exr_bytes(4, 2, {"Y": [0.5] * 8}))
    b = GltfBuilder()
    b.add_scene("plane", [grey_plane(b, 1.0)])
    write_gltf(directory, "plane.gltf", b)
    write_gltf(directory, "facing-quads.gltf", facing_quads())
