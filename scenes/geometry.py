"""Points and triangles, before they become glTF: vector helpers, polygons wound to face a
direction, quads and boxes, tessellated disks and spheres, and the rotation that aims a glTF
light. Counter-clockwise triangles face their normal (shared/DESIGN.md)."""

import math


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def centroid(points):
    n = float(len(points))
    return tuple(sum(p[k] for p in points) / n for k in range(3))


def polygon_normal(points):
    """Newell's (unnormalised) normal of a planar or near-planar polygon."""
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return tuple(n)


def facing(points, direction):
    """Return the polygon's vertices ordered so its normal has a positive dot with direction."""
    if dot(polygon_normal(points), direction) < 0.0:
        return [points[0]] + list(reversed(points[1:]))
    return list(points)


def clean(x):
    """Snap cos/sin round-off at multiples of pi/2 to exact values; no negative zero."""
    return round(x, 15) + 0.0


def rotation_to(direction):
    """The unit quaternion [x, y, z, w] that turns -Z (where a glTF light shines) to `direction`."""
    length = math.sqrt(dot(direction, direction))
    d = tuple(c / length for c in direction)
    a = (0.0, 0.0, -1.0)
    c = dot(a, d)
    if c < -0.999999:
        return [0.0, 1.0, 0.0, 0.0]  # a half turn about +Y
    axis = cross(a, d)
    w = math.sqrt((1.0 + c) / 2.0)
    k = 0.5 / w
    return [clean(axis[0] * k), clean(axis[1] * k), clean(axis[2] * k), clean(w)]


def square(axis, level, normal_sign):
    """Unit square [0,1]^2 in the plane axis = level, facing +axis (sign +1) or -axis (-1)."""
    u, v = [k for k in range(3) if k != axis]
    quad = []
    for a, b in ((0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)):
        p = [0.0, 0.0, 0.0]
        p[axis], p[u], p[v] = float(level), a, b
        quad.append(tuple(p))
    direction = [0.0, 0.0, 0.0]
    direction[axis] = float(normal_sign)
    return facing(quad, direction)


def quads_to_mesh(quads):
    """Quads (lists of 4 points, already oriented) -> (positions, triangle indices)."""
    positions, indices = [], []
    for quad in quads:
        base = len(positions)
        positions.extend(quad)
        indices.extend([base, base + 1, base + 2, base, base + 2, base + 3])
    return positions, indices


def cut_quad(quad, k):
    """The quad (4 points, oriented) cut into k x k quads by bilinear interpolation, wound as it
    is: tessellated content with many small faces in the same places."""
    def at(s, t):
        return tuple((1 - s) * (1 - t) * a + s * (1 - t) * b + s * t * c + (1 - s) * t * d
                     for a, b, c, d in zip(*quad))
    return [[at(i / k, j / k), at((i + 1) / k, j / k), at((i + 1) / k, (j + 1) / k), at(i / k, (j + 1) / k)]
            for j in range(k) for i in range(k)]


def rect(axis, level, span_u, span_v, direction):
    """The rectangle axis = level, span_u x span_v over the other two axes (in x, y, z order),
    wound to face `direction`."""
    u, v = [k for k in range(3) if k != axis]
    quad = []
    for a, b in ((span_u[0], span_v[0]), (span_u[1], span_v[0]), (span_u[1], span_v[1]),
                 (span_u[0], span_v[1])):
        p = [0.0, 0.0, 0.0]
        p[axis], p[u], p[v] = float(level), float(a), float(b)
        quad.append(tuple(p))
    return facing(quad, direction)


def inward_box(lo, hi):
    """The six faces of the box [lo, hi], facing into it: (name, quad)."""
    centre = tuple(0.5 * (lo[k] + hi[k]) for k in range(3))
    faces = []
    for axis, names in ((0, ("left", "right")), (1, ("floor", "ceiling")), (2, ("back", "front"))):
        u, v = [k for k in range(3) if k != axis]
        for level, name in zip((lo[axis], hi[axis]), names):
            inward = [0.0, 0.0, 0.0]
            inward[axis] = centre[axis] - level
            faces.append((name, rect(axis, level, (lo[u], hi[u]), (lo[v], hi[v]), inward)))
    return faces


def box_quads(lo, hi):
    """The six faces of an axis-aligned box, facing out."""
    middle = tuple(0.5 * (a + c) for a, c in zip(lo, hi))
    quads = []
    for axis in range(3):
        for level in (lo[axis], hi[axis]):
            u, v = [k for k in range(3) if k != axis]
            quad = []
            for a, c in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis] = level
                p[u] = (lo[u], hi[u])[a]
                p[v] = (lo[v], hi[v])[c]
                quad.append(tuple(p))
            direction = [0.0, 0.0, 0.0]
            direction[axis] = 1.0 if level > middle[axis] else -1.0
            quads.append(facing(quad, direction))
    return quads


def disk(level, normal_sign, sides=64):
    """Regular polygon inscribed in the unit circle at y = level, fanned around its centre."""
    centre = (0.0, float(level), 0.0)
    rim = [(clean(math.cos(2.0 * math.pi * k / sides)), float(level),
            clean(math.sin(2.0 * math.pi * k / sides))) for k in range(sides)]
    positions = [centre] + rim
    indices = []
    for k in range(sides):
        tri = [0, 1 + k, 1 + (k + 1) % sides]
        normal = cross(sub(positions[tri[1]], centre), sub(positions[tri[2]], centre))
        if normal[1] * normal_sign < 0.0:
            tri = [tri[0], tri[2], tri[1]]
        indices.extend(tri)
    return positions, indices


def icosphere(radius, subdivisions, outward=True):
    """A sphere of triangles: an icosahedron split `subdivisions` times, its vertices on the
    sphere; counter-clockwise seen from outside when `outward`, else from inside."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = tuple((points[a][k] + points[b][k]) / 2.0 for k in range(3))
                length = math.sqrt(sum(x * x for x in m))
                points.append(tuple(x / length for x in m))
                middle[key] = len(points) - 1
            return middle[key]
        faces = [f for a, b, c in faces
                 for f in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                           (mid(a, b), mid(b, c), mid(c, a)))]
    positions = [tuple(round(radius * x, 9) for x in p) for p in points]
    indices = [i for f in faces for i in (f if outward else (f[0], f[2], f[1]))]
    return positions, indices


def uv_sphere(centre, radius, rings=16, segments=32):
    """A closed sphere of triangles facing out, with radial NORMALs (smooth)."""
    positions, normals, indices = [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2.0 * math.pi * j / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            normals.append(n)
            positions.append(tuple(c + radius * k for c, k in zip(centre, n)))
    for i in range(rings):
        for j in range(segments):
            a, b2 = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
            tris = [(a, b2, a + 1), (a + 1, b2, b2 + 1)]
            for t in tris:
                p = [positions[k] for k in t]
                if i == 0 and t == tris[0]:
                    continue  # degenerate at the pole
                if i == rings - 1 and t == tris[1]:
                    continue
                outward = sub(centroid(p), centre)
                if dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), outward) < 0.0:
                    t = (t[0], t[2], t[1])
                indices.extend(t)
    return positions, normals, indices
