#!/usr/bin/env python3
"""How many device buffers a command creates and what host data it copies to the device, by an
LD_PRELOAD shim (clcount.c, built here with gcc) around clCreateBuffer and clEnqueueWriteBuffer.
Prints the totals and every block of identical bytes uploaded more than once (same size, same
FNV-1a hash), with the calls' order numbers: a scene array uploaded twice shows there. Blocks of
zeros are placeholders (an empty array's one zeroed element) or cleared counters, listed apart.

Usage: bench/uploads/count_uploads.py RADIOSITY_BINARY ARGS...
  e.g. bench/uploads/count_uploads.py build/radiosity solve scenes/cornell-box.gltf \\
           --render final-gather --lightmap --quiet --output /tmp/out"""
import collections
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ZEROS = {}  # size -> hash of that many zero bytes


def zero_hash(size):
    if size not in ZEROS:
        h = 1469598103934665603
        for _ in range(size):
            h = (h * 1099511628211) & 0xFFFFFFFFFFFFFFFF  # h ^ 0 == h
        ZEROS[size] = f"{h:016x}"
    return ZEROS[size]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    with tempfile.TemporaryDirectory() as work:
        shim = os.path.join(work, "clcount.so")
        subprocess.run(["gcc", "-shared", "-fPIC", "-O2", "-o", shim, os.path.join(HERE, "clcount.c"), "-ldl",
                        "-lpthread"], check=True)
        out = os.path.join(work, "calls.txt")
        env = dict(os.environ, LD_PRELOAD=shim, CLCOUNT_OUT=out)
        subprocess.run(sys.argv[1:], env=env, check=True, stdout=subprocess.DEVNULL)
        calls = [line.split() for line in open(out)]
    uploads = [(int(size), h) for kind, size, h in calls if h != "0" * 16]
    creates = sum(1 for c in calls if c[0] == "create")
    print(f"buffers created: {creates}; host data copied: {len(uploads)} times, "
          f"{sum(s for s, _ in uploads)} bytes")
    seen = collections.defaultdict(list)
    for order, (kind, size, h) in enumerate(calls):
        if h != "0" * 16:
            seen[(int(size), h)].append(order)
    repeated = [(k, v) for k, v in sorted(seen.items()) if len(v) > 1]
    data = [(k, v) for k, v in repeated if k[1] != zero_hash(k[0])]
    zeros = [(k, v) for k, v in repeated if k[1] == zero_hash(k[0])]
    print(f"the same bytes copied more than once: {len(data)}")
    for (size, h), orders in data:
        print(f"  {size} bytes x{len(orders)} (calls {', '.join(map(str, orders))})")
    print(f"zeros copied more than once (placeholders, cleared counters): {len(zeros)}")
    for (size, h), orders in zeros:
        print(f"  {size} bytes x{len(orders)}")


if __name__ == "__main__":
    main()
