"""Small valid files for the glTF loader's tests (tests/data/gltf/): node transforms, strips and
fans, double-sided materials, points and lines, external buffers, .glb, quantized positions,
degenerate triangles, and smooth and hard normals. The one-triangle file here is also what the
bad fixtures (bad_fixtures.py) break."""

import math
import os
import struct

from bundled_scenes import perpendicular_squares
from geometry import quads_to_mesh, square
from gltf_encoder import (ARRAY_BUFFER, LINES, POINTS, SHORT, TRIANGLE_FAN, TRIANGLE_STRIP, TRIANGLES,
                          GltfBuilder, glb_bytes, gltf_text, write, write_gltf)

# Unit right triangle in the z = 0 plane, counter-clockwise seen from +Z (normal +Z).
UNIT_TRI = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


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


def morph_targets():
    """The unit triangle with two morph targets: the first lifts every corner by (0, 0, 1), the
    second moves corner 1 by (1, 0, 0); the mesh's default weights are (0.5, 0), so the file's
    default pose is the triangle at z = 0.5."""
    b = unit_triangle("morphed")
    view = b.add_view(b"".join(struct.pack("<3f", 0.0, 0.0, 1.0) for _ in range(3)), ARRAY_BUFFER)
    lift = b.add_accessor(view, 5126, 3, "VEC3", (0.0, 0.0, 1.0), (0.0, 0.0, 1.0))
    view = b.add_view(b"".join(struct.pack("<3f", *d) for d in ((0, 0, 0), (1, 0, 0), (0, 0, 0))), ARRAY_BUFFER)
    stretch = b.add_accessor(view, 5126, 3, "VEC3", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    mesh = b.doc["meshes"][0]
    mesh["primitives"][0]["targets"] = [{"POSITION": lift}, {"POSITION": stretch}]
    mesh["weights"] = [0.5, 0.0]
    return b


def instanced():
    """The unit triangle drawn three times by EXT_mesh_gpu_instancing (required, as
    glTF-Transform writes it): as it is, moved by (2, 0, 0) and doubled, and moved by (0, 3, 0)
    and turned a quarter about z; all under a node moved by (0, 0, 1)."""
    b = unit_triangle("instanced", translation=(0.0, 0.0, 1.0))
    moves = [(0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.0, 3.0, 0.0)]
    scales = [(1.0, 1.0, 1.0), (2.0, 2.0, 2.0), (1.0, 1.0, 1.0)]
    h = math.sqrt(0.5)
    turns = [(0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 1.0), (0.0, 0.0, h, h)]
    attributes = {}
    for name, values, kind, width in (("TRANSLATION", moves, "VEC3", 3), ("SCALE", scales, "VEC3", 3),
                                      ("ROTATION", turns, "VEC4", 4)):
        view = b.add_view(b"".join(struct.pack("<%df" % width, *v) for v in values))
        attributes[name] = b.add_accessor(view, 5126, len(values), kind)
    b.doc["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": attributes}}
    b.use_extension("EXT_mesh_gpu_instancing", required=True)
    return b


def skinned():
    """The unit triangle under a skin of two joints, in the file's pose: joint "root" moved by
    (0, 0, 2) (inverse bind matrix: a move by (0, 0, -1)), its child "arm" turned a quarter about
    z (inverse bind matrix: the identity). Corner 0 follows the root alone, corner 1 the arm alone,
    corner 2 both by half (weights of a second set, JOINTS_1 / WEIGHTS_1, each half of it). The
    skinned node's own move by (100, 0, 0) is ignored, as glTF says: the corners land at
    (0, 0, 1), (0, 1, 2) and (-0.5, 0.5, 1.5)."""
    b = unit_triangle("skinned", translation=(100.0, 0.0, 0.0))
    h = math.sqrt(0.5)
    arm = b.add_node("arm", rotation=(0.0, 0.0, h, h))
    root = b.add_node("root", children=[arm], translation=(0.0, 0.0, 2.0))
    b.doc["scenes"][0]["nodes"].append(root)
    matrices = [(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1), (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)]
    view = b.add_view(b"".join(struct.pack("<16f", *m) for m in matrices))
    inverse_bind = b.add_accessor(view, 5126, 2, "MAT4")
    b.doc["skins"] = [{"name": "two joints", "joints": [root, arm], "inverseBindMatrices": inverse_bind}]
    b.doc["nodes"][0]["skin"] = 0
    attributes = b.doc["meshes"][0]["primitives"][0]["attributes"]
    sets = [([(0, 0, 0, 0), (1, 0, 0, 0), (0, 0, 0, 0)], [(1, 0, 0, 0), (1, 0, 0, 0), (0.5, 0, 0, 0)]),
            ([(0, 0, 0, 0), (0, 0, 0, 0), (1, 0, 0, 0)], [(0, 0, 0, 0), (0, 0, 0, 0), (0.5, 0, 0, 0)])]
    for k, (joints, weights) in enumerate(sets):
        view = b.add_view(b"".join(struct.pack("<4B", *j) for j in joints), ARRAY_BUFFER)
        attributes["JOINTS_%d" % k] = b.add_accessor(view, 5121, 3, "VEC4")
        view = b.add_view(b"".join(struct.pack("<4f", *w) for w in weights), ARRAY_BUFFER)
        attributes["WEIGHTS_%d" % k] = b.add_accessor(view, 5126, 3, "VEC4")
    return b


def write_loader_scenes(root):
    """tests/data/gltf/ under `root`: valid files for the loader's tests."""
    directory = os.path.join(root, "tests", "data", "gltf")
    write_gltf(directory, "transforms.gltf", transforms())
    t = transforms()
    write(directory, "transforms.glb", glb_bytes(t.document(uri=None), t.padded_data()))
    write_gltf(directory, "strip.gltf",
               single_primitive("strip", STRIP_VERTICES, [0, 1, 2, 3, 4], TRIANGLE_STRIP))
    write_gltf(directory, "fan.gltf", single_primitive("fan", FAN_VERTICES, None, TRIANGLE_FAN))
    write_gltf(directory, "double-sided.gltf", double_sided())
    write_gltf(directory, "points-lines.gltf", points_lines())
    ext = unit_triangle()
    write(directory, "external-buffer.gltf", gltf_text(ext.document(uri="external-buffer.bin")))
    write(directory, "external-buffer.bin", ext.padded_data())
    write_gltf(directory, "emissive-strength.gltf", emissive_strength())
    write_gltf(directory, "mirrored.gltf", unit_triangle("mirrored", scale=(-1.0, 1.0, 1.0)))
    write_gltf(directory, "degenerate.gltf", degenerate())
    write_gltf(directory, "quantized.gltf", quantized())
    write_gltf(directory, "morph-targets.gltf", morph_targets())
    write_gltf(directory, "instanced.gltf", instanced())
    write_gltf(directory, "skinned.gltf", skinned())
    write_gltf(directory, "prism-smooth.gltf", prism())
    write_gltf(directory, "prism-flat.gltf", prism(smooth=False))
    write_gltf(directory, "fold-10-split.gltf", fold(10.0, shared_normals=False))
    write_gltf(directory, "fold-90-shared.gltf", fold(90.0, shared_normals=True))
    write_gltf(directory, "fold-45-shared.gltf", fold(45.0, shared_normals=True))
    # Normals under a node that turns about z by 90 degrees and stretches x by 4: they follow the
    # inverse transpose (a triangle in the x-y plane keeps facing +z).
    write_gltf(directory, "normals-transformed.gltf",
               normals_mesh("tilted", UNIT_TRI, [(0.0, 0.0, 1.0), (0.6, 0.0, 0.8), (0.0, 0.6, 0.8)], [0, 1, 2],
                            {"rotation": (0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4)),
                             "scale": (4.0, 1.0, 1.0)}))
    doc = unit_triangle().document(matte=False)  # the loader tests' base: glTF's own defaults
    del doc["scene"]
    write(directory, "no-scene-field.gltf", gltf_text(doc))

    # The perpendicular squares under a root node far from the world's origin, as site models
    # are: view factors must not change.
    b = perpendicular_squares()
    b.doc["nodes"].append({"name": "site", "translation": [10000.0, 500.0, -30000.0],
                           "children": list(b.doc["scenes"][0]["nodes"])})
    b.doc["scenes"][0]["nodes"] = [len(b.doc["nodes"]) - 1]
    write_gltf(directory, "far-from-origin.gltf", b)
