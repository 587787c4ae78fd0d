#!/usr/bin/env python3
"""The scene generator still writes the checked-in files, byte for byte.

Runs `scenes/generate.py --out TMP` and compares every file it wrote with the file of the same
path in the repository (found from this file). Fails, naming them, when any differs or is
missing from the repository (in a git checkout: not tracked by git): a recipe was edited
without regenerating, or a checked-in file by hand. Exit status 0 when all match, 1 otherwise.

    python3 tests/scenes/same_bytes.py
"""

import filecmp
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def written_files(directory):
    """Every file under `directory`, as sorted paths relative to it."""
    return sorted(os.path.relpath(os.path.join(parent, name), directory)
                  for parent, _, names in os.walk(directory) for name in names)


def tracked_files():
    """The files git tracks in the repository (relative paths), or None where git cannot tell
    (a source archive, no git)."""
    try:
        listed = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    return {os.path.normpath(p) for p in listed.stdout.decode("utf-8").split("\0") if p}


def main():
    tracked = tracked_files()
    with tempfile.TemporaryDirectory(prefix="scenes-same-bytes-") as out:
        subprocess.run([sys.executable, os.path.join(ROOT, "scenes", "generate.py"), "--out", out], check=True)
        files = written_files(out)
        missing = [f for f in files
                   if not os.path.isfile(os.path.join(ROOT, f)) or (tracked is not None and f not in tracked)]
        differ = [f for f in files if f not in missing
                  and not filecmp.cmp(os.path.join(out, f), os.path.join(ROOT, f), shallow=False)]
    if not files:
        print("scenes/generate.py wrote no files")
        return 1
    for f in differ:
        print("differs from what scenes/generate.py writes: %s" % f)
    for f in missing:
        print("written by scenes/generate.py but not in the repository: %s" % f)
    if differ or missing:
        print("%d of %d files differ or are missing; run python3 scenes/generate.py and commit them"
              % (len(differ) + len(missing), len(files)))
        return 1
    print("scenes/generate.py writes all %d checked-in files byte for byte" % len(files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
