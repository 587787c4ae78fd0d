#include "io/lightmapped_gltf.h"

#include <cmath>
#include <map>

#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>

#include "io/gltf_buffers.h"
#include "render/tone_map.h"
#include "util/error.h"

namespace rad {
namespace {

template <typename T>
int addArray(tinygltf::Model& model, const std::vector<T>& values, int type, std::size_t count, int target,
             std::vector<double> lo = {}, std::vector<double> hi = {}) {
    return addAccessor(model, addView(model, values.data(), values.size() * sizeof(values[0]), target),
                       TINYGLTF_COMPONENT_TYPE_FLOAT, type, count, std::move(lo), std::move(hi));
}

// The page's radiance over `strength`, sRGB-encoded, as an 8-bit image.
TextureImage encodePage(const Image& page, double strength, std::size_t index) {
    TextureImage image;
    image.name = "lightmap " + std::to_string(index);
    image.width = page.width;
    image.height = page.height;
    image.rgba.resize(page.pixels.size() * 4);
    const auto scale = static_cast<float>(1.0 / strength);
    for (std::size_t i = 0; i < page.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            image.rgba[4 * i + static_cast<std::size_t>(c)] =
                static_cast<std::uint8_t>(std::lround(255.0f * srgb(page.pixels[i][c] * scale)));
        image.rgba[4 * i + 3] = 255;
    }
    return image;
}

}  // namespace

void writeLightmappedGltf(const std::string& path, const Scene& scene, const Mesh& mesh, const LightmapLayout& layout,
                          const std::vector<Image>& radiancePages, double strength) {
    if (radiancePages.size() != layout.pages)
        throw InputError("lightmapped.glb: " + std::to_string(radiancePages.size()) + " pages given for a layout of " +
                         std::to_string(layout.pages));
    if (!(strength > 0.0) || !std::isfinite(strength))
        throw InputError("lightmapped.glb: the emissive strength must be a positive number");
    tinygltf::Model model =
        startGlb("radiosity (lightmap: radiance as the emissive texture, on TEXCOORD_1)", scene.origin);
    // A strength of at most 1 is the emissive factor itself; above 1 it needs the extension.
    const bool extension = strength > 1.0;
    if (extension) model.extensionsUsed.push_back("KHR_materials_emissive_strength");
    // No specular layer either: glTF gives a black non-metal one (4 % at normal incidence), which
    // viewers would draw as highlights over the baked light.
    model.extensionsUsed.push_back("KHR_materials_specular");
    tinygltf::Sampler sampler;
    sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    // No mipmaps: past the gutters' two texels a mip level would blend neighbouring charts.
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    model.samplers.push_back(sampler);
    for (std::size_t page = 0; page < radiancePages.size(); ++page) {
        tinygltf::Texture texture;
        texture.source = addPngImage(model, encodePage(radiancePages[page], strength, page));
        texture.sampler = 0;
        model.textures.push_back(texture);
    }
    std::map<std::pair<int, std::uint32_t>, int> materialOf;  // (scene material, page): file material
    auto material = [&](int sceneMaterial, std::uint32_t page) {
        const auto found = materialOf.find({sceneMaterial, page});
        if (found != materialOf.end()) return found->second;
        const Material& m = scene.materials[static_cast<std::size_t>(sceneMaterial)];
        tinygltf::Material out;
        out.name = (m.name.empty() ? "material " + std::to_string(sceneMaterial) : m.name) + " (lightmap page " +
                   std::to_string(page) + ")";
        out.pbrMetallicRoughness.baseColorFactor = {0.0, 0.0, 0.0, 1.0};
        out.pbrMetallicRoughness.metallicFactor = 0.0;
        out.pbrMetallicRoughness.roughnessFactor = 1.0;
        out.emissiveTexture.index = static_cast<int>(page);
        out.emissiveTexture.texCoord = 1;
        const double factor = extension ? 1.0 : strength;
        out.emissiveFactor = {factor, factor, factor};
        tinygltf::Value::Object noLayer;
        noLayer["specularFactor"] = tinygltf::Value(0.0);
        out.extensions["KHR_materials_specular"] = tinygltf::Value(noLayer);
        if (extension) {
            tinygltf::Value::Object strengthObject;
            strengthObject["emissiveStrength"] = tinygltf::Value(strength);
            out.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(strengthObject);
        }
        out.doubleSided = m.doubleSided;
        model.materials.push_back(out);
        const int index = static_cast<int>(model.materials.size() - 1);
        materialOf.emplace(std::make_pair(sceneMaterial, page), index);
        return index;
    };
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& surface = scene.surfaces[s];
        if (surface.triangles.empty()) continue;
        const LightmapUvs uvs = lightmapUvs(scene, mesh, layout, s);
        const std::size_t count = uvs.uv.size();
        std::vector<float> positions, normals, uv0, uv1, colors;
        std::vector<double> lo(3, HUGE_VAL), hi(3, -HUGE_VAL);
        bool normalsUsable = !surface.normals.empty();
        for (std::uint32_t v : uvs.vertexOf)
            if (normalsUsable && surface.normals[v] == glm::vec3(0.0f)) normalsUsable = false;
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint32_t v = uvs.vertexOf[i];
            for (int c = 0; c < 3; ++c) {
                positions.push_back(surface.positions[v][c]);
                lo[static_cast<std::size_t>(c)] =
                    std::min<double>(lo[static_cast<std::size_t>(c)], surface.positions[v][c]);
                hi[static_cast<std::size_t>(c)] =
                    std::max<double>(hi[static_cast<std::size_t>(c)], surface.positions[v][c]);
                if (normalsUsable) normals.push_back(surface.normals[v][c]);
            }
            if (!surface.colors.empty())  // COLOR_0 still multiplies the base colour
                for (int c = 0; c < 3; ++c) colors.push_back(surface.colors[v][c]);
            if (!surface.texCoords[0].empty()) {
                uv0.push_back(surface.texCoords[0][v].x);
                uv0.push_back(surface.texCoords[0][v].y);
            }
            uv1.push_back(uvs.uv[i].x);
            uv1.push_back(uvs.uv[i].y);
        }
        std::map<std::string, int> attributes;
        attributes["POSITION"] =
            addArray(model, positions, TINYGLTF_TYPE_VEC3, count, TINYGLTF_TARGET_ARRAY_BUFFER, lo, hi);
        if (normalsUsable)
            attributes["NORMAL"] = addArray(model, normals, TINYGLTF_TYPE_VEC3, count, TINYGLTF_TARGET_ARRAY_BUFFER);
        if (!colors.empty())
            attributes["COLOR_0"] = addArray(model, colors, TINYGLTF_TYPE_VEC3, count, TINYGLTF_TARGET_ARRAY_BUFFER);
        attributes["TEXCOORD_1"] = addArray(model, uv1, TINYGLTF_TYPE_VEC2, count, TINYGLTF_TARGET_ARRAY_BUFFER);
        // glTF numbers a primitive's UV sets from 0 without a gap (3.7.2.1), and viewers read
        // them so (Blender's importer stops at the first missing one): without a UV set of the
        // scene's own, TEXCOORD_0 is the lightmap's too, one accessor for both.
        attributes["TEXCOORD_0"] = uv0.empty() ? attributes["TEXCOORD_1"]
                                               : addArray(model, uv0, TINYGLTF_TYPE_VEC2, count, TINYGLTF_TARGET_ARRAY_BUFFER);
        // One primitive per (material, page), the triangles in the file's order within each.
        std::map<std::pair<int, std::uint32_t>, std::vector<std::uint32_t>> groups;
        for (std::size_t t = 0; t < uvs.triangles.size(); ++t) {
            std::vector<std::uint32_t>& indices = groups[{surface.triangleMaterial[t], uvs.page[t]}];
            indices.insert(indices.end(), uvs.triangles[t].begin(), uvs.triangles[t].end());
        }
        tinygltf::Mesh gltfMesh;
        gltfMesh.name = surface.name;
        for (const auto& [key, indices] : groups) {
            tinygltf::Primitive primitive;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            primitive.material = material(key.first, key.second);
            primitive.attributes = attributes;
            primitive.indices = addAccessor(
                model, addView(model, indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
            gltfMesh.primitives.push_back(primitive);
        }
        addSurfaceNode(model, std::move(gltfMesh), surface.name);
    }
    // The scene's cameras, so that a viewer (or solve --camera) sees it as the solve's render did.
    for (const Camera& c : scene.cameras) {
        tinygltf::Camera camera;
        camera.name = c.name;
        if (c.projection == Camera::Projection::Perspective) {
            camera.type = "perspective";
            camera.perspective.yfov = c.yfov;
            camera.perspective.znear = c.znear;
            camera.perspective.aspectRatio = c.aspectRatio;
        } else {
            camera.type = "orthographic";
            camera.orthographic.xmag = c.xmag;
            camera.orthographic.ymag = c.ymag;
            camera.orthographic.znear = c.znear;
            camera.orthographic.zfar = std::max(1e3, 2.0 * scene.bounds().diagonal() + c.znear);
        }
        model.cameras.push_back(camera);
        tinygltf::Node node;
        node.name = c.name;
        node.camera = static_cast<int>(model.cameras.size() - 1);
        node.translation = {c.position.x, c.position.y, c.position.z};
        const glm::dquat q = glm::quat_cast(glm::dmat3(c.orientation));
        node.rotation = {q.x, q.y, q.z, q.w};
        model.nodes.push_back(node);
        model.nodes[0].children.push_back(static_cast<int>(model.nodes.size() - 1));
    }
    writeGlb(path, model);
}

}  // namespace rad
