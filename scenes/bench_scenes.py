"""Scenes built to break methods (bench/scenes/, run by bench/stability, bench/furnace and
bench/gather_cost): (b)
small receivers, (c) reflectance near 1, (d) light leaks through thin walls, (e) tiny emitters,
(f) slivers, and the white furnace near reflectance 1."""

import os

from bundled_scenes import closed_cube
from geometry import cross, inward_box, rect, sub
from gltf_encoder import GltfBuilder, write_gltf
from scene_parts import add_quads, lamp


def ceiling_lamp(b, centre, side, level, material):
    """A square lamp of the given side centred at (centre x, level, centre z), facing down."""
    half = 0.5 * side
    quad = rect(1, level, (centre[0] - half, centre[0] + half), (centre[1] - half, centre[1] + half),
                (0.0, -1.0, 0.0))
    return add_quads(b, "lamp", [quad], material)


def small_receiver(side):
    """(b) A unit-square lamp 2 m above a small square receiver of the given side, coaxial:
    the receiver's view factors from the lamp are below a hemicube pixel's when it is small."""
    b = GltfBuilder()
    light, grey = lamp(b), b.grey()
    lo, hi = 0.5 - 0.5 * side, 0.5 + 0.5 * side
    nodes = [add_quads(b, "lamp", [rect(1, 2.0, (0.0, 1.0), (0.0, 1.0), (0.0, -1.0, 0.0))], light),
             add_quads(b, "receiver", [rect(1, 0.0, (lo, hi), (lo, hi), (0.0, 1.0, 0.0))], grey)]
    b.add_scene("small_receiver", nodes)
    return b


def reflective_cube(rho, floor_rho=None):
    """(c) The closed unit cube, every face of reflectance rho, the floor emitting Le = 1: by
    energy balance the area-weighted mean radiosity is E A_floor / ((1 - rho) A) =
    pi / (6 (1 - rho)), whatever the form factors. `floor_rho`: the floor's own reflectance
    (a room of two reflectances; the closed form above is then not its mean)."""
    b = GltfBuilder()
    wall = b.material("wall", (rho, rho, rho))
    f = rho if floor_rho is None else floor_rho
    light = b.material("lamp", (f, f, f), emissive=(1.0, 1.0, 1.0))
    nodes = [add_quads(b, name, [quad], light if name == "floor" else wall)
             for name, quad in inward_box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))]
    b.add_scene("reflective_cube", nodes)
    return b


PARTITION_X = 1.03125  # off the patch grid of the shared floor at most patch sizes


def two_rooms_apart():
    """(d) Two closed rooms 1 mm apart, the left one lit: any light in the right one leaked
    through the 1 mm gap (numerical precision, not meshing: no surface is shared)."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    nodes = []
    for prefix, lo, hi in (("lit", (0.0, 0.0, 0.0), (1.0, 1.0, 1.0)),
                           ("dark", (1.001, 0.0, 0.0), (2.001, 1.0, 1.0))):
        for name, quad in inward_box(lo, hi):
            nodes.append(add_quads(b, prefix + "_" + name, [quad], grey))
    nodes.append(ceiling_lamp(b, (0.5, 0.5), 0.2, 0.999, light))
    b.add_scene("two_rooms_apart", nodes)
    return b


def shared_floor_rooms(thickness):
    """(d) A lit and a dark room under one floor and one ceiling (single surfaces spanning
    both), parted at x = PARTITION_X by a wall `thickness` thick (two single-sided faces), or
    with thickness 0 by one double-sided wall that pierces the floor and ceiling by 0.1 m.
    Floor and ceiling patches that straddle the wall carry light from one room into the other."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    two = b.material("partition", (0.5, 0.5, 0.5), double_sided=True)
    x0, x1 = PARTITION_X, PARTITION_X + thickness
    nodes = [add_quads(b, "floor", [rect(1, 0.0, (0.0, 2.0), (0.0, 1.0), (0.0, 1.0, 0.0))], grey),
             add_quads(b, "ceiling", [rect(1, 1.0, (0.0, 2.0), (0.0, 1.0), (0.0, -1.0, 0.0))], grey)]
    for prefix, xa, xb, end, inward in (("lit", 0.0, x0, 0.0, 1.0), ("dark", x1, 2.0, 2.0, -1.0)):
        nodes.append(add_quads(b, prefix + "_back", [rect(2, 0.0, (xa, xb), (0.0, 1.0), (0.0, 0.0, 1.0))], grey))
        nodes.append(add_quads(b, prefix + "_front", [rect(2, 1.0, (xa, xb), (0.0, 1.0), (0.0, 0.0, -1.0))], grey))
        nodes.append(add_quads(b, prefix + "_end", [rect(0, end, (0.0, 1.0), (0.0, 1.0), (inward, 0.0, 0.0))], grey))
    if thickness > 0.0:
        nodes.append(add_quads(b, "lit_partition", [rect(0, x0, (0.0, 1.0), (0.0, 1.0), (-1.0, 0.0, 0.0))], grey))
        nodes.append(add_quads(b, "dark_partition", [rect(0, x1, (0.0, 1.0), (0.0, 1.0), (1.0, 0.0, 0.0))], grey))
    else:  # front faces the lit room; its back (":back") the dark one
        nodes.append(add_quads(b, "partition", [rect(0, x0, (-0.1, 1.1), (-0.1, 1.1), (-1.0, 0.0, 0.0))], two))
    nodes.append(ceiling_lamp(b, (0.5, 0.5), 0.2, 0.999, light))
    b.add_scene("shared_floor_rooms", nodes)
    return b


def tiny_emitter(side):
    """(e) A square lamp of the given side under the ceiling of a 4 x 3 x 4 m room, its radiance
    0.01 / side^2 so its power stays pi / 100 W. Only the floor reflects (0.5); walls and
    ceiling are black, so the floor's radiosity is direct light alone, which has a closed form."""
    b = GltfBuilder()
    grey = b.grey()
    black = b.material("black", (0.0, 0.0, 0.0))
    light = b.material("lamp", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), strength=0.01 / (side * side))
    nodes = [add_quads(b, name, [quad], grey if name == "floor" else black)
             for name, quad in inward_box((0.0, 0.0, 0.0), (4.0, 3.0, 4.0))]
    nodes.append(ceiling_lamp(b, (2.0, 2.0), side, 2.999, light))
    b.add_scene("tiny_emitter", nodes)
    return b


def slivers(strips):
    """(f) The facing squares with the bottom square cut into `strips` strips along x, each split
    along its diagonal: 2 x strips triangles of aspect ratio about `strips` to 1."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    positions, indices = [], []
    for i in range(strips + 1):
        x = i / strips
        positions.extend([(x, 0.0, 0.0), (x, 0.0, 1.0)])
    for i in range(strips):
        a, c = 2 * i, 2 * i + 2  # (x_i, 0), (x_i+1, 0); +1: z = 1
        for tri in ((a, a + 1, c + 1), (a, c + 1, c)):
            normal = cross(sub(positions[tri[1]], positions[tri[0]]), sub(positions[tri[2]], positions[tri[0]]))
            if normal[1] < 0.0:
                tri = (tri[0], tri[2], tri[1])
            indices.extend(tri)
    nodes = [b.surface("bottom", positions, indices, grey),
             add_quads(b, "top", [rect(1, 1.0, (0.0, 1.0), (0.0, 1.0), (0.0, -1.0, 0.0))], light)]
    b.add_scene("slivers", nodes)
    return b


SMALL_RECEIVER_SIDES = (0.3, 0.1, 0.03, 0.01, 0.003)
REFLECTANCES = (0.5, 0.9, 0.99, 0.999)
TINY_EMITTER_SIDES = (0.3, 0.1, 0.03, 0.01, 0.003)
SLIVER_STRIPS = (1, 10, 100, 1000)


def long_room():
    """A closed 1 x 2 x 3 m room (grey walls) lit by a 0.2 m square lamp under the middle of its
    ceiling: a convex room where nothing blocks any shadow ray (bench/gather_cost)."""
    b = GltfBuilder()
    grey, light = b.grey(), lamp(b)
    nodes = [add_quads(b, name, [quad], grey) for name, quad in inward_box((0.0, 0.0, 0.0), (1.0, 2.0, 3.0))]
    nodes.append(add_quads(b, "lamp", [rect(1, 1.999, (0.4, 0.6), (1.4, 1.6), (0.0, -1.0, 0.0))], light))
    b.add_scene("long_room", nodes)
    return b


def write_bench_scenes(root):
    """bench/scenes/ under `root`: the scenes of bench/stability and bench/furnace."""
    directory = os.path.join(root, "bench", "scenes")
    for side in SMALL_RECEIVER_SIDES:
        write_gltf(directory, "small-receiver-%g.gltf" % side, small_receiver(side))
    for rho in REFLECTANCES:
        write_gltf(directory, "reflective-cube-%g.gltf" % rho, reflective_cube(rho))
    for rho in (0.5, 0.9, 0.99):  # the white furnace near rho = 1 (bench/furnace)
        write_gltf(directory, "white-furnace-%g.gltf" % rho, closed_cube(furnace=True, rho=rho))
    write_gltf(directory, "two-rooms-apart.gltf", two_rooms_apart())
    write_gltf(directory, "thin-wall.gltf", shared_floor_rooms(0.001))
    write_gltf(directory, "pierced-floor.gltf", shared_floor_rooms(0.0))
    for side in TINY_EMITTER_SIDES:
        write_gltf(directory, "tiny-emitter-%g.gltf" % side, tiny_emitter(side))
    for strips in SLIVER_STRIPS:
        write_gltf(directory, "slivers-%d.gltf" % strips, slivers(strips))
    write_gltf(directory, "long-room.gltf", long_room())
