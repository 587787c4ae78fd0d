#include "scene/mesh_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scene/material_model.h"
#include "scene/mesh_readers.h"
#include "scene/tangents.h"
#include "scene/world_surfaces.h"
#include "util/error.h"

namespace rad {

double srgbComponentToLinear(double value) {
    const double c = std::clamp(value, 0.0, 1.0);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

FileMesh readMeshFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw FileError(path, "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "not a regular file");
    const std::string ext = lowerExtension(path);
    if (ext == ".obj") return readObj(path);
    if (ext == ".stl") return readStl(path);
    if (ext == ".ply") return readPly(path);
    throw FileError(path, "is not an OBJ, STL or PLY file (by its extension)");
}

// One file's surfaces and materials into the scene being built, coordinates times `scale`.
class MeshAssembly {
public:
    MeshAssembly(Scene& scene, double scale) : scene_(scene), scale_(scale) {}

    // `named`: warnings name the file (several files; one file's name the command prints anyway).
    void add(const std::string& path, FileMesh file, bool named) {
        for (const std::string& warning : file.warnings) scene_.warnings.push_back((named ? path + ": " : "") + warning);
        for (const std::string& extra : file.extraFiles) scene_.files.push_back(extra);
        skipped_ += file.skippedElements;
        const int firstMaterial = static_cast<int>(scene_.materials.size());
        const int firstImage = static_cast<int>(scene_.images.size());
        for (TextureImage& image : file.images) scene_.images.push_back(std::move(image));
        for (Material& m : file.materials) {
            for (TextureRef* ref : {&m.baseColorTexture, &m.emissiveTexture, &m.normalTexture, &m.metallicRoughnessTexture})
                if (ref->present()) ref->image += firstImage;
            scene_.materials.push_back(std::move(m));
        }
        for (FileSurface& source : file.surfaces) {
            if (source.triangles.empty()) continue;
            WorldSurface built;
            built.surface.name = uniqueName(source.name);
            built.world.reserve(source.positions.size());
            for (const glm::dvec3& p : source.positions) {
                constexpr double kLargest = std::numeric_limits<float>::max();
                if (!(std::fabs(p.x) <= kLargest && std::fabs(p.y) <= kLargest && std::fabs(p.z) <= kLargest))
                    throw FileError(path, "a vertex of '" + source.name + "' lies beyond single precision");
                // The coordinates as floats first, as a glTF file of the same mesh holds them.
                const glm::dvec3 world = glm::dvec3(glm::vec3(p)) * scale_;
                built.world.push_back(world);
            }
            if (!source.normals.empty()) {
                for (const glm::dvec3& given : source.normals) {
                    // As floats first, as glTF's NORMAL holds them; unit in double, as the glTF loader makes them.
                    const glm::dvec3 n(glm::vec3(glm::clamp(given, -1e30, 1e30)));
                    const double length = glm::length(n);
                    const bool usable = length > 1e-12 && std::isfinite(length);
                    built.surface.normals.emplace_back(usable ? n / length : glm::dvec3(0.0));
                }
            }
            for (const glm::dvec2& uv : source.texCoords) built.surface.texCoords[0].emplace_back(uv);
            for (const glm::dvec3& colour : source.colors) built.surface.colors.emplace_back(colour);
            if (source.zeroNormals > 0)
                scene_.warnings.push_back((named ? path + ": " : "") + "'" + source.name + "' has " +
                                          std::to_string(source.zeroNormals) +
                                          " normal(s) of zero length or not finite: the faces around them are "
                                          "shaded flat");
            source.materials.resize(source.triangles.size(), -1);
            for (std::size_t t = 0; t < source.triangles.size(); ++t) {
                for (std::uint32_t v : source.triangles[t])
                    if (v >= source.positions.size())
                        throw FileError(path, "a triangle of '" + source.name + "' names a vertex that does not exist");
                built.surface.triangles.push_back(source.triangles[t]);
                const int m = source.materials[t];
                built.surface.triangleMaterial.push_back(m >= 0 ? firstMaterial + m : defaultMaterial());
            }
            building_.push_back(std::move(built));
        }
    }

    void finish(const std::string& path) {
        if (building_.empty()) throw FileError(path, "has no triangles");
        if (skipped_ > 0)
            scene_.warnings.push_back(std::to_string(skipped_) +
                                      " point, line or face with fewer than three corners skipped: only triangles take part");
        placeSurfaces(building_, path, scene_);
        if (scene_.surfaces.empty()) throw FileError(path, "has no triangle of non-zero area");
        for (Surface& surface : scene_.surfaces) frameNormalMaps(surface, scene_.materials);  // OBJ's map_Bump
    }

private:
    std::string uniqueName(const std::string& name) {
        if (usedNames_.insert(name).second) return name;
        for (int k = 2;; ++k) {
            const std::string unique = name + "@" + std::to_string(k);
            if (usedNames_.insert(unique).second) return unique;
        }
    }

    int defaultMaterial() {
        if (defaultMaterial_ < 0) {
            defaultMaterial_ = static_cast<int>(scene_.materials.size());
            scene_.materials.push_back(rad::defaultMaterial());
        }
        return defaultMaterial_;
    }

    Scene& scene_;
    double scale_;
    std::vector<WorldSurface> building_;
    std::set<std::string> usedNames_;
    int defaultMaterial_ = -1;
    std::size_t skipped_ = 0;
};

}  // namespace

bool isMeshFile(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".obj" || ext == ".stl" || ext == ".ply";
}

Scene loadMeshFiles(const std::vector<std::string>& paths, double metresPerUnit) {
    if (paths.empty()) throw InputError("no mesh file given");
    if (!(metresPerUnit > 0.0) || !std::isfinite(metresPerUnit))
        throw InputError("the length unit must be a positive number of metres");
    Scene scene;
    for (std::size_t k = 0; k < paths.size(); ++k) scene.path += (k ? ", " : "") + paths[k];
    scene.files = paths;
    MeshAssembly assembly(scene, metresPerUnit);
    for (const std::string& path : paths) assembly.add(path, readMeshFile(path), paths.size() > 1);
    assembly.finish(paths.size() == 1 ? paths.front() : scene.path);
    return scene;
}

}  // namespace rad
