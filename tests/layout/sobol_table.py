#!/usr/bin/python3
"""kernels/rng.h's Sobol table, from the direction numbers.

The 4-D Sobol points of kernels/rng.h (dimension 0 the van der Corput sequence, 1 to 3 by Joe and
Kuo's primitive polynomials) are the XOR of one direction number per set bit of the index. The
kernel takes the index four bits at a time instead, from a table of the XORs of each nibble's
four direction numbers (8 nibbles x 16 values): a quarter of the steps per point, the same bits.
This script holds the direction numbers and makes that table from them.

  tests/layout/sobol_table.py            print the table as rng.h holds it
  tests/layout/sobol_table.py --check    exit 1 unless rng.h holds exactly that table (a test)"""

import os
import re
import sys

# Row b: the direction numbers of index bit b, one per dimension.
DIRECTIONS = [
    (0x80000000, 0x80000000, 0x80000000, 0x80000000),
    (0x40000000, 0xc0000000, 0xc0000000, 0xc0000000),
    (0x20000000, 0xa0000000, 0x60000000, 0x20000000),
    (0x10000000, 0xf0000000, 0x90000000, 0x50000000),
    (0x08000000, 0x88000000, 0xe8000000, 0xf8000000),
    (0x04000000, 0xcc000000, 0x5c000000, 0x74000000),
    (0x02000000, 0xaa000000, 0x8e000000, 0xa2000000),
    (0x01000000, 0xff000000, 0xc5000000, 0x93000000),
    (0x00800000, 0x80800000, 0x68800000, 0xd8800000),
    (0x00400000, 0xc0c00000, 0x9cc00000, 0x25400000),
    (0x00200000, 0xa0a00000, 0xee600000, 0x59e00000),
    (0x00100000, 0xf0f00000, 0x55900000, 0xe6d00000),
    (0x00080000, 0x88880000, 0x80680000, 0x78080000),
    (0x00040000, 0xcccc0000, 0xc09c0000, 0xb40c0000),
    (0x00020000, 0xaaaa0000, 0x60ee0000, 0x82020000),
    (0x00010000, 0xffff0000, 0x90550000, 0xc3050000),
    (0x00008000, 0x80008000, 0xe8808000, 0x208f8000),
    (0x00004000, 0xc000c000, 0x5cc0c000, 0x51474000),
    (0x00002000, 0xa000a000, 0x8e606000, 0xfbea2000),
    (0x00001000, 0xf000f000, 0xc5909000, 0x75d93000),
    (0x00000800, 0x88008800, 0x6868e800, 0xa0858800),
    (0x00000400, 0xcc00cc00, 0x9c9c5c00, 0x914e5400),
    (0x00000200, 0xaa00aa00, 0xeeee8e00, 0xdbe79e00),
    (0x00000100, 0xff00ff00, 0x5555c500, 0x25db6d00),
    (0x00000080, 0x80808080, 0x8000e880, 0x58800080),
    (0x00000040, 0xc0c0c0c0, 0xc0005cc0, 0xe54000c0),
    (0x00000020, 0xa0a0a0a0, 0x60008e60, 0x79e00020),
    (0x00000010, 0xf0f0f0f0, 0x9000c590, 0xb6d00050),
    (0x00000008, 0x88888888, 0xe8006868, 0x800800f8),
    (0x00000004, 0xcccccccc, 0x5c009c9c, 0xc00c0074),
    (0x00000002, 0xaaaaaaaa, 0x8e00eeee, 0x200200a2),
    (0x00000001, 0xffffffff, 0xc5005555, 0x50050093),
]


def table():
    rows = []
    for nibble in range(8):
        entries = []
        for value in range(16):
            x = [0, 0, 0, 0]
            for bit in range(4):
                if value >> bit & 1:
                    x = [a ^ d for a, d in zip(x, DIRECTIONS[4 * nibble + bit])]
            entries.append("{%s}" % ", ".join("0x%08xu" % a for a in x))
        pairs = [", ".join(entries[i:i + 2]) for i in range(0, 16, 2)]
        rows.append("    {" + ",\n     ".join(pairs) + "},")
    return "__constant uint kSobolNibbles[8][16][4] = {\n" + "\n".join(rows) + "\n};"


def main():
    text = table()
    if "--check" not in sys.argv[1:]:
        print(text)
        return
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    with open(os.path.join(root, "kernels", "rng.h"), encoding="utf-8") as f:
        held = re.search(r"__constant uint kSobolNibbles\[8\]\[16\]\[4\] = \{.*?\n\};", f.read(), re.S)
    if not held or held.group(0) != text:
        sys.exit("kernels/rng.h: kSobolNibbles is not the table tests/layout/sobol_table.py makes from the "
                 "direction numbers; run it and paste its output")
    print("kernels/rng.h: kSobolNibbles matches the direction numbers")


if __name__ == "__main__":
    main()
