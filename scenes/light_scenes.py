"""Scenes lit by KHR_lights_punctual lights, for closed-form tests (tests/data/lights/): point,
spot and directional lights over planes, a sky over an open box, and many point lights."""

import math
import os

from geometry import cut_quad, inward_box, rect, rotation_to
from gltf_encoder import LUMENS_PER_WATT, GltfBuilder, write_gltf
from scene_parts import add_quads, grey_plane


def point_over_plane():
    """A point light of 683 cd (1 W/sr) 1 m above the middle of a 2 x 2 m grey plane:
    E = I h / r^3 at (x, 0, z), r^2 = x^2 + z^2 + 1."""
    b = GltfBuilder()
    light = b.add_light({"name": "bulb", "type": "point", "intensity": LUMENS_PER_WATT})
    b.add_scene("point_over_plane", [grey_plane(b, 1.0), b.light_node("bulb", light, translation=(0.0, 1.0, 0.0))])
    return b


def spot_over_plane():
    """A spot light of 683 cd (1 W/sr), inner cone 0.3 rad, outer 0.6 rad, 1 m above the middle
    of a 4 x 4 m grey plane, pointing straight down; the specification's default colour."""
    b = GltfBuilder()
    light = b.add_light({"name": "spot", "type": "spot", "intensity": LUMENS_PER_WATT,
                         "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}})
    b.add_scene("spot_over_plane", [grey_plane(b, 2.0),
                                    b.light_node("spot", light, translation=(0.0, 1.0, 0.0),
                                                 rotation=rotation_to((0.0, -1.0, 0.0)))])
    return b


def directional_occluder():
    """A directional light of 683 lux (1 W/m^2 across its beam) travelling along
    (sin 30deg, -cos 30deg, 0) onto a 4 x 4 m grey floor at y = 0, with a 1 x 1 m square occluder
    at y = 1 (x, z in [-0.5, 0.5], facing down). Lit floor: E = cos 30deg; the shadow is the
    occluder moved by tan 30deg along +x: x in [-0.5 + tan 30deg, 0.5 + tan 30deg]."""
    b = GltfBuilder()
    direction = (math.sin(math.radians(30.0)), -math.cos(math.radians(30.0)), 0.0)
    light = b.add_light({"name": "sun", "type": "directional", "intensity": LUMENS_PER_WATT})
    occluder = add_quads(b, "occluder", [rect(1, 1.0, (-0.5, 0.5), (-0.5, 0.5), (0.0, -1.0, 0.0))], b.grey())
    b.add_scene("directional_occluder", [grey_plane(b, 2.0, "floor"), occluder,
                                         b.light_node("sun", light, rotation=rotation_to(direction))])
    return b


def open_box(cut=1):
    """The unit box [0, 1]^3 without its ceiling, facing in, grey: under a uniform sky of
    radiance L the floor's mean irradiance is pi L F(floor -> opening), parallel unit squares
    1 m apart (F = 0.1998). cut > 1: each face cut into cut x cut quads."""
    b = GltfBuilder()
    nodes = [add_quads(b, name, cut_quad(quad, cut), b.grey()) for name, quad in inward_box((0, 0, 0), (1, 1, 1))
             if name != "ceiling"]
    b.add_scene("open_box", nodes)
    return b


def point_in_cube():
    """A point light of 683 cd (1 W/sr, 4 pi W) at the centre of the closed unit cube, facing
    in, grey: each face receives a sixth of the power, a mean irradiance of 2 pi / 3 W/m^2."""
    b = GltfBuilder()
    light = b.add_light({"name": "bulb", "type": "point", "intensity": LUMENS_PER_WATT})
    nodes = [add_quads(b, name, [quad], b.grey()) for name, quad in inward_box((0, 0, 0), (1, 1, 1))]
    b.add_scene("point_in_cube", nodes + [b.light_node("bulb", light, translation=(0.5, 0.5, 0.5))])
    return b


def many_lights(count, side=4.0, height=1.0):
    """A grey plane side x side m at y = 0 under `count` point lights on a square grid at
    y = height spanning the plane, together 683 cd (1 W/sr): the light cut's test and bench."""
    b = GltfBuilder()
    n = int(round(math.sqrt(count)))
    assert n * n == count
    nodes = [grey_plane(b, 0.5 * side)]
    for i in range(n):
        for j in range(n):
            light = b.add_light({"type": "point", "intensity": round(LUMENS_PER_WATT / count, 9)})
            x = -0.5 * side + (i + 0.5) * side / n
            z = -0.5 * side + (j + 0.5) * side / n
            nodes.append(b.light_node("bulb%d_%d" % (i, j), light, translation=(x, height, z)))
    b.add_scene("many_lights", nodes)
    return b


def write_light_scenes(root):
    """tests/data/lights/ under `root`: scenes lit by punctual lights."""
    directory = os.path.join(root, "tests", "data", "lights")
    write_gltf(directory, "point-over-plane.gltf", point_over_plane())
    write_gltf(directory, "spot-over-plane.gltf", spot_over_plane())
    write_gltf(directory, "directional-occluder.gltf", directional_occluder())
    write_gltf(directory, "open-box.gltf", open_box())
    write_gltf(directory, "open-box-cut.gltf", open_box(cut=16))
    write_gltf(directory, "point-in-cube.gltf", point_in_cube())
    write_gltf(directory, "many-lights.gltf", many_lights(64))
