"""The glTF encoding every recipe builds with: GltfBuilder, its document as .gltf text (the
buffer a base64 data URI) or as binary .glb, PNG textures embedded in either, and the file
writer (UTF-8 with LF line ends: the same bytes on every platform)."""

import base64
import json
import math
import os
import struct

from image_encoders import png_bytes

# Every file's asset.generator: changing it changes every generated file.
GENERATOR = "radiosity scenes/generate.py"

# glTF enums
FLOAT, SHORT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5122, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
POINTS, LINES, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 0, 1, 4, 5, 6

GLB_MAGIC, GLB_JSON, GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942

# 683 lm/W: glTF's photometric light units over radiometric ones (as Blender converts them).
LUMENS_PER_WATT = 683.0


def f32(x):
    """Round a Python float to the nearest float32 (what ends up in the buffer)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


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

    def triangle_mesh(self, name, positions, indices, material, index_type=None):
        """index_type None: unsigned short where every index fits, else unsigned int."""
        if index_type is None:
            index_type = UNSIGNED_SHORT if len(positions) <= 65536 else UNSIGNED_INT
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

    def document(self, uri="embed", matte=True):
        """The JSON document. uri: "embed" (base64 data URI), None (GLB), or a file name.

        Every material that does not say otherwise is matte: glTF gives a non-metal a specular
        layer (F0 0.04) by default, and these scenes model Lambertian surfaces (the Cornell box's
        paints, the closed forms' reflectors), so each gets KHR_materials_specular with
        specularFactor 0. A scene that wants the layer writes the extension itself; matte=False
        leaves the materials as they are (glTF's defaults)."""
        for material in (self.doc["materials"] if matte else []):
            extensions = material.setdefault("extensions", {})
            if "KHR_materials_specular" not in extensions:
                extensions["KHR_materials_specular"] = {"specularFactor": 0.0}
                self.use_extension("KHR_materials_specular")
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
