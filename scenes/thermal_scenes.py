"""Enclosures and surface properties for radiative heat exchange (tests/data/thermal/)."""

import os

from geometry import icosphere
from gltf_encoder import GltfBuilder, write, write_gltf


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


def write_thermal_scenes(root):
    """tests/data/thermal/ under `root`: the spheres and their properties."""
    directory = os.path.join(root, "tests", "data", "thermal")
    write_gltf(directory, "concentric-spheres.gltf", concentric_spheres())
    write(directory, "spheres.csv", "surface,emissivity,temperature\ninner,0.8,400\nouter,0.5,300\n")
    write(directory, "spheres-reradiating.csv", "surface,emissivity,temperature,heat_flux\ninner,0.8,400,\n"
          "outer,0.5,,0\n")
