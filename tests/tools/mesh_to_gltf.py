#!/usr/bin/env python3
"""Converts STL, PLY and OBJ (with its MTL) files into one glTF, independently of the program's
readers, so that tests can hold the program's reading of other projects' files to the same
geometry read from glTF. Each STL or PLY file is one node named after the file; each OBJ object
or group is one node (a group named again adds to it). Polygons are split as fans from their
first corner; coordinates are parsed as doubles and stored as the nearest float. MTL `Kd` and
`Ke` become the base colour and emitted colour; STL and PLY get glTF's default material.

Usage: mesh_to_gltf.py OUTPUT.gltf INPUT [INPUT ...]   (writes OUTPUT.bin beside it)"""
import json, os, struct, sys


def stl(path):
    data = open(path, "rb").read()
    if len(data) >= 84:
        count, = struct.unpack_from("<I", data, 80)
        ascii = data.lstrip().startswith(b"solid") and b"facet" in data[:1024]
        if len(data) == 84 + 50 * count or (not ascii and len(data) > 84 + 50 * count):
            points = [struct.unpack_from("<9f", data, 84 + 50 * k + 12) for k in range(count)]
            return [[tuple(t[0:3]), tuple(t[3:6]), tuple(t[6:9])] for t in points]
    triangles, corners = [], []
    for line in data.decode("ascii", "replace").splitlines():
        words = line.split()
        if words[:1] == ["vertex"]:
            corners.append(tuple(float(w) for w in words[1:4]))
        elif words[:1] == ["endloop"]:
            triangles.append(corners)
            corners = []
    return triangles


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h", "ushort": "H",
             "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}


def ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    elements, fmt = [], None
    for line in data[:end].decode("ascii", "replace").splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            elements[-1][2].append(words[1:])
    if fmt == "ascii":
        tokens = iter(data[end:].split())
        def take(kind):
            word = next(tokens)
            return float(word) if kind in "fd" else int(word)
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        at = [end]
        def take(kind):
            value, = struct.unpack_from(order + kind, data, at[0])
            at[0] += struct.calcsize(kind)
            return value
    vertices, triangles = [], []
    for name, count, properties in elements:
        for _ in range(count):
            row = {}
            for p in properties:
                if p[0] == "list":
                    n = take(PLY_TYPES[p[1]])
                    row[p[3]] = [take(PLY_TYPES[p[2]]) for _ in range(n)]
                else:
                    row[p[1]] = take(PLY_TYPES[p[0]])
            if name == "vertex":
                vertices.append((row["x"], row["y"], row["z"]))
            elif name == "face":
                corners = row.get("vertex_indices", row.get("vertex_index"))
                if any(not 0 <= c < len(vertices) for c in corners):
                    sys.exit("%s: a face names a vertex out of range" % path)
                for k in range(1, len(corners) - 1):
                    triangles.append([vertices[corners[0]], vertices[corners[k]], vertices[corners[k + 1]]])
    return triangles


def obj(path):
    """[(surface name, material name, triangles)] in the order surfaces first appear."""
    positions, surfaces, order, materials = [], {}, [], {}
    current, material = None, None
    folder = os.path.dirname(path)
    for line in open(path, encoding="utf-8", errors="replace"):
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            positions.append(tuple(float(w) for w in words[1:4]))
        elif words[0] in ("g", "o"):
            current = " ".join(words[1:]) or "default"
        elif words[0] == "usemtl":
            material = " ".join(words[1:])
        elif words[0] == "mtllib":
            materials.update(mtl(os.path.join(folder, " ".join(words[1:]))))
        elif words[0] == "f":
            name = current or os.path.splitext(os.path.basename(path))[0]
            if name not in surfaces:
                surfaces[name] = []
                order.append(name)
            corners = []
            for w in words[1:]:
                k = int(w.split("/")[0])
                if k == 0 or abs(k) > len(positions):
                    sys.exit("%s: a face names vertex %d of %d" % (path, k, len(positions)))
                corners.append(positions[k - 1] if k > 0 else positions[k])
            for k in range(1, len(corners) - 1):
                surfaces[name].append((material, [corners[0], corners[k], corners[k + 1]]))
    return [(name, surfaces[name], materials) for name in order]


def mtl(path):
    out, current = {}, None
    for line in open(path, encoding="utf-8", errors="replace"):
        words = line.split()
        if words[:1] == ["newmtl"]:
            current = " ".join(words[1:])
            out[current] = {}
        elif current and words[:1] in (["Kd"], ["Ke"]):
            values = [float(w) for w in words[1:4]]
            values = values * 3 if len(values) == 1 else values  # "Kd 0.5" is grey
            out[current][words[0]] = [min(1.0, max(0.0, v)) if words[0] == "Kd" else v for v in values]
    return out


def main():
    target, sources = sys.argv[1], sys.argv[2:]
    gltf = {"asset": {"version": "2.0", "generator": "tests/tools/mesh_to_gltf.py"}, "scene": 0,
            "extensionsUsed": ["KHR_materials_specular"],
            "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [], "accessors": [],
            "bufferViews": []}
    blob = bytearray()
    material_index = {}

    def material(name, spec):
        if name not in material_index:
            m = {"name": name or "default"}
            if spec:
                m["pbrMetallicRoughness"] = {"baseColorFactor": spec.get("Kd", [0.8, 0.8, 0.8]) + [1.0], "metallicFactor": 0.0}
                # an MTL's Kd is Lambertian: no glTF specular layer
                m["extensions"] = {"KHR_materials_specular": {"specularFactor": 0.0}}
                if "Ke" in spec and any(spec["Ke"]):
                    m["emissiveFactor"] = spec["Ke"]
            material_index[name] = len(gltf["materials"])
            gltf["materials"].append(m)
        return material_index[name]

    def view(payload):
        while len(blob) % 4:
            blob.append(0)
        gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(payload)})
        blob.extend(payload)
        return len(gltf["bufferViews"]) - 1

    def primitive(triangles, material_id):
        corners = [c for t in triangles for c in t]
        floats = struct.pack("<%df" % (3 * len(corners)), *[x for c in corners for x in c])
        stored = [struct.unpack_from("<3f", floats, 12 * k) for k in range(len(corners))]
        gltf["accessors"].append({"bufferView": view(floats), "componentType": 5126, "count": len(corners),
                                  "type": "VEC3", "min": [min(c[i] for c in stored) for i in range(3)],
                                  "max": [max(c[i] for c in stored) for i in range(3)]})
        positions = len(gltf["accessors"]) - 1
        gltf["accessors"].append({"bufferView": view(struct.pack("<%dI" % len(corners), *range(len(corners)))),
                                  "componentType": 5125, "count": len(corners), "type": "SCALAR"})
        p = {"attributes": {"POSITION": positions}, "indices": len(gltf["accessors"]) - 1}
        if material_id is not None:
            p["material"] = material_id
        return p

    def node(name, primitives):
        gltf["meshes"].append({"name": name, "primitives": primitives})
        gltf["nodes"].append({"name": name, "mesh": len(gltf["meshes"]) - 1})
        gltf["scenes"][0]["nodes"].append(len(gltf["nodes"]) - 1)

    for source in sources:
        stem, ext = os.path.splitext(os.path.basename(source))
        if ext.lower() == ".stl":
            node(stem, [primitive(stl(source), None)])
        elif ext.lower() == ".ply":
            node(stem, [primitive(ply(source), None)])
        else:
            for name, faces, materials in obj(source):
                runs = []  # consecutive faces of one material: one primitive each, in file order
                for m, t in faces:
                    if not runs or runs[-1][0] != m:
                        runs.append((m, []))
                    runs[-1][1].append(t)
                node(name, [primitive(t, material(m, materials.get(m, {}))) for m, t in runs])
    if not gltf["materials"]:
        del gltf["materials"]
    gltf["buffers"] = [{"byteLength": len(blob), "uri": os.path.splitext(os.path.basename(target))[0] + ".bin"}]
    open(os.path.splitext(target)[0] + ".bin", "wb").write(blob)
    json.dump(gltf, open(target, "w"), indent=1)


main()
