#pragma once
// Helpers shared by the tests.

#include <fstream>
#include <iterator>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace rad::test {

inline std::string sourcePath(const std::string& relative) { return std::string(RADIOSITY_SOURCE_DIR) + "/" + relative; }

inline std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline const Surface& surfaceNamed(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces)
        if (s.name == name) return s;
    throw std::runtime_error("no surface named " + name);
}

inline glm::dvec3 triangleNormal(const Surface& s, std::size_t t) {
    const auto& tri = s.triangles[t];
    const glm::dvec3 a(s.positions[tri[0]]), b(s.positions[tri[1]]), c(s.positions[tri[2]]);
    return glm::normalize(glm::cross(b - a, c - a));
}

inline double triangleArea(const Surface& s, std::size_t t) {
    const auto& tri = s.triangles[t];
    const glm::dvec3 a(s.positions[tri[0]]), b(s.positions[tri[1]]), c(s.positions[tri[2]]);
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

inline double surfaceArea(const Surface& s) {
    double area = 0.0;
    for (std::size_t t = 0; t < s.triangles.size(); ++t) area += triangleArea(s, t);
    return area;
}

}  // namespace rad::test
