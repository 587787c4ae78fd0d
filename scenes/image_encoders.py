"""Image files written without libraries: 8-bit RGBA PNG (textures) and uncompressed scanline
OpenEXR of 32-bit floats (environment maps)."""

import struct
import zlib


def png_bytes(width, height, rgba):
    """An 8-bit RGBA PNG of the given texels (rows from the top, 4 bytes per texel)."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    rows = b"".join(b"\0" + bytes(rgba[4 * width * y:4 * width * (y + 1)]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def exr_bytes(width, height, channels):
    """An uncompressed scanline OpenEXR image of 32-bit float channels: `channels` maps a
    channel name to its width * height values, rows from the top."""
    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    names = sorted(channels)
    chlist = b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for n in names) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (attribute("channels", "chlist", chlist) + attribute("compression", "compression", b"\0")
              + attribute("dataWindow", "box2i", box) + attribute("displayWindow", "box2i", box)
              + attribute("lineOrder", "lineOrder", b"\0")
              + attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + attribute("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
              + attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    start = b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + header
    line_bytes = 4 * width * len(names)
    table_end = len(start) + 8 * height
    offsets = b"".join(struct.pack("<Q", table_end + y * (8 + line_bytes)) for y in range(height))
    lines = b"".join(struct.pack("<ii", y, line_bytes)
                     + b"".join(struct.pack("<%df" % width, *channels[n][y * width:(y + 1) * width])
                                for n in names)
                     for y in range(height))
    return start + offsets + lines


def rgb_exr(width, height, texel):
    """An RGB map whose texel (x, y) is texel(x, y) = (r, g, b)."""
    values = [texel(x, y) for y in range(height) for x in range(width)]
    return exr_bytes(width, height, {c: [v[i] for v in values] for i, c in enumerate("RGB")})
