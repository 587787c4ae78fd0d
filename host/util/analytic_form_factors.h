#pragma once
// Unoccluded form factors from closed forms and contour integrals, in double precision. They
// are references for tests and for the estimators' error: no visibility is considered.

#include <vector>

#include <glm/vec3.hpp>

namespace rad {

// Form factor from a differential area at `point` with unit normal `normal` to a planar
// polygon (Lambert): (1 / 2 pi) sum over edges of the angle the edge subtends times the
// normal's component along the edge's plane normal. Valid when the whole polygon lies in front
// of the point; the polygon's winding does not matter.
double pointToPolygonFactor(const glm::dvec3& point, const glm::dvec3& normal, const std::vector<glm::dvec3>& polygon);

// Form factor F_12 between two planar polygons by Stokes's double contour integral
// A1 F12 = (1 / 2 pi) |sum of integral of ln r dx1 . dx2| with Gauss-Legendre quadrature on
// every edge pair. Valid when each polygon lies wholly in front of the other and they do not
// touch (ln r is singular where edges meet); then accurate to about 1e-10.
double polygonToPolygonFactor(const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to);

// Area of a planar polygon.
double polygonArea(const std::vector<glm::dvec3>& polygon);

// Closed forms of the classic test cases (facing and perpendicular unit squares, coaxial disks).
double parallelSquaresFactor(double side, double gap);       // coaxial facing squares
double perpendicularSquaresFactor();                         // unit squares sharing an edge
double coaxialDisksFactor(double r1, double r2, double gap); // F from disk 1 to disk 2

}  // namespace rad
