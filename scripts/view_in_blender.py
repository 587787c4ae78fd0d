#!/usr/bin/env python3
"""Renders a glTF file as Blender's glTF importer shows it: a headless picture of lightmapped.glb.

    /tmp/bpyvenv/bin/python scripts/view_in_blender.py IN.glb OUT.png [--width W --height H --samples N]

The scene is imported with Blender's own glTF importer (which reads TEXCOORD_1 and
KHR_materials_emissive_strength), framed by a camera looking at the centre of the imported meshes'
bounding box from a three-quarter view above, at the distance that fits the whole box, and rendered
by Cycles on the CPU against a black world with the "Standard" view transform, so the emissive
lightmap's values reach the PNG as the file states them (sRGB-encoded, clipped at 1, no tone curve).
lightmapped.glb's materials are emission only, so there are no light bounces to trace: few samples
(for antialiasing) are enough.

It needs Blender as a Python module: the `bpy` package from PyPI, which wants Python 3.11, e.g.

    python3.11 -m venv /tmp/bpyvenv && /tmp/bpyvenv/bin/pip install bpy

Only this script needs it; the program and its tests never do.

--print-materials prints each imported material's shader nodes and links (to see how the importer
wired the emissive texture), and the script warns where a material reads a UV map that the mesh
using it lacks (Blender then samples the texture at one point: a flat colour).
"""
import argparse
import math
import sys
import time

import bpy
from mathutils import Vector


def parse_arguments():
    parser = argparse.ArgumentParser(description="Render a glTF file as Blender's glTF importer shows it.")
    parser.add_argument("input", help="the glTF file (.glb or .gltf)")
    parser.add_argument("output", help="the PNG to write")
    parser.add_argument("--width", type=int, default=960, help="image width in pixels (default 960)")
    parser.add_argument("--height", type=int, default=640, help="image height in pixels (default 640)")
    parser.add_argument("--samples", type=int, default=16, help="Cycles samples per pixel (default 16)")
    parser.add_argument("--azimuth", type=float, default=45.0,
                        help="camera direction about the vertical, degrees from the front (default 45)")
    parser.add_argument("--elevation", type=float, default=30.0,
                        help="camera direction above the horizontal, degrees (default 30)")
    parser.add_argument("--fov", type=float, default=40.0, help="horizontal field of view, degrees (default 40)")
    parser.add_argument("--print-materials", action="store_true",
                        help="print the imported materials' shader nodes and links")
    return parser.parse_args()


def empty_scene():
    """Blender's factory settings without the default cube, camera and light."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    return bpy.context.scene


def mesh_bounds(objects):
    """The world-space axis-aligned box around the mesh objects' vertices: (lowest, highest) corners."""
    lo = Vector((math.inf, math.inf, math.inf))
    hi = Vector((-math.inf, -math.inf, -math.inf))
    for obj in objects:
        # bound_box is the object's own box, in its local frame: take its 8 corners to the world
        for corner in obj.bound_box:
            p = obj.matrix_world @ Vector(corner)
            for axis in range(3):
                lo[axis] = min(lo[axis], p[axis])
                hi[axis] = max(hi[axis], p[axis])
    return lo, hi


def add_framing_camera(scene, lo, hi, azimuth, elevation, fov_x):
    """A camera at the given direction from the box's centre, pointed at it, as close as fits the box."""
    centre = (lo + hi) / 2
    # Blender is Z up and its front view looks along +Y (the importer turns glTF's +Y up into +Z):
    # azimuth 0 is in front (-Y), positive turns towards +X
    az, el = math.radians(azimuth), math.radians(elevation)
    towards_camera = Vector((math.sin(az) * math.cos(el), -math.cos(az) * math.cos(el), math.sin(el)))

    camera_data = bpy.data.cameras.new("view_in_blender")
    camera_data.sensor_fit = "HORIZONTAL"
    camera_data.angle = fov_x
    camera = bpy.data.objects.new("view_in_blender", camera_data)
    scene.collection.objects.link(camera)
    # A camera looks down its local -Z with +Y up
    rotation = (-towards_camera).to_track_quat("-Z", "Y")
    camera.rotation_euler = rotation.to_euler()

    # The camera's axes in the world: right, up and forward (the direction it looks)
    right = rotation @ Vector((1, 0, 0))
    up = rotation @ Vector((0, 1, 0))
    forward = -towards_camera
    aspect = scene.render.resolution_y / scene.render.resolution_x
    tan_x = math.tan(fov_x / 2)
    tan_y = tan_x * aspect

    # A box corner at offset p from the centre lies (d + p.forward) in front of a camera at distance
    # d; it is in the picture when |p.right| <= tan_x (d + p.forward), and so for up. The smallest d
    # that holds for all 8 corners frames the box; 5 % more leaves a margin.
    distance = 0.0
    for i in range(8):
        corner = Vector((hi.x if i & 1 else lo.x, hi.y if i & 2 else lo.y, hi.z if i & 4 else lo.z))
        p = corner - centre
        depth_offset = p.dot(forward)
        distance = max(distance,
                       abs(p.dot(right)) / tan_x - depth_offset,
                       abs(p.dot(up)) / tan_y - depth_offset)
    distance *= 1.05
    camera.location = centre + towards_camera * distance

    # Clip planes around the box, whatever the scene's scale (the default far plane is 100 m)
    radius = (hi - lo).length / 2
    camera_data.clip_start = max(distance - radius, distance * 1e-3) * 0.5
    camera_data.clip_end = (distance + radius) * 2
    scene.camera = camera
    return camera, distance


def black_world(scene):
    """A world that gives no light and shows black behind the model."""
    world = bpy.data.worlds.new("black")
    if world.node_tree is None:
        world.use_nodes = True  # Blender before 5 gives a new world nodes only when asked
    background = world.node_tree.nodes.get("Background")
    if background is None:
        background = world.node_tree.nodes.new("ShaderNodeBackground")
        output = world.node_tree.nodes.get("World Output") or world.node_tree.nodes.new("ShaderNodeOutputWorld")
        world.node_tree.links.new(background.outputs["Background"], output.inputs["Surface"])
    background.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    background.inputs["Strength"].default_value = 0.0
    scene.world = world


def set_up_render(scene, width, height, samples, output):
    """Cycles on the CPU, emission seen directly, Standard view transform, an 8-bit RGB PNG."""
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False  # the only noise is antialiasing: nothing to denoise
    # The materials only emit: camera rays that see the emission are all there is. One bounce
    # would add the (black, roughness 1) surfaces' reflection of the others' emission, which the
    # baked lightmap already holds.
    scene.cycles.max_bounces = 0
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    # No tone curve: the emissive values go to the picture as sRGB, clipped at 1
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "8"
    scene.render.filepath = output


def print_materials(materials):
    for material in materials:
        print(f"material {material.name!r}")
        if material.node_tree is None:
            continue
        for node in material.node_tree.nodes:
            extra = ""
            if node.type == "UVMAP":
                extra = f" uv_map={node.uv_map!r}"
            elif node.type == "TEX_IMAGE" and node.image is not None:
                extra = f" image={node.image.name!r} colorspace={node.image.colorspace_settings.name!r}"
            print(f"  node {node.name!r} ({node.bl_idname}){extra}")
            for socket in node.inputs:
                if not socket.is_linked and hasattr(socket, "default_value") and socket.name in (
                        "Base Color", "Emission Color", "Emission Strength", "Metallic", "Roughness"):
                    value = socket.default_value
                    value = tuple(value) if hasattr(value, "__len__") else value
                    print(f"    {socket.name} = {value}")
        for link in material.node_tree.links:
            print(f"  link {link.from_node.name}.{link.from_socket.name} -> {link.to_node.name}.{link.to_socket.name}")


def warn_missing_uv_maps(mesh_objects):
    """Warns where a material's UV Map node names a UV map that a mesh using the material lacks."""
    problems = 0
    for obj in mesh_objects:
        have = {layer.name for layer in obj.data.uv_layers}
        for material in obj.data.materials:
            if material is None or material.node_tree is None:
                continue
            for node in material.node_tree.nodes:
                if node.type == "UVMAP" and node.uv_map and node.uv_map not in have:
                    problems += 1
                    if problems <= 5:
                        print(f"warning: mesh {obj.name!r} has UV maps {sorted(have)} but its material "
                              f"{material.name!r} reads {node.uv_map!r}: the texture shows as one flat colour",
                              file=sys.stderr)
    if problems > 5:
        print(f"warning: ... {problems} such mesh/material pairs in all", file=sys.stderr)
    return problems


def main():
    args = parse_arguments()
    scene = empty_scene()

    started = time.perf_counter()
    bpy.ops.import_scene.gltf(filepath=args.input)
    imported = time.perf_counter() - started
    mesh_objects = [obj for obj in scene.objects if obj.type == "MESH"]
    if not mesh_objects:
        sys.exit(f"{args.input}: no meshes imported")
    print(f"imported {len(mesh_objects)} meshes in {imported:.1f} s")

    materials = sorted({m for obj in mesh_objects for m in obj.data.materials if m is not None},
                       key=lambda m: m.name)
    if args.print_materials:
        print_materials(materials)
    warn_missing_uv_maps(mesh_objects)

    set_up_render(scene, args.width, args.height, args.samples, args.output)
    black_world(scene)
    lo, hi = mesh_bounds(mesh_objects)
    _, distance = add_framing_camera(scene, lo, hi, args.azimuth, args.elevation, math.radians(args.fov))
    print(f"box {tuple(round(v, 3) for v in lo)} to {tuple(round(v, 3) for v in hi)}; camera {distance:.3f} from its centre")

    started = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print(f"rendered {args.width} x {args.height}, {args.samples} samples, in {time.perf_counter() - started:.1f} s: "
          f"wrote {args.output}")


if __name__ == "__main__":
    main()
