#!/usr/bin/env python3
"""Writes an uncompressed glTF's geometry as a plain glTF with its positions quantized the way
Draco quantizes them: per primitive, onto a grid of 2^bits - 1 steps across the largest extent of
its bounding box, from the box's minimum corner. Triangles and node transforms are kept; normals,
texture coordinates and textures are left out (view factors need none of them).

Usage: quantize_gltf.py INPUT.glb|INPUT.gltf BITS OUTPUT.gltf   (writes OUTPUT.bin beside it)"""
import array, copy, json, math, os, struct, sys

source, bits, target = sys.argv[1], int(sys.argv[2]), sys.argv[3]
data = open(source, "rb").read()
if data[:4] == b"glTF":
    json_length, = struct.unpack_from("<I", data, 12)
    gltf = json.loads(data[20:20 + json_length])
    at = 20 + json_length
    bin_length, = struct.unpack_from("<I", data, at)
    buffers = [data[at + 8:at + 8 + bin_length]]
else:
    gltf = json.loads(data)
    buffers = [open(os.path.join(os.path.dirname(source), b["uri"]), "rb").read() for b in gltf["buffers"]]

COMPONENTS = {"SCALAR": 1, "VEC3": 3}
FORMATS = {5121: "B", 5123: "H", 5125: "I", 5126: "f"}  # little-endian, as glTF stores them


def read(index):
    """An accessor's values as a flat list (tuples of `n` for vectors)."""
    a = gltf["accessors"][index]
    view = gltf["bufferViews"][a["bufferView"]]
    n, code = COMPONENTS[a["type"]], FORMATS[a["componentType"]]
    size = struct.calcsize("<" + code)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    stride = view.get("byteStride", 0) or n * size
    raw = buffers[view["buffer"]]
    rows = [struct.unpack_from("<%d%s" % (n, code), raw, start + k * stride) for k in range(a["count"])]
    return rows if n > 1 else [r[0] for r in rows]


out = copy.deepcopy(gltf)
blob, views, accessors = bytearray(), [], []


def write(values, vector):
    """Float VEC3 positions or uint32 indices, appended to the one buffer."""
    while len(blob) % 4:
        blob.append(0)
    flat = array.array("f" if vector else "I", [c for v in values for c in v] if vector else values)
    if sys.byteorder != "little":
        flat.byteswap()
    views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(flat) * flat.itemsize})
    blob.extend(flat.tobytes())
    a = {"bufferView": len(views) - 1, "componentType": 5126 if vector else 5125, "count": len(values),
         "type": "VEC3" if vector else "SCALAR"}
    if vector:
        stored = [tuple(flat[3 * k:3 * k + 3]) for k in range(len(values))]
        a["min"] = [min(v[c] for v in stored) for c in range(3)]
        a["max"] = [max(v[c] for v in stored) for c in range(3)]
    accessors.append(a)
    return len(accessors) - 1


steps = (1 << bits) - 1
for m, mesh in enumerate(gltf["meshes"]):
    for p, primitive in enumerate(mesh["primitives"]):
        positions = read(primitive["attributes"]["POSITION"])
        low = [min(v[c] for v in positions) for c in range(3)]
        extent = max(max(v[c] for v in positions) - low[c] for c in range(3))
        if extent > 0:
            step = extent / steps
            positions = [tuple(low[c] + math.floor((v[c] - low[c]) / step + 0.5) * step for c in range(3))
                         for v in positions]
        indices = read(primitive["indices"]) if "indices" in primitive else list(range(len(positions)))
        q = out["meshes"][m]["primitives"][p]
        q["attributes"] = {"POSITION": write(positions, True)}
        q["indices"] = write(indices, False)
        q.pop("extensions", None)
        q.pop("targets", None)
out["accessors"], out["bufferViews"] = accessors, views
out["buffers"] = [{"byteLength": len(blob), "uri": os.path.splitext(os.path.basename(target))[0] + ".bin"}]
for key in ("images", "textures", "samplers", "extensionsRequired", "extensionsUsed", "skins", "animations"):
    out.pop(key, None)
for node in out.get("nodes", []):
    node.pop("skin", None)
for material in out.get("materials", []):
    for key in [k for k in material if k.endswith("Texture")]:
        material.pop(key)
    for key in [k for k in material.get("pbrMetallicRoughness", {}) if k.endswith("Texture")]:
        material["pbrMetallicRoughness"].pop(key)
    material.pop("extensions", None)
open(os.path.splitext(target)[0] + ".bin", "wb").write(blob)
json.dump(out, open(target, "w"))
