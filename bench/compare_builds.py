#!/usr/bin/env python3
"""The same jobs on two builds of the program, interleaved (A, B, A, B, ...) so that a shared
machine's noise falls on both alike; prints each job's median per build, B / A, and the median and quartiles of each round's B / A.

Usage: bench/compare_builds.py BUILD_A BUILD_B [--rounds N] [--warmup N] [--scene FILE]
                               [--jobs rays,solve,command]

Jobs, on the Cornell box (or --scene) with the device's default threads:
  rays        bench_rays: the shoot kernel's median rays per second (higher is better)
  solve       bench_solve --rays 4e6: the whole progressive solve's seconds
  render      radiosity solve --render final-gather --lightmap: report.json's seconds.render
              (the final-gather image, with the solution's device inputs it shares)
  lightmap    the same run's seconds.lightmap (the lightmap bake, fill and seams)
  whole       the same run's wall time
Each build runs from its own directory, so each reads its own kernels."""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run_rays(build, scene):
    out = subprocess.run([os.path.join(build, "bench", "bench_rays"), "--scene", scene], capture_output=True, text=True,
                         check=True).stdout.strip().splitlines()
    header, row = out[0].split(","), out[-1].split(",")
    return {"rays": float(row[header.index("median_rays_per_s")])}


def run_solve(build, scene):
    out = subprocess.run([os.path.join(build, "bench", "bench_solve"), "--scene", scene, "--rays", "4e6"],
                         capture_output=True, text=True, check=True).stdout.strip().splitlines()
    header, row = out[0].split(","), out[-1].split(",")
    return {"solve": float(row[header.index("solve_s")])}


def run_command(build, scene):
    with tempfile.TemporaryDirectory() as work:
        start = time.monotonic()
        subprocess.run([os.path.join(build, "radiosity"), "solve", scene, "--render", "final-gather", "--lightmap",
                        "--quiet", "--output", work], capture_output=True, text=True, check=True)
        whole = time.monotonic() - start
        with open(os.path.join(work, "report.json")) as f:
            seconds = json.load(f)["seconds"]
    return {"render": seconds["render"], "lightmap": seconds["lightmap"], "whole": whole}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=1,
                        help="rounds run first and not counted (PoCL compiles and caches the kernels then)")
    parser.add_argument("--scene", default=os.path.join(HERE, "..", "scenes", "cornell-box.gltf"))
    parser.add_argument("--jobs", default="rays,solve,command",
                        help="which of rays, solve and command (render, lightmap, whole) to run")
    args = parser.parse_args()
    scene = os.path.abspath(args.scene)
    builds = [os.path.abspath(args.a), os.path.abspath(args.b)]
    samples = [{}, {}]
    known = {"rays": run_rays, "solve": run_solve, "command": run_command}
    jobs = [known[name] for name in args.jobs.split(",")]
    for round in range(args.warmup + args.rounds):
        for job in jobs:
            for k, build in enumerate(builds):
                # Each build from its source tree (the parent of its build directory).
                os.chdir(os.path.dirname(build))
                for name, value in job(build, scene).items():
                    if round >= args.warmup:
                        samples[k].setdefault(name, []).append(value)
    # Each round's B / A: the two runs of a round were made minutes apart at most, so their ratio
    # is less noisy than the ratio of the medians; its quartiles say how far to trust it.
    print("job,median_a,median_b,b_over_a,paired_ratio_median,paired_ratio_q1,paired_ratio_q3,rounds")
    for name in ("rays", "solve", "render", "lightmap", "whole"):
        if name not in samples[0]:
            continue
        a, b = statistics.median(samples[0][name]), statistics.median(samples[1][name])
        ratios = sorted(y / x for x, y in zip(samples[0][name], samples[1][name]))
        q = statistics.quantiles(ratios, n=4) if len(ratios) > 1 else [ratios[0]] * 3
        print(f"{name},{a:.4g},{b:.4g},{b / a:.3f},{statistics.median(ratios):.3f},{q[0]:.3f},{q[2]:.3f},"
              f"{args.rounds}")

if __name__ == "__main__":
    main()
