"""What the experiments share: running the built programs with timing and peak memory, the
machine's description, CSV files, and the sizes of a run (--quick, --tiny).

Programs run as child processes; wall time is measured around each, peak resident memory
comes from the child's own rusage (os.wait4), so it is that process's, not the largest seen."""

import argparse
import atexit
import contextlib
import csv
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# The process's umask, for the mode of files made by mkstemp (which makes them 0600).
_UMASK = os.umask(0o022)
os.umask(_UMASK)


def log(*words):
    print(time.strftime("%H:%M:%S"), *words, file=sys.stderr, flush=True)


def arguments(description, extra=None):
    """The options every experiment takes."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (default: build)")
    p.add_argument("--output", default=os.path.join(ROOT, "docs", "results"),
                   help="where CSV files and charts go (default: docs/results)")
    p.add_argument("--work", default=None, help="scratch directory for the runs' own outputs (default: a temporary one)")
    p.add_argument("--device", default="", help="OpenCL device for every run (see 'radiosity devices')")
    p.add_argument("--quick", action="store_true", help="fewer and smaller runs (the whole pipeline in minutes)")
    p.add_argument("--tiny", action="store_true", help="the smallest runs that exercise every step (smoke test)")
    if extra:
        extra(p)
    args = p.parse_args()
    args.level = "tiny" if args.tiny else "quick" if args.quick else "full"
    os.makedirs(args.output, exist_ok=True)
    if args.work is None:  # a scratch directory of our own: removed at exit (a given --work is kept)
        args.work = tempfile.mkdtemp(prefix="radiosity-bench-")
        atexit.register(shutil.rmtree, args.work, ignore_errors=True)
    os.makedirs(args.work, exist_ok=True)
    return args


def pick(level, full, quick, tiny):
    return {"full": full, "quick": quick, "tiny": tiny}[level]


class Run:
    """The outcome of one process: wall seconds, peak RSS (MiB), exit status, stdout, stderr."""

    def __init__(self, cmd, wall, rss, status, stdout, stderr):
        self.cmd, self.wall, self.rss, self.status, self.stdout, self.stderr = cmd, wall, rss, status, stdout, stderr

    def check(self):
        if self.status != 0:
            raise RuntimeError("%s failed (%d): %s" % (" ".join(self.cmd), self.status, self.stderr.strip()[-2000:]))
        return self


def run(cmd, env=None, threads=None, timeout=None):
    """Runs cmd to completion; threads sets POCL_MAX_PTHREAD_COUNT."""
    environment = dict(os.environ)
    if env:
        environment.update(env)
    if threads is not None:
        environment["POCL_MAX_PTHREAD_COUNT"] = str(threads)
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        start = time.perf_counter()
        child = subprocess.Popen([str(c) for c in cmd], stdout=out, stderr=err, env=environment)
        deadline = None if timeout is None else start + timeout
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG if deadline else 0)
            if pid:
                break
            if time.perf_counter() > deadline:
                child.kill()
                pid, status, usage = os.wait4(child.pid, 0)
                break
            time.sleep(0.02)
        wall = time.perf_counter() - start
        child.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return Run([str(c) for c in cmd], wall, usage.ru_maxrss / 1024.0, child.returncode,
                   out.read().decode(errors="replace"), err.read().decode(errors="replace"))


def run_together(cmds, threads=None):
    """Starts every command at once and waits for all: [Run] in order. For control runs, as
    two independent single-thread processes side by side."""
    environment = dict(os.environ)
    if threads is not None:
        environment["POCL_MAX_PTHREAD_COUNT"] = str(threads)
    files, children, start = [], [], time.perf_counter()
    for cmd in cmds:
        out, err = tempfile.TemporaryFile(), tempfile.TemporaryFile()
        files.append((out, err))
        children.append(subprocess.Popen([str(c) for c in cmd], stdout=out, stderr=err, env=environment))
    runs = []
    for cmd, child, (out, err) in zip(cmds, children, files):
        _, status, usage = os.wait4(child.pid, 0)
        child.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        runs.append(Run([str(c) for c in cmd], time.perf_counter() - start, usage.ru_maxrss / 1024.0, child.returncode,
                        out.read().decode(errors="replace"), err.read().decode(errors="replace")))
        out.close()
        err.close()
    return runs


def csv_line(run_result):
    """The last two lines of a benchmark's output (header, values) as a dict."""
    lines = [l for l in run_result.stdout.splitlines() if l.strip()]
    return dict(zip(lines[-2].split(","), lines[-1].split(",")))


def load_average():
    try:
        with open("/proc/loadavg", encoding="utf-8") as f:
            return float(f.read().split()[0])
    except OSError:
        return float("nan")


class Radiosity:
    """The command line, with the device every run uses."""

    def __init__(self, args):
        self.exe = os.path.join(args.build, "radiosity")
        self.bench = os.path.join(args.build, "bench")
        self.device = args.device
        self.work = args.work
        if not os.access(self.exe, os.X_OK):
            sys.exit("%s not found: build first (scripts/setup.sh)" % self.exe)
        self.count = 0

    def _device(self):
        return ["--device", self.device] if self.device else []

    def scratch(self, name):
        self.count += 1
        path = os.path.join(self.work, "%04d-%s" % (self.count, name))
        shutil.rmtree(path, ignore_errors=True)
        return path

    def solve(self, scene, options, threads=None, timeout=None, keep=False):
        """report.json of `radiosity solve scene options`, with 'wall', 'rss' and 'warnings'
        added; the output directory in 'output' (removed unless keep)."""
        out = self.scratch(os.path.basename(scene).split(".")[0])
        cmd = [self.exe, "solve", scene, "--quiet", "--output", out] + self._device() + [str(o) for o in options]
        r = run(cmd, threads=threads, timeout=timeout)
        if r.status != 0:
            raise RuntimeError("%s failed (%d): %s" % (" ".join(cmd), r.status, r.stderr.strip()[-2000:]))
        with open(os.path.join(out, "report.json"), encoding="utf-8") as f:
            report = json.load(f)
        report["wall"], report["rss"], report["output"] = r.wall, r.rss, out
        if not keep:
            shutil.rmtree(out, ignore_errors=True)
        return report

    def viewfactors(self, scene, options, threads=None):
        """Rows of `radiosity viewfactors` CSV as {(from, to): F}, with the Run."""
        out = self.scratch("vf") + ".csv"
        cmd = [self.exe, "viewfactors", scene, "--output", out] + self._device() + [str(o) for o in options]
        r = run(cmd, threads=threads).check()
        table = {}
        with open(out, newline="", encoding="utf-8") as f:
            for row in csv.DictReader(f):
                table[(row["from"], row["to"])] = float(row["F"])
        os.remove(out)
        return table, r

    def pathtrace(self, scene, exr, options, threads=None):
        cmd = [self.exe, "pathtrace", scene, "--output", exr] + self._device() + [str(o) for o in options]
        return run(cmd, threads=threads).check()

    def bench_program(self, name, options, threads=None):
        """One CSV line (header + values) of build/bench/<name>, as a dict."""
        cmd = [os.path.join(self.bench, name)] + self._device() + [str(o) for o in options]
        r = run(cmd, threads=threads).check()
        row = csv_line(r)
        row["wall"], row["rss"] = r.wall, r.rss
        return row

    def bench_command(self, name, options):
        return [os.path.join(self.bench, name)] + self._device() + [str(o) for o in options]


@contextlib.contextmanager
def replacing(path):
    """`with replacing(path) as tmp:` gives the name of a new, empty file beside path to write;
    when the block ends without an exception it is renamed to path (os.replace: atomic on one
    file system), so a reader never sees half a file and a run that fails midway leaves the
    previous file whole. On an exception the temporary file is removed. The file gets the
    mode an ordinary open() would give it."""
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=directory, prefix="." + os.path.basename(path) + ".", suffix=".tmp")
    os.close(fd)
    try:
        os.chmod(tmp, 0o666 & ~_UMASK)
        yield tmp
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.remove(tmp)
        raise


def write_csv(path, rows, fields=None):
    fields = fields or list(dict.fromkeys(k for row in rows for k in row))
    with replacing(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in row.items()})
    log("wrote", os.path.relpath(path, ROOT) if path.startswith(ROOT) else path)


def machine(args):
    """What the figures were measured on."""
    info = {"date": time.strftime("%Y-%m-%d %H:%M %Z"), "host": platform.node(), "cpus": os.cpu_count(),
            "python": platform.python_version(), "level": args.level, "device_option": args.device or "(default)"}
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            info["cpu"] = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
        with open("/proc/meminfo", encoding="utf-8") as f:
            info["memory_gib"] = round(int(f.readline().split()[1]) / 1048576.0, 1)
    except OSError:
        pass
    r = run([os.path.join(args.build, "radiosity"), "devices"])
    info["devices"] = r.stdout.strip()
    r = run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"])
    info["commit"] = r.stdout.strip()
    try:
        with open("/proc/loadavg", encoding="utf-8") as f:
            info["load_average_at_start"] = f.read().split()[:3]
    except OSError:
        pass
    return info


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def timed_seconds(report):
    """Seconds a result took to compute: load, mesh, BVH and device setup, and the solve (form
    factors included); not the rendering and writing that every run does alike."""
    s = report["seconds"]
    return s["load"] + s["mesh"] + s["bvh"] + s["solve"]
