#!/usr/bin/env python3
"""Generate the bundled glTF scenes and the loader test data.

Run from anywhere:  python3 scenes/generate.py
Writes (paths relative to the repository root, found from this file):
  scenes/*.gltf                 bundled scenes (Cornell box, analytic view-factor scenes)
  tests/data/gltf/*             small valid files for loader tests
  tests/data/bad/*              small invalid files, one problem each
  tests/data/lights/*           scenes lit by KHR_lights_punctual lights, for closed-form tests
  tests/data/textures/*         textured scenes (PNG written here, without libraries)
  tests/data/environment/*      environment maps (OpenEXR written here) and scenes they light
  tests/data/thermal/*          enclosures and properties for radiative heat exchange
  tests/data/specular/*         a mirror and a glass slab before a lamp (closed forms)
  bench/scenes/*.gltf           scenes built to break methods (bench/stability)

Python 3 standard library only. Output is deterministic: the same bytes on every run.
Conventions (shared/DESIGN.md): metres, +Y up, right-handed, counter-clockwise triangles
face their normal, single-sided unless material.doubleSided.
"""

import base64
import json
import math
import os
import struct
import zlib

GENERATOR = "radiosity scenes/generate.py"

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.path.join(ROOT, "scenes")
GOOD = os.path.join(ROOT, "tests", "data", "gltf")
BAD = os.path.join(ROOT, "tests", "data", "bad")
SOLVE = os.path.join(ROOT, "tests", "data", "solve")
BENCH = os.path.join(ROOT, "bench", "scenes")
LIGHTS = os.path.join(ROOT, "tests", "data", "lights")
TEXTURES = os.path.join(ROOT, "tests", "data", "textures")
ENVIRONMENT = os.path.join(ROOT, "tests", "data", "environment")
THERMAL = os.path.join(ROOT, "tests", "data", "thermal")
SPECULAR = os.path.join(ROOT, "tests", "data", "specular")

# glTF enums
FLOAT, SHORT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5122, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
POINTS, LINES, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 0, 1, 4, 5, 6

GLB_MAGIC, GLB_JSON, GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942

# Unit right triangle in the z = 0 plane, counter-clockwise seen from +Z (normal +Z).
UNIT_TRI = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


# ----------------------------------------------------------------------------- vectors

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def centroid(points):
    n = float(len(points))
    return tuple(sum(p[k] for p in points) / n for k in range(3))


def polygon_normal(points):
    """Newell's (unnormalised) normal of a planar or near-planar polygon."""
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return tuple(n)


def facing(points, direction):
    """Return the polygon's vertices ordered so its normal has a positive dot with direction."""
    if dot(polygon_normal(points), direction) < 0.0:
        return [points[0]] + list(reversed(points[1:]))
    return list(points)


def f32(x):
    """Round a Python float to the nearest float32 (what ends up in the buffer)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def square(axis, level, normal_sign):
    """Unit square [0,1]^2 in the plane axis = level, facing +axis (sign +1) or -axis (-1)."""
    u, v = [k for k in range(3) if k != axis]
    quad = []
    for a, b in ((0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)):
        p = [0.0, 0.0, 0.0]
        p[axis], p[u], p[v] = float(level), a, b
        quad.append(tuple(p))
    direction = [0.0, 0.0, 0.0]
    direction[axis] = float(normal_sign)
    return facing(quad, direction)


def quads_to_mesh(quads):
    """Quads (lists of 4 points, already oriented) -> (positions, triangle indices)."""
    positions, indices = [], []
    for quad in quads:
        base = len(positions)
        positions.extend(quad)
        indices.extend([base, base + 1, base + 2, base, base + 2, base + 3])
    return positions, indices


# ----------------------------------------------------------------------------- builder

class GltfBuilder:
    """Tiny glTF 2.0 writer: one binary buffer, 4-byte aligned bufferViews, accessors with
    POSITION min/max, named materials, meshes, nodes, one scene."""

    def __init__(self):
        self.data = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": GENERATOR},
            "scene": 0,
            "scenes": [],
            "nodes": [],
            "cameras": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }
        self.material_index = {}
        self.extensions_used = []
        self.extensions_required = []

    # -- buffer, views, accessors

    def add_view(self, blob, target=None, stride=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(blob)}
        if stride is not None:
            view["byteStride"] = stride
        if target is not None:
            view["target"] = target
        self.data.extend(blob)
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def add_accessor(self, view, component_type, count, type_, minimum=None, maximum=None,
                     normalized=False):
        acc = {"bufferView": view, "componentType": component_type, "count": count,
               "type": type_}
        if normalized:
            acc["normalized"] = True
        if minimum is not None:
            acc["min"] = list(minimum)
            acc["max"] = list(maximum)
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def add_positions(self, points):
        """float32 VEC3 POSITION accessor. min/max are the float32 values actually stored;
        non-finite components (deliberately bad data) are left out of the bounds."""
        blob = b"".join(struct.pack("<3f", *p) for p in points)
        lo, hi = [], []
        for k in range(3):
            values = [f32(p[k]) for p in points if math.isfinite(p[k])]
            lo.append(min(values))
            hi.append(max(values))
        view = self.add_view(blob, ARRAY_BUFFER)
        return self.add_accessor(view, FLOAT, len(points), "VEC3", lo, hi)

    def add_normals(self, normals):
        """float32 VEC3 NORMAL accessor."""
        view = self.add_view(b"".join(struct.pack("<3f", *n) for n in normals), ARRAY_BUFFER)
        return self.add_accessor(view, FLOAT, len(normals), "VEC3")

    def add_indices(self, indices, component_type=UNSIGNED_SHORT):
        fmt = {UNSIGNED_SHORT: "<%dH", UNSIGNED_INT: "<%dI"}[component_type]
        view = self.add_view(struct.pack(fmt % len(indices), *indices), ELEMENT_ARRAY_BUFFER)
        return self.add_accessor(view, component_type, len(indices), "SCALAR")

    # -- materials, meshes, nodes

    def material(self, name, base=(0.5, 0.5, 0.5), emissive=None, strength=None,
                 double_sided=False):
        """Add (once) and return the index of a named material."""
        if name in self.material_index:
            return self.material_index[name]
        mat = {"name": name,
               "pbrMetallicRoughness": {"baseColorFactor": [base[0], base[1], base[2], 1.0],
                                        "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if emissive is not None:
            mat["emissiveFactor"] = list(emissive)
        if strength is not None:
            mat["extensions"] = {"KHR_materials_emissive_strength":
                                 {"emissiveStrength": strength}}
            self.use_extension("KHR_materials_emissive_strength")
        if double_sided:
            mat["doubleSided"] = True
        self.doc["materials"].append(mat)
        self.material_index[name] = len(self.doc["materials"]) - 1
        return self.material_index[name]

    def grey(self):
        return self.material("grey", (0.5, 0.5, 0.5))

    def use_extension(self, name, required=False):
        if name not in self.extensions_used:
            self.extensions_used.append(name)
        if required and name not in self.extensions_required:
            self.extensions_required.append(name)

    def add_mesh(self, name, primitives):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        return len(self.doc["meshes"]) - 1

    def primitive(self, positions, indices, material, mode=TRIANGLES,
                  index_type=UNSIGNED_SHORT):
        prim = {"attributes": {"POSITION": self.add_positions(positions)}}
        if indices is not None:
            prim["indices"] = self.add_indices(indices, index_type)
        prim["material"] = material
        if mode != TRIANGLES:
            prim["mode"] = mode
        return prim

    def triangle_mesh(self, name, positions, indices, material, index_type=UNSIGNED_SHORT):
        return self.add_mesh(name, [self.primitive(positions, indices, material,
                                                   index_type=index_type)])

    def add_node(self, name, mesh=None, children=None, **transform):
        """transform: translation=, rotation=, scale= or matrix= (glTF lists)."""
        node = {"name": name}
        if mesh is not None:
            node["mesh"] = mesh
        if children:
            node["children"] = list(children)
        for key in ("camera", "matrix", "translation", "rotation", "scale"):
            if key in transform:
                node[key] = list(transform[key]) if key != "camera" else transform[key]
        self.doc["nodes"].append(node)
        return len(self.doc["nodes"]) - 1

    def add_light(self, light):
        """A KHR_lights_punctual light (a dict as the extension writes it); returns its index."""
        self.use_extension("KHR_lights_punctual")
        extension = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})
        extension["lights"].append(light)
        return len(extension["lights"]) - 1

    def light_node(self, name, light, **transform):
        """A node that places light `light` (it shines down its local -Z)."""
        node = self.add_node(name, **transform)
        self.doc["nodes"][node]["extensions"] = {"KHR_lights_punctual": {"light": light}}
        return node

    def add_scene(self, name, nodes):
        self.doc["scenes"].append({"name": name, "nodes": list(nodes)})
        return len(self.doc["scenes"]) - 1

    def surface(self, name, positions, indices, material, **transform):
        """A node named `name` whose own mesh (same name) holds one triangle list."""
        return self.add_node(name, self.triangle_mesh(name, positions, indices, material),
                             **transform)

    # -- output

    def padded_data(self):
        data = bytes(self.data)
        return data + b"\0" * (-len(data) % 4)

    def document(self, uri="embed"):
        """The JSON document. uri: "embed" (base64 data URI), None (GLB), or a file name."""
        doc = {}
        for key, value in self.doc.items():
            if isinstance(value, list) and not value:
                continue  # glTF forbids empty top-level arrays
            doc[key] = value
        if self.extensions_used:
            doc["extensionsUsed"] = list(self.extensions_used)
        if self.extensions_required:
            doc["extensionsRequired"] = list(self.extensions_required)
        data = self.padded_data()
        buf = {"byteLength": len(data)}
        if uri == "embed":
            buf["uri"] = ("data:application/octet-stream;base64,"
                          + base64.b64encode(data).decode("ascii"))
        elif uri is not None:
            buf["uri"] = uri
        doc["buffers"] = [buf]
        return doc


def gltf_text(doc):
    return json.dumps(doc, indent=2) + "\n"


def glb_bytes(doc, bin_data):
    """Binary glTF: JSON chunk padded with spaces, BIN chunk padded with zeros."""
    js = json.dumps(doc, separators=(",", ":")).encode("utf-8")
    js += b" " * (-len(js) % 4)
    bin_data = bin_data + b"\0" * (-len(bin_data) % 4)
    total = 12 + 8 + len(js) + 8 + len(bin_data)
    return (struct.pack("<III", GLB_MAGIC, 2, total)
            + struct.pack("<II", len(js), GLB_JSON) + js
            + struct.pack("<II", len(bin_data), GLB_BIN) + bin_data)


def write(directory, name, content):
    os.makedirs(directory, exist_ok=True)
    path = os.path.join(directory, name)
    mode = "wb" if isinstance(content, bytes) else "w"
    with open(path, mode, **({} if mode == "wb" else {"encoding": "utf-8", "newline": "\n"})) as f:
        f.write(content)
    return path


def write_gltf(directory, name, builder):
    return write(directory, name, gltf_text(builder.document()))


# ----------------------------------------------------------------------------- scenes

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


def cornell_box(lamp=True, blocks=True):
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
        positions, indices = quads_to_mesh([mm_to_m(facing(quad, inward))])
        children.append(b.surface(name, positions, indices, materials[mat]))
    if lamp:
        # emissiveFactor x strength = (17, 12, 4) radiance.
        light_mat = b.material("light", (0.78, 0.78, 0.78), emissive=(1.0, 12.0 / 17.0, 4.0 / 17.0),
                               strength=17.0)
        positions, indices = quads_to_mesh([mm_to_m(facing(CORNELL_LIGHT, (0.0, -1.0, 0.0)))])
        children.append(b.surface("light", positions, indices, light_mat))
    for name, quads in CORNELL_BLOCKS if blocks else []:
        middle = centroid([p for q in quads for p in q])
        oriented = [mm_to_m(facing(q, sub(centroid(q), middle))) for q in quads]
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


# 683 lm/W: glTF's photometric light units over radiometric ones (as Blender converts them).
LUMENS_PER_WATT = 683.0


def rotation_to(direction):
    """The unit quaternion [x, y, z, w] that turns -Z (where a glTF light shines) to `direction`."""
    length = math.sqrt(dot(direction, direction))
    d = tuple(c / length for c in direction)
    a = (0.0, 0.0, -1.0)
    c = dot(a, d)
    if c < -0.999999:
        return [0.0, 1.0, 0.0, 0.0]  # a half turn about +Y
    axis = cross(a, d)
    w = math.sqrt((1.0 + c) / 2.0)
    k = 0.5 / w
    return [clean(axis[0] * k), clean(axis[1] * k), clean(axis[2] * k), clean(w)]


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


def lamp(b, base=0.0):
    return b.material("lamp", (base, base, base), emissive=(1.0, 1.0, 1.0))


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


def clean(x):
    """Snap cos/sin round-off at multiples of pi/2 to exact values; no negative zero."""
    return round(x, 15) + 0.0


def disk(level, normal_sign, sides=64):
    """Regular polygon inscribed in the unit circle at y = level, fanned around its centre."""
    centre = (0.0, float(level), 0.0)
    rim = [(clean(math.cos(2.0 * math.pi * k / sides)), float(level),
            clean(math.sin(2.0 * math.pi * k / sides))) for k in range(sides)]
    positions = [centre] + rim
    indices = []
    for k in range(sides):
        tri = [0, 1 + k, 1 + (k + 1) % sides]
        normal = cross(sub(positions[tri[1]], centre), sub(positions[tri[2]], centre))
        if normal[1] * normal_sign < 0.0:
            tri = [tri[0], tri[2], tri[1]]
        indices.extend(tri)
    return positions, indices


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


def closed_cube(furnace=False, strength=None, rho=0.5):
    """The closed unit cube. With furnace=True every face emits Le = 1/pi (exitance E = 1)
    with reflectance rho (0.5 unless given): the white furnace, B = E / (1 - rho) everywhere
    (2 at 0.5). `strength` scales the emission (KHR_materials_emissive_strength)."""
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
        positions, indices = quads_to_mesh([square(axis, level, sign)])
        nodes.append(b.surface(name, positions, indices, light if name == "floor" else grey))
    b.add_scene("closed_cube", nodes)
    return b


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


# ----------------------------------------------------------------------------- loader tests

def unit_triangle(name="tri", positions=UNIT_TRI, indices=(0, 1, 2), **transform):
    """The base file of most tests: one node `name` with a one-triangle mesh, grey."""
    b = GltfBuilder()
    node = b.surface(name, list(positions), list(indices), b.grey(), **transform)
    b.add_scene("scene", [node])
    return b


def transforms():
    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    h = math.sqrt(0.5)
    plain = b.add_node("plain", mesh)
    trs = b.add_node("trs", mesh, translation=(1.0, 2.0, 3.0), rotation=(0.0, 0.0, h, h),
                     scale=(2.0, 2.0, 2.0))
    child = b.add_node("child", mesh, translation=(0.0, 5.0, 0.0))
    parent = b.add_node("parent", children=[child],
                        matrix=(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                0.0, 0.0, 1.0, 0.0, 10.0, 0.0, 0.0, 1.0))
    b.add_scene("scene", [plain, trs, parent])
    return b


STRIP_VERTICES = [(0.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0),
                  (2.0, 0.0, 0.0)]
FAN_VERTICES = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0),
                (-1.0, 1.0, 0.0)]


def single_primitive(node, positions, indices, mode, material=None):
    b = GltfBuilder()
    mat = b.grey() if material is None else material(b)
    mesh = b.add_mesh(node, [b.primitive(positions, indices, mat, mode=mode)])
    b.add_scene("scene", [b.add_node(node, mesh)])
    return b


def double_sided():
    b = GltfBuilder()
    two = b.material("two_sided", (0.5, 0.5, 0.5), double_sided=True)
    grey = b.grey()
    nodes = []
    for name, level, sign, mat in (("plate", 0, +1, two), ("above", 1, -1, grey),
                                   ("below", -1, +1, grey)):
        positions, indices = quads_to_mesh([square(1, level, sign)])
        nodes.append(b.surface(name, positions, indices, mat))
    b.add_scene("scene", nodes)
    return b


def points_lines():
    b = GltfBuilder()
    grey = b.grey()
    prims = [
        b.primitive([(0.0, 0.0, 1.0), (1.0, 0.0, 1.0), (0.0, 1.0, 1.0)], None, grey, POINTS),
        b.primitive([(0.0, 0.0, 2.0), (1.0, 0.0, 2.0), (0.0, 1.0, 2.0), (1.0, 1.0, 2.0)],
                    None, grey, LINES),
        b.primitive(UNIT_TRI, None, grey, TRIANGLES),
    ]
    b.add_scene("scene", [b.add_node("mixed", b.add_mesh("mixed", prims))])
    return b


def emissive_strength():
    b = GltfBuilder()
    mat = b.material("glow", (0.5, 0.5, 0.5), emissive=(0.5, 0.25, 1.0), strength=4.0)
    b.add_scene("scene", [b.surface("lamp", UNIT_TRI, [0, 1, 2], mat)])
    return b


def degenerate():
    positions = UNIT_TRI + [(0.0, 0.0, 1.0), (0.0, 0.0, 1.0), (1.0, 1.0, 1.0),  # repeated
                            (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (2.0, 0.0, 0.0)]  # collinear
    return unit_triangle("mostly_ok", positions, range(9))


def quantized():
    b = GltfBuilder()
    b.use_extension("KHR_mesh_quantization", required=True)
    q = [(0, 0, 0), (32767, 0, 0), (0, 32767, 0)]
    # SHORT VEC3 is 6 bytes; vertex attributes must be 4-byte aligned -> byteStride 8.
    blob = b"".join(struct.pack("<3hxx", *p) for p in q)
    view = b.add_view(blob, ARRAY_BUFFER, stride=8)
    pos = b.add_accessor(view, SHORT, 3, "VEC3", [0, 0, 0], [32767, 32767, 0],
                         normalized=True)
    prim = {"attributes": {"POSITION": pos}, "indices": b.add_indices([0, 1, 2]),
            "material": b.grey()}
    b.add_scene("scene", [b.add_node("tri", b.add_mesh("tri", [prim]))])
    return b


def normals_mesh(name, positions, normals, indices, node_transform=None):
    """One grey primitive with the given per-vertex NORMALs (None: without)."""
    b = GltfBuilder()
    prim = b.primitive(positions, indices, b.grey())
    if normals is not None:
        prim["attributes"]["NORMAL"] = b.add_normals(normals)
    mesh = b.add_mesh(name, [prim])
    b.add_scene(name, [b.add_node(name, mesh=mesh, **(node_transform or {}))])
    return b


def prism(sides=8, smooth=True):
    """The open side of a prism of `sides` faces around the y axis, radius 1, height 1, facing
    out; with `smooth`, radial NORMALs on shared vertices (a cylinder, 360/sides degrees
    between faces), else no normals."""
    positions, normals, indices = [], [], []
    for k in range(sides):
        a = 2.0 * math.pi * k / sides
        for y in (0.0, 1.0):
            positions.append((round(math.cos(a), 9), y, round(math.sin(a), 9)))
            normals.append((round(math.cos(a), 9), 0.0, round(math.sin(a), 9)))
    for k in range(sides):
        i0, i1, j0, j1 = 2 * k, 2 * k + 1, 2 * ((k + 1) % sides), 2 * ((k + 1) % sides) + 1
        indices += [i0, i1, j1, i0, j1, j0]  # facing out
    return normals_mesh("prism", positions, normals if smooth else None, indices)


def fold(degrees, shared_normals):
    """Two unit quads meeting along the z axis's edge x = 0, the second folded up by `degrees`,
    facing up. shared_normals: one vertex per point with normals averaged over the two faces
    (smooth); else each quad has its own vertices and its face's normal (a hard edge)."""
    t = math.radians(degrees)
    n1 = (0.0, 1.0, 0.0)
    n2 = (round(-math.sin(t), 9), round(math.cos(t), 9), 0.0)
    far = (round(math.cos(t), 9), round(math.sin(t), 9))
    if shared_normals:
        mid = (n1[0] + n2[0], n1[1] + n2[1], 0.0)
        length = math.hypot(mid[0], mid[1])
        mid = (round(mid[0] / length, 9), round(mid[1] / length, 9), 0.0)
        positions = [(-1.0, 0.0, 0.0), (-1.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0),
                     (far[0], far[1], 0.0), (far[0], far[1], 1.0)]
        normals = [n1, n1, mid, mid, n2, n2]
        indices = [0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4]
    else:
        positions = [(-1.0, 0.0, 0.0), (-1.0, 0.0, 1.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0),
                     (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (far[0], far[1], 0.0), (far[0], far[1], 1.0)]
        normals = [n1, n1, n1, n1, n2, n2, n2, n2]
        indices = [0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6]
    return normals_mesh("fold", positions, normals, indices)


def write_good():
    write_gltf(GOOD, "transforms.gltf", transforms())
    t = transforms()
    write(GOOD, "transforms.glb", glb_bytes(t.document(uri=None), t.padded_data()))
    write_gltf(GOOD, "strip.gltf",
               single_primitive("strip", STRIP_VERTICES, [0, 1, 2, 3, 4], TRIANGLE_STRIP))
    write_gltf(GOOD, "fan.gltf", single_primitive("fan", FAN_VERTICES, None, TRIANGLE_FAN))
    write_gltf(GOOD, "double-sided.gltf", double_sided())
    write_gltf(GOOD, "points-lines.gltf", points_lines())
    ext = unit_triangle()
    write(GOOD, "external-buffer.gltf", gltf_text(ext.document(uri="external-buffer.bin")))
    write(GOOD, "external-buffer.bin", ext.padded_data())
    write_gltf(GOOD, "emissive-strength.gltf", emissive_strength())
    write_gltf(GOOD, "mirrored.gltf", unit_triangle("mirrored", scale=(-1.0, 1.0, 1.0)))
    write_gltf(GOOD, "degenerate.gltf", degenerate())
    write_gltf(GOOD, "quantized.gltf", quantized())
    write_gltf(GOOD, "prism-smooth.gltf", prism())
    write_gltf(GOOD, "prism-flat.gltf", prism(smooth=False))
    write_gltf(GOOD, "fold-10-split.gltf", fold(10.0, shared_normals=False))
    write_gltf(GOOD, "fold-90-shared.gltf", fold(90.0, shared_normals=True))
    write_gltf(GOOD, "fold-45-shared.gltf", fold(45.0, shared_normals=True))
    # Normals under a node that turns about z by 90 degrees and stretches x by 4: they follow the
    # inverse transpose (a triangle in the x-y plane keeps facing +z).
    write_gltf(GOOD, "normals-transformed.gltf",
               normals_mesh("tilted", UNIT_TRI, [(0.0, 0.0, 1.0), (0.6, 0.0, 0.8), (0.0, 0.6, 0.8)], [0, 1, 2],
                            {"rotation": (0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4)),
                             "scale": (4.0, 1.0, 1.0)}))
    doc = unit_triangle().document()
    del doc["scene"]
    write(GOOD, "no-scene-field.gltf", gltf_text(doc))

    # The perpendicular squares under a root node far from the world's origin, as site models
    # are: view factors must not change.
    b = perpendicular_squares()
    b.doc["nodes"].append({"name": "site", "translation": [10000.0, 500.0, -30000.0],
                           "children": list(b.doc["scenes"][0]["nodes"])})
    b.doc["scenes"][0]["nodes"] = [len(b.doc["nodes"]) - 1]
    write_gltf(GOOD, "far-from-origin.gltf", b)


# ----------------------------------------------------------------------------- bad files

def write_bad():
    def base():
        return unit_triangle().document()

    text = gltf_text(base())
    write(BAD, "malformed.gltf", text[:len(text) // 2] + "\n")

    # 64 bytes with a near-miss magic ("GLTF" instead of "glTF").
    write(BAD, "not-gltf.glb", b"GLTF" + struct.pack("<II", 2, 64) + bytes(range(52)))

    tri = unit_triangle()
    glb = glb_bytes(tri.document(uri=None), tri.padded_data())
    write(BAD, "truncated.glb", glb[:len(glb) // 2])

    doc = unit_triangle().document(uri="does-not-exist.bin")
    write(BAD, "missing-buffer.gltf", gltf_text(doc))

    # The data URI holds only half of the bytes that byteLength (and the views) claim.
    tri = unit_triangle()
    doc = tri.document()
    half = tri.padded_data()[:len(tri.padded_data()) // 2]
    doc["buffers"][0]["uri"] = ("data:application/octet-stream;base64,"
                                + base64.b64encode(half).decode("ascii"))
    write(BAD, "short-buffer.gltf", gltf_text(doc))

    doc = base()
    doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]]["count"] = 1000
    write(BAD, "accessor-out-of-range.gltf", gltf_text(doc))

    b = normals_mesh("tri", UNIT_TRI, [(0.0, 0.0, 1.0)], [0, 1, 2])
    write_gltf(BAD, "normal-count.gltf", b)
    b = normals_mesh("tri", UNIT_TRI, [(0.0, 0.0, 1.0), (float("nan"), 0.0, 1.0), (0.0, 0.0, 1.0)], [0, 1, 2])
    write_gltf(BAD, "normal-not-finite.gltf", b)

    write(BAD, "index-out-of-range.gltf", gltf_text(unit_triangle(indices=(0, 1, 7)).document()))

    nan_tri = [(0.0, 0.0, 0.0), (1.0, float("nan"), 0.0), (0.0, 1.0, 0.0)]
    write(BAD, "nan-position.gltf", gltf_text(unit_triangle(positions=nan_tri).document()))
    inf_tri = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, float("inf"), 0.0)]
    write(BAD, "inf-position.gltf", gltf_text(unit_triangle(positions=inf_tri).document()))

    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    b.add_node("a", mesh, children=[1])
    b.add_node("b", children=[0])
    b.add_scene("scene", [0])
    write_gltf(BAD, "node-cycle.gltf", b)

    write_gltf(BAD, "no-triangles.gltf", single_primitive("dots", UNIT_TRI, None, POINTS))

    doc = base()
    del doc["scenes"][0]["nodes"]  # schema-valid, but nothing to render
    write(BAD, "empty-scene.gltf", gltf_text(doc))

    # Each scale is a finite JSON number; their product, the child's world transform, is not.
    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    b.add_node("outer", children=[1], scale=(1e200, 1e200, 1e200))
    b.add_node("inner", mesh, scale=(1e200, 1e200, 1e200))
    b.add_scene("scene", [0])
    write_gltf(BAD, "nan-transform.gltf", b)

    doc = base()
    doc["nodes"][0]["mesh"] = 5
    write(BAD, "bad-mesh-index.gltf", gltf_text(doc))

    # A NORMAL attribute keeps `attributes` non-empty (schema: minProperties 1).
    b = GltfBuilder()
    normals = b.add_view(struct.pack("<9f", *(0, 0, 1) * 3), ARRAY_BUFFER)
    prim = {"attributes": {"NORMAL": b.add_accessor(normals, FLOAT, 3, "VEC3")},
            "indices": b.add_indices([0, 1, 2]), "material": b.grey()}
    b.add_scene("scene", [b.add_node("tri", b.add_mesh("tri", [prim]))])
    write_gltf(BAD, "missing-position.gltf", b)

    b = unit_triangle()
    b.use_extension("KHR_draco_mesh_compression", required=True)
    write_gltf(BAD, "required-extension.gltf", b)

    b = GltfBuilder()
    view = b.add_view(struct.pack("<9I", 0, 0, 0, 1, 0, 0, 0, 1, 0), ARRAY_BUFFER)
    pos = b.add_accessor(view, UNSIGNED_INT, 3, "VEC3", [0, 0, 0], [1, 1, 0])
    prim = {"attributes": {"POSITION": pos}, "indices": b.add_indices([0, 1, 2]),
            "material": b.grey()}
    b.add_scene("scene", [b.add_node("tri", b.add_mesh("tri", [prim]))])
    write_gltf(BAD, "bad-component-type.gltf", b)

    # External URIs that would read outside the scene's directory.
    write(BAD, "absolute-uri.gltf", gltf_text(unit_triangle().document(uri="/etc/passwd")))
    write(BAD, "parent-uri.gltf", gltf_text(unit_triangle().document(uri="../gltf/external-buffer.bin")))
    write(BAD, "scheme-uri.gltf", gltf_text(unit_triangle().document(uri="http://example.com/buffer.bin")))
    doc = base()
    doc["images"] = [{"uri": "..%2F..%2Fsecret.png"}]  # percent-encoded ".."
    write(BAD, "encoded-parent-image-uri.gltf", gltf_text(doc))

    # Wrong JSON types where the schema wants numbers and arrays.
    doc = base()
    doc["accessors"][0]["count"] = "three"
    write(BAD, "wrong-type-count.gltf", gltf_text(doc))
    doc = base()
    doc["nodes"][0]["children"] = {"0": 1}
    write(BAD, "wrong-type-children.gltf", gltf_text(doc))

    # A chain of 2000 nodes, each the child of the one before: deeper than any real scene.
    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    depth = 2000
    for k in range(depth):
        b.add_node("n%d" % k, mesh if k == depth - 1 else None,
                   children=[k + 1] if k + 1 < depth else None)
    b.add_scene("scene", [0])
    write_gltf(BAD, "absurd-depth.gltf", b)

    # An accessor that claims four billion vertices.
    doc = base()
    doc["accessors"][0]["count"] = 4000000000
    write(BAD, "absurd-count.gltf", gltf_text(doc))

    doc = base()
    doc["materials"][0]["emissiveFactor"] = [-1.0, 0.0, 0.0]
    write(BAD, "negative-emission.gltf", gltf_text(doc))
    # 1e999 is valid JSON but no finite double.
    text = gltf_text(base()).replace('"baseColorFactor": [', '"baseColorFactor": [1e999, ', 1)
    text = text.replace('1e999, 0.5, 0.5, 0.5, 1.0', '1e999, 0.5, 0.5, 1.0')
    write(BAD, "infinite-factor.gltf", text)

    # What the schema says about every object, checked everywhere.
    doc = base()
    doc["asset"]["version"] = "1.0"
    write(BAD, "gltf-1-version.gltf", gltf_text(doc))
    doc = base()
    del doc["asset"]
    write(BAD, "no-asset.gltf", gltf_text(doc))
    doc = base()
    doc["nodes"][0]["name"] = 5
    write(BAD, "name-not-string.gltf", gltf_text(doc))
    doc = base()
    doc["materials"][0]["extensions"] = ["KHR_materials_ior"]
    write(BAD, "extensions-not-object.gltf", gltf_text(doc))
    text = gltf_text(base()).replace('"mesh": 0', '"mesh": 0.5', 1)
    write(BAD, "fractional-index.gltf", text)
    doc = base()
    doc["meshes"][0]["primitives"][0]["material"] = -1
    write(BAD, "negative-index.gltf", gltf_text(doc))

    # Lights (KHR_lights_punctual).
    def lit(light, node_light=0):
        doc = base()
        doc["extensionsUsed"] = ["KHR_lights_punctual"]
        doc["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        doc["nodes"].append({"name": "lamp", "translation": [0.0, 0.0, 1.0],
                             "extensions": {"KHR_lights_punctual": {"light": node_light}}})
        doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
        return gltf_text(doc)
    write(BAD, "light-negative-intensity.gltf", lit({"type": "point", "intensity": -1.0}))
    write(BAD, "light-bad-colour.gltf", lit({"type": "point", "color": [1.0, 1.0]}))
    write(BAD, "light-missing.gltf", lit({"type": "point"}, node_light=3))
    write(BAD, "light-without-type.gltf", lit({"intensity": 1.0}))
    write(BAD, "spot-cone-order.gltf",
          lit({"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.3}}))
    write(BAD, "spot-without-cone.gltf", lit({"type": "spot"}))

    # Materials, textures and samplers.
    doc = base()
    doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = "1"
    write(BAD, "metallic-not-number.gltf", gltf_text(doc))
    doc = base()
    doc["extensionsUsed"] = ["KHR_materials_ior"]
    doc["materials"][0]["extensions"] = {"KHR_materials_ior": {"ior": 0.5}}
    write(BAD, "ior-below-one.gltf", gltf_text(doc))
    doc = base()
    doc["materials"][0]["alphaMode"] = "CUTOUT"
    write(BAD, "bad-alpha-mode.gltf", gltf_text(doc))
    doc = base()
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 3}
    write(BAD, "texture-out-of-range.gltf", gltf_text(doc))
    doc = base()
    doc["images"] = [{"uri": "texture.png"}]
    doc["samplers"] = [{"wrapS": 1234}]
    doc["textures"] = [{"source": 0, "sampler": 0}]
    write(BAD, "bad-sampler-wrap.gltf", gltf_text(doc))

# ----------------------------------------------------------------------------- experiment scenes

def rect(axis, level, span_u, span_v, direction):
    """The rectangle axis = level, span_u x span_v over the other two axes (in x, y, z order),
    wound to face `direction`."""
    u, v = [k for k in range(3) if k != axis]
    quad = []
    for a, b in ((span_u[0], span_v[0]), (span_u[1], span_v[0]), (span_u[1], span_v[1]),
                 (span_u[0], span_v[1])):
        p = [0.0, 0.0, 0.0]
        p[axis], p[u], p[v] = float(level), float(a), float(b)
        quad.append(tuple(p))
    return facing(quad, direction)


def inward_box(lo, hi):
    """The six faces of the box [lo, hi], facing into it: (name, quad)."""
    centre = tuple(0.5 * (lo[k] + hi[k]) for k in range(3))
    faces = []
    for axis, names in ((0, ("left", "right")), (1, ("floor", "ceiling")), (2, ("back", "front"))):
        u, v = [k for k in range(3) if k != axis]
        for level, name in zip((lo[axis], hi[axis]), names):
            inward = [0.0, 0.0, 0.0]
            inward[axis] = centre[axis] - level
            faces.append((name, rect(axis, level, (lo[u], hi[u]), (lo[v], hi[v]), inward)))
    return faces


def add_quads(b, name, quads, material):
    positions, indices = quads_to_mesh(quads)
    return b.surface(name, positions, indices, material)


def ceiling_lamp(b, centre, side, level, material):
    """A square lamp of the given side centred at (centre x, level, centre z), facing down."""
    half = 0.5 * side
    quad = rect(1, level, (centre[0] - half, centre[0] + half), (centre[1] - half, centre[1] + half),
                (0.0, -1.0, 0.0))
    return add_quads(b, "lamp", [quad], material)


def small_receiver(side):
    """(b) A unit-square lamp 2 m above a small square receiver of the given side, coaxial:
    the receiver's view factors from the lamp are below a hemicube pixel's when it is small."""
    b = GltfBuilder()
    light, grey = lamp(b), b.grey()
    lo, hi = 0.5 - 0.5 * side, 0.5 + 0.5 * side
    nodes = [add_quads(b, "lamp", [rect(1, 2.0, (0.0, 1.0), (0.0, 1.0), (0.0, -1.0, 0.0))], light),
             add_quads(b, "receiver", [rect(1, 0.0, (lo, hi), (lo, hi), (0.0, 1.0, 0.0))], grey)]
    b.add_scene("small_receiver", nodes)
    return b


def reflective_cube(rho, floor_rho=None):
    """(c) The closed unit cube, every face of reflectance rho, the floor emitting Le = 1: by
    energy balance the area-weighted mean radiosity is E A_floor / ((1 - rho) A) =
    pi / (6 (1 - rho)), whatever the form factors. `floor_rho`: the floor's own reflectance
    (a room of two reflectances; the closed form above is then not its mean)."""
    b = GltfBuilder()
    wall = b.material("wall", (rho, rho, rho))
    f = rho if floor_rho is None else floor_rho
    light = b.material("lamp", (f, f, f), emissive=(1.0, 1.0, 1.0))
    nodes = [add_quads(b, name, [quad], light if name == "floor" else wall)
             for name, quad in inward_box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))]
    b.add_scene("reflective_cube", nodes)
    return b


PARTITION_X = 1.03125  # off the patch grid of the shared floor at most patch sizes


def two_rooms_apart():
    """(d) Two closed rooms 1 mm apart, the left one lit: any light in the right one leaked
    through the 1 mm gap (numerical precision, not meshing: no surface is shared)."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    nodes = []
    for prefix, lo, hi in (("lit", (0.0, 0.0, 0.0), (1.0, 1.0, 1.0)),
                           ("dark", (1.001, 0.0, 0.0), (2.001, 1.0, 1.0))):
        for name, quad in inward_box(lo, hi):
            nodes.append(add_quads(b, prefix + "_" + name, [quad], grey))
    nodes.append(ceiling_lamp(b, (0.5, 0.5), 0.2, 0.999, light))
    b.add_scene("two_rooms_apart", nodes)
    return b


def shared_floor_rooms(thickness):
    """(d) A lit and a dark room under one floor and one ceiling (single surfaces spanning
    both), parted at x = PARTITION_X by a wall `thickness` thick (two single-sided faces), or
    with thickness 0 by one double-sided wall that pierces the floor and ceiling by 0.1 m.
    Floor and ceiling patches that straddle the wall carry light from one room into the other."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    two = b.material("partition", (0.5, 0.5, 0.5), double_sided=True)
    x0, x1 = PARTITION_X, PARTITION_X + thickness
    nodes = [add_quads(b, "floor", [rect(1, 0.0, (0.0, 2.0), (0.0, 1.0), (0.0, 1.0, 0.0))], grey),
             add_quads(b, "ceiling", [rect(1, 1.0, (0.0, 2.0), (0.0, 1.0), (0.0, -1.0, 0.0))], grey)]
    for prefix, xa, xb, end, inward in (("lit", 0.0, x0, 0.0, 1.0), ("dark", x1, 2.0, 2.0, -1.0)):
        nodes.append(add_quads(b, prefix + "_back", [rect(2, 0.0, (xa, xb), (0.0, 1.0), (0.0, 0.0, 1.0))], grey))
        nodes.append(add_quads(b, prefix + "_front", [rect(2, 1.0, (xa, xb), (0.0, 1.0), (0.0, 0.0, -1.0))], grey))
        nodes.append(add_quads(b, prefix + "_end", [rect(0, end, (0.0, 1.0), (0.0, 1.0), (inward, 0.0, 0.0))], grey))
    if thickness > 0.0:
        nodes.append(add_quads(b, "lit_partition", [rect(0, x0, (0.0, 1.0), (0.0, 1.0), (-1.0, 0.0, 0.0))], grey))
        nodes.append(add_quads(b, "dark_partition", [rect(0, x1, (0.0, 1.0), (0.0, 1.0), (1.0, 0.0, 0.0))], grey))
    else:  # front faces the lit room; its back (":back") the dark one
        nodes.append(add_quads(b, "partition", [rect(0, x0, (-0.1, 1.1), (-0.1, 1.1), (-1.0, 0.0, 0.0))], two))
    nodes.append(ceiling_lamp(b, (0.5, 0.5), 0.2, 0.999, light))
    b.add_scene("shared_floor_rooms", nodes)
    return b


def tiny_emitter(side):
    """(e) A square lamp of the given side under the ceiling of a 4 x 3 x 4 m room, its radiance
    0.01 / side^2 so its power stays pi / 100 W. Only the floor reflects (0.5); walls and
    ceiling are black, so the floor's radiosity is direct light alone, which has a closed form."""
    b = GltfBuilder()
    grey = b.grey()
    black = b.material("black", (0.0, 0.0, 0.0))
    light = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), strength=0.01 / (side * side))
    nodes = [add_quads(b, name, [quad], grey if name == "floor" else black)
             for name, quad in inward_box((0.0, 0.0, 0.0), (4.0, 3.0, 4.0))]
    nodes.append(ceiling_lamp(b, (2.0, 2.0), side, 2.999, light))
    b.add_scene("tiny_emitter", nodes)
    return b


def slivers(strips):
    """(f) The facing squares with the bottom square cut into `strips` strips along x, each split
    along its diagonal: 2 x strips triangles of aspect ratio about `strips` to 1."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    positions, indices = [], []
    for i in range(strips + 1):
        x = i / strips
        positions.extend([(x, 0.0, 0.0), (x, 0.0, 1.0)])
    for i in range(strips):
        a, c = 2 * i, 2 * i + 2  # (x_i, 0), (x_i+1, 0); +1: z = 1
        for tri in ((a, a + 1, c + 1), (a, c + 1, c)):
            normal = cross(sub(positions[tri[1]], positions[tri[0]]), sub(positions[tri[2]], positions[tri[0]]))
            if normal[1] < 0.0:
                tri = (tri[0], tri[2], tri[1])
            indices.extend(tri)
    nodes = [b.surface("bottom", positions, indices, grey),
             add_quads(b, "top", [rect(1, 1.0, (0.0, 1.0), (0.0, 1.0), (0.0, -1.0, 0.0))], light)]
    b.add_scene("slivers", nodes)
    return b


SMALL_RECEIVER_SIDES = (0.3, 0.1, 0.03, 0.01, 0.003)
REFLECTANCES = (0.5, 0.9, 0.99, 0.999)
TINY_EMITTER_SIDES = (0.3, 0.1, 0.03, 0.01, 0.003)
SLIVER_STRIPS = (1, 10, 100, 1000)


def grey_plane(b, half, name="plane"):
    """The square [-half, half]^2 in x and z at y = 0, facing up, grey."""
    return add_quads(b, name, [rect(1, 0.0, (-half, half), (-half, half), (0.0, 1.0, 0.0))], b.grey())


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


def open_box():
    """The unit box [0, 1]^3 without its ceiling, facing in, grey: under a uniform sky of
    radiance L the floor's mean irradiance is pi L F(floor -> opening), parallel unit squares
    1 m apart (F = 0.1998)."""
    b = GltfBuilder()
    nodes = [add_quads(b, name, [quad], b.grey()) for name, quad in inward_box((0, 0, 0), (1, 1, 1))
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


def write_lights():
    write_gltf(LIGHTS, "point-over-plane.gltf", point_over_plane())
    write_gltf(LIGHTS, "spot-over-plane.gltf", spot_over_plane())
    write_gltf(LIGHTS, "directional-occluder.gltf", directional_occluder())
    write_gltf(LIGHTS, "open-box.gltf", open_box())
    write_gltf(LIGHTS, "point-in-cube.gltf", point_in_cube())
    write_gltf(LIGHTS, "many-lights.gltf", many_lights(64))


def png_bytes(width, height, rgba):
    """An 8-bit RGBA PNG of the given texels (rows from the top, 4 bytes per texel)."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    rows = b"".join(b"\0" + bytes(rgba[4 * width * y:4 * width * (y + 1)]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def add_png_texture(b, name, width, height, rgba, sampler=None, embed="uri"):
    """An image (a data URI, or a bufferView for .glb), a sampler and a texture; the texture's index."""
    data = png_bytes(width, height, rgba)
    image = {"name": name, "mimeType": "image/png"}
    if embed == "uri":
        image["uri"] = "data:image/png;base64," + base64.b64encode(data).decode("ascii")
    else:
        image["bufferView"] = b.add_view(data)
    b.doc.setdefault("images", []).append(image)
    texture = {"source": len(b.doc["images"]) - 1}
    if sampler is not None:
        b.doc.setdefault("samplers", []).append(sampler)
        texture["sampler"] = len(b.doc["samplers"]) - 1
    b.doc.setdefault("textures", []).append(texture)
    return len(b.doc["textures"]) - 1


def textured_quad(b, name, quad, uv, material):
    """One quad (two triangles) with TEXCOORD_0."""
    positions = [tuple(p) for p in quad]
    view = b.add_view(b"".join(struct.pack("<2f", *t) for t in uv), ARRAY_BUFFER)
    texcoord = b.add_accessor(view, FLOAT, len(uv), "VEC2")
    prim = {"attributes": {"POSITION": b.add_positions(positions), "TEXCOORD_0": texcoord},
            "indices": b.add_indices([0, 1, 2, 0, 2, 3]), "material": material}
    return b.add_node(name, b.add_mesh(name, [prim]))


def textured_material(b, name, base_texture=None, emissive_texture=None, emissive=None, base=(1.0, 1.0, 1.0)):
    mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [base[0], base[1], base[2], 1.0],
                                                  "metallicFactor": 0.0}}
    if base_texture is not None:
        mat["pbrMetallicRoughness"]["baseColorTexture"] = {"index": base_texture}
    if emissive is not None:
        mat["emissiveFactor"] = list(emissive)
    if emissive_texture is not None:
        mat["emissiveTexture"] = {"index": emissive_texture}
    b.doc["materials"].append(mat)
    return len(b.doc["materials"]) - 1


UNIT_FLOOR = [(0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (1.0, 0.0, 1.0), (1.0, 0.0, 0.0)]  # facing +Y
UNIT_FLOOR_UV = [(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]


def uniform_texture(embed="uri"):
    """A unit floor whose base colour texture is 4 x 4 texels of sRGB 128 (linear 0.2158605),
    factor (1, 0.5, 0.25): reflectance (0.2158605, 0.1079303, 0.0539651) wherever it is read."""
    b = GltfBuilder()
    texture = add_png_texture(b, "grey128", 4, 4, [128, 128, 128, 255] * 16, embed=embed)
    material = textured_material(b, "textured", base_texture=texture, base=(1.0, 0.5, 0.25))
    b.add_scene("uniform_texture", [textured_quad(b, "floor", UNIT_FLOOR, UNIT_FLOOR_UV, material)])
    return b


def checker_floor():
    """A unit floor under a 2 x 2 black-and-white checker (sRGB 0 and 255), nearest filtering,
    repeated 4 times across (UV 0..4): mean reflectance 0.5 over the floor. A lamp 1 m above
    (Le = 30, 0.2 x 0.2 m, facing down) and an orthographic camera looking straight down."""
    b = GltfBuilder()
    checker = [0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255]
    texture = add_png_texture(b, "checker", 2, 2, checker,
                              sampler={"magFilter": 9728, "minFilter": 9728, "wrapS": 10497, "wrapT": 10497})
    material = textured_material(b, "checker", base_texture=texture)
    uv = [(4.0 * u, 4.0 * v) for u, v in UNIT_FLOOR_UV]
    floor = textured_quad(b, "floor", UNIT_FLOOR, uv, material)
    bright = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), strength=30.0)
    lamp_node = add_quads(b, "lamp", [rect(1, 1.0, (0.4, 0.6), (0.4, 0.6), (0.0, -1.0, 0.0))], bright)
    b.doc["cameras"].append({"name": "plan", "type": "orthographic",
                             "orthographic": {"xmag": 0.5, "ymag": 0.5, "znear": 0.01, "zfar": 10.0}})
    camera = b.add_node("plan", camera=0, translation=(0.5, 0.9, 0.5),
                        rotation=rotation_to((0.0, -1.0, 0.0)))
    b.add_scene("checker_floor", [floor, lamp_node, camera])
    return b


def half_lit_lamp():
    """A unit lamp (facing down, 1 m above a unit floor) with emissiveFactor 1 and an emissive
    texture of one black and one white texel side by side, nearest, clamped: half of it emits,
    so it emits pi x 0.5 W."""
    b = GltfBuilder()
    texture = add_png_texture(b, "half", 2, 1, [0, 0, 0, 255, 255, 255, 255, 255],
                              sampler={"magFilter": 9728, "wrapS": 33071, "wrapT": 33071})
    material = textured_material(b, "half_lamp", emissive_texture=texture, emissive=(1.0, 1.0, 1.0),
                                 base=(0.0, 0.0, 0.0))
    lamp_quad = [(0.0, 1.0, 0.0), (1.0, 1.0, 0.0), (1.0, 1.0, 1.0), (0.0, 1.0, 1.0)]  # facing -Y
    lamp_node = textured_quad(b, "lamp", lamp_quad, UNIT_FLOOR_UV, material)
    floor = add_quads(b, "floor", [rect(1, 0.0, (0.0, 1.0), (0.0, 1.0), (0.0, 1.0, 0.0))], b.grey())
    b.add_scene("half_lit_lamp", [lamp_node, floor])
    return b


def masked_quad(texture=True):
    """A unit grey floor at y = 0 under a unit quad at y = 0.5 (facing up, baseColor 0.2,
    alphaMode MASK, cutoff 0.5) and a directional light straight down (683 lux: E = 1 W/m^2). With `texture`, the
    quad's base colour texture is one opaque and one clear texel side by side (nearest,
    clamped) across x: the floor's half x > 0.5 is lit, 0.5 W in all. Without, its
    baseColorFactor alpha is 0.3: all of the quad is clear, 1 W arrives."""
    b = GltfBuilder()
    mat = {"name": "masked", "alphaMode": "MASK", "alphaCutoff": 0.5,
           "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.2, 0.2, 1.0 if texture else 0.3],
                                    "metallicFactor": 0.0}}
    if texture:
        index = add_png_texture(b, "half_clear", 2, 1, [255, 255, 255, 255, 255, 255, 255, 0],
                                sampler={"magFilter": 9728, "wrapS": 33071, "wrapT": 33071})
        mat["pbrMetallicRoughness"]["baseColorTexture"] = {"index": index}
    b.doc["materials"].append(mat)
    masked = len(b.doc["materials"]) - 1
    quad = [(0.0, 0.5, 0.0), (0.0, 0.5, 1.0), (1.0, 0.5, 1.0), (1.0, 0.5, 0.0)]  # facing +Y
    screen = textured_quad(b, "screen", quad, UNIT_FLOOR_UV, masked)
    floor = add_quads(b, "floor", [rect(1, 0.0, (0.0, 1.0), (0.0, 1.0), (0.0, 1.0, 0.0))], b.grey())
    light = b.add_light({"name": "sun", "type": "directional", "intensity": LUMENS_PER_WATT})
    b.add_scene("masked_quad", [screen, floor, b.light_node("sun", light, rotation=rotation_to((0.0, -1.0, 0.0)))])
    return b


def write_textures():
    write_gltf(TEXTURES, "uniform-texture.gltf", uniform_texture())
    glb = uniform_texture(embed="view")
    write(TEXTURES, "uniform-texture.glb", glb_bytes(glb.document(uri=None), glb.padded_data()))
    write_gltf(TEXTURES, "checker-floor.gltf", checker_floor())
    write_gltf(TEXTURES, "half-lit-lamp.gltf", half_lit_lamp())
    write_gltf(TEXTURES, "masked-quad.gltf", masked_quad())
    write_gltf(TEXTURES, "clear-quad.gltf", masked_quad(texture=False))


def exr_bytes(width, height, channels):
    """An uncompressed scanline OpenEXR image of 32-bit float channels: `channels` maps a
    channel name to its width * height values, rows from the top."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    names = sorted(channels)
    chlist = b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for n in names) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (attribute("channels", "chlist", chlist) + attribute("compression", "compression", b"\0")
              + attribute("dataWindow", "box2i", box) + attribute("displayWindow", "box2i", box)
              + attribute("lineOrder", "lineOrder", b"\0")
              + attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
              + attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    start = b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + header
    line_bytes = 4 * width * len(names)
    table_end = len(start) + 8 * height
    offsets = b"".join(struct.pack("<Q", table_end + y * (8 + line_bytes)) for y in range(height))
    lines = b"".join(struct.pack("<ii", y, line_bytes)
                     + b"".join(struct.pack("<%df" % width, *channels[n][y * width:(y + 1) * width])
                                for n in names)
                     for y in range(height))
    return start + offsets + lines


def rgb_exr(width, height, texel):
    """An RGB map whose texel (x, y) is texel(x, y) = (r, g, b)."""
    values = [texel(x, y) for y in range(height) for x in range(width)]
    return exr_bytes(width, height, {c: [v[i] for v in values] for i, c in enumerate("RGB")})


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


def write_environment():
    write(ENVIRONMENT, "uniform.exr", rgb_exr(8, 4, lambda x, y: (1.0, 1.0, 1.0)))
    write(ENVIRONMENT, "sun.exr", rgb_exr(64, 32, sun_and_sky))
    write(ENVIRONMENT, "grey-y.exr", exr_bytes(4, 2, {"Y": [0.5] * 8}))
    b = GltfBuilder()
    b.add_scene("plane", [grey_plane(b, 1.0)])
    write_gltf(ENVIRONMENT, "plane.gltf", b)
    write_gltf(ENVIRONMENT, "facing-quads.gltf", facing_quads())
    # Maps the program must refuse, one problem each.
    write(ENVIRONMENT, "bad-negative.exr", rgb_exr(4, 2, lambda x, y: (1.0, -1.0, 1.0) if x == 1 else (1.0,) * 3))
    write(ENVIRONMENT, "bad-nan.exr", rgb_exr(4, 2, lambda x, y: (float("nan"),) * 3 if y == 1 else (1.0,) * 3))
    write(ENVIRONMENT, "bad-black.exr", rgb_exr(4, 2, lambda x, y: (0.0, 0.0, 0.0)))
    write(ENVIRONMENT, "bad-no-colour.exr", exr_bytes(4, 2, {"Z": [1.0] * 8}))
    write(ENVIRONMENT, "bad-luminance-chroma.exr", exr_bytes(4, 2, {"Y": [1.0] * 8, "RY": [0.0] * 8, "BY": [0.0] * 8}))
    write(ENVIRONMENT, "bad-not-exr.exr", "this is not an OpenEXR image\n")
    sun = rgb_exr(64, 32, sun_and_sky)
    write(ENVIRONMENT, "bad-truncated.exr", sun[:len(sun) // 2])


def icosphere(radius, subdivisions, outward=True):
    """A sphere of triangles: an icosahedron split `subdivisions` times, its vertices on the
    sphere; counter-clockwise seen from outside when `outward`, else from inside."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = tuple((points[a][k] + points[b][k]) / 2.0 for k in range(3))
                length = math.sqrt(sum(x * x for x in m))
                points.append(tuple(x / length for x in m))
                middle[key] = len(points) - 1
            return middle[key]
        faces = [f for a, b, c in faces
                 for f in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                           (mid(a, b), mid(b, c), mid(c, a)))]
    positions = [tuple(round(radius * x, 9) for x in p) for p in points]
    indices = [i for f in faces for i in (f if outward else (f[0], f[2], f[1]))]
    return positions, indices


def concentric_spheres():
    """A sphere of radius 0.5 facing out inside one of radius 1 facing in, both tessellated
    alike (1,280 triangles each). The inner one is convex: it sees only the outer one
    (F_12 = 1), whatever the tessellation, so the closed form of the net heat holds with the
    tessellated areas."""
    b = GltfBuilder()
    nodes = []
    for name, radius, outward in (("inner", 0.5, True), ("outer", 1.0, False)):
        positions, indices = icosphere(radius, 3, outward)
        nodes.append(b.add_node(name, mesh=b.triangle_mesh(name, positions, indices, b.grey())))
    b.add_scene("concentric_spheres", nodes)
    return b


def write_thermal():
    write_gltf(THERMAL, "concentric-spheres.gltf", concentric_spheres())
    write(THERMAL, "spheres.csv", "surface,emissivity,temperature\ninner,0.8,400\nouter,0.5,300\n")
    write(THERMAL, "spheres-reradiating.csv", "surface,emissivity,temperature,heat_flux\ninner,0.8,400,\n"
          "outer,0.5,,0\n")


def write_bench():
    for side in SMALL_RECEIVER_SIDES:
        write_gltf(BENCH, "small-receiver-%g.gltf" % side, small_receiver(side))
    for rho in REFLECTANCES:
        write_gltf(BENCH, "reflective-cube-%g.gltf" % rho, reflective_cube(rho))
    for rho in (0.5, 0.9, 0.99):  # the white furnace near rho = 1 (bench/furnace)
        write_gltf(BENCH, "white-furnace-%g.gltf" % rho, closed_cube(furnace=True, rho=rho))
    write_gltf(BENCH, "two-rooms-apart.gltf", two_rooms_apart())
    write_gltf(BENCH, "thin-wall.gltf", shared_floor_rooms(0.001))
    write_gltf(BENCH, "pierced-floor.gltf", shared_floor_rooms(0.0))
    for side in TINY_EMITTER_SIDES:
        write_gltf(BENCH, "tiny-emitter-%g.gltf" % side, tiny_emitter(side))
    for strips in SLIVER_STRIPS:
        write_gltf(BENCH, "slivers-%d.gltf" % strips, slivers(strips))


# ----------------------------------------------------------------------------- specular

def specular_material(b, name, base, metallic=0.0, transmission=None, ior=None, thickness=None):
    """A smooth (roughness 0) metal or dielectric: a mirror with metallic 1, glass with
    transmission 1 (KHR_materials_transmission, _ior, and _volume where thickness is given)."""
    mat = {"name": name,
           "pbrMetallicRoughness": {"baseColorFactor": [base[0], base[1], base[2], 1.0],
                                    "metallicFactor": metallic, "roughnessFactor": 0.0}}
    extensions = {}
    if transmission is not None:
        extensions["KHR_materials_transmission"] = {"transmissionFactor": transmission}
        b.use_extension("KHR_materials_transmission")
    if ior is not None:
        extensions["KHR_materials_ior"] = {"ior": ior}
        b.use_extension("KHR_materials_ior")
    if thickness is not None:
        extensions["KHR_materials_volume"] = {"thicknessFactor": thickness}
        b.use_extension("KHR_materials_volume")
    if extensions:
        mat["extensions"] = extensions
    b.doc["materials"].append(mat)
    return len(b.doc["materials"]) - 1


def box_quads(lo, hi):
    """The six faces of an axis-aligned box, facing out."""
    middle = tuple(0.5 * (a + c) for a, c in zip(lo, hi))
    quads = []
    for axis in range(3):
        for level in (lo[axis], hi[axis]):
            u, v = [k for k in range(3) if k != axis]
            quad = []
            for a, c in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis] = level
                p[u] = (lo[u], hi[u])[a]
                p[v] = (lo[v], hi[v])[c]
                quad.append(tuple(p))
            direction = [0.0, 0.0, 0.0]
            direction[axis] = 1.0 if level > middle[axis] else -1.0
            quads.append(facing(quad, direction))
    return quads


def uv_sphere(centre, radius, rings=16, segments=32):
    """A closed sphere of triangles facing out, with radial NORMALs (smooth)."""
    positions, normals, indices = [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2.0 * math.pi * j / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            normals.append(n)
            positions.append(tuple(c + radius * k for c, k in zip(centre, n)))
    for i in range(rings):
        for j in range(segments):
            a, b2 = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            tris = [(a, b2, a + 1), (a + 1, b2, b2 + 1)]
            for t in tris:
                p = [positions[k] for k in t]
                if i == 0 and t == tris[0]:
                    continue  # degenerate at the pole
                if i == rings - 1 and t == tris[1]:
                    continue
                outward = sub(centroid(p), centre)
                if dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), outward) < 0.0:
                    t = (t[0], t[2], t[1])
                indices.extend(t)
    return positions, normals, indices


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


def write_specular():
    write_gltf(SPECULAR, "mirror-facing-lamp.gltf", mirror_facing_lamp())
    write_gltf(SPECULAR, "glass-slab.gltf", glass_slab_before_lamp())
    write_gltf(SPECULAR, "glass-slab-tilted.gltf", glass_tilted_before_lamp())
    write_gltf(SPECULAR, "thin-pane.gltf", thin_pane_before_lamp())
    write_gltf(SPECULAR, "mirror-over-lamp.gltf", mirror_over_lamp())
    write_gltf(SPECULAR, "pane-between-squares.gltf", pane_between_squares())
    write_gltf(SPECULAR, "furnace-with-spheres.gltf", furnace_with_spheres())
    write_gltf(SPECULAR, "lamp-through-pane.gltf", lamp_through_pane())
    write_gltf(SPECULAR, "window-box.gltf", window_box())
    write_gltf(SPECULAR, "point-under-pane.gltf", point_under_pane())
    write_gltf(SPECULAR, "point-over-mirror.gltf", point_over_specular_floor("mirror"))
    write_gltf(SPECULAR, "point-over-pane.gltf", point_over_specular_floor("pane"))
    write_gltf(SPECULAR, "point-over-rough-metal.gltf", point_over_rough_metal())
    write_gltf(SPECULAR, "lamp-over-rough-metal.gltf", lamp_over_rough_metal())


def main():
    write_gltf(SCENES, "cornell-box.gltf", cornell_box())
    write_gltf(SCENES, "facing-squares.gltf", facing_squares())
    write_gltf(SCENES, "perpendicular-squares.gltf", perpendicular_squares())
    write_gltf(SCENES, "coaxial-disks.gltf", coaxial_disks())
    write_gltf(SCENES, "closed-cube.gltf", closed_cube())
    write_gltf(SCENES, "cornell-box-point-light.gltf", cornell_box_point_light())
    write_gltf(SCENES, "cornell-box-specular.gltf", cornell_box_specular())
    write_gltf(SOLVE, "white-furnace.gltf", closed_cube(furnace=True))
    # Near rho = 1: overshooting and the power per ray (solver/amplification.h).
    write_gltf(SOLVE, "white-furnace-0.99.gltf", closed_cube(furnace=True, rho=0.99))
    write_gltf(SOLVE, "reflective-cube-0.95.gltf", reflective_cube(0.95))
    write_gltf(SOLVE, "two-reflectance-cube.gltf", reflective_cube(0.98, floor_rho=0.5))
    write_gltf(SOLVE, "occluder.gltf", occluder_scene())
    # The same furnace at 1e-30 and 1e30 times the light: only the units may change.
    write_gltf(SOLVE, "faint-furnace.gltf", closed_cube(furnace=True, strength=1e-30))
    write_gltf(SOLVE, "bright-furnace.gltf", closed_cube(furnace=True, strength=1e30))
    write_good()
    write_bad()
    write_lights()
    write_textures()
    write_environment()
    write_thermal()
    write_bench()
    write_specular()


if __name__ == "__main__":
    main()
