#!/usr/bin/env python3
"""Generate the bundled glTF scenes and the loader test data.

Run from anywhere:  python3 scenes/generate.py [--out DIR]
Writes (paths relative to the repository root, found from this file, or to DIR):
  scenes/*.gltf                 bundled scenes (Cornell box, analytic view-factor scenes)
  tests/data/solve/*            furnaces, reflective cubes and a shadow for the solver's tests
  tests/data/gltf/*             small valid files for loader tests
  tests/data/bad/*              small invalid files, one problem each
  tests/data/lights/*           scenes lit by KHR_lights_punctual lights, for closed-form tests
  tests/data/textures/*         textured scenes (PNG written here, without libraries)
  tests/data/environment/*      environment maps (OpenEXR written here) and scenes they light
  tests/data/thermal/*          enclosures and properties for radiative heat exchange
  tests/data/specular/*         a mirror and a glass slab before a lamp (closed forms)
  tests/data/meshes/*           one room as glTF, OBJ + MTL, STL and PLY (the same float32 coordinates)
  bench/scenes/*.gltf           scenes built to break methods (bench/stability)

Python 3 standard library only. Output is deterministic: the same bytes on every run.
Conventions (shared/DESIGN.md): metres, +Y up, right-handed, counter-clockwise triangles
face their normal, single-sided unless material.doubleSided.

This file only runs the modules beside it; scenes/README.md says which one holds what.
"""

import argparse
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ beside the modules

from bad_fixtures import write_bad_environment_maps, write_bad_gltf  # noqa: E402
from bench_scenes import write_bench_scenes  # noqa: E402
from bundled_scenes import write_bundled_scenes  # noqa: E402
from environment_scenes import write_environment_scenes  # noqa: E402
from light_scenes import write_light_scenes  # noqa: E402
from loader_scenes import write_loader_scenes  # noqa: E402
from mesh_scenes import write_bad_meshes, write_mesh_scenes  # noqa: E402
from solve_scenes import write_solve_scenes  # noqa: E402
from specular_scenes import write_specular_scenes  # noqa: E402
from texture_scenes import write_texture_scenes  # noqa: E402
from thermal_scenes import write_thermal_scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", metavar="DIR", default=ROOT,
                        help="write every file under DIR instead of the repository (default: %(default)s)")
    root = parser.parse_args(argv).out
    write_bundled_scenes(root)
    write_solve_scenes(root)
    write_loader_scenes(root)
    write_bad_gltf(root)
    write_light_scenes(root)
    write_texture_scenes(root)
    write_environment_scenes(root)
    write_bad_environment_maps(root)
    write_thermal_scenes(root)
    write_bench_scenes(root)
    write_specular_scenes(root)
    write_mesh_scenes(root)
    write_bad_meshes(root)


if __name__ == "__main__":
    main()
