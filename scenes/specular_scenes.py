"""Mirrors, glass and rough metals with closed forms (tests/data/specular/): a mirror facing a
lamp, glass slabs and thin panes before one, mirrors and panes in the radiosity pass, the camera
pass and under punctual lights, rough (GGX) metals, and the white furnace with a mirror and a
glass sphere inside."""

import math
import os

from bundled_scenes import closed_cube
from geometry import box_quads, facing, inward_box, quads_to_mesh, rect, square, uv_sphere
from gltf_encoder import LUMENS_PER_WATT, GltfBuilder, write_gltf
from scene_parts import add_quads, grey_plane, specular_material


def mirror_facing_lamp():
    """A mirror (F0 = 0.9) on z = 0 facing +z and a lamp (Le = 1, black) on z = 1 facing it."""
    b = GltfBuilder()
    lamp_mat = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    mirror = specular_material(b, "mirror", (0.9, 0.9, 0.9), metallic=1.0)
    nodes = []
    for name, level, sign, mat in (("mirror", 0, +1, mirror), ("lamp", 1, -1, lamp_mat)):
        positions, indices = quads_to_mesh([square(2, level, sign)])
        nodes.append(b.surface(name, positions, indices, mat))
    b.add_scene("mirror_facing_lamp", nodes)
    return b


def glass_slab_before_lamp():
    """A lamp (Le = 1, black) on z = 1 facing -z, and a slab of glass (IOR 1.5, a volume) filling
    x, y in [-1, 2], z in [0.3, 0.6] between it and the plane z = 0."""
    b = GltfBuilder()
    lamp_mat = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    glass = specular_material(b, "glass", (1.0, 1.0, 1.0), transmission=1.0, ior=1.5, thickness=0.3)
    positions, indices = quads_to_mesh([square(2, 1, -1)])
    nodes = [b.surface("lamp", positions, indices, lamp_mat)]
    positions, indices = quads_to_mesh(box_quads((-1.0, -1.0, 0.3), (2.0, 2.0, 0.6)))
    nodes.append(b.surface("slab", positions, indices, glass))
    b.add_scene("glass_slab_before_lamp", nodes)
    return b


def glass_tilted_before_lamp():
    """As glass_slab_before_lamp, but the slab (tinted 0.8, 0.3 thick, 3 x 1.1 m) is turned 45
    degrees about x about its centre (0.5, 0.5, 0.45), so light crosses it at 45 degrees, and
    stays clear of the lamp's plane; a camera looks from z = -0.5 at its middle."""
    b = GltfBuilder()
    lamp_mat = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    glass = specular_material(b, "glass", (0.8, 0.8, 0.8), transmission=1.0, ior=1.5, thickness=0.3)
    positions, indices = quads_to_mesh([square(2, 1, -1)])
    nodes = [b.surface("lamp", positions, indices, lamp_mat)]
    positions, indices = quads_to_mesh(box_quads((-1.5, -0.55, -0.15), (1.5, 0.55, 0.15)))
    half = math.radians(22.5)
    nodes.append(b.surface("slab", positions, indices, glass, translation=[0.5, 0.5, 0.45],
                           rotation=[math.sin(half), 0.0, 0.0, math.cos(half)]))
    b.add_scene("glass_tilted_before_lamp", nodes)
    return b


def thin_pane_before_lamp():
    """A lamp (Le = 1, black) on z = 1 facing -z and a thin-walled glass pane (one quad, no
    volume, tint 0.9) on z = 0.5 facing -z, x, y in [-1, 2]."""
    b = GltfBuilder()
    lamp_mat = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    glass = specular_material(b, "pane", (0.9, 0.9, 0.9), transmission=1.0, ior=1.5)
    positions, indices = quads_to_mesh([square(2, 1, -1)])
    nodes = [b.surface("lamp", positions, indices, lamp_mat)]
    quad = [(x, y, 0.5) for x, y in ((-1.0, -1.0), (2.0, -1.0), (2.0, 2.0), (-1.0, 2.0))]
    positions, indices = quads_to_mesh([facing(quad, (0.0, 0.0, -1.0))])
    nodes.append(b.surface("pane", positions, indices, glass))
    b.add_scene("thin_pane_before_lamp", nodes)
    return b


def mirror_over_lamp():
    """For the radiosity pass's shots: a lamp (Le = 1/pi, exitance 1, black) and a black receiver
    side by side on z = 0 facing +z (x in [0, 1] and [1.5, 2.5], y in [0, 1]), under a lossless
    mirror (F0 = 1) on z = 0.5 facing -z that covers both (x in [-0.5, 3], y in [-0.5, 1.5]). The
    receiver sees the lamp only in the mirror: its power is the lamp's times the form factor from
    the lamp to the receiver's image on z = 1."""
    b = GltfBuilder()
    lamp_mat = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0 / math.pi,) * 3)
    black = b.material("black", (0.0, 0.0, 0.0))
    mirror = specular_material(b, "mirror", (1.0, 1.0, 1.0), metallic=1.0)
    nodes = [add_quads(b, "lamp", [rect(2, 0.0, (0.0, 1.0), (0.0, 1.0), (0, 0, 1))], lamp_mat),
             add_quads(b, "receiver", [rect(2, 0.0, (1.5, 2.5), (0.0, 1.0), (0, 0, 1))], black),
             add_quads(b, "mirror", [rect(2, 0.5, (-0.5, 3.0), (-0.5, 1.5), (0, 0, -1))], mirror)]
    b.add_scene("mirror_over_lamp", nodes)
    return b


def pane_between_squares(name="pane_between_squares", receiver=(0.0, 0.0, 0.0)):
    """For the radiosity pass's shots: a lamp (Le = 1/pi, black) on z = 0 facing +z and a
    receiver (black unless given) on z = 0.25 facing it (unit squares, close, so light crosses at
    every angle), with a thin-walled glass pane (IOR 1.5, tint 0.9, no volume) on z = 0.125 between
    them, x, y in [-1, 2]."""
    b = GltfBuilder()
    lamp_mat = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0 / math.pi,) * 3)
    receiving = b.material("black" if receiver == (0.0, 0.0, 0.0) else "grey", receiver)
    pane = specular_material(b, "pane", (0.9, 0.9, 0.9), transmission=1.0, ior=1.5)
    nodes = [add_quads(b, "lamp", [rect(2, 0.0, (0.0, 1.0), (0.0, 1.0), (0, 0, 1))], lamp_mat),
             add_quads(b, "receiver", [rect(2, 0.25, (0.0, 1.0), (0.0, 1.0), (0, 0, -1))], receiving),
             add_quads(b, "pane", [rect(2, 0.125, (-1.0, 2.0), (-1.0, 2.0), (0, 0, -1))], pane)]
    b.add_scene(name, nodes)
    return b


def lamp_through_pane():
    """For the camera pass's caustics: pane_between_squares with a grey receiver (rho 0.5), all
    of whose light came through the pane; a camera at z = 0.2 looks at it."""
    return pane_between_squares("lamp_through_pane", (0.5, 0.5, 0.5))


def window_box():
    """For the sky through glass: the unit box facing in, grey (rho 0.5) but for its ceiling, a
    thin-walled glass pane (IOR 1.5, tint 0.9, no volume): under a sky (given on the command
    line or by the test) all its light comes in through the window."""
    b = GltfBuilder()
    grey = b.material("grey", (0.5, 0.5, 0.5))
    pane = specular_material(b, "window", (0.9, 0.9, 0.9), transmission=1.0, ior=1.5)
    nodes = [add_quads(b, name, [quad], pane if name == "ceiling" else grey)
             for name, quad in inward_box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))]
    b.add_scene("window_box", nodes)
    return b


def point_under_pane():
    """For punctual lights through glass: point_over_plane's light (1 W/sr, 1 m above a 2 x 2 m
    grey plane) with a thin-walled glass pane (IOR 1.5, tint (0.9, 0.8, 0.7), no volume) between
    them at y = 0.5, x, z in [-2, 2], facing up. Each shadow ray crosses it at the angle it meets
    the plane, so E = I h / r^3 x (1 - R(h / r)) x tint, R the Fresnel reflectance."""
    b = GltfBuilder()
    light = b.add_light({"name": "bulb", "type": "point", "intensity": LUMENS_PER_WATT})
    pane = specular_material(b, "pane", (0.9, 0.8, 0.7), transmission=1.0, ior=1.5)
    b.add_scene("point_under_pane",
                [grey_plane(b, 1.0), add_quads(b, "pane", [rect(1, 0.5, (-2.0, 2.0), (-2.0, 2.0), (0.0, 1.0, 0.0))], pane),
                 b.light_node("bulb", light, translation=(0.0, 1.0, 0.0))])
    return b


def point_over_specular_floor(kind):
    """For punctual lights' light off mirrors and glass: a point light (1 W/sr) 1 m above a
    specular floor at y = 0 (x, z in [-2, 2], facing up): a lossless mirror (kind "mirror", F0 1)
    or a thin-walled pane (kind "pane", IOR 1.5, tint 0.9); a grey (rho 0.5) receiver at y = 2
    facing down (x, z in [-1, 1]) sees the light directly and its image at y = -1 in the floor,
    and for the pane a black square at y = -0.5 facing up sees the light through it."""
    b = GltfBuilder()
    light = b.add_light({"name": "bulb", "type": "point", "intensity": LUMENS_PER_WATT})
    black = b.material("black", (0.0, 0.0, 0.0))
    grey = b.material("grey", (0.5, 0.5, 0.5))
    if kind == "mirror":
        floor = specular_material(b, "mirror", (1.0, 1.0, 1.0), metallic=1.0)
    else:
        floor = specular_material(b, "pane", (0.9, 0.9, 0.9), transmission=1.0, ior=1.5)
    nodes = [add_quads(b, kind, [rect(1, 0.0, (-2.0, 2.0), (-2.0, 2.0), (0.0, 1.0, 0.0))], floor),
             add_quads(b, "receiver", [rect(1, 2.0, (-1.0, 1.0), (-1.0, 1.0), (0.0, -1.0, 0.0))], grey),
             b.light_node("bulb", light, translation=(0.0, 1.0, 0.0))]
    if kind == "pane":
        nodes.append(add_quads(b, "below", [rect(1, -0.5, (-1.0, 1.0), (-1.0, 1.0), (0.0, 1.0, 0.0))], black))
    b.add_scene("point_over_" + kind, nodes)
    return b


def rough_metal(b, name, base, roughness):
    """A metal (metallic 1) of the given roughness: GGX reflection, F0 = base (kernels/ggx.h)."""
    b.doc["materials"].append({"name": name,
                               "pbrMetallicRoughness": {"baseColorFactor": [base[0], base[1], base[2], 1.0],
                                                        "metallicFactor": 1.0, "roughnessFactor": roughness}})
    return len(b.doc["materials"]) - 1


def point_over_rough_metal():
    """For rough metals (GGX): point_over_specular_floor's layout with a rough metal floor
    (roughness 0.5, F0 (0.9, 0.7, 0.4)): a point light (1 W/sr) 1 m above it at the origin, a grey
    (rho 0.5) receiver at y = 2 facing down (x, z in [-1, 1]) that the lobe lights."""
    b = GltfBuilder()
    light = b.add_light({"name": "bulb", "type": "point", "intensity": LUMENS_PER_WATT})
    grey = b.material("grey", (0.5, 0.5, 0.5))
    metal = rough_metal(b, "metal", (0.9, 0.7, 0.4), 0.5)
    b.add_scene("point_over_rough_metal",
                [add_quads(b, "metal", [rect(1, 0.0, (-2.0, 2.0), (-2.0, 2.0), (0.0, 1.0, 0.0))], metal),
                 add_quads(b, "receiver", [rect(1, 2.0, (-1.0, 1.0), (-1.0, 1.0), (0.0, -1.0, 0.0))], grey),
                 b.light_node("bulb", light, translation=(0.0, 1.0, 0.0))])
    return b


def rough_glass(b, name, tint, roughness):
    """A thin pane of rough glass (transmission 1, IOR 1.5, no volume) of the given tint and
    roughness: GGX microfacet transmission (kernels/material.h: rough_glass_scatter)."""
    b.doc["materials"].append({"name": name,
                               "pbrMetallicRoughness": {"baseColorFactor": [tint[0], tint[1], tint[2], 1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": roughness},
                               "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}})
    b.use_extension("KHR_materials_transmission")
    return len(b.doc["materials"]) - 1


def point_over_rough_pane(height=1.0, tint=(1.0, 1.0, 1.0)):
    """For light sampling at rough glass: point_over_rough_metal's layout with a thin pane of
    rough glass (transmission 1, roughness 0.5, IOR 1.5, base colour `tint`, no volume) for the
    floor: what its microfacets reflect of the point light (1 W/sr, `height` above it; below, what
    the pane passes of it) is found only by a shadow ray."""
    b = GltfBuilder()
    light = b.add_light({"name": "bulb", "type": "point", "intensity": LUMENS_PER_WATT})
    grey = b.material("grey", (0.5, 0.5, 0.5))
    pane = rough_glass(b, "frosted", tint, 0.5)
    b.add_scene("point_over_rough_pane",
                [add_quads(b, "pane", [rect(1, 0.0, (-2.0, 2.0), (-2.0, 2.0), (0.0, 1.0, 0.0))], pane),
                 add_quads(b, "receiver", [rect(1, 2.0, (-1.0, 1.0), (-1.0, 1.0), (0.0, -1.0, 0.0))], grey),
                 b.light_node("bulb", light, translation=(0.0, height, 0.0))])
    return b


def lamps_about_rough_pane():
    """For light sampling at rough glass against its paths alone: a thin pane of rough glass
    (roughness 0.3, IOR 1.5, tint (0.9, 0.8, 0.7), no volume; x, z in [-2, 2] at y = 0, facing
    up) with a lamp (Le 1, black, 0.4 m square) 0.6 m under it facing up at x = 0.3 and another
    0.8 m over it facing down at x = -1.2: seen from above, the pane shows the one through it and
    the other's reflection."""
    b = GltfBuilder()
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    pane = rough_glass(b, "frosted", (0.9, 0.8, 0.7), 0.3)
    b.add_scene("lamps_about_rough_pane",
                [add_quads(b, "pane", [rect(1, 0.0, (-2.0, 2.0), (-2.0, 2.0), (0.0, 1.0, 0.0))], pane),
                 add_quads(b, "under", [rect(1, -0.6, (0.1, 0.5), (-0.2, 0.2), (0.0, 1.0, 0.0))], lamp),
                 add_quads(b, "over", [rect(1, 0.8, (-1.4, -1.0), (-0.2, 0.2), (0.0, -1.0, 0.0))], lamp)])
    return b


def lamp_over_tilted_pane():
    """For light sampling at rough glass where shading normals tilt: a thin pane of rough glass
    (roughness 0.7, IOR 1.5, clear; x, z in [-2, 2] at y = 0, facing up) whose vertex normals
    (NORMAL) lean 30 degrees toward +x, and a lamp (Le 1, black, 2.6 x 3.2 m) 3 m from the origin
    toward -x at 45 degrees over the pane, facing the origin. Seen at 70 degrees from the +x side,
    rough_glass_scatter turns many of the pane's mirrored directions, bent back by the tilted
    normal, into reflections."""
    b = GltfBuilder()
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    pane = rough_glass(b, "frosted", (1.0, 1.0, 1.0), 0.7)
    positions, indices = quads_to_mesh([rect(1, 0.0, (-2.0, 2.0), (-2.0, 2.0), (0.0, 1.0, 0.0))])
    prim = b.primitive(positions, indices, pane)
    lean = math.radians(30.0)
    prim["attributes"]["NORMAL"] = b.add_normals([(math.sin(lean), math.cos(lean), 0.0)] * len(positions))
    nodes = [b.add_node("pane", b.add_mesh("pane", [prim]))]
    h = math.sqrt(0.5)
    centre, along = (-3.0 * h, 3.0 * h, 0.0), (h, h, 0.0)
    corners = [tuple(centre[k] + a * along[k] + (c if k == 2 else 0.0) for k in range(3))
               for a, c in ((-1.3, -1.6), (1.3, -1.6), (1.3, 1.6), (-1.3, 1.6))]
    nodes.append(add_quads(b, "lamp", [facing(corners, (h, -h, 0.0))], lamp))
    b.add_scene("lamp_over_tilted_pane", nodes)
    return b


def lamp_over_rough_metal():
    """For rough metals in the camera pass: a lamp (Le 1, black, 0.4 m square at y = 1, facing
    down, centred over x = 0.3) over a rough metal floor (roughness 0.4, F0 (0.95, 0.8, 0.5); x
    in [0, 1], z in [0, 1]) beside a grey wall at x = 0 facing +x (y in [0, 1], z in [0, 1]):
    the wall is lit by the lamp directly and by its glossy reflection in the floor."""
    b = GltfBuilder()
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))
    grey = b.material("grey", (0.5, 0.5, 0.5))
    metal = rough_metal(b, "metal", (0.95, 0.8, 0.5), 0.4)
    b.add_scene("lamp_over_rough_metal",
                [add_quads(b, "metal", [rect(1, 0.0, (0.0, 1.0), (0.0, 1.0), (0.0, 1.0, 0.0))], metal),
                 add_quads(b, "wall", [rect(0, 0.0, (0.0, 1.0), (0.0, 1.0), (1.0, 0.0, 0.0))], grey),
                 add_quads(b, "lamp", [rect(1, 1.0, (0.1, 0.5), (0.3, 0.7), (0.0, -1.0, 0.0))], lamp)])
    return b


def furnace_with_spheres():
    """The white furnace (every face of the unit cube emits exitance 1, reflectance 0.5) with a
    lossless mirror sphere (F0 = 1) and a clear glass sphere (IOR 1.5, a volume) inside, radius
    0.15: neither absorbs, so the walls' radiosity stays 2 everywhere."""
    b = closed_cube(furnace=True)
    mirror = specular_material(b, "mirror", (1.0, 1.0, 1.0), metallic=1.0)
    glass = specular_material(b, "glass", (1.0, 1.0, 1.0), transmission=1.0, ior=1.5, thickness=0.3)
    nodes = b.doc["scenes"][0]["nodes"]
    for name, centre, mat in (("mirror_sphere", (0.3, 0.35, 0.4), mirror), ("glass_sphere", (0.68, 0.6, 0.6), glass)):
        positions, normals, indices = uv_sphere(centre, 0.15)
        prim = b.primitive(positions, indices, mat)
        prim["attributes"]["NORMAL"] = b.add_normals(normals)
        nodes.append(b.add_node(name, mesh=b.add_mesh(name, [prim])))
    return b


def glossy_room():
    """glTF's material model together, for the camera pass against the path tracer: a unit room
    (grey walls and ceiling, rho 0.5, matte; open at z = 1) lit by a ceiling lamp (Le 1, x and z in
    [0.35, 0.65]) with a floor painted under glTF's default specular layer (base 0.7, roughness
    0.5), a red painted box (base (0.8, 0.3, 0.2), roughness 0.6, layered), a rough metal box
    (F0 (0.95, 0.8, 0.5), roughness 0.4) and an upright rough thin pane (roughness 0.3) before
    them, seen along -z through the open side."""
    b = GltfBuilder()
    grey = b.grey()
    lamp_material = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0))

    def painted(name, base, roughness):
        b.doc["materials"].append({"name": name,
                                   "pbrMetallicRoughness": {"baseColorFactor": [base[0], base[1], base[2], 1.0],
                                                            "metallicFactor": 0.0, "roughnessFactor": roughness},
                                   "extensions": {"KHR_materials_specular": {"specularFactor": 1.0}}})
        b.use_extension("KHR_materials_specular")
        return len(b.doc["materials"]) - 1

    floor_paint = painted("floor paint", (0.7, 0.7, 0.7), 0.5)
    red = painted("red paint", (0.8, 0.3, 0.2), 0.6)
    metal = rough_metal(b, "metal", (0.95, 0.8, 0.5), 0.4)
    b.doc["materials"].append({"name": "frosted",
                               "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": 0.3},
                               "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}})
    b.use_extension("KHR_materials_transmission")
    frosted = len(b.doc["materials"]) - 1
    walls = [quad for name, quad in inward_box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0)) if name not in ("floor", "front")]
    floor = [quad for name, quad in inward_box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0)) if name == "floor"]
    b.add_scene("glossy_room",
                [add_quads(b, "walls", walls, grey),
                 add_quads(b, "floor", floor, floor_paint),
                 add_quads(b, "lamp", [rect(1, 0.99, (0.35, 0.65), (0.35, 0.65), (0.0, -1.0, 0.0))], lamp_material),
                 add_quads(b, "red box", box_quads((0.12, 0.0, 0.25), (0.42, 0.35, 0.55)), red),
                 add_quads(b, "metal box", box_quads((0.58, 0.0, 0.3), (0.88, 0.25, 0.6)), metal),
                 add_quads(b, "pane", [rect(2, 0.75, (0.3, 0.7), (0.0, 0.3), (0.0, 0.0, 1.0))], frosted)])
    return b


def write_specular_scenes(root):
    """tests/data/specular/ under `root`: mirrors, glass and rough metals."""
    directory = os.path.join(root, "tests", "data", "specular")
    write_gltf(directory, "mirror-facing-lamp.gltf", mirror_facing_lamp())
    write_gltf(directory, "glass-slab.gltf", glass_slab_before_lamp())
    write_gltf(directory, "glass-slab-tilted.gltf", glass_tilted_before_lamp())
    write_gltf(directory, "thin-pane.gltf", thin_pane_before_lamp())
    write_gltf(directory, "mirror-over-lamp.gltf", mirror_over_lamp())
    write_gltf(directory, "pane-between-squares.gltf", pane_between_squares())
    write_gltf(directory, "furnace-with-spheres.gltf", furnace_with_spheres())
    write_gltf(directory, "lamp-through-pane.gltf", lamp_through_pane())
    write_gltf(directory, "window-box.gltf", window_box())
    write_gltf(directory, "point-under-pane.gltf", point_under_pane())
    write_gltf(directory, "point-over-mirror.gltf", point_over_specular_floor("mirror"))
    write_gltf(directory, "point-over-pane.gltf", point_over_specular_floor("pane"))
    write_gltf(directory, "point-over-rough-metal.gltf", point_over_rough_metal())
    write_gltf(directory, "lamp-over-rough-metal.gltf", lamp_over_rough_metal())
    write_gltf(directory, "point-over-rough-pane.gltf", point_over_rough_pane())
    write_gltf(directory, "point-under-rough-pane.gltf", point_over_rough_pane(-1.0, (0.9, 0.6, 0.3)))
    write_gltf(directory, "lamps-about-rough-pane.gltf", lamps_about_rough_pane())
    write_gltf(directory, "lamp-over-tilted-pane.gltf", lamp_over_tilted_pane())
    write_gltf(directory, "glossy-room.gltf", glossy_room())
