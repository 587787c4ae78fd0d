"""Textured scenes (tests/data/textures/): base colour and emissive textures, samplers, alpha
masks, as .gltf with data URIs and as .glb."""

import os
import struct

from geometry import rect, rotation_to
from gltf_encoder import (ARRAY_BUFFER, FLOAT, LUMENS_PER_WATT, GltfBuilder, add_png_texture, glb_bytes,
                          write, write_gltf)
from scene_parts import add_quads


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


def metal_roughness_floor():
    """A unit floor of base colour (0.9, 0.7, 0.4) under glTF's defaults (metallicFactor and
    roughnessFactor 1, the specular layer) whose metallicRoughnessTexture (2 x 1 texels, nearest,
    clamped; linear) says metal at roughness 128/255 where x < 0.5 (green 128, blue 255) and a
    rough non-metal (green 255, blue 0) where x > 0.5."""
    b = GltfBuilder()
    texture = add_png_texture(b, "metal_roughness", 2, 1, [0, 128, 255, 255, 0, 255, 0, 255],
                              sampler={"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071})
    b.doc["materials"].append({"name": "painted",
                               "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.4, 1.0],
                                                        "metallicRoughnessTexture": {"index": texture}},
                               "extensions": {"KHR_materials_specular": {"specularFactor": 1.0}}})
    b.use_extension("KHR_materials_specular")
    material = len(b.doc["materials"]) - 1
    b.add_scene("metal_roughness_floor", [textured_quad(b, "floor", UNIT_FLOOR, UNIT_FLOOR_UV, material)])
    return b


def specular_texture_floor():
    """A unit floor of base colour (0.9, 0.7, 0.4), metallicFactor 0, roughness 0.5, whose
    KHR_materials_specular (specularFactor 1, specularColorFactor 30: 1.2 times F0(1.5), beyond
    the clamp at 1) has a specularTexture (2 x 1 texels, alpha 0 where x < 0.5, 128 where
    x > 0.5) and a specularColorTexture (1 x 2 texels, sRGB white where z < 0.5, (255, 128, 0)
    where z > 0.5), both nearest and clamped: no layer on the half x < 0.5, a white one and a
    tinted one of half strength on the other half's two quarters."""
    b = GltfBuilder()
    nearest = {"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}
    strength = add_png_texture(b, "specular", 2, 1, [255, 255, 255, 0, 255, 255, 255, 128], sampler=nearest)
    colour = add_png_texture(b, "specular_colour", 1, 2, [255, 255, 255, 255, 255, 128, 0, 255], sampler=nearest)
    b.doc["materials"].append({"name": "painted",
                               "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.4, 1.0],
                                                        "metallicFactor": 0.0, "roughnessFactor": 0.5},
                               "extensions": {"KHR_materials_specular": {
                                   "specularFactor": 1.0, "specularColorFactor": [30.0, 30.0, 30.0],
                                   "specularTexture": {"index": strength},
                                   "specularColorTexture": {"index": colour}}}})
    b.use_extension("KHR_materials_specular")
    material = len(b.doc["materials"]) - 1
    b.add_scene("specular_texture_floor", [textured_quad(b, "floor", UNIT_FLOOR, UNIT_FLOOR_UV, material)])
    return b


def vertex_colour_floor():
    """A unit floor of base colour (0.9, 0.7, 0.4), unlit (plain diffuse: KHR_materials_unlit),
    in two quads with COLOR_0: where z < 0.5, normalized unsigned bytes (VEC4, alpha 255), white
    at x = 0 and black at x = 1, so the base colour is scaled by 1 - x; where z > 0.5, floats
    (VEC3) of (0.2, 0.6, 1.0) at every corner."""
    b = GltfBuilder()
    b.doc["materials"].append({"name": "tinted", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.4, 1.0]},
                               "extensions": {"KHR_materials_unlit": {}}})
    b.use_extension("KHR_materials_unlit")
    material = len(b.doc["materials"]) - 1
    nodes = []
    near = [(0.0, 0.0, 0.0), (0.0, 0.0, 0.5), (1.0, 0.0, 0.5), (1.0, 0.0, 0.0)]  # facing +Y
    grey = [255 if x == 0.0 else 0 for x, _, _ in near]
    view = b.add_view(bytes(v for g in grey for v in (g, g, g, 255)), ARRAY_BUFFER)
    colour = b.add_accessor(view, 5121, 4, "VEC4", normalized=True)
    far = [(0.0, 0.0, 0.5), (0.0, 0.0, 1.0), (1.0, 0.0, 1.0), (1.0, 0.0, 0.5)]
    view = b.add_view(b"".join(struct.pack("<3f", 0.2, 0.6, 1.0) for _ in far), ARRAY_BUFFER)
    blue = b.add_accessor(view, FLOAT, 4, "VEC3")
    for name, quad, accessor in (("gradient", near, colour), ("blue", far, blue)):
        prim = {"attributes": {"POSITION": b.add_positions(quad), "COLOR_0": accessor},
                "indices": b.add_indices([0, 1, 2, 0, 2, 3]), "material": material}
        nodes.append(b.add_node(name, b.add_mesh(name, [prim])))
    b.add_scene("vertex_colour_floor", nodes)
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


# tangent-space (0.498, -0.333, 0.843) before normalising: about 35 degrees off the normal, toward +u
# and down the image (the bitangent's -y)
NORMAL_TILT_TEXEL = (191, 85, 235)
NORMAL_MAP_LIGHT = (0.6, 0.7, 0.4)  # toward the directional light (unnormalised)


def normal_map_floors():
    """Unit floors (facing +Y) side by side under a directional light from NORMAL_MAP_LIGHT (683
    lux: E = 1 W/m^2 across the beam), each under a normal map of one texel NORMAL_TILT_TEXEL
    (linear), which tilts the normal toward +u and down the image (+v, here +z):
      x in [0, 1]: grey 0.5, matte (specularFactor 0), u = x, v = z, tangents generated (+x);
      x in [2, 3]: the same with the file's TANGENT (0, 0, 1, 1): tangent +z, bitangent +x;
      x in [4, 5]: the same with u = 1 - x (tangents generated, now -x);
      x in [6, 7]: the same as the first but normalTexture.scale 0: no tilt at all;
      x in [8, 9]: grey 0.5 under glTF's specular layer at roughness 0.5, u = x;
      x in [10, 11] and [12, 13]: the first and the fifth floor's materials without the map, on
        floors turned so their geometric normals are the mapped normal (about the floor's centre);
      x in [-3, -2]: the first floor's mesh with TANGENT (1, 0, 0, 1) under a node that mirrors x
        (scale -1, 1, 1): in the world its tangent is -x and the bitangent's sign flips;
      x in [20, 21] and [24, 25]: a rough metal (F0 0.9, roughness 0.4) mapped as the first, and
        unmapped on a floor turned as the others (far from the rest: a glossy floor reflects
        their light).
    With nothing else in the scene, each floor's radiance is its BRDF's response to the one light
    about the normal it is shaded by: a mapped floor and a turned one look alike."""
    import math
    b = GltfBuilder()
    texture = add_png_texture(b, "tilt30", 1, 1, list(NORMAL_TILT_TEXEL) + [255],
                              sampler={"magFilter": 9728, "wrapS": 33071, "wrapT": 33071})

    def material(name, layered, mapped, scale=1.0):
        mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0],
                                                      "metallicFactor": 0.0, "roughnessFactor": 0.5}}
        if mapped:
            mat["normalTexture"] = {"index": texture}
            if scale != 1.0:
                mat["normalTexture"]["scale"] = scale
        mat["extensions"] = {"KHR_materials_specular": {"specularFactor": 1.0 if layered else 0.0}}
        b.doc["materials"].append(mat)
        return len(b.doc["materials"]) - 1

    b.use_extension("KHR_materials_specular")
    matte, painted = material("matte", False, True), material("painted", True, True)
    flat, plain = material("matte-unmapped", False, False), material("painted-unmapped", True, False)
    unscaled = material("matte-scale-0", False, True, scale=0.0)
    metals = []
    for name, mapped in (("metal", True), ("metal-unmapped", False)):
        metal = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1.0],
                                                        "metallicFactor": 1.0, "roughnessFactor": 0.4}}
        if mapped:
            metal["normalTexture"] = {"index": texture}
        b.doc["materials"].append(metal)
        metals.append(len(b.doc["materials"]) - 1)

    def floor(x0, uv=UNIT_FLOOR_UV, tangents=None):
        return [(x0 + p[0], p[1], p[2]) for p in UNIT_FLOOR], uv, tangents

    def node(name, quad, uv, mat, tangents=None):
        positions = [tuple(p) for p in quad]
        view = b.add_view(b"".join(struct.pack("<2f", *t) for t in uv), ARRAY_BUFFER)
        attributes = {"POSITION": b.add_positions(positions),
                      "TEXCOORD_0": b.add_accessor(view, FLOAT, len(uv), "VEC2")}
        if tangents is not None:
            tview = b.add_view(b"".join(struct.pack("<4f", *t) for t in tangents), ARRAY_BUFFER)
            attributes["TANGENT"] = b.add_accessor(tview, FLOAT, len(tangents), "VEC4")
        prim = {"attributes": attributes, "indices": b.add_indices([0, 1, 2, 0, 2, 3]), "material": mat}
        return b.add_node(name, b.add_mesh(name, [prim]))

    # the mapped normal in world space (tangent +x, bitangent -z, normal +y) from the texel as read
    c = [2.0 * v / 255.0 - 1.0 for v in NORMAL_TILT_TEXEL]
    length = math.sqrt(sum(v * v for v in c))
    n = (c[0] / length, c[2] / length, -c[1] / length)
    # a unit square about (x0 + 0.5, 0, 0.5) whose normal is n, its corners in the floor's order
    e_x = (n[1], -n[0], 0.0)
    e_x = tuple(v / math.sqrt(sum(w * w for w in e_x)) for v in e_x)
    e_z = (n[1] * e_x[2] - n[2] * e_x[1], n[2] * e_x[0] - n[0] * e_x[2], n[0] * e_x[1] - n[1] * e_x[0])
    e_z = tuple(-v for v in e_z) if e_z[2] < 0.0 else e_z

    def turned(x0):
        centre = (x0 + 0.5, 0.0, 0.5)
        return [tuple(centre[k] + (p[0] - 0.5) * e_x[k] + (p[2] - 0.5) * e_z[k] for k in range(3))
                for p in UNIT_FLOOR]

    mirrored_uv = [(1.0 - u, v) for (u, v) in UNIT_FLOOR_UV]
    nodes = [node("mapped", floor(0.0)[0], UNIT_FLOOR_UV, matte),
             node("mapped-tangents", floor(2.0)[0], UNIT_FLOOR_UV, matte, tangents=[(0.0, 0.0, 1.0, 1.0)] * 4),
             node("mapped-mirrored", floor(4.0)[0], mirrored_uv, matte),
             node("mapped-scale-0", floor(6.0)[0], UNIT_FLOOR_UV, unscaled),
             node("mapped-layered", floor(8.0)[0], UNIT_FLOOR_UV, painted),
             node("turned", turned(10.0), UNIT_FLOOR_UV, flat),
             node("turned-layered", turned(12.0), UNIT_FLOOR_UV, plain),
             node("mapped-metal", floor(20.0)[0], UNIT_FLOOR_UV, metals[0]),
             node("turned-metal", turned(24.0), UNIT_FLOOR_UV, metals[1])]
    mirrored = node("mapped-under-a-mirror", floor(2.0)[0], UNIT_FLOOR_UV, matte, tangents=[(1.0, 0.0, 0.0, 1.0)] * 4)
    b.doc["nodes"][mirrored]["scale"] = [-1.0, 1.0, 1.0]
    light = b.add_light({"name": "sun", "type": "directional", "intensity": LUMENS_PER_WATT})
    direction = tuple(-v for v in NORMAL_MAP_LIGHT)
    b.add_scene("normal_map_floors",
                nodes + [mirrored, b.light_node("sun", light, rotation=rotation_to(direction))])
    return b


def write_texture_scenes(root):
    """tests/data/textures/ under `root`: textured scenes."""
    directory = os.path.join(root, "tests", "data", "textures")
    write_gltf(directory, "uniform-texture.gltf", uniform_texture())
    glb = uniform_texture(embed="view")
    write(directory, "uniform-texture.glb", glb_bytes(glb.document(uri=None), glb.padded_data()))
    write_gltf(directory, "checker-floor.gltf", checker_floor())
    write_gltf(directory, "metal-roughness-floor.gltf", metal_roughness_floor())
    write_gltf(directory, "specular-texture-floor.gltf", specular_texture_floor())
    write_gltf(directory, "vertex-colour-floor.gltf", vertex_colour_floor())
    write_gltf(directory, "normal-map-floors.gltf", normal_map_floors())
    write_gltf(directory, "half-lit-lamp.gltf", half_lit_lamp())
    write_gltf(directory, "masked-quad.gltf", masked_quad())
    write_gltf(directory, "clear-quad.gltf", masked_quad(texture=False))
