"""The bundled scenes (scenes/*.gltf, described in scenes/README.md): the measured Cornell box,
with a point light and with a mirror and a glass sphere, and the analytic view-factor scenes
(facing and perpendicular squares, coaxial disks, the closed cube and its white furnace)."""

import math
import os

from geometry import centroid, cut_quad, disk, facing, quads_to_mesh, square, sub, uv_sphere
from gltf_encoder import LUMENS_PER_WATT, UNSIGNED_INT, GltfBuilder, write_gltf
from scene_parts import lamp, specular_material


# Cornell box, measured data (mm), https://www.graphics.cornell.edu/online/box/data.html
CORNELL_ROOM = [  # (node, material, quad)
    ("floor", "white", [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]),
    ("ceiling", "white", [(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2),
                          (0, 548.8, 0)]),
    ("back_wall", "white", [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2),
                            (556, 548.8, 559.2)]),
    ("right_wall", "green", [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]),
    ("left_wall", "red", [(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2),
                          (556, 548.8, 0)]),
]
CORNELL_ROOM_CENTRE = (278.0, 274.4, 279.6)
# Measured light at y = 548.8 (in the ceiling plane); moved 0.5 mm down so it is a separate
# emitter just below the ceiling.
CORNELL_LIGHT = [(343, 548.3, 227), (343, 548.3, 332), (213, 548.3, 332), (213, 548.3, 227)]
CORNELL_BLOCKS = [
    ("short_block", [
        [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)],
        [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)],
        [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)],
        [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)],
        [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)],
    ]),
    ("tall_block", [
        [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)],
        [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)],
        [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)],
        [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)],
        [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)],
    ]),
]


def mm_to_m(quad):
    return [tuple(c / 1000.0 for c in p) for p in quad]


def cornell_box(lamp=True, blocks=True, cut=1):
    """The measured Cornell box; cut > 1: every quad cut into cut x cut quads (2 cut^2 triangles
    each; scenes/cornell_cut.py), the same box as finely tessellated content."""
    b = GltfBuilder()
    materials = {
        "white": b.material("white", (0.725, 0.71, 0.68)),
        "red": b.material("red", (0.63, 0.065, 0.05)),
        "green": b.material("green", (0.14, 0.45, 0.091)),
    }
    children = []
    # Orientation is decided geometrically; the listed vertex order is not trusted.
    for name, mat, quad in CORNELL_ROOM:
        inward = sub(CORNELL_ROOM_CENTRE, centroid(quad))
        positions, indices = quads_to_mesh(cut_quad(mm_to_m(facing(quad, inward)), cut))
        children.append(b.surface(name, positions, indices, materials[mat]))
    if lamp:
        # emissiveFactor x strength = (17, 12, 4) radiance.
        light_mat = b.material("light", (0.78, 0.78, 0.78), emissive=(1.0, 12.0 / 17.0, 4.0 / 17.0),
                               strength=17.0)
        positions, indices = quads_to_mesh(cut_quad(mm_to_m(facing(CORNELL_LIGHT, (0.0, -1.0, 0.0))), cut))
        children.append(b.surface("light", positions, indices, light_mat))
    for name, quads in CORNELL_BLOCKS if blocks else []:
        middle = centroid([p for q in quads for p in q])
        oriented = [part for q in quads for part in cut_quad(mm_to_m(facing(q, sub(centroid(q), middle))), cut)]
        positions, indices = quads_to_mesh(oriented)
        children.append(b.surface(name, positions, indices, materials["white"]))
    root = b.add_node("cornell_box", children=children)
    b.doc["cameras"].append({"name": "cornell", "type": "perspective",
                             "perspective": {"yfov": 2.0 * math.atan(12.5 / 35.0),
                                             "aspectRatio": 1.0, "znear": 0.01}})
    # glTF cameras look down local -Z: a half turn about +Y makes it look along +Z.
    camera = b.add_node("camera", camera=0, translation=(0.278, 0.273, -0.8),
                        rotation=(0.0, 1.0, 0.0, 0.0))
    b.add_scene("cornell_box", [root, camera])
    return b


def cornell_box_point_light():
    """The Cornell box lit by a point light where its lamp was, 1 cm under the ceiling: the
    lamp's intensity along its normal, Le x area = (17, 12, 4) x 0.01365 W/sr, in candela."""
    b = cornell_box(lamp=False)
    root = next(n for n in b.doc["nodes"] if n["name"] == "cornell_box")
    intensity = 17.0 * 0.130 * 0.105  # W/sr, red
    light = b.add_light({"name": "bulb", "type": "point", "color": [1.0, 12.0 / 17.0, 4.0 / 17.0],
                         "intensity": round(intensity * LUMENS_PER_WATT, 6)})
    root["children"].append(b.light_node("bulb", light, translation=(0.278, 0.5388, 0.2795)))
    return b


def facing_squares():
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    nodes = []
    for name, level, sign, mat in (("bottom", 0, +1, grey), ("top", 1, -1, light)):
        positions, indices = quads_to_mesh([square(1, level, sign)])
        nodes.append(b.surface(name, positions, indices, mat))
    b.add_scene("facing_squares", nodes)
    return b


def perpendicular_squares():
    b = GltfBuilder()
    light, grey = lamp(b), b.grey()
    nodes = []
    for name, axis, mat in (("floor", 1, light), ("wall", 2, grey)):
        positions, indices = quads_to_mesh([square(axis, 0, +1)])
        nodes.append(b.surface(name, positions, indices, mat))
    b.add_scene("perpendicular_squares", nodes)
    return b


def coaxial_disks():
    b = GltfBuilder()
    light, grey = lamp(b), b.grey()
    nodes = []
    for name, level, sign, mat in (("lower", 0, +1, light), ("upper", 1, -1, grey)):
        positions, indices = disk(level, sign)
        mesh = b.triangle_mesh(name, positions, indices, mat, index_type=UNSIGNED_INT)
        nodes.append(b.add_node(name, mesh))
    b.add_scene("coaxial_disks", nodes)
    return b


def closed_cube(furnace=False, strength=None, rho=0.5, cut=1):
    """The closed unit cube. With furnace=True every face emits Le = 1/pi (exitance E = 1)
    with reflectance rho (0.5 unless given): the white furnace, B = E / (1 - rho) everywhere
    (2 at 0.5). `strength` scales the emission (KHR_materials_emissive_strength). cut > 1: each
    face cut into cut x cut quads, as tessellated content would be."""
    b = GltfBuilder()
    if furnace:
        glow = b.material("glow", (rho, rho, rho), emissive=(1.0 / math.pi,) * 3, strength=strength)
        light, grey = glow, glow
    else:
        light, grey = lamp(b, base=0.5), b.grey()
    faces = [  # (name, axis, level, inward sign)
        ("floor", 1, 0, +1), ("ceiling", 1, 1, -1),
        ("left", 0, 0, +1), ("right", 0, 1, -1),
        ("front", 2, 1, -1), ("back", 2, 0, +1),
    ]
    nodes = []
    for name, axis, level, sign in faces:
        positions, indices = quads_to_mesh(cut_quad(square(axis, level, sign), cut))
        nodes.append(b.surface(name, positions, indices, light if name == "floor" else grey))
    b.add_scene("closed_cube", nodes)
    return b


def cornell_box_specular():
    """The Cornell box with its blocks replaced by a mirror sphere (F0 0.95) at the back and a
    glass sphere (IOR 1.5) at the front (on the image's left), both of radius 0.1 m, smooth."""
    b = cornell_box(blocks=False)
    mirror = specular_material(b, "mirror", (0.95, 0.95, 0.95), metallic=1.0)
    glass = specular_material(b, "glass", (1.0, 1.0, 1.0), transmission=1.0, ior=1.5, thickness=0.2)
    root = b.doc["nodes"][b.doc["scenes"][0]["nodes"][0]]
    for name, centre, mat in (("mirror_sphere", (0.185, 0.1, 0.37), mirror),
                              ("glass_sphere", (0.37, 0.1, 0.17), glass)):
        positions, normals, indices = uv_sphere(centre, 0.1)
        prim = b.primitive(positions, indices, mat)
        prim["attributes"]["NORMAL"] = b.add_normals(normals)
        root["children"].append(b.add_node(name, mesh=b.add_mesh(name, [prim])))
    return b


def write_bundled_scenes(root):
    """scenes/ under `root`: the scenes users are given."""
    directory = os.path.join(root, "scenes")
    write_gltf(directory, "cornell-box.gltf", cornell_box())
    write_gltf(directory, "facing-squares.gltf", facing_squares())
    write_gltf(directory, "perpendicular-squares.gltf", perpendicular_squares())
    write_gltf(directory, "coaxial-disks.gltf", coaxial_disks())
    write_gltf(directory, "closed-cube.gltf", closed_cube())
    write_gltf(directory, "cornell-box-point-light.gltf", cornell_box_point_light())
    write_gltf(directory, "cornell-box-specular.gltf", cornell_box_specular())
