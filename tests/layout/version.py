#!/usr/bin/env python3
"""The version is written once: CMakeLists.txt's project() version (what --version prints) and
CITATION.cff's must agree. Exit status 1, naming both, when they do not."""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
cmake = re.search(r"project\(radiosity VERSION ([0-9.]+)", open(os.path.join(ROOT, "CMakeLists.txt")).read())
citation = re.search(r"^version: *([0-9.]+)", open(os.path.join(ROOT, "CITATION.cff")).read(), re.M)
if not cmake or not citation or cmake.group(1) != citation.group(1):
    sys.exit("version mismatch: CMakeLists.txt %s, CITATION.cff %s" %
             (cmake and cmake.group(1), citation and citation.group(1)))
print("ok   version %s in CMakeLists.txt and CITATION.cff" % cmake.group(1))
