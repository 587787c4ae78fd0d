"""Reads the glTF scenes this project generates (scenes/generate.py: embedded base64 buffers,
float32 positions, uint16/uint32 indices, triangle lists, nodes without transforms) and
rebuilds their patches exactly as host/mesh/mesh.cpp and patch_grid.h do, so per-patch
results (viewfactors --level patch, named <surface>#<k>) can be matched with geometry."""

import base64
import json
import math
import struct

import numpy as np

COMPONENT = {5126: ("f", 4), 5123: ("H", 2), 5125: ("I", 4)}
WIDTH = {"SCALAR": 1, "VEC3": 3}


def _accessor(doc, data, index):
    acc = doc["accessors"][index]
    view = doc["bufferViews"][acc["bufferView"]]
    fmt, size = COMPONENT[acc["componentType"]]
    count = acc["count"] * WIDTH[acc["type"]]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    values = struct.unpack_from("<%d%s" % (count, fmt), data, start)
    return np.array(values, dtype=np.float64).reshape(acc["count"], WIDTH[acc["type"]])


def load(path):
    """[{'name', 'triangles': (T x 3 x 3) array, 'material': {...}}] per node with a mesh, in
    the order the loader makes surfaces (scene nodes depth first); 'normals' (T x 3 x 3, each
    corner's NORMAL) too where every primitive of the node has them."""
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    uri = doc["buffers"][0]["uri"]
    data = base64.b64decode(uri.split(",", 1)[1])
    surfaces = []

    def visit(index):
        node = doc["nodes"][index]
        moved = any(k in node for k in ("matrix", "translation", "rotation", "scale"))
        if moved and ("mesh" in node or node.get("children")):  # camera nodes may move
            raise ValueError("%s: node transforms are not supported here" % path)
        if "mesh" in node:
            tris, normals, materials = [], [], []
            for prim in doc["meshes"][node["mesh"]]["primitives"]:
                pos = _accessor(doc, data, prim["attributes"]["POSITION"])
                idx = _accessor(doc, data, prim["indices"]).astype(np.int64).ravel()
                # The loader works in float: positions are float32 already.
                tris.append(pos[idx].reshape(-1, 3, 3))
                if "NORMAL" in prim["attributes"]:
                    normals.append(_accessor(doc, data, prim["attributes"]["NORMAL"])[idx].reshape(-1, 3, 3))
                materials.append(doc["materials"][prim.get("material", 0)])
            surface = {"name": node.get("name", "node%d" % index), "triangles": np.concatenate(tris),
                       "material": materials[0]}
            if len(normals) == len(tris):
                surface["normals"] = np.concatenate(normals)
            surfaces.append(surface)
        for child in node.get("children", []):
            visit(child)

    for root in doc["scenes"][doc.get("scene", 0)]["nodes"]:
        visit(root)
    return surfaces


def subdivision(triangle, patch_size):
    edges = [np.linalg.norm(triangle[(k + 1) % 3] - triangle[k]) for k in range(3)]
    return max(1, int(math.ceil(max(edges) / patch_size)))


def grid_cells(n):
    """(a, b, down) in patch index order (patch_grid.h forEachGridCell)."""
    for b in range(n):
        for a in range(n - b):
            yield a, b, False
            if a + b + 1 < n:
                yield a, b, True


def patches(triangle, n):
    """The n x n patches of a triangle, in index order, each (3 x 3)."""
    v0, e1, e2 = triangle[0], triangle[1] - triangle[0], triangle[2] - triangle[0]

    def point(a, b):
        return v0 + (a / n) * e1 + (b / n) * e2

    out = []
    for a, b, down in grid_cells(n):
        if down:
            out.append(np.array([point(a + 1, b), point(a + 1, b + 1), point(a, b + 1)]))
        else:
            out.append(np.array([point(a, b), point(a + 1, b), point(a, b + 1)]))
    return out


def surface_patches(surface, patch_size):
    """Front-side patches of a surface, in the mesh's order (its faces in turn)."""
    out = []
    for tri in surface["triangles"]:
        out.extend(patches(tri, subdivision(tri, patch_size)))
    return out


def normal(triangle):
    n = np.cross(triangle[1] - triangle[0], triangle[2] - triangle[0])
    return n / np.linalg.norm(n)
