#!/usr/bin/env python3
"""The Cornell box as finely tessellated content: each of its 16 quads cut into K x K quads, so
32 K^2 triangles (K = 31: 30,752; K = 90: 259,200; K = 177: about 1M) in the places of the
bundled box's 32. Not bundled (the files grow with K): bench programs write them where they work.

    python3 scenes/cornell_cut.py K OUT.glb"""

import os
import sys

sys.dont_write_bytecode = True

from bundled_scenes import cornell_box  # noqa: E402
from gltf_encoder import glb_bytes, write  # noqa: E402


def main(argv):
    if len(argv) != 2 or not argv[0].isdigit() or int(argv[0]) < 1:
        sys.exit(__doc__.split("\n\n")[-1].strip())
    b = cornell_box(cut=int(argv[0]))
    directory, name = os.path.split(os.path.abspath(argv[1]))
    write(directory, name, glb_bytes(b.document(uri=None), b.padded_data()))


if __name__ == "__main__":
    main(sys.argv[1:])
