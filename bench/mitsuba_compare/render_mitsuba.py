"""Renders a scene described by bench/mitsuba_compare/run with Mitsuba 3's path tracer, run by the
Python of the virtual environment that bench made (Mitsuba comes from PyPI; this program does not
use it). Reads the description (JSON: PLY meshes, each diffuse, a mirror or glass, and, for
emitters, a radiance; a pinhole camera; the image size), and at each sample count renders twice:
once untimed, which compiles the kernels Dr.Jit makes for that count (or finds them in its cache,
~/.drjit: the first of these seconds are reported apart), and once timed, whose image it keeps.
Writes each image as a .npy of linear RGB, with the seconds in mitsuba.json.

    python render_mitsuba.py DESCRIPTION.json OUTPUT_DIR VARIANT SPP [SPP ...]"""

import json
import os
import sys
import time

import drjit as dr
import mitsuba as mi
import numpy as np


def scene_dict(desc):
    cam = desc["camera"]
    scene = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 64},
        "sensor": {
            "type": "perspective",
            "fov_axis": "y",
            "fov": cam["yfov_degrees"],
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["origin"], target=cam["target"], up=cam["up"]),
            "film": {"type": "hdrfilm", "width": desc["width"], "height": desc["height"],
                     "rfilter": {"type": "box"}, "pixel_format": "rgb"},
            "sampler": {"type": "multijitter", "sample_count": 4},  # stratified, as the program's are
        },
    }
    for k, shape in enumerate(desc["shapes"]):
        kind = shape.get("kind", "diffuse")
        if kind == "mirror":  # a perfect mirror of the base colour (glTF's Schlick factor toward 1 aside)
            bsdf = {"type": "conductor", "material": "none",
                    "specular_reflectance": {"type": "rgb", "value": shape["reflectance"]}}
        elif kind == "glass":
            bsdf = {"type": "dielectric", "int_ior": shape["ior"], "ext_ior": 1.0}
        else:
            bsdf = {"type": "diffuse", "reflectance": {"type": "rgb", "value": shape["reflectance"]}}
        s = {"type": "ply", "filename": shape["ply"], "face_normals": not shape.get("smooth", False), "bsdf": bsdf}
        if shape.get("radiance"):
            s["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": shape["radiance"]}}
        scene["shape_%d" % k] = s
    return scene


def main():
    description, out, variant = sys.argv[1], sys.argv[2], sys.argv[3]
    counts = [int(x) for x in sys.argv[4:]]
    mi.set_variant(variant)
    with open(description, encoding="utf-8") as f:
        desc = json.load(f)
    start = time.perf_counter()
    scene = mi.load_dict(scene_dict(desc))
    loaded = time.perf_counter() - start
    rows = []
    compile_seconds = None
    for n in counts:
        start = time.perf_counter()
        dr.eval(mi.render(scene, spp=n, seed=0))  # compiles this count's kernels (LLVM variants)
        dr.sync_thread()  # launches are asynchronous: the timed render must not wait for this one
        if compile_seconds is None:
            compile_seconds = time.perf_counter() - start
        start = time.perf_counter()
        image = mi.render(scene, spp=n, seed=desc.get("seed", 7))
        pixels = np.array(image, dtype=np.float64)[..., :3]
        seconds = time.perf_counter() - start
        np.save(os.path.join(out, "mitsuba-%d.npy" % n), pixels)
        rows.append({"samples_per_pixel": n, "seconds": seconds})
    with open(os.path.join(out, "mitsuba.json"), "w", encoding="utf-8") as f:
        json.dump({"variant": variant, "load_seconds": loaded, "first_render_seconds": compile_seconds,
                   "mitsuba_version": mi.__version__, "renders": rows}, f, indent=1)


if __name__ == "__main__":
    main()
