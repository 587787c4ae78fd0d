#include "scene/gltf_lights.h"

#include <cmath>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>

#include "util/error.h"

namespace rad {
namespace {

constexpr const char* kExtension = "KHR_lights_punctual";
constexpr double kHalfPi = 1.5707963267948966;

std::string describe(std::size_t index, const tinygltf::Light& light) {
    return "light " + std::to_string(index) + (light.name.empty() ? "" : " ('" + light.name + "')");
}

}  // namespace

GltfLights::GltfLights(const tinygltf::Model& model, const std::string& path, std::vector<std::string>& warnings)
    : path_(path), warnings_(warnings) {
    bool rangeGiven = false;
    for (std::size_t i = 0; i < model.lights.size(); ++i) {
        const tinygltf::Light& source = model.lights[i];
        const std::string what = describe(i, source);
        Light light;
        light.name = source.name.empty() ? "light" + std::to_string(i) : source.name;
        if (source.type == "point") {
            light.type = Light::Type::Point;
        } else if (source.type == "spot") {
            light.type = Light::Type::Spot;
        } else if (source.type == "directional") {
            light.type = Light::Type::Directional;
        } else {
            warnings_.push_back(what + " has type '" + source.type +
                                "', which this program does not know (point, spot, directional): it is skipped");
            lights_.emplace_back();
            continue;
        }
        glm::dvec3 color(1.0);
        if (!source.color.empty()) {
            if (source.color.size() != 3) throw FileError(path_, what + ": color must be 3 numbers");
            color = glm::dvec3(source.color[0], source.color[1], source.color[2]);
        }
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(color[c]) || color[c] < 0.0)
                throw FileError(path_, what + ": color must be 3 finite numbers >= 0");
        if (!std::isfinite(source.intensity) || source.intensity < 0.0)
            throw FileError(path_, what + ": intensity must be a finite number >= 0");
        light.intensity = color * (source.intensity / kLumensPerWatt);
        if (!(light.intensity.x < 1e36 && light.intensity.y < 1e36 && light.intensity.z < 1e36))
            throw FileError(path_, what + ": intensity beyond what single precision can hold");
        if (source.range != 0.0) {
            if (!std::isfinite(source.range) || source.range < 0.0)
                throw FileError(path_, what + ": range must be a finite number > 0");
            rangeGiven = true;
        }
        if (light.type == Light::Type::Spot) {
            const double inner = source.spot.innerConeAngle, outer = source.spot.outerConeAngle;
            if (!std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0 || outer <= 0.0 || outer > kHalfPi ||
                inner >= outer)
                throw FileError(path_, what + ": a spot's cone angles must satisfy 0 <= innerConeAngle < " +
                                           "outerConeAngle <= pi/2 (they are " + std::to_string(inner) + " and " +
                                           std::to_string(outer) + ")");
            light.innerConeAngle = inner;
            light.outerConeAngle = outer;
        }
        lights_.emplace_back(light);
    }
    if (rangeGiven)
        warnings_.push_back(std::string(kExtension) +
                            ": `range` is a cut-off for real-time engines; light transport ignores it (light falls "
                            "off as 1 / r^2 at every distance)");
}

std::optional<Light> GltfLights::place(const tinygltf::Node& node, int nodeIndex, const glm::dmat4& world) const {
    const auto found = node.extensions.find(kExtension);
    if (found == node.extensions.end()) return std::nullopt;
    const std::string what = "node " + std::to_string(nodeIndex);
    const tinygltf::Value& extension = found->second;
    if (!extension.IsObject() || !extension.Has("light") || !extension.Get("light").IsInt())
        throw FileError(path_, what + ": extensions." + kExtension + ".light must be a light index");
    const int index = extension.Get("light").GetNumberAsInt();
    if (index < 0 || index >= static_cast<int>(lights_.size()))
        throw FileError(path_, what + " places light " + std::to_string(index) + ", which does not exist");
    std::optional<Light> light = lights_[static_cast<std::size_t>(index)];
    if (!light) return std::nullopt;
    // glTF: a light shines down its node's -Z; scale does not change its intensity.
    const glm::dvec3 axis = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
    const double length = glm::length(axis);
    if (light->type != Light::Type::Point) {
        if (!(length > 1e-12) || !std::isfinite(length)) {
            warnings_.push_back("light '" + light->name + "' on " + what +
                                " has a degenerate transform (no direction): it is skipped");
            return std::nullopt;
        }
        light->direction = axis / length;
    }
    light->position = glm::dvec3(world[3]);
    return light;
}

}  // namespace rad
