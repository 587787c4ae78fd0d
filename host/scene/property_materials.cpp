#include "scene/property_materials.h"

#include <array>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include "scene/scene.h"
#include "util/csv_fields.h"
#include "util/error.h"

namespace rad {
namespace {

const std::set<std::string> kThermalColumns = {"emissivity", "temperature", "heat_flux"};

// Where one quantity's columns are: a grey column, or three per channel.
struct ColourColumns {
    int grey = -1;
    std::array<int, 3> channel{-1, -1, -1};
    bool any() const { return grey >= 0 || channel[0] >= 0 || channel[1] >= 0 || channel[2] >= 0; }
};

struct Look {
    std::optional<glm::vec3> reflectance;
    std::optional<glm::vec3> emission;
};

}  // namespace

bool isMaterialColumn(const std::string& column) {
    for (const char* base : {"reflectance", "emission"}) {
        const std::string b = base;
        if (column == b || column == b + "_r" || column == b + "_g" || column == b + "_b") return true;
    }
    return false;
}

void applyPropertyMaterials(Scene& scene, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot open the properties file");
    std::map<std::string, std::size_t> index;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) index.emplace(scene.surfaces[s].name, s);

    std::string line;
    std::size_t number = 0;
    int surfaceColumn = -1;
    ColourColumns reflectance, emission;
    bool header = true;
    std::map<std::size_t, Look> looks;
    while (std::getline(in, line)) {
        ++number;
        const auto fail = [&](const std::string& problem) {
            throw FileError(path, "line " + std::to_string(number) + ": " + problem);
        };
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const std::vector<std::string> fields = csvFields(line);
        if (header) {
            header = false;
            for (std::size_t c = 0; c < fields.size(); ++c) {
                const std::string& name = fields[c];
                int* column = nullptr;
                if (name == "surface") column = &surfaceColumn;
                for (auto [base, columns] : {std::pair{"reflectance", &reflectance}, std::pair{"emission", &emission}}) {
                    const std::string b = base;
                    if (name == b) column = &columns->grey;
                    for (int k = 0; k < 3; ++k)
                        if (name == b + "_" + "rgb"[k]) column = &columns->channel[static_cast<std::size_t>(k)];
                }
                if (!column && kThermalColumns.count(name)) continue;  // exchange's
                if (!column)
                    fail("unknown column '" + name + "' (" + kMaterialColumnsListed +
                         "; exchange reads emissivity, temperature, heat_flux)");
                if (*column >= 0) fail("column '" + name + "' appears twice");
                *column = static_cast<int>(c);
            }
            if (surfaceColumn < 0) fail("the header has no 'surface' column");
            if (!reflectance.any() && !emission.any())
                fail("the header has no reflectance or emission column (" + std::string(kMaterialColumnsListed) + ")");
            for (auto [base, columns] : {std::pair{"reflectance", &reflectance}, std::pair{"emission", &emission}}) {
                const int channels = (columns->channel[0] >= 0) + (columns->channel[1] >= 0) + (columns->channel[2] >= 0);
                if (columns->grey >= 0 && channels > 0)
                    fail(std::string("both '") + base + "' and per-channel " + base + " columns: give one or the other");
                if (channels != 0 && channels != 3)
                    fail(std::string("per-channel ") + base + " needs all three columns, " + base + "_r, _g and _b");
            }
            continue;
        }
        const std::string& name =
            static_cast<std::size_t>(surfaceColumn) < fields.size() ? fields[static_cast<std::size_t>(surfaceColumn)] : "";
        const auto found = index.find(name);
        if (found == index.end()) {
            if (name.size() > 5 && name.compare(name.size() - 5, 5, ":back") == 0 &&
                index.count(name.substr(0, name.size() - 5)))
                continue;  // a back side's row, for exchange: a material is the same on both sides
            fail("the scene has no surface named '" + name + "'");
        }
        if (looks.count(found->second)) fail("surface '" + name + "' is listed twice");
        Look look;
        auto colour = [&](const ColourColumns& columns, const char* what) -> std::optional<glm::vec3> {
            auto field = [&](int c) -> std::optional<double> {
                if (c < 0) return std::nullopt;
                if (static_cast<std::size_t>(c) >= fields.size())
                    fail("has " + std::to_string(fields.size()) + " fields, fewer than the header's");
                return csvNumber(fields[static_cast<std::size_t>(c)], fail, what);
            };
            if (columns.grey >= 0) {
                const auto v = field(columns.grey);
                if (!v) return std::nullopt;
                return glm::vec3(static_cast<float>(*v));
            }
            std::array<std::optional<double>, 3> v{field(columns.channel[0]), field(columns.channel[1]),
                                                   field(columns.channel[2])};
            if (!v[0] && !v[1] && !v[2]) return std::nullopt;
            if (!v[0] || !v[1] || !v[2]) fail(std::string("surface '") + name + "' gives some channels of its " + what + ", not all");
            return glm::vec3(static_cast<float>(*v[0]), static_cast<float>(*v[1]), static_cast<float>(*v[2]));
        };
        look.reflectance = colour(reflectance, "reflectance");
        look.emission = colour(emission, "emission");
        for (int k = 0; k < 3; ++k) {
            if (look.reflectance && !((*look.reflectance)[k] >= 0.0f && (*look.reflectance)[k] <= 1.0f))
                fail("the reflectance of '" + name + "' lies outside [0, 1]");
            if (look.emission && !((*look.emission)[k] >= 0.0f && (*look.emission)[k] <= 1e30f))
                fail("the emission of '" + name + "' is negative or above 1e30 W/m^2/sr");
        }
        looks[found->second] = look;
    }
    if (header) throw FileError(path, "the properties file is empty (it needs a header: surface,reflectance)");

    // One new material for each (surface, material it had), so surfaces that shared a material
    // and are listed with different values part, and triangles of one surface keep apart what
    // the file does not change.
    for (const auto& [s, look] : looks) {
        if (!look.reflectance && !look.emission) continue;
        Surface& surface = scene.surfaces[s];
        std::map<int, int> replaced;
        for (int& m : surface.triangleMaterial) {
            auto [at, inserted] = replaced.emplace(m, 0);
            if (inserted) {
                Material material = scene.materials[static_cast<std::size_t>(m)];
                material.name = surface.name + " (" + path + ")";
                if (look.reflectance) {
                    material.reflectance = material.baseColor = *look.reflectance;
                    material.metallic = 0.0f;
                    material.transmission = 0.0f;
                    material.specular = 0.0f;
                    material.baseColorTexture = TextureRef{};
                    material.metallicRoughnessTextured = false;
                    material.metallicRoughnessTexture = TextureRef{};
                    material.specularTexture = TextureRef{};
                    material.specularColorTexture = TextureRef{};
                    material.alphaMode = Material::AlphaMode::Opaque;
                }
                if (look.emission) {
                    material.emission = *look.emission;
                    material.emissiveTexture = TextureRef{};
                }
                scene.materials.push_back(material);
                at->second = static_cast<int>(scene.materials.size() - 1);
            }
            m = at->second;
        }
    }
}

}  // namespace rad
