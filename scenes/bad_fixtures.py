"""Deliberately broken inputs the program must refuse with a clear error: the invalid glTF files
of tests/data/bad/ (the valid one-triangle file of loader_scenes.py with exactly one thing
broken) and the invalid environment maps tests/data/environment/bad-*.exr."""

import base64
import os
import struct

from environment_scenes import sun_and_sky
from gltf_encoder import (ARRAY_BUFFER, FLOAT, POINTS, UNSIGNED_INT, GltfBuilder, glb_bytes, gltf_text, write,
                          write_gltf)
from image_encoders import exr_bytes, rgb_exr
from loader_scenes import UNIT_TRI, normals_mesh, single_primitive, unit_triangle


def write_bad_gltf(root):
    """tests/data/bad/ under `root`: invalid glTF files, one problem each (tests/data/bad/README.md)."""
    directory = os.path.join(root, "tests", "data", "bad")

    def base():
        return unit_triangle().document()

    text = gltf_text(base())
    write(directory, "malformed.gltf", text[:len(text) // 2] + "\n")

    # The valid file with 1,000 nested arrays in its extras: deeper than any glTF needs.
    doc = base()
    doc["extras"] = "NEST"
    write(directory, "deep-nesting.gltf", gltf_text(doc).replace('"NEST"', "[" * 1000 + "]" * 1000))

    # 64 bytes with a near-miss magic ("GLTF" instead of "glTF").
    write(directory, "not-gltf.glb", b"GLTF" + struct.pack("<II", 2, 64) + bytes(range(52)))

    tri = unit_triangle()
    glb = glb_bytes(tri.document(uri=None), tri.padded_data())
    write(directory, "truncated.glb", glb[:len(glb) // 2])

    doc = unit_triangle().document(uri="does-not-exist.bin")
    write(directory, "missing-buffer.gltf", gltf_text(doc))

    # The data URI holds only half of the bytes that byteLength (and the views) claim.
    tri = unit_triangle()
    doc = tri.document()
    half = tri.padded_data()[:len(tri.padded_data()) // 2]
    doc["buffers"][0]["uri"] = ("data:application/octet-stream;base64,"
                                + base64.b64encode(half).decode("ascii"))
    write(directory, "short-buffer.gltf", gltf_text(doc))

    doc = base()
    doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]]["count"] = 1000
    write(directory, "accessor-out-of-range.gltf", gltf_text(doc))

    b = normals_mesh("tri", UNIT_TRI, [(0.0, 0.0, 1.0)], [0, 1, 2])
    write_gltf(directory, "normal-count.gltf", b)
    b = normals_mesh("tri", UNIT_TRI, [(0.0, 0.0, 1.0), (float("nan"), 0.0, 1.0), (0.0, 0.0, 1.0)], [0, 1, 2])
    write_gltf(directory, "normal-not-finite.gltf", b)

    write(directory, "index-out-of-range.gltf", gltf_text(unit_triangle(indices=(0, 1, 7)).document()))

    nan_tri = [(0.0, 0.0, 0.0), (1.0, float("nan"), 0.0), (0.0, 1.0, 0.0)]
    write(directory, "nan-position.gltf", gltf_text(unit_triangle(positions=nan_tri).document()))
    inf_tri = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, float("inf"), 0.0)]
    write(directory, "inf-position.gltf", gltf_text(unit_triangle(positions=inf_tri).document()))

    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    b.add_node("a", mesh, children=[1])
    b.add_node("b", children=[0])
    b.add_scene("scene", [0])
    write_gltf(directory, "node-cycle.gltf", b)

    write_gltf(directory, "no-triangles.gltf", single_primitive("dots", UNIT_TRI, None, POINTS))

    doc = base()
    del doc["scenes"][0]["nodes"]  # schema-valid, but nothing to render
    write(directory, "empty-scene.gltf", gltf_text(doc))

    # Each scale is a finite JSON number; their product, the child's world transform, is not.
    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    b.add_node("outer", children=[1], scale=(1e200, 1e200, 1e200))
    b.add_node("inner", mesh, scale=(1e200, 1e200, 1e200))
    b.add_scene("scene", [0])
    write_gltf(directory, "nan-transform.gltf", b)

    doc = base()
    doc["nodes"][0]["mesh"] = 5
    write(directory, "bad-mesh-index.gltf", gltf_text(doc))

    # A NORMAL attribute keeps `attributes` non-empty (schema: minProperties 1).
    b = GltfBuilder()
    normals = b.add_view(struct.pack("<9f", *(0, 0, 1) * 3), ARRAY_BUFFER)
    prim = {"attributes": {"NORMAL": b.add_accessor(normals, FLOAT, 3, "VEC3")},
            "indices": b.add_indices([0, 1, 2]), "material": b.grey()}
    b.add_scene("scene", [b.add_node("tri", b.add_mesh("tri", [prim]))])
    write_gltf(directory, "missing-position.gltf", b)

    b = unit_triangle()
    b.use_extension("KHR_texture_basisu", required=True)
    write_gltf(directory, "required-extension.gltf", b)

    b = GltfBuilder()
    view = b.add_view(struct.pack("<9I", 0, 0, 0, 1, 0, 0, 0, 1, 0), ARRAY_BUFFER)
    pos = b.add_accessor(view, UNSIGNED_INT, 3, "VEC3", [0, 0, 0], [1, 1, 0])
    prim = {"attributes": {"POSITION": pos}, "indices": b.add_indices([0, 1, 2]),
            "material": b.grey()}
    b.add_scene("scene", [b.add_node("tri", b.add_mesh("tri", [prim]))])
    write_gltf(directory, "bad-component-type.gltf", b)

    # External URIs that would read outside the scene's directory.
    write(directory, "absolute-uri.gltf", gltf_text(unit_triangle().document(uri="/etc/passwd")))
    write(directory, "parent-uri.gltf", gltf_text(unit_triangle().document(uri="../gltf/external-buffer.bin")))
    write(directory, "scheme-uri.gltf", gltf_text(unit_triangle().document(uri="http://example.com/buffer.bin")))
    doc = base()
    doc["images"] = [{"uri": "..%2F..%2Fsecret.png"}]  # percent-encoded ".."
    write(directory, "encoded-parent-image-uri.gltf", gltf_text(doc))

    # Wrong JSON types where the schema wants numbers and arrays.
    doc = base()
    doc["accessors"][0]["count"] = "three"
    write(directory, "wrong-type-count.gltf", gltf_text(doc))
    doc = base()
    doc["nodes"][0]["children"] = {"0": 1}
    write(directory, "wrong-type-children.gltf", gltf_text(doc))

    # A chain of 2000 nodes, each the child of the one before: deeper than any real scene.
    b = GltfBuilder()
    mesh = b.triangle_mesh("tri", UNIT_TRI, [0, 1, 2], b.grey())
    depth = 2000
    for k in range(depth):
        b.add_node("n%d" % k, mesh if k == depth - 1 else None,
                   children=[k + 1] if k + 1 < depth else None)
    b.add_scene("scene", [0])
    write_gltf(directory, "absurd-depth.gltf", b)

    # An accessor that claims four billion vertices.
    doc = base()
    doc["accessors"][0]["count"] = 4000000000
    write(directory, "absurd-count.gltf", gltf_text(doc))

    doc = base()
    doc["materials"][0]["emissiveFactor"] = [-1.0, 0.0, 0.0]
    write(directory, "negative-emission.gltf", gltf_text(doc))
    # 1e999 is valid JSON but no finite double.
    text = gltf_text(base()).replace('"baseColorFactor": [', '"baseColorFactor": [1e999, ', 1)
    text = text.replace('1e999, 0.5, 0.5, 0.5, 1.0', '1e999, 0.5, 0.5, 1.0')
    write(directory, "infinite-factor.gltf", text)

    # What the schema says about every object, checked everywhere.
    doc = base()
    doc["asset"]["version"] = "1.0"
    write(directory, "gltf-1-version.gltf", gltf_text(doc))
    doc = base()
    del doc["asset"]
    write(directory, "no-asset.gltf", gltf_text(doc))
    doc = base()
    doc["nodes"][0]["name"] = 5
    write(directory, "name-not-string.gltf", gltf_text(doc))
    doc = base()
    doc["materials"][0]["extensions"] = ["KHR_materials_ior"]
    write(directory, "extensions-not-object.gltf", gltf_text(doc))
    text = gltf_text(base()).replace('"mesh": 0', '"mesh": 0.5', 1)
    write(directory, "fractional-index.gltf", text)
    doc = base()
    doc["meshes"][0]["primitives"][0]["material"] = -1
    write(directory, "negative-index.gltf", gltf_text(doc))

    # Lights (KHR_lights_punctual).
    def lit(light, node_light=0):
        doc = base()
        doc["extensionsUsed"] = ["KHR_lights_punctual"]
        doc["extensions"] = {"KHR_lights_punctual": {"lights": [light]}}
        doc["nodes"].append({"name": "lamp", "translation": [0.0, 0.0, 1.0],
                             "extensions": {"KHR_lights_punctual": {"light": node_light}}})
        doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
        return gltf_text(doc)
    write(directory, "light-negative-intensity.gltf", lit({"type": "point", "intensity": -1.0}))
    write(directory, "light-bad-colour.gltf", lit({"type": "point", "color": [1.0, 1.0]}))
    write(directory, "light-missing.gltf", lit({"type": "point"}, node_light=3))
    write(directory, "light-without-type.gltf", lit({"intensity": 1.0}))
    write(directory, "spot-cone-order.gltf",
          lit({"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.3}}))
    write(directory, "spot-without-cone.gltf", lit({"type": "spot"}))

    # Materials, textures and samplers.
    doc = base()
    doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = "1"
    write(directory, "metallic-not-number.gltf", gltf_text(doc))
    doc = base()
    doc["extensionsUsed"] = ["KHR_materials_ior"]
    doc["materials"][0]["extensions"] = {"KHR_materials_ior": {"ior": 0.5}}
    write(directory, "ior-below-one.gltf", gltf_text(doc))
    doc = base()
    doc["materials"][0]["alphaMode"] = "CUTOUT"
    write(directory, "bad-alpha-mode.gltf", gltf_text(doc))
    doc = base()
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 3}
    write(directory, "texture-out-of-range.gltf", gltf_text(doc))
    doc = base()
    doc["extensionsUsed"] = ["KHR_materials_specular"]
    doc["materials"][0]["extensions"] = {"KHR_materials_specular": {"specularTexture": {"index": 0, "extensions": []}}}
    write(directory, "extension-texture-extensions-array.gltf", gltf_text(doc))
    doc = base()
    doc["images"] = [{"uri": "texture.png"}]
    doc["samplers"] = [{"wrapS": 1234}]
    doc["textures"] = [{"source": 0, "sampler": 0}]
    write(directory, "bad-sampler-wrap.gltf", gltf_text(doc))


def write_bad_environment_maps(root):
    """The bad-*.exr maps in tests/data/environment/ under `root`: maps the program must refuse,
    one problem each."""
    directory = os.path.join(root, "tests", "data", "environment")
    write(directory, "bad-negative.exr", rgb_exr(4, 2, lambda x, y: (1.0, -1.0, 1.0) if x == 1 else (1.0,) * 3))
    write(directory, "bad-nan.exr", rgb_exr(4, 2, lambda x, y: (float("nan"),) * 3 if y == 1 else (1.0,) * 3))
    write(directory, "bad-black.exr", rgb_exr(4, 2, lambda x, y: (0.0, 0.0, 0.0)))
    write(directory, "bad-no-colour.exr", exr_bytes(4, 2, {"Z": [1.0] * 8}))
    write(directory, "bad-luminance-chroma.exr", exr_bytes(4, 2, {"Y": [1.0] * 8, "RY": [0.0] * 8, "BY": [0.0] * 8}))
    write(directory, "bad-not-exr.exr", "this is not an OpenEXR image\n")
    sun = rgb_exr(64, 32, sun_and_sky)
    write(directory, "bad-truncated.exr", sun[:len(sun) // 2])
