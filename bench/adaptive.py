#!/usr/bin/env python3
"""Uniform against adaptive meshing on the Cornell box: error against a converged reference,
element count and time.

Every configuration is one `radiosity solve`: uniform meshes at several patch sizes (one
element per patch), and adaptive meshes (patches of a given size shoot; elements split where
the light bends) at several thresholds, each at several ray counts. The reference is a uniform
mesh finer than any configuration, solved with many more rays. Errors:

  image    mean |I - R| / mean R over the pixels and channels of render.exr (the scene's camera,
           linear radiance): what a user sees, whatever the mesh;
  surfaces largest relative difference of a surface's mean radiosity (report.json), over
           surfaces and channels.

Two steps, so that the solves can run on a machine without numpy (a bare GPU machine):

  bench/adaptive.py run [--radiosity build/radiosity] [--device D] [--out DIR] [--quick]
      solves the reference (unless DIR/reference holds one) and every configuration into DIR;
  bench/adaptive.py analyse [--out DIR]
      writes DIR/adaptive.csv (a row per configuration) and, with matplotlib,
      DIR/adaptive-elements.png/.svg and DIR/adaptive-time.png/.svg (both errors against
      elements and against total time, as report.json's seconds.total has it);
  bench/adaptive.py chart [--out DIR]
      the charts again from DIR/adaptive.csv.

Default DIR: bench-out/adaptive. On the 2-core CPU machine `run` takes about an hour (--quick:
about 10 minutes, fewer configurations and rays); on an H100, a few minutes.
"""

import argparse
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from common import replacing  # noqa: E402  (standard library only, like this step's `run`)

SCENE = "scenes/cornell-box.gltf"
DIAGONAL = 0.5556 * 3 ** 0.5  # the Cornell box's bounding-box diagonal, m (about 0.96)
IMAGE = ["--width", "256", "--height", "256", "--samples", "4"]


def configurations(quick):
    """(name, method, patch divisions, threshold, rays, arguments) of every run."""
    rays = [4e6, 16e6] if quick else [16e6, 64e6, 256e6]
    uniform = [16, 32, 64] if quick else [16, 24, 32, 48, 64, 96, 128]
    bases = [16, 32] if quick else [16, 24, 32, 48]
    thresholds = [0.05] if quick else [0.1, 0.05, 0.02]
    for r in rays:
        for n in uniform:
            yield (f"uniform-{n}-{r / 1e6:.0f}M", "uniform", n, None, r,
                   ["--patch-size", f"{DIAGONAL / n:.6f}", "--rays", f"{r:.0f}"])
        for n in bases:
            for t in thresholds:
                yield (f"adaptive-{n}-{t}-{r / 1e6:.0f}M", "adaptive", n, t, r,
                       ["--patch-size", f"{DIAGONAL / n:.6f}", "--rays", f"{r:.0f}", "--adaptive",
                        "--refine-threshold", str(t)])


def run(args):
    os.makedirs(args.out, exist_ok=True)
    device = ["--device", args.device] if args.device else []

    def solve(name, extra):
        out = os.path.join(args.out, name)
        if os.path.exists(os.path.join(out, "report.json")):
            return
        cmd = [args.radiosity, "solve", SCENE, "--output", out, "--quiet", "--max-patches", "2000000"] + IMAGE
        subprocess.run(cmd + device + extra, check=True)
        print(name, file=sys.stderr, flush=True)

    solve("reference", ["--patch-size", f"{DIAGONAL / args.reference_divisions:.6f}",
                        "--rays", f"{args.reference_rays:.0f}", "--tolerance", "1e-4"])
    for name, _, _, _, _, extra in configurations(args.quick):
        solve(name, extra)


def analyse(args):
    import numpy as np
    from exr import read_exr

    def load(name):
        with open(os.path.join(args.out, name, "report.json")) as f:
            report = json.load(f)
        return report, read_exr(os.path.join(args.out, name, "render.exr"))[..., :3]

    ref_report, ref_image = load("reference")
    ref_means = {s["name"]: np.array(s["radiosity"]) for s in ref_report["surfaces"]}
    rows = []
    for name, method, divisions, threshold, rays, _ in configurations(args.quick):
        if not os.path.exists(os.path.join(args.out, name, "report.json")):
            continue
        report, image = load(name)
        surface_error = 0.0
        for s in report["surfaces"]:
            ref = ref_means[s["name"]]
            lit = ref > 0
            if lit.any():
                rel = np.abs(np.array(s["radiosity"])[lit] - ref[lit]) / ref[lit]
                surface_error = max(surface_error, float(rel.max()))
        rows.append({"name": name, "method": method, "patch_divisions": divisions, "threshold": threshold or "",
                     "rays": int(rays), "patches": report["mesh"]["patches"], "elements": report["mesh"]["elements"],
                     "seconds": round(report["seconds"]["total"], 4),
                     "image_error": round(float(np.abs(image - ref_image).mean() / ref_image.mean()), 6),
                     "surface_error": round(surface_error, 6), "device": report["device"]["name"]})
    with replacing(os.path.join(args.out, "adaptive.csv")) as tmp, open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    for r in rows:
        print(f"{r['name']:26s} elements {r['elements']:7d}  {r['seconds']:8.2f} s  image {r['image_error']:.4f}"
              f"  surfaces {r['surface_error']:.4f}")
    chart(rows, args.out)


def chart(rows, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no charts", file=sys.stderr)
        return
    device = rows[0]["device"]
    for x_key, x_label, name in (("elements", "elements", "adaptive-elements"),
                                 ("seconds", f"total time, s ({device})", "adaptive-time")):
        fig, axes = plt.subplots(1, 2, figsize=(11.0, 4.6))
        for ax, y_key, y_label in ((axes[0], "image_error", "image error, mean |I - R| / mean R"),
                                   (axes[1], "surface_error", "surface error, largest relative")):
            for method, style in (("uniform", "-"), ("adaptive", "--")):
                groups = {}
                for r in rows:
                    if r["method"] == method:
                        groups.setdefault((int(r["rays"]), str(r["threshold"])), []).append(r)
                for (rays, threshold), sel in sorted(groups.items()):
                    sel.sort(key=lambda r: float(r[x_key]))
                    label = f"uniform, {rays / 1e6:.0f}M rays" if method == "uniform" else \
                        f"adaptive {threshold}, {rays / 1e6:.0f}M rays"
                    ax.plot([float(r[x_key]) for r in sel], [float(r[y_key]) for r in sel], linestyle=style,
                            marker="o" if method == "uniform" else "^", label=label)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel(x_label)
            ax.set_ylabel(y_label)
            ax.grid(True, which="both", alpha=0.3)
        axes[0].legend(fontsize=6, ncol=2)
        fig.suptitle("Cornell box: uniform against adaptive meshing (reference: 1/160 of the diagonal)")
        fig.tight_layout()
        for ext in ("png", "svg"):
            with replacing(os.path.join(out, f"{name}.{ext}")) as tmp:
                fig.savefig(tmp, format=ext, dpi=100)
        plt.close(fig)


def chart_from_csv(args):
    with open(os.path.join(args.out, "adaptive.csv")) as f:
        chart(list(csv.DictReader(f)), args.out)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("step", choices=["run", "analyse", "chart"])
    parser.add_argument("--radiosity", default="build/radiosity")
    parser.add_argument("--device", default="")
    parser.add_argument("--out", default="bench-out/adaptive")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--reference-divisions", type=int, default=160,
                        help="reference patch size: the diagonal over this (default 160)")
    parser.add_argument("--reference-rays", type=float, default=1e9)
    args = parser.parse_args()
    {"run": run, "analyse": analyse, "chart": chart_from_csv}[args.step](args)


if __name__ == "__main__":
    main()
