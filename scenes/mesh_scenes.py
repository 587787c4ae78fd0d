"""One small room in every mesh format the program reads (tests/data/meshes/), with the same
float32 coordinates and triangles in each, and broken OBJ, STL and PLY files (tests/data/bad/).

The room: a floor, a panel tilted towards it and a lamp over both, at coordinates that are not
round numbers (turned by 17 degrees about Y), so that reading them differently shows in the bits.
Text formats write each coordinate with 9 significant digits (a float32 reads back exactly);
the OBJ writes the lamp's corners with 17, as a double, to check that they round to the same
float32 the glTF file holds."""

import math
import os
import struct

from gltf_encoder import GltfBuilder, f32, write, write_gltf
from image_encoders import png_bytes

ANGLE = math.radians(17.0)


def turned(x, y, z):
    c, s = math.cos(ANGLE), math.sin(ANGLE)
    return (c * x + s * z + 0.137, y + 0.021, -s * x + c * z - 0.311)


# Quads, counter-clockwise seen from their front; each splits as a fan from its first corner.
QUADS = {
    "floor": [turned(0, 0, 0), turned(0, 0, 1.3), turned(1.1, 0, 1.3), turned(1.1, 0, 0)],
    "panel": [turned(0.05, 0.1, 0.2), turned(0.9, 0.1, 0.2), turned(0.9, 0.8, 0.05), turned(0.05, 0.8, 0.05)],
    "lamp": [turned(0.3, 1.2, 0.4), turned(0.8, 1.2, 0.4), turned(0.8, 1.2, 0.9), turned(0.3, 1.2, 0.9)],
}
KD = {"floor": (0.7, 0.7, 0.7), "panel": (0.6, 0.3, 0.2), "lamp": (0.0, 0.0, 0.0)}
KE = {"lamp": (4.0, 4.0, 4.0)}
FAN = [(0, 1, 2), (0, 2, 3)]


def exact(point):
    return tuple(f32(c) for c in point)


def nine(x):
    return "%.9g" % f32(x)


def normal(quad):
    """The quad's unit normal, a little tilted (so that it is not a round number either)."""
    a, b, c = quad[0], quad[1], quad[2]
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1] + 0.1, u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n))
    return tuple(f32(x / length) for x in n)


def room_gltf(with_materials):
    """With materials, the vertices carry normals too (room.obj's vn)."""
    b = GltfBuilder()
    nodes = []
    for name, quad in QUADS.items():
        positions = [exact(p) for p in quad]
        indices = [i for t in FAN for i in t]
        if with_materials:
            material = b.material(name, KD[name], KE.get(name))
        else:
            material = None
        primitive = b.primitive(positions, indices, material)
        if material is None:
            del primitive["material"]
        else:
            primitive["attributes"]["NORMAL"] = b.add_normals([normal(quad)] * 4)
        nodes.append(b.add_node(name, b.add_mesh(name, [primitive])))
    b.add_scene("room", nodes)
    return b


def room_obj():
    lines = ["# the room of room.gltf: objects floor, panel, lamp", "mtllib room.mtl"]
    base = 0
    for name, quad in QUADS.items():
        lines.append("o " + name)
        for p in quad:
            if name == "lamp":  # as doubles: they must round to the glTF file's float32 values
                lines.append("v %.17g %.17g %.17g" % p)
            else:
                lines.append("v " + " ".join(nine(c) for c in p))
        lines.append("vn " + " ".join(nine(c) for c in normal(quad)))
        lines.append("usemtl " + name)
        n = base // 4 + 1
        if name == "panel":  # as two triangles, with relative (negative) indices
            lines.append("f -4//-1 -3//-1 -2//-1")
            lines.append("f -4//-1 -2//-1 -1//-1")
        else:
            lines.append("f %d//%d %d//%d %d//%d %d//%d" % (base + 1, n, base + 2, n, base + 3, n, base + 4, n))
        base += 4
    mtl = ["# materials of room.obj"]
    for name in QUADS:
        mtl.append("newmtl " + name)
        mtl.append("Kd %g %g %g" % KD[name])
        if name in KE:
            mtl.append("Ke %g %g %g" % KE[name])
    return "\n".join(lines) + "\n", "\n".join(mtl) + "\n"


def ascii_stl(name, quad):
    out = ["solid " + name]
    for t in FAN:
        out.append("  facet normal 0 0 0")  # not read: the winding says the front
        out.append("    outer loop")
        for i in t:
            out.append("      vertex " + " ".join(nine(c) for c in quad[i]))
        out.append("    endloop")
        out.append("  endfacet")
    out.append("endsolid " + name)
    return "\n".join(out) + "\n"


def binary_stl(quad):
    header = b"solid but binary: an 80-byte header may begin with 'solid'".ljust(80, b" ")
    body = b""
    for t in FAN:
        body += struct.pack("<3f", 0.0, 0.0, 0.0)
        for i in t:
            body += struct.pack("<3f", *quad[i])
        body += struct.pack("<H", 0)
    return header + struct.pack("<I", len(FAN)) + body


def ascii_ply(quad):
    head = ["ply", "format ascii 1.0", "comment the floor of room.gltf, one quad", "element vertex 4",
            "property float x", "property float y", "property float z", "element face 1",
            "property list uchar int vertex_indices", "end_header"]
    rows = [" ".join(nine(c) for c in p) for p in quad] + ["4 0 1 2 3"]
    return "\n".join(head + rows) + "\n"


def binary_ply(quad, order):
    """Doubles with an extra property, faces with an int count and a per-face property, and an
    element of its own after them: what the reader must read past."""
    fmt = "binary_little_endian" if order == "<" else "binary_big_endian"
    head = ["ply", "format %s 1.0" % fmt, "element vertex 4", "property double x", "property float confidence",
            "property double y", "property double z", "element face 2", "property uchar flags",
            "property list int uint vertex_indices", "element edge 1", "property int vertex1",
            "property int vertex2", "end_header"]
    body = b""
    for p in quad:
        body += struct.pack(order + "dfdd", p[0], 0.5, p[1], p[2])
    for t in FAN:
        body += struct.pack(order + "Bi3I", 7, 3, *t)
    body += struct.pack(order + "ii", 0, 1)
    return ("\n".join(head) + "\n").encode("ascii") + body


def polygons_obj():
    """Faces of many corners, each its own group facing +z: a disc of 300 corners (more than
    tinyobjloader counts in its byte), a star of 600 (200 pointed, 400 reflex corners) and an
    L-shaped panel of area 3 (a fan from its first corner would cover its notch); and a face of
    two corners."""
    def circle(n, x0, radius):
        return [(x0 + radius(k) * math.cos(2 * math.pi * k / n), radius(k) * math.sin(2 * math.pi * k / n))
                for k in range(n)]
    shapes = [("disc", circle(300, 0.0, lambda k: 1.0)),
              ("star", circle(600, 3.0, lambda k: 1.0 if k % 3 == 0 else 0.5)),
              ("notch", [(6, 1), (5, 1), (5, -1), (7, -1), (7, 0), (6, 0)])]
    lines, first = [], 1
    for name, points in shapes:
        lines += ["v %.6f %.6f 0" % p for p in points]
        lines += ["g " + name, "f " + " ".join(str(first + k) for k in range(len(points)))]
        first += len(points)
    lines.append("f 1 2")  # a face of two corners, which tinyobjloader drops, after the long ones
    return "\n".join(lines) + "\n"


def textured_obj():
    """Unit quads facing +z whose vt are their own x and y: at x in [0, 1], material 'stripes': Kd
    (0.5, 0.6, 0.7) times map_Kd stripes.png, named as a Windows program names it
    (.\\stripes.png), clamped (2 x 2 texels: the top row white, the bottom black; OBJ's v counts
    from the image's bottom, so the quad is white at the top); at [2, 3], 'lost', whose map_Kd
    names no file; at [4, 5], 'leaf', stripes.png cut by map_d mask.png (white on the left,
    black on the right); at [6, 7], 'window', d 0.3."""
    obj = ["mtllib textured.mtl"]
    for x0 in (0.0, 2.0, 4.0, 6.0):
        obj += ["v %g %g 0" % (x0 + x, y) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))]
    obj += ["vt %g %g" % p for p in ((0, 0), (1, 0), (1, 1), (0, 1))]
    obj += ["g stripes", "usemtl stripes", "f 1/1 2/2 3/3 4/4", "g lost", "usemtl lost", "f 5/1 6/2 7/3 8/4",
            "g leaf", "usemtl leaf", "f 9/1 10/2 11/3 12/4", "g window", "usemtl window", "f 13/1 14/2 15/3 16/4"]
    mtl = ["newmtl stripes", "Kd 0.5 0.6 0.7", "map_Kd -clamp on .\\stripes.png",
           "newmtl lost", "Kd 0.3 0.3 0.3", "map_Kd missing.png",
           "newmtl leaf", "Kd 1 1 1", "map_Kd stripes.png", "map_d mask.png",
           "newmtl window", "Kd 1 1 1", "d 0.3"]
    return "\n".join(obj) + "\n", "\n".join(mtl) + "\n"


def blender_obj():
    """Unit quads facing +z whose vt are their own x and y, with the maps Blender's OBJ exporter
    writes for a Principled BSDF: at x in [0, 1], 'blender': map_Ns rough.png (its roughness,
    2 x 1 texels, 64 and 192), map_refl metal.png (its metallic, 1 x 1, 200) and map_Bump -bm 0.7
    tilt.png (a normal map of one texel that leans the normal 30 degrees toward +x); at [2, 3],
    'height', a light grey height map as older tools write bump (200: (2 rgb - 1) a unit vector
    leaning toward +z, but grey); at [4, 5], 'pbr', the PBR extension's Pr 0.4 and map_Pm
    metal.png; at [6, 7], 'wide', map_Pr wide.png, 50,000 x 1 texels (0 to 249 along x)."""
    obj = ["mtllib blender.mtl"]
    for x0 in (0.0, 2.0, 4.0, 6.0):
        obj += ["v %g %g 0" % (x0 + x, y) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1))]
    obj += ["vt %g %g" % p for p in ((0, 0), (1, 0), (1, 1), (0, 1))]
    obj += ["g blender", "usemtl blender", "f 1/1 2/2 3/3 4/4", "g height", "usemtl height", "f 5/1 6/2 7/3 8/4",
            "g pbr", "usemtl pbr", "f 9/1 10/2 11/3 12/4", "g wide", "usemtl wide", "f 13/1 14/2 15/3 16/4"]
    mtl = ["newmtl blender", "Ka 1.000000 1.000000 1.000000", "Kd 0.800000 0.800000 0.800000",
           "Ks 0.500000 0.500000 0.500000", "Ni 1.500000", "d 1.000000", "illum 2", "map_Ns rough.png",
           "map_refl metal.png", "map_Bump -bm 0.700000 tilt.png",
           "newmtl height", "Kd 0.5 0.5 0.5", "bump height.png",
           "newmtl pbr", "Kd 0.5 0.5 0.5", "Pr 0.4", "map_Pm metal.png",
           "newmtl wide", "Kd 0.5 0.5 0.5", "map_Pr wide.png", "map_Pm metal.png"]
    return "\n".join(obj) + "\n", "\n".join(mtl) + "\n"


def textured_ply():
    """The unit quad facing +z as MeshLab writes a textured scan: "comment TextureFile
    stripes.png" and each face's corners' texture coordinates (texcoord, v from the image's
    bottom), the quad's own x and y."""
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
    header = ["ply", "format ascii 1.0", "comment TextureFile stripes.png", "element vertex 4",
              "property float x", "property float y", "property float z", "element face 2",
              "property list uchar int vertex_indices", "property list uchar float texcoord", "end_header"]
    faces = []
    for face in ((0, 1, 2), (0, 2, 3)):
        faces.append("3 %d %d %d 6 " % face + " ".join("%g %g" % corners[k] for k in face))
    return "\n".join(header + ["%g %g 0" % c for c in corners] + faces) + "\n"


def write_mesh_scenes(root):
    """tests/data/meshes/: room.gltf (materials) and room-plain.gltf (no materials), room.obj and
    room.mtl, the three quads as STL (floor, lamp ASCII; panel binary) and as PLY (floor ASCII,
    panel little-endian, lamp big-endian), thermal properties by surface name, polygons.obj
    (polygons_obj) and textured.obj with its MTL and image (textured_obj)."""
    directory = os.path.join(root, "tests", "data", "meshes")
    write_gltf(directory, "room.gltf", room_gltf(True))
    write_gltf(directory, "room-plain.gltf", room_gltf(False))
    obj, mtl = room_obj()
    write(directory, "room.obj", obj)
    write(directory, "room.mtl", mtl)
    quads = {name: [exact(p) for p in quad] for name, quad in QUADS.items()}
    write(directory, "floor.stl", ascii_stl("floor", quads["floor"]))
    write(directory, "panel.stl", binary_stl(quads["panel"]))
    write(directory, "lamp.stl", ascii_stl("lamp", quads["lamp"]))
    write(directory, "floor.ply", ascii_ply(quads["floor"]))
    write(directory, "panel.ply", binary_ply(quads["panel"], "<"))
    write(directory, "lamp.ply", binary_ply(quads["lamp"], ">"))
    write(directory, "polygons.obj", polygons_obj())
    obj, mtl = textured_obj()
    write(directory, "textured.obj", obj)
    write(directory, "textured.mtl", mtl)
    write(directory, "stripes.png", png_bytes(2, 2, [255] * 8 + [0, 0, 0, 255] * 2))
    write(directory, "mask.png", png_bytes(2, 2, [255, 255, 255, 255, 0, 0, 0, 255] * 2))
    write(directory, "textured.ply", textured_ply())
    obj, mtl = blender_obj()
    write(directory, "blender.obj", obj)
    write(directory, "blender.mtl", mtl)
    write(directory, "rough.png", png_bytes(2, 1, [64, 64, 64, 255, 192, 192, 192, 255]))
    write(directory, "metal.png", png_bytes(1, 1, [200, 200, 200, 255]))
    write(directory, "tilt.png", png_bytes(1, 1, [191, 128, 238, 255]))  # (sin 30, 0, cos 30)
    write(directory, "height.png", png_bytes(2, 2, [200, 200, 200, 255] * 4))
    write(directory, "wide.png", png_bytes(50000, 1, [v for x in range(50000) for v in (x // 200, x // 200, x // 200, 255)]))
    write(directory, "room-properties.csv", "surface,emissivity,temperature\nfloor,0.9,300\npanel,0.8,350\nlamp,0.9,500\n")


def write_bad_meshes(root):
    """tests/data/bad/: one problem each, listed in its README."""
    directory = os.path.join(root, "tests", "data", "bad")
    quad = [exact(p) for p in QUADS["floor"]]
    write(directory, "truncated.stl", binary_stl(quad)[:-20])
    write(directory, "bad-number.stl", ascii_stl("floor", quad).replace("vertex ", "vertex x", 1))
    write(directory, "not-stl.stl", "this is not an STL file, neither binary nor ASCII\n")
    write(directory, "no-end-header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n")
    ply = ascii_ply(quad)
    write(directory, "face-out-of-range.ply", ply.replace("4 0 1 2 3", "4 0 1 2 9"))
    write(directory, "short.ply", "\n".join(ply.split("\n")[:-3]) + "\n")
    write(directory, "index-out-of-range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
    write(directory, "only-points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n")
    write(directory, "inf-vertex.ply", ply.replace(nine(quad[1][0]), "inf", 1))
    write(directory, "nan-vertex.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")
    write(directory, "two-vertex-elements.ply", ply.replace("element face 1", "element vertex 1\nproperty float x\n"
                                                            "property float y\nproperty float z\nelement face 1")
          .replace("4 0 1 2 3", "0 0 0\n4 0 1 2 3"))
