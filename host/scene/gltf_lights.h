#pragma once
// KHR_lights_punctual: the document's point, spot and directional lights, and the nodes that
// place them. The file's intensities are photometric (candela; lux for directional lights);
// the scene's are radiometric, color x intensity / 683 lm/W, as Blender's glTF importer and
// exporter convert them.

#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/scene.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace rad {

// Lumens per watt: the luminous efficacy glTF's photometric units are converted with.
inline constexpr double kLumensPerWatt = 683.0;

class GltfLights {
public:
    // Converts and checks the document's lights. Throws FileError for what the specification
    // forbids (negative or non-finite intensity or colour, a spot's cone out of order); warns
    // by name for what it cannot honour (a light type it does not know, `range`).
    GltfLights(const tinygltf::Model& model, const std::string& path, std::vector<std::string>& warnings);

    // The light the node places, in world coordinates (positions not yet relative to the
    // scene's origin); none when it places none or one this program skips.
    std::optional<Light> place(const tinygltf::Node& node, int nodeIndex, const glm::dmat4& world) const;

private:
    const std::string& path_;
    std::vector<std::string>& warnings_;
    std::vector<std::optional<Light>> lights_;  // none for lights that are skipped
};

}  // namespace rad
