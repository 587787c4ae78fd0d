"""Closed forms and precise quadratures that the experiments measure against.

The form factor from a differential area at x (unit normal n) to a polygon P fully in front of
it is Lambert's contour formula (the point-to-shooter form of kernels/polygon_factor.h):
    F(x -> P) = 1/(2 pi) sum_k gamma_k  n . (a_k x a_k+1) / |a_k x a_k+1|,  a_k = v_k - x,
gamma_k the angle between a_k and a_k+1. Area-to-polygon factors average it over the area with
Gauss-Legendre rules, refined towards edges that touch the polygon, where the integrand's
derivative is singular."""

import math

import numpy as np

PI = math.pi
F_FACING_UNIT_SQUARES = 0.19982490    # Howell's catalogue, X = Y = 1 (scenes/README.md)
F_PERPENDICULAR_UNIT_SQUARES = 0.20004378


def point_to_polygon(points, normal, polygon):
    """F from each point (N x 3 array) with the given unit normal (3,) to the polygon (K x 3,
    counter-clockwise seen from the points)."""
    points = np.atleast_2d(np.asarray(points, dtype=np.float64))
    normal = np.asarray(normal, dtype=np.float64)
    poly = np.asarray(polygon, dtype=np.float64)
    total = np.zeros(len(points))
    for k in range(len(poly)):
        a = poly[k] - points
        b = poly[(k + 1) % len(poly)] - points
        c = np.cross(a, b)
        norm_c = np.linalg.norm(c, axis=1)
        gamma = np.arctan2(norm_c, np.einsum("ij,ij->i", a, b))
        with np.errstate(invalid="ignore", divide="ignore"):
            term = np.where(norm_c > 0, gamma * (c @ normal) / norm_c, 0.0)
        total += term
    return np.abs(total) / (2.0 * PI)


def gauss_legendre(n, lo, hi):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (hi - lo) * x + 0.5 * (hi + lo), 0.5 * (hi - lo) * w


def graded_intervals(lo, hi, towards_lo, levels=40):
    """[lo, hi] cut geometrically towards lo (each piece half the next), or one piece."""
    if not towards_lo:
        return [(lo, hi)]
    cuts = [lo + (hi - lo) * 0.5 ** k for k in range(levels)] + [lo]
    return [(cuts[k + 1], cuts[k]) for k in range(len(cuts) - 1)]


def rectangle_points(origin, edge_u, edge_v, n=12, graded_u=False, graded_v=False):
    """Quadrature points and weights (summing to the area) of the parallelogram origin + s edge_u +
    t edge_v, s, t in [0, 1]; graded towards s = 0 (t = 0) when asked."""
    origin, edge_u, edge_v = (np.asarray(v, dtype=np.float64) for v in (origin, edge_u, edge_v))
    su, wu = zip(*[gauss_legendre(n, a, b) for a, b in graded_intervals(0.0, 1.0, graded_u)])
    sv, wv = zip(*[gauss_legendre(n, a, b) for a, b in graded_intervals(0.0, 1.0, graded_v)])
    su, wu, sv, wv = (np.concatenate(v) for v in (su, wu, sv, wv))
    s, t = np.meshgrid(su, sv, indexing="ij")
    w = np.outer(wu, wv).ravel() * np.linalg.norm(np.cross(edge_u, edge_v))
    pts = origin + s.ravel()[:, None] * edge_u + t.ravel()[:, None] * edge_v
    return pts, w


def triangle_points(tri, n=8, singular_edge=None):
    """Quadrature points and weights of a triangle (3 x 3) by the collapsed square
    (s, t) -> v0 + s (v1 - v0) + s t (v2 - v1), Jacobian 2 A s. With singular_edge = k, the
    triangle is first ordered so that edge k lies at s = 1 and s is graded towards it."""
    v = np.asarray(tri, dtype=np.float64)
    if singular_edge is not None:  # put the edge (k, k+1) opposite the collapsed vertex
        k = singular_edge
        v = np.array([v[(k + 2) % 3], v[k], v[(k + 1) % 3]])
    area2 = np.linalg.norm(np.cross(v[1] - v[0], v[2] - v[0]))
    if singular_edge is None:
        pieces_s = [(0.0, 1.0)]
    else:  # towards s = 1: mirror a grading towards 0
        pieces_s = [(1.0 - b, 1.0 - a) for a, b in graded_intervals(0.0, 1.0, True)]
    ss, ws = zip(*[gauss_legendre(n, a, b) for a, b in pieces_s])
    ss, ws = np.concatenate(ss), np.concatenate(ws)
    tt, wt = gauss_legendre(n, 0.0, 1.0)
    s, t = np.meshgrid(ss, tt, indexing="ij")
    w = (np.outer(ws, wt) * s * area2).ravel()
    s, t = s.ravel()[:, None], t.ravel()[:, None]
    pts = v[0] + s * (v[1] - v[0]) + s * t * (v[2] - v[1])
    return pts, w


def area_to_polygon(points, weights, normal, polygon):
    """F from an area (its quadrature) to a polygon: the area-weighted mean of the point factor."""
    return float(np.sum(weights * point_to_polygon(points, normal, polygon)) / np.sum(weights))


def unit_square(y, facing_down):
    quad = [(0.0, y, 0.0), (1.0, y, 0.0), (1.0, y, 1.0), (0.0, y, 1.0)]
    return quad[::-1] if not facing_down else quad


def facing_squares_factor(side_a, side_b, distance):
    """F from a square of side a to a coaxial parallel square of side b, `distance` apart."""
    lo = 0.5 - 0.5 * side_a
    pts, w = rectangle_points((lo, 0.0, lo), (side_a, 0, 0), (0, 0, side_a), n=24)
    lo_b = 0.5 - 0.5 * side_b
    target = [(lo_b, distance, lo_b), (lo_b + side_b, distance, lo_b), (lo_b + side_b, distance, lo_b + side_b),
              (lo_b, distance, lo_b + side_b)]
    return area_to_polygon(pts, w, (0.0, 1.0, 0.0), target)


def self_check():
    """The closed forms the scenes' README quotes, from the quadratures here."""
    f1 = facing_squares_factor(1.0, 1.0, 1.0)
    pts, w = rectangle_points((0, 0, 0), (1, 0, 0), (0, 1, 0), n=16, graded_v=True)  # wall z = 0, towards y = 0
    floor = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 0.0, 1.0), (0.0, 0.0, 1.0)]
    f2 = area_to_polygon(pts, w, (0.0, 0.0, 1.0), floor)
    return f1, f2


if __name__ == "__main__":
    f1, f2 = self_check()
    print("facing %.8f (exact %.8f)  perpendicular %.8f (exact %.8f)" %
          (f1, F_FACING_UNIT_SQUARES, f2, F_PERPENDICULAR_UNIT_SQUARES))
    tri_lo = triangle_points([(0, 0, 0), (1, 0, 0), (1, 1, 0)], n=16, singular_edge=0)
    tri_hi = triangle_points([(0, 0, 0), (1, 1, 0), (0, 1, 0)], n=16)
    floor = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 0.0, 1.0), (0.0, 0.0, 1.0)]
    a = area_to_polygon(*tri_lo, (0, 0, 1), floor)
    b = area_to_polygon(*tri_hi, (0, 0, 1), floor)
    print("two wall triangles: %.8f %.8f, mean %.8f" % (a, b, 0.5 * (a + b)))


def _graded_both(levels, n):
    """Gauss-Legendre on [0, 1] cut geometrically towards both ends."""
    half = graded_intervals(0.0, 0.5, True, levels)
    pieces = half + [(1.0 - b, 1.0 - a) for a, b in half]
    x, w = zip(*[gauss_legendre(n, a, b) for a, b in pieces])
    return np.concatenate(x), np.concatenate(w)


def triangle_to_polygon(tri, polygon, n=12, levels=30):
    """F from a triangle (3 x 3, counter-clockwise seen from its front) to a polygon in front of
    it. An edge that lies in the polygon's plane (a shared edge, as where a wall meets the
    floor) is singular for the integrand's derivative, and so are its ends: the rule is graded
    towards that edge and along it towards both ends."""
    v = np.asarray(tri, dtype=np.float64)
    poly = np.asarray(polygon, dtype=np.float64)
    normal = np.cross(v[1] - v[0], v[2] - v[0])
    area2 = np.linalg.norm(normal)
    normal /= area2
    plane_n = np.cross(poly[1] - poly[0], poly[2] - poly[0])
    plane_n /= np.linalg.norm(plane_n)
    on_plane = [abs(np.dot(p - poly[0], plane_n)) < 1e-9 for p in v]
    edge = next((k for k in range(3) if on_plane[k] and on_plane[(k + 1) % 3]), None)
    if edge is None:
        s, ws = gauss_legendre(n, 0.0, 1.0)
        t, wt = gauss_legendre(n, 0.0, 1.0)
    else:  # edge (k, k+1) opposite the collapsed vertex: at s = 1, t running along it
        v = np.array([v[(edge + 2) % 3], v[edge], v[(edge + 1) % 3]])
        pieces = [(1.0 - b, 1.0 - a) for a, b in graded_intervals(0.0, 1.0, True, levels)]
        s, ws = (np.concatenate(x) for x in zip(*[gauss_legendre(n, a, b) for a, b in pieces]))
        t, wt = _graded_both(levels, n)
    S, T = np.meshgrid(s, t, indexing="ij")
    w = (np.outer(ws, wt) * S).ravel()
    S, T = S.ravel()[:, None], T.ravel()[:, None]
    pts = v[0] + S * (v[1] - v[0]) + S * T * (v[2] - v[1])
    return float(np.sum(w * point_to_polygon(pts, normal, poly)) / np.sum(w))
