#!/usr/bin/python3
"""Every method and solver gives bitwise the results it gave before a change.

Runs a fixed list of small `viewfactors`, `solve` and `pathtrace` runs (every form-factor
method at both levels, every solver, two levels, adaptive refinement, a checkpoint, the path
tracer) and fingerprints what each writes: the CSV, Matrix Market, EXR, PNG, glTF and
files byte for byte, checkpoints and report.json without what varies from run to run (timings,
rays per second, the device's description, a checkpoint's solving time). `expected.txt` holds the fingerprints; a
refactoring must leave every line as it is.

  same_results.py RADIOSITY SOURCE_DIR WORKDIR            compare with expected.txt (CI)
  same_results.py RADIOSITY SOURCE_DIR WORKDIR --record   rewrite expected.txt

Record only from a build whose results are meant to change (a new method, a fixed bug), and
say why in the commit. The numbers are bitwise the same across threads and across the OpenCL
implementations measured (docs/devices.md), so the fingerprints do not depend on the machine
CI runs on. Each run is small: the whole list takes well under a minute on two cores."""

import hashlib
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXPECTED = os.path.join(HERE, "expected.txt")

# name, command, arguments ({s}: the source tree), the files it writes (relative to its folder).
SOLVE_FILES = ["render.exr", "render.png", "lit.glb", "report.json"]
SMALL_IMAGE = ["--width", "24", "--height", "24", "--seed", "5", "--quiet"]
CASES = [
    ("vf-shoot-surface", "viewfactors",
     ["{s}/scenes/cornell-box.gltf", "--rays", "20000", "--seed", "3", "--enforce", "none"], ["out.csv"]),
    ("vf-shoot-surface-mtx-enforce", "viewfactors",
     ["{s}/scenes/closed-cube.gltf", "--rays", "20000", "--format", "mtx", "--enforce", "both"], ["out.csv"]),
    ("vf-shoot-patch", "viewfactors",
     ["{s}/scenes/cornell-box.gltf", "--level", "patch", "--patch-size", "0.3", "--rays-per-patch", "256",
      "--enforce", "none"], ["out.csv"]),
    ("vf-hemicube-patch-jitter", "viewfactors",
     ["{s}/scenes/cornell-box.gltf", "--method", "hemicube", "--level", "patch", "--patch-size", "0.3",
      "--hemicube-res", "16", "--hemicube-jitter", "--enforce", "none"], ["out.csv"]),
    ("vf-hemicube-surface", "viewfactors",
     ["{s}/scenes/closed-cube.gltf", "--method", "hemicube", "--patch-size", "0.5", "--hemicube-res", "16",
      "--enforce", "reciprocity"], ["out.csv"]),
    ("vf-gather-surface", "viewfactors",
     ["{s}/scenes/cornell-box.gltf", "--method", "gather", "--patch-size", "0.3", "--shadow-rays", "2",
      "--enforce", "none"], ["out.csv"]),
    ("vf-gather-patch-mtx", "viewfactors",
     ["{s}/scenes/perpendicular-squares.gltf", "--method", "gather", "--level", "patch", "--patch-size", "0.4",
      "--format", "mtx", "--enforce", "none"], ["out.csv"]),
    ("solve-progressive", "solve",
     ["{s}/scenes/cornell-box.gltf", "--patch-size", "0.1", "--rays", "300000", "--element-csv"] + SMALL_IMAGE,
     SOLVE_FILES + ["elements.csv"]),
    ("solve-progressive-checkpoint", "solve",
     ["{s}/tests/data/solve/white-furnace.gltf", "--patch-size", "0.2", "--rays", "200000", "--max-shots", "300",
      "--checkpoint", "{o}/state.ckpt"] + SMALL_IMAGE, SOLVE_FILES + ["state.ckpt"]),
    ("solve-shoot-jacobi-bounces", "solve",
     ["{s}/scenes/cornell-box.gltf", "--solver", "jacobi", "--bounces", "2", "--patch-size", "0.2",
      "--rays-per-patch", "512"] + SMALL_IMAGE, SOLVE_FILES),
    ("solve-shoot-jacobi-residual", "solve",
     ["{s}/scenes/cornell-box.gltf", "--solver", "jacobi", "--residual", "1e-4", "--patch-size", "0.2",
      "--rays-per-patch", "512"] + SMALL_IMAGE, SOLVE_FILES),
    ("solve-shoot-gauss-seidel", "solve",
     ["{s}/scenes/cornell-box.gltf", "--solver", "gauss-seidel", "--patch-size", "0.2", "--rays-per-patch", "512"]
     + SMALL_IMAGE, SOLVE_FILES),
    ("solve-shoot-direct", "solve",
     ["{s}/scenes/cornell-box.gltf", "--solver", "direct", "--patch-size", "0.2", "--rays-per-patch", "512",
      "--element-csv"] + SMALL_IMAGE, SOLVE_FILES + ["elements.csv"]),
    ("solve-hemicube-progressive", "solve",
     ["{s}/scenes/cornell-box.gltf", "--method", "hemicube", "--patch-size", "0.2", "--hemicube-res", "16",
      "--tolerance", "1e-4"] + SMALL_IMAGE, SOLVE_FILES),
    ("solve-hemicube-gauss-seidel", "solve",
     ["{s}/scenes/cornell-box.gltf", "--method", "hemicube", "--solver", "gauss-seidel", "--patch-size", "0.2",
      "--hemicube-res", "16", "--hemicube-jitter"] + SMALL_IMAGE, SOLVE_FILES),
    ("solve-gather-direct", "solve",
     ["{s}/scenes/cornell-box.gltf", "--method", "gather", "--solver", "direct", "--patch-size", "0.2",
      "--shadow-rays", "2"] + SMALL_IMAGE, SOLVE_FILES),
    ("solve-elements", "solve",
     ["{s}/scenes/cornell-box.gltf", "--patch-size", "0.2", "--element-size", "0.06", "--rays", "300000",
      "--element-csv"] + SMALL_IMAGE, SOLVE_FILES + ["elements.csv"]),
    ("solve-adaptive", "solve",
     ["{s}/tests/data/solve/occluder.gltf", "--adaptive", "--rays", "1e6", "--camera", "plan", "--debug-mesh",
      "--element-csv"] + SMALL_IMAGE, SOLVE_FILES + ["elements.csv", "render-mesh.png"]),
    ("solve-point-light-adaptive", "solve",
     ["{s}/scenes/cornell-box-point-light.gltf", "--adaptive", "--patch-size", "0.1", "--rays", "300000",
      "--element-csv"] + SMALL_IMAGE, SOLVE_FILES + ["elements.csv"]),
    ("solve-sky-gauss-seidel", "solve",
     ["{s}/tests/data/lights/open-box.gltf", "--sky", "1,0.8,0.6", "--solver", "gauss-seidel", "--patch-size",
      "0.25", "--rays-per-patch", "256"] + SMALL_IMAGE, SOLVE_FILES),
    ("pathtrace-point-light-sky", "pathtrace",
     ["{s}/scenes/cornell-box-point-light.gltf", "--sky", "0.5", "--width", "24", "--height", "24", "--samples", "8"],
     ["out.exr"]),
    ("solve-textures-masks", "solve",
     ["{s}/tests/data/textures/masked-quad.gltf", "--patch-size", "0.1", "--rays", "100000"] + SMALL_IMAGE,
     SOLVE_FILES),
    ("solve-checker-floor", "solve",
     ["{s}/tests/data/textures/checker-floor.gltf", "--camera", "plan", "--patch-size", "0.1", "--rays", "100000"]
     + SMALL_IMAGE, SOLVE_FILES),
    ("solve-environment", "solve",
     ["{s}/tests/data/lights/open-box.gltf", "--environment", "{s}/tests/data/environment/sun.exr",
      "--environment-strength", "0.5", "--patch-size", "0.25", "--rays", "100000"] + SMALL_IMAGE, SOLVE_FILES),
    ("pathtrace-environment", "pathtrace",
     ["{s}/tests/data/lights/open-box.gltf", "--environment", "{s}/tests/data/environment/sun.exr", "--width", "16",
      "--height", "16", "--samples", "8"], ["out.exr"]),
    ("solve-render-direct", "solve",
     ["{s}/scenes/cornell-box.gltf", "--patch-size", "0.1", "--rays", "300000", "--render", "direct"] + SMALL_IMAGE,
     ["render.exr"]),
    ("solve-render-final-gather-lights", "solve",
     ["{s}/scenes/cornell-box-point-light.gltf", "--sky", "0.5", "--patch-size", "0.1", "--rays", "300000",
      "--render", "final-gather"] + SMALL_IMAGE, ["render.exr"]),
    ("solve-render-final-gather-environment", "solve",
     ["{s}/tests/data/lights/open-box.gltf", "--environment", "{s}/tests/data/environment/sun.exr",
      "--environment-strength", "0.5", "--patch-size", "0.25", "--rays", "100000", "--render", "final-gather"]
     + SMALL_IMAGE, ["render.exr"]),
    ("solve-render-direct-textures", "solve",
     ["{s}/tests/data/textures/checker-floor.gltf", "--camera", "plan", "--patch-size", "0.1", "--rays", "100000",
      "--render", "direct"] + SMALL_IMAGE, ["render.exr"]),
    ("solve-render-final-gather-specular", "solve",
     ["{s}/scenes/cornell-box-specular.gltf", "--patch-size", "0.1", "--rays", "300000", "--render", "final-gather"]
     + SMALL_IMAGE, ["render.exr"]),
    ("solve-render-direct-point-light-mirror", "solve",
     ["{s}/tests/data/specular/point-over-mirror.gltf", "--patch-size", "0.25", "--rays", "100000", "--render",
      "direct"] + SMALL_IMAGE, ["render.exr", "report.json"]),
    ("solve-point-light-under-pane", "solve",
     ["{s}/tests/data/specular/point-under-pane.gltf", "--patch-size", "0.25", "--rays", "100000"] + SMALL_IMAGE,
     ["report.json"]),
    ("solve-render-final-gather-rough-metal", "solve",
     ["{s}/tests/data/specular/lamp-over-rough-metal.gltf", "--patch-size", "0.1", "--rays", "100000", "--render",
      "final-gather"] + SMALL_IMAGE, ["render.exr", "report.json"]),
    ("solve-lightmap", "solve",
     ["{s}/scenes/cornell-box.gltf", "--patch-size", "0.1", "--rays", "300000", "--lightmap", "--lightmap-size", "64",
      "--lightmap-samples", "4"] + SMALL_IMAGE, ["lightmap.exr", "lightmapped.glb", "report.json"]),
    ("solve-lightmap-direct-specular", "solve",
     ["{s}/scenes/cornell-box-specular.gltf", "--patch-size", "0.1", "--rays", "300000", "--lightmap",
      "--lightmap-mode", "direct", "--lightmap-size", "256", "--lightmap-samples", "2"] + SMALL_IMAGE,
     ["lightmap.exr", "report.json"]),
    ("pathtrace-rough-metal-point-light", "pathtrace",
     ["{s}/tests/data/specular/point-over-rough-metal.gltf", "--width", "16", "--height", "16", "--samples", "8"],
     ["out.exr"]),
    ("pathtrace-specular", "pathtrace",
     ["{s}/scenes/cornell-box-specular.gltf", "--width", "24", "--height", "24", "--samples", "16"], ["out.exr"]),
    ("pathtrace-cornell", "pathtrace",
     ["{s}/scenes/cornell-box.gltf", "--width", "24", "--height", "24", "--samples", "16", "--seed", "5"],
     ["out.exr"]),
    ("pathtrace-two-sided", "pathtrace",
     ["{s}/tests/data/pathtrace/two-sided-lamp.gltf", "--width", "16", "--height", "16", "--samples", "8",
      "--max-bounces", "3"], ["out.exr"]),
]

# report.json keys that change from run to run or machine to machine, not with the results.
VOLATILE = {("seconds",), ("device",), ("processes", "devices"), ("solve", "rays_per_second"), ("scene",),
            ("outside", "environment", "file")}


def normalised_report(path):
    report = json.load(open(path))
    for key in VOLATILE:
        node = report
        for part in key[:-1]:
            node = node.get(part, {})
        node.pop(key[-1], None)
    return json.dumps(report, sort_keys=False, indent=1).encode()


def normalised_checkpoint(path):
    """The state without the solving time it took (host/io/checkpoint.cpp, format 5: bytes
    68-75, after the magic, version, fingerprint, three counts and three tallies) and the
    checksum over it (the last 8)."""
    data = open(path, "rb").read()
    return data[:68] + bytes(8) + data[76:-8]


def fingerprint(path):
    if path.endswith("report.json"):
        data = normalised_report(path)
    elif path.endswith(".ckpt"):
        data = normalised_checkpoint(path)
    else:
        data = open(path, "rb").read()
    return hashlib.sha256(data).hexdigest()[:32]


def run_case(radiosity, source, work, name, command, arguments, files):
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    args = [a.format(s=source, o=folder) for a in arguments]
    if command == "solve":
        args += ["--output", folder]
    elif command == "pathtrace":
        args += ["--output", os.path.join(folder, "out.exr")]
    else:
        args += ["--output", os.path.join(folder, "out.csv")]
    done = subprocess.run([radiosity, command] + args, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit("%s: %s %s failed (%d):\n%s" % (name, command, " ".join(args), done.returncode, done.stderr))
    return ["%s %s %s" % (name, f, fingerprint(os.path.join(folder, f))) for f in files]


def main():
    if len(sys.argv) not in (4, 5) or (len(sys.argv) == 5 and sys.argv[4] != "--record"):
        raise SystemExit(__doc__)
    radiosity, source, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    lines = []
    for case in CASES:
        lines += run_case(radiosity, source, work, *case)
    if len(sys.argv) == 5:
        with open(EXPECTED, "w") as out:
            out.write("# tests/regression/same_results.py --record: case, file, SHA-256 (first 128 bits)\n")
            out.write("\n".join(lines) + "\n")
        print("recorded %d fingerprints in %s" % (len(lines), EXPECTED))
        return
    expected = [line for line in open(EXPECTED).read().splitlines() if line and not line.startswith("#")]
    differ = sorted(set(expected) ^ set(lines))
    if differ:
        want = {tuple(l.split()[:2]): l.split()[2] for l in expected}
        have = {tuple(l.split()[:2]): l.split()[2] for l in lines}
        for key in sorted(set(want) | set(have)):
            if want.get(key) != have.get(key):
                print("DIFFERS: %s %s: expected %s, got %s" % (key[0], key[1], want.get(key), have.get(key)))
        raise SystemExit("%d of %d outputs differ from tests/regression/expected.txt (outputs kept in %s)"
                         % (len({k for k in set(want) | set(have) if want.get(k) != have.get(k)}), len(want), work))
    print("bitwise the same: %d outputs of %d runs" % (len(lines), len(CASES)))


if __name__ == "__main__":
    main()
