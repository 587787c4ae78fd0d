#pragma once
// Light from outside the scene as an equirectangular image (--environment FILE.exr), mapped as
// Blender's Environment Texture node maps it, glTF's +Y being Blender's +Z (Blender's (x, y, z)
// is glTF's (x, -z, y)), so one EXR lights a scene alike in both. For a unit glTF direction
// (x, y, z):
//   u = 0.5 + atan2(z, x) / (2 pi)   across the image, from its left edge;
//   t = acos(y) / pi                 down the image, from its top row (straight up).
// So the image's centre column looks along glTF +X, its quarter column along -Z (Blender's +Y);
// texels are filtered bilinearly between their centres, wrapping across the left and right
// edges and clamped at the top and bottom rows, as Blender's Linear interpolation does.
// The kernels evaluate the same mapping (kernels/environment.h) with their own arctangent,
// so every device finds the same texels.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

namespace rad {

struct EnvironmentMap {
    std::string path;       // the file it came from, for messages and reports
    double strength = 1.0;  // --environment-strength, already applied to `radiance`
    int width = 0, height = 0;
    std::vector<glm::vec3> radiance;  // W / m^2 / sr, row 0 at the top; width * height

    bool empty() const { return width == 0; }
    const glm::vec3& at(int x, int y) const { return radiance[static_cast<std::size_t>(y) * width + x]; }
};

// Reads an OpenEXR image (R, G, B channels, or Y alone for grey) as an environment map,
// multiplied by `strength`. Throws FileError naming the file for a file that is missing or not
// an EXR, lacks the channels, is larger than kMaxEnvironmentTexels, or holds a negative or
// non-finite texel, and for a map that is black everywhere.
EnvironmentMap loadEnvironmentMap(const std::string& path, double strength);
constexpr std::uint64_t kMaxEnvironmentTexels = std::uint64_t{1} << 26;

// The map coordinates (u, t) of a unit direction, and the direction of coordinates (u, t).
glm::dvec2 environmentCoordinates(const glm::dvec3& direction);
glm::dvec3 environmentDirection(double u, double t);

// The radiance the map shows in a unit direction (bilinear, as above).
glm::dvec3 environmentRadiance(const EnvironmentMap& map, const glm::dvec3& direction);

// The solid angle of a texel of row y (all texels of a row subtend the same).
double environmentTexelSolidAngle(const EnvironmentMap& map, int y);

// The integral of the filtered radiance over all directions (W / m^2 per channel).
glm::dvec3 environmentIntegral(const EnvironmentMap& map);

// How directions are drawn in proportion to the light they bring (the device's sampling
// tables, kernels/environment.h): a row is picked by `rows`, then a texel within it by its row's
// run of `columns`, each as the ends of shares of 2^32 (the last end, 2^32, implied); the
// direction is then uniform in solid angle within the texel. A texel's weight is the largest
// mean radiance among the texels its bilinear filter blends (itself and its eight neighbours)
// times its solid angle, so every direction the filter lights can be drawn.
struct EnvironmentSampling {
    std::vector<std::uint32_t> rows;     // height
    std::vector<std::uint32_t> columns;  // width * height
};
EnvironmentSampling environmentSampling(const EnvironmentMap& map);

// The probability density (per steradian) with which those tables draw `direction`.
double environmentPdf(const EnvironmentMap& map, const EnvironmentSampling& sampling, const glm::dvec3& direction);

// A fingerprint of the map's texels and strength (checkpoints).
std::uint64_t environmentFingerprint(const EnvironmentMap& map);

}  // namespace rad
