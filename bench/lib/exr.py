"""A minimal OpenEXR reader for the images this project writes: scanline files with FLOAT or
HALF channels, uncompressed or ZIP/ZIPS-compressed (OpenEXR's default for new files is ZIP).
Returns a numpy array (height, width, channels) in the order R, G, B when present.

Standard library + numpy only, so the benchmarks need no Python OpenEXR bindings."""

import struct
import zlib

import numpy as np

MAGIC = 20000630
NO_COMPRESSION, RLE, ZIPS, ZIP = 0, 1, 2, 3
LINES_PER_BLOCK = {NO_COMPRESSION: 1, RLE: 1, ZIPS: 1, ZIP: 16}
PIXEL_TYPES = {1: np.dtype("<f2"), 2: np.dtype("<f4"), 0: np.dtype("<u4")}


def _cstring(data, pos):
    end = data.index(b"\0", pos)
    return data[pos:end].decode("latin-1"), end + 1


def _header(data):
    if len(data) < 8 or struct.unpack_from("<i", data, 0)[0] != MAGIC:
        raise ValueError("not an OpenEXR file")
    if struct.unpack_from("<i", data, 4)[0] & 0x200:
        raise ValueError("tiled OpenEXR files are not supported")
    pos, attrs = 8, {}
    while data[pos] != 0:
        name, pos = _cstring(data, pos)
        _type, pos = _cstring(data, pos)
        size = struct.unpack_from("<i", data, pos)[0]
        attrs[name] = data[pos + 4:pos + 4 + size]
        pos += 4 + size
    return attrs, pos + 1


def _channels(raw):
    out, pos = [], 0
    while raw[pos] != 0:
        name, pos = _cstring(raw, pos)
        pixel_type = struct.unpack_from("<i", raw, pos)[0]
        out.append((name, PIXEL_TYPES[pixel_type]))
        pos += 16  # pixel type, pLinear + reserved, xSampling, ySampling
    return out


def _undo_predictor(raw):
    t = np.frombuffer(raw, dtype=np.uint8).astype(np.int64)
    if len(t) == 0:
        return b""
    d = t.copy()
    d[1:] -= 128
    return (np.cumsum(d) & 0xFF).astype(np.uint8)


def _deinterleave(t):
    half = (len(t) + 1) // 2
    out = np.empty(len(t), dtype=np.uint8)
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return out.tobytes()


def read_exr(path):
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _header(data)
    compression = attrs["compression"][0]
    if compression not in LINES_PER_BLOCK:
        raise ValueError("%s: compression %d is not supported" % (path, compression))
    xmin, ymin, xmax, ymax = struct.unpack("<4i", attrs["dataWindow"])
    width, height = xmax - xmin + 1, ymax - ymin + 1
    channels = _channels(attrs["channels"])  # stored in alphabetical order
    lines = LINES_PER_BLOCK[compression]
    blocks = (height + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % blocks, data, pos)
    planes = {name: np.zeros((height, width), dtype=np.float64) for name, _ in channels}
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        raw = data[offset + 8:offset + 8 + size]
        count = min(lines, ymax + 1 - y)
        expected = count * width * sum(dt.itemsize for _, dt in channels)
        if compression in (ZIP, ZIPS) and size < expected:
            raw = _deinterleave(_undo_predictor(zlib.decompress(raw)))
        elif compression == RLE and size < expected:
            raise ValueError("%s: RLE-compressed blocks are not supported" % path)
        at = 0
        for line in range(count):
            for name, dt in channels:
                n = width * dt.itemsize
                planes[name][y - ymin + line] = np.frombuffer(raw[at:at + n], dtype=dt)
                at += n
    order = [c for c in ("R", "G", "B") if c in planes] or sorted(planes)
    return np.stack([planes[c] for c in order], axis=-1)
