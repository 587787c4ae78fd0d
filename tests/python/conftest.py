"""Fixtures of the Python module's tests (tests/python/).

Run by CTest (`python_module`, tests/CMakeLists.txt) with PYTHONPATH at the built package
(build/python) and RADIOSITY_PROGRAM at the built program, whose output the module must match bit
for bit. By hand, from the repository root:

    PYTHONPATH=build/python RADIOSITY_PROGRAM=build/radiosity python3 -m pytest -q tests/python
"""

import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORNELL = os.path.join(ROOT, "scenes", "cornell-box.gltf")


@pytest.fixture(scope="session")
def program():
    path = os.environ.get("RADIOSITY_PROGRAM", os.path.join(ROOT, "build", "radiosity"))
    assert os.access(path, os.X_OK), "no program at %s: set RADIOSITY_PROGRAM" % path
    return path


@pytest.fixture(scope="session")
def run(program):
    """Runs the program; returns its standard output (text). Fails the test on a non-zero status."""

    def run(*args, expect=0):
        done = subprocess.run([program] + [str(a) for a in args], capture_output=True, text=True)
        assert done.returncode == expect, "radiosity %s: status %d\n%s" % (" ".join(map(str, args)),
                                                                           done.returncode, done.stderr)
        return done.stdout

    return run
