#!/usr/bin/env python3
"""A room of ordinary Blender materials, exported to glTF and rendered by Cycles: the outside
reference of bench/cycles_compare. Run with a Python that has Blender as a module (`bpy` from
PyPI, Python 3.11):

    PYTHON blender_scene.py --output DIR [--size N] [--samples N ...] [--threads N] [--matte]

Builds the scene in an empty Blender file: a closed room 4 x 5 x 2.7 m lit by an emissive lamp
box under its ceiling, with walls painted at roughness 0.5 to 0.7 (Principled BSDF, specular
IOR level 0.5, i.e. glTF's default layer), a floor at roughness 0.35, a red plastic sphere at
roughness 0.25, a gold metal cube at roughness 0.4, a rough glass slab (transmission 1,
roughness 0.2), a panel with a normal map of bumps, and a box whose metal and roughness come
from a checker texture (blue metal, green roughness, as glTF's metallicRoughnessTexture). The
images (normal map, checker) are made here from formulas. Writes DIR/scene.gltf with Blender's
glTF exporter (cameras on, modifiers applied, no tangents: the program generates them), and
for each --samples N DIR/cycles-N.exr (linear, Standard view transform, a box pixel filter of
one pixel, no clamping, no denoising, no glossy filter, 64 bounces of each kind) with its
render seconds in DIR/cycles-N.json (--reference N: one more, with another seed), and DIR/objects.json: the object each pixel's centre sees,
by Blender's own ray cast from the camera (no antialiasing), for per-object means. --matte
makes every surface Lambertian (a control: what differs then is not the materials)."""
import argparse
import json
import math
import os
import sys
import time
import warnings

import bpy
from mathutils import Vector

# Blender 5 says use_nodes will go in Blender 6; until then it is needed for the node trees below
warnings.filterwarnings("ignore", category=DeprecationWarning)

ROOM = (4.0, 5.0, 2.7)   # x width, y depth, z height (Blender is +Z up; the exporter writes +Y up)


def arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--output", required=True)
    p.add_argument("--size", type=int, default=256, help="image width and height (default 256)")
    p.add_argument("--samples", type=int, nargs="*", default=[], help="Cycles renders to make, samples per pixel")
    p.add_argument("--reference", type=int, default=0,
                   help="also a reference of this many samples per pixel, with a seed of its own (2; the others 1), "
                        "so that the others' samples are not a prefix of its own")
    p.add_argument("--threads", type=int, default=0, help="Cycles threads (0: every core)")
    p.add_argument("--matte", action="store_true",
                   help="every surface Lambertian (specular IOR level 0, no metal, glass or normal map): a control")
    return p.parse_args(argv)


MATTE = False


def material(name, base, roughness, metallic=0.0, transmission=0.0, emission=None, strength=0.0):
    if MATTE:
        metallic = transmission = 0.0
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*base, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Metallic"].default_value = metallic
    bsdf.inputs["Specular IOR Level"].default_value = 0.0 if MATTE else 0.5
    bsdf.inputs["IOR"].default_value = 1.5
    bsdf.inputs["Transmission Weight"].default_value = transmission
    if emission is not None:
        bsdf.inputs["Emission Color"].default_value = (*emission, 1.0)
        bsdf.inputs["Emission Strength"].default_value = strength
    return m


def mesh_object(name, vertices, faces, mat, smooth=False):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    if smooth:
        mesh.shade_smooth()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    mesh.materials.append(mat)
    return obj


def added(name, mat, scale=None, smooth=False):
    """The object a primitive_*_add just made: named, scaled and given its material."""
    obj = bpy.context.active_object
    obj.name = name
    if scale:
        obj.scale = scale
    if smooth:
        obj.data.shade_smooth()
    obj.data.materials.append(mat)
    return obj


def image(name, size, pixel):
    """An image of size x size made by pixel(u, v) -> (r, g, b), stored non-colour (data) and packed
    into the file (the colour space is set first: setting it afterwards reloads the image, empty)."""
    img = bpy.data.images.new(name, size, size, alpha=False)
    img.colorspace_settings.name = "Non-Color"
    px = []
    for j in range(size):
        for i in range(size):
            r, g, b = pixel((i + 0.5) / size, (j + 0.5) / size)
            px += [r, g, b, 1.0]
    img.pixels.foreach_set(px)
    img.pack()
    return img


def bumps(u, v):
    """A tangent-space normal of h = 0.06 sin(2 pi 4u) sin(2 pi 3v) (in units of the panel's uv)."""
    k = 0.35
    dx = k * math.cos(2 * math.pi * 4 * u) * math.sin(2 * math.pi * 3 * v)
    dy = k * math.sin(2 * math.pi * 4 * u) * math.cos(2 * math.pi * 3 * v)
    n = Vector((-dx, -dy, 1.0)).normalized()
    return 0.5 + 0.5 * n.x, 0.5 + 0.5 * n.y, 0.5 + 0.5 * n.z


def checker(u, v):
    """Blue metal 1 and green roughness 0.3 on the dark squares; metal 0, roughness 0.7 on the others."""
    dark = (int(u * 4) + int(v * 4)) % 2 == 0
    return (0.0, 0.3, 1.0) if dark else (0.0, 0.7, 0.0)


def build():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    w, d, h = ROOM
    x0, x1, y0, y1 = -w / 2, w / 2, -d / 2, d / 2
    white = material("wall paint", (0.75, 0.75, 0.72), 0.6)
    green = material("green paint", (0.25, 0.5, 0.3), 0.7)
    floor = material("floor", (0.5, 0.35, 0.22), 0.35)
    ceiling = material("ceiling", (0.8, 0.8, 0.8), 0.5)
    # the room's faces, wound so that their normals face in
    mesh_object("floor", [(x0, y0, 0), (x1, y0, 0), (x1, y1, 0), (x0, y1, 0)], [(0, 1, 2, 3)], floor)
    mesh_object("ceiling", [(x0, y0, h), (x0, y1, h), (x1, y1, h), (x1, y0, h)], [(0, 1, 2, 3)], ceiling)
    mesh_object("left wall", [(x0, y0, 0), (x0, y1, 0), (x0, y1, h), (x0, y0, h)], [(0, 1, 2, 3)], green)
    mesh_object("right wall", [(x1, y0, 0), (x1, y0, h), (x1, y1, h), (x1, y1, 0)], [(0, 1, 2, 3)], white)
    mesh_object("back wall", [(x0, y1, 0), (x1, y1, 0), (x1, y1, h), (x0, y1, h)], [(0, 1, 2, 3)], white)
    mesh_object("front wall", [(x0, y0, 0), (x0, y0, h), (x1, y0, h), (x1, y0, 0)], [(0, 1, 2, 3)], white)

    lamp = material("lamp", (0.0, 0.0, 0.0), 0.5, emission=(1.0, 0.95, 0.85), strength=12.0)
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.6, h - 0.15))
    added("lamp", lamp, scale=(0.9, 0.9, 0.06))

    plastic = material("red plastic", (0.8, 0.1, 0.08), 0.25)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=64, ring_count=32, radius=0.4, location=(-1.0, 0.9, 0.4))
    added("plastic sphere", plastic, smooth=True)

    gold = material("rough gold", (0.95, 0.75, 0.4), 0.4, metallic=1.0)
    bpy.ops.mesh.primitive_cube_add(size=0.7, location=(1.0, 1.2, 0.35), rotation=(0, 0, math.radians(30)))
    added("metal cube", gold)

    glass = material("rough glass", (1.0, 1.0, 1.0), 0.2, transmission=1.0)
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.35, -0.2, 0.46))
    added("glass slab", glass, scale=(1.0, 0.06, 0.9))

    panel = material("bumpy panel", (0.35, 0.5, 0.75), 0.5)
    nodes, links = panel.node_tree.nodes, panel.node_tree.links
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image("bumps", 256, bumps)
    normal_map = nodes.new("ShaderNodeNormalMap")
    links.new(tex.outputs["Color"], normal_map.inputs["Color"])
    if not MATTE:
        links.new(normal_map.outputs["Normal"], nodes["Principled BSDF"].inputs["Normal"])
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=(-0.6, y1 - 0.02, 1.45), rotation=(math.radians(90), 0, 0))
    added("normal-mapped panel", panel, scale=(1.4, 0.9, 1.0))

    tiles = material("metal checker", (0.7, 0.7, 0.72), 0.5)
    nodes, links = tiles.node_tree.nodes, tiles.node_tree.links
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image("checker", 64, checker)
    tex.interpolation = "Closest"
    split = nodes.new("ShaderNodeSeparateColor")
    links.new(tex.outputs["Color"], split.inputs["Color"])
    links.new(split.outputs["Green"], nodes["Principled BSDF"].inputs["Roughness"])
    if not MATTE:
        links.new(split.outputs["Blue"], nodes["Principled BSDF"].inputs["Metallic"])
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(-0.9, -0.6, 0.2), rotation=(0, 0, math.radians(-20)))
    added("checker box", tiles, scale=(0.9, 0.6, 0.4))

    bpy.ops.object.camera_add(location=(0.0, y0 + 0.25, 1.5), rotation=(math.radians(80), 0, 0))
    cam = bpy.context.active_object
    cam.name = "camera"
    cam.data.lens = 18.0
    cam.data.sensor_fit = "AUTO"
    scene.camera = cam
    scene.world = bpy.data.worlds.new("black")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    return scene


def settings(scene, size, threads):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED" if threads else "AUTO"
    if threads:
        scene.render.threads = threads
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.pixel_filter_type = "BOX"
    scene.cycles.filter_width = 1.0
    scene.cycles.sample_clamp_direct = 0.0
    scene.cycles.sample_clamp_indirect = 0.0
    scene.cycles.blur_glossy = 0.0
    scene.cycles.caustics_reflective = True
    scene.cycles.caustics_refractive = True
    scene.cycles.max_bounces = 64
    scene.cycles.diffuse_bounces = 64
    scene.cycles.glossy_bounces = 64
    scene.cycles.transmission_bounces = 64
    scene.cycles.transparent_max_bounces = 64
    scene.cycles.seed = 1
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.render.image_settings.color_mode = "RGB"


def objects_seen(scene, size):
    """The name of the object each pixel's centre sees (row 0 at the top), by Blender's ray cast."""
    cam = scene.camera
    depsgraph = bpy.context.evaluated_depsgraph_get()
    frame = [cam.matrix_world @ v for v in cam.data.view_frame(scene=scene)]  # top right, bottom right, bottom left, top left
    origin = cam.matrix_world.translation
    top_left, top_right, bottom_left = frame[3], frame[0], frame[2]
    names = []
    for j in range(size):
        row = []
        for i in range(size):
            p = top_left + (top_right - top_left) * ((i + 0.5) / size) + (bottom_left - top_left) * ((j + 0.5) / size)
            hit, _, _, _, obj, _ = scene.ray_cast(depsgraph, origin, (p - origin).normalized())
            row.append(obj.name if hit else "")
        names.append(row)
    return names


def main():
    global MATTE
    args = arguments()
    MATTE = args.matte
    os.makedirs(args.output, exist_ok=True)
    scene = build()
    settings(scene, args.size, args.threads)
    bpy.ops.export_scene.gltf(filepath=os.path.join(args.output, "scene.gltf"), export_format="GLTF_SEPARATE",
                              export_cameras=True, export_lights=False, export_apply=True)
    with open(os.path.join(args.output, "objects.json"), "w") as f:
        json.dump(objects_seen(scene, args.size), f)
    for n, seed in [(n, 1) for n in args.samples] + ([(args.reference, 2)] if args.reference else []):
        scene.cycles.samples = n
        scene.cycles.seed = seed
        scene.render.filepath = os.path.join(args.output, "cycles-%d.exr" % n)
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds = time.perf_counter() - start
        with open(os.path.join(args.output, "cycles-%d.json" % n), "w") as f:
            json.dump({"samples": n, "seconds": seconds, "size": args.size, "seed": seed,
                       "blender": bpy.app.version_string}, f)
        print("cycles: %d samples per pixel in %.1f s" % (n, seconds), flush=True)


if __name__ == "__main__":
    main()
