"""Materials and surfaces that recipes of several kinds share: the lamp, a surface made of
quads, the grey floor plane, and smooth mirrors and glass."""

from geometry import quads_to_mesh, rect


def lamp(b, base=0.0):
    """The material `lamp`: emissiveFactor (1, 1, 1), so Le = 1, over baseColor `base`."""
    return b.material("lamp", (base, base, base), emissive=(1.0, 1.0, 1.0))


def add_quads(b, name, quads, material):
    """A surface `name` made of quads (already wound), two triangles each."""
    positions, indices = quads_to_mesh(quads)
    return b.surface(name, positions, indices, material)


def grey_plane(b, half, name="plane"):
    """The square [-half, half]^2 in x and z at y = 0, facing up, grey."""
    return add_quads(b, name, [rect(1, 0.0, (-half, half), (-half, half), (0.0, 1.0, 0.0))], b.grey())


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
