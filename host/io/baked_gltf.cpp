#include "io/baked_gltf.h"

#include <algorithm>
#include <cstring>

#include <map>

#include <tiny_gltf.h>

#include "io/gltf_buffers.h"
#include "mesh/patch_textures.h"
#include "scene/texture_sampling.h"
#include "shared_math.h"
#include "util/error.h"

namespace rad {
namespace {

// One primitive of a surface side: its vertices (renumbered from 0), their values, and its
// triangles. Untextured, a vertex is a welded vertex and its value the radiance; textured
// (`material` set), a vertex is a welded vertex at one texture coordinate (split along seams)
// and its value rho H / pi.
class SideBuilder {
public:
    SideBuilder(const Mesh& mesh, const MeshVertices& vertices, const std::vector<glm::vec3>& radiance,
                const Scene* scene = nullptr, const Material* material = nullptr)
        : mesh_(mesh),
          vertices_(vertices),
          values_(radiance),
          scene_(scene),
          material_(material),
          local_(vertices.positions.size(), 0xFFFFFFFFu) {}

    // The vertex v as element corner of face `face`.
    std::uint32_t vertex(std::uint32_t v, std::uint32_t face) {
        if (!material_) {
            if (local_[v] == 0xFFFFFFFFu) local_[v] = add(vertices_.positions[v], values_[v], {});
            return local_[v];
        }
        const glm::vec2 uv = texCoordOn(face, vertices_.positions[v]);
        std::uint32_t ux, uy;
        std::memcpy(&ux, &uv.x, 4);
        std::memcpy(&uy, &uv.y, 4);
        const auto key = std::make_pair(v, (std::uint64_t{ux} << 32) | uy);
        const auto found = seamed_.find(key);
        if (found != seamed_.end()) return found->second;
        const std::uint32_t index = add(vertices_.positions[v], values_[v], uv);
        seamed_.emplace(key, index);
        return index;
    }

    std::uint32_t add(const glm::vec3& position, const glm::vec3& value, const glm::vec2& uv) {
        for (int c = 0; c < 3; ++c) {
            positions.push_back(position[c]);
            colours.push_back(value[c]);
            lo[c] = std::min(lo[c], static_cast<double>(position[c]));
            hi[c] = std::max(hi[c], static_cast<double>(position[c]));
        }
        texCoords.push_back(uv.x);
        texCoords.push_back(uv.y);
        return static_cast<std::uint32_t>(positions.size() / 3 - 1);
    }

    // An element's triangle; with T-vertices on its edges, a fan around its centroid, whose
    // value is the mean of its corners' (what linear interpolation gives there).
    void element(std::size_t e, std::uint32_t face) {
        const auto& c = vertices_.corners[e];
        const auto& points = vertices_.edgePoints[e];
        if (points[0].empty() && points[1].empty() && points[2].empty()) {
            for (std::uint32_t v : c) indices.push_back(vertex(v, face));
            return;
        }
        std::vector<std::uint32_t> ring;
        for (int k = 0; k < 3; ++k) {
            ring.push_back(vertex(c[k], face));
            for (std::uint32_t v : points[k]) ring.push_back(vertex(v, face));
        }
        const glm::vec3 centre = (vertices_.positions[c[0]] + vertices_.positions[c[1]] + vertices_.positions[c[2]]) / 3.0f;
        const glm::vec3 value = (values_[c[0]] + values_[c[1]] + values_[c[2]]) / 3.0f;
        const std::uint32_t middle = add(centre, value, material_ ? texCoordOn(face, centre) : glm::vec2(0.0f));
        for (std::size_t k = 0; k < ring.size(); ++k) indices.insert(indices.end(), {middle, ring[k], ring[(k + 1) % ring.size()]});
    }

    std::vector<float> positions, colours, texCoords;
    std::vector<std::uint32_t> indices;
    std::vector<double> lo = std::vector<double>(3, 1e300), hi = std::vector<double>(3, -1e300);

private:
    // The base colour texture's coordinates at point q of face `face`, transformed.
    glm::vec2 texCoordOn(std::uint32_t face, const glm::vec3& q) const {
        const Face& f = mesh_.faces[face];
        const glm::dvec2 w = barycentric(glm::dvec3(q), glm::dvec3(f.p[0]), glm::dvec3(f.p[1]), glm::dvec3(f.p[2]));
        const TextureRef& ref = material_->baseColorTexture;
        return transformedUv(ref,
                             texCoordAt(scene_->surfaces[f.sceneSurface], f.sceneTriangle, ref.texCoord, w.x, w.y));
    }

    const Mesh& mesh_;
    const MeshVertices& vertices_;
    const std::vector<glm::vec3>& values_;
    const Scene* scene_;
    const Material* material_;
    std::vector<std::uint32_t> local_;
    std::map<std::pair<std::uint32_t, std::uint64_t>, std::uint32_t> seamed_;
};

// Whether lit.glb keeps a material's texture (above).
bool keepsTexture(const Material& m) {
    return m.baseColorTexture.present() && m.emission == glm::vec3(0.0f) && !m.emissiveTexture.present();
}

// An unlit material showing the scene material's base colour texture times COLOR_0, with its
// sampler and alpha mask; its index among the file's materials.
int addTexturedMaterial(tinygltf::Model& model, const Material& m, int image) {
    const TextureRef& ref = m.baseColorTexture;
    const auto wrap = [](TextureRef::Wrap w) {
        return w == TextureRef::Wrap::ClampToEdge      ? TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE
               : w == TextureRef::Wrap::MirroredRepeat ? TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT
                                                       : TINYGLTF_TEXTURE_WRAP_REPEAT;
    };
    tinygltf::Sampler sampler;
    sampler.wrapS = wrap(ref.wrapS);
    sampler.wrapT = wrap(ref.wrapT);
    sampler.magFilter = ref.nearest ? TINYGLTF_TEXTURE_FILTER_NEAREST : TINYGLTF_TEXTURE_FILTER_LINEAR;
    model.samplers.push_back(sampler);
    tinygltf::Texture texture;
    texture.source = image;
    texture.sampler = static_cast<int>(model.samplers.size() - 1);
    model.textures.push_back(texture);
    tinygltf::Material out;
    out.name = m.name.empty() ? "baked textured" : "baked " + m.name;
    out.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, m.alpha};
    out.pbrMetallicRoughness.baseColorTexture.index = static_cast<int>(model.textures.size() - 1);
    out.pbrMetallicRoughness.metallicFactor = 0.0;
    if (m.alphaMode == Material::AlphaMode::Mask) {
        out.alphaMode = "MASK";
        out.alphaCutoff = m.alphaCutoff;
    }
    out.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
    model.materials.push_back(out);
    return static_cast<int>(model.materials.size() - 1);
}

void addPrimitive(tinygltf::Model& model, tinygltf::Mesh& gltfMesh, const SideBuilder& b, int material) {
    const std::size_t count = b.positions.size() / 3;
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = material;
    primitive.attributes["POSITION"] =
        addAccessor(model, addView(model, b.positions.data(), b.positions.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count, b.lo, b.hi);
    primitive.attributes["COLOR_0"] =
        addAccessor(model, addView(model, b.colours.data(), b.colours.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
    if (material != 0)
        primitive.attributes["TEXCOORD_0"] =
            addAccessor(model, addView(model, b.texCoords.data(), b.texCoords.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
    primitive.indices =
        addAccessor(model, addView(model, b.indices.data(), b.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, b.indices.size());
    gltfMesh.primitives.push_back(primitive);
}

// The side's elements, one primitive per file material: the plain baked material (0) first,
// then the textured ones in order. `bakedMaterial[m]` is scene material m's file material;
// `textured[v]` the value textured vertices carry.
void addSide(tinygltf::Model& model, const Mesh& mesh, std::size_t side, const ElementMesh& elements,
             const MeshVertices& vertices, const std::vector<glm::vec3>& radiance, const BakedTextures* textures,
             const std::vector<int>& bakedMaterial, const std::vector<std::vector<glm::vec3>>& texturedValues) {
    const MeshSurface& surface = mesh.surfaces[side];
    std::map<int, std::vector<std::pair<std::uint32_t, std::uint32_t>>> groups;  // file material: (element, face)
    for (std::uint32_t k = 0; k < surface.patchCount; ++k) {
        const std::uint32_t patch = surface.firstPatch + k;
        const std::uint32_t face = mesh.patches[patch].face;
        const int material = textures ? bakedMaterial[static_cast<std::size_t>(mesh.faces[face].material)] : 0;
        for (std::uint32_t e = elements.elementStart()[patch]; e < elements.elementStart()[patch + 1]; ++e)
            groups[material].emplace_back(e, face);
    }
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = surface.name;
    for (const auto& [material, list] : groups) {
        if (material == 0) {
            SideBuilder b(mesh, vertices, radiance);
            for (const auto& [e, face] : list) b.element(e, face);
            addPrimitive(model, gltfMesh, b, 0);
            continue;
        }
        const int sceneMaterial = mesh.faces[list.front().second].material;
        SideBuilder b(mesh, vertices, texturedValues[static_cast<std::size_t>(sceneMaterial)], &textures->scene,
                      &textures->scene.materials[static_cast<std::size_t>(sceneMaterial)]);
        for (const auto& [e, face] : list) b.element(e, face);
        addPrimitive(model, gltfMesh, b, material);
    }
    addSurfaceNode(model, std::move(gltfMesh), surface.name);
}

}  // namespace

void writeBakedGltf(const std::string& path, const Mesh& mesh, const ElementMesh& elements,
                    const MeshVertices& vertices, const std::vector<glm::vec3>& vertexRadiance,
                    const glm::dvec3& origin, const BakedTextures* textures) {
    tinygltf::Model model = startGlb("radiosity (baked lighting: linear radiance in COLOR_0)", origin);
    tinygltf::Material unlit;
    unlit.name = "baked";
    unlit.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    unlit.pbrMetallicRoughness.metallicFactor = 0.0;
    unlit.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
    model.materials.push_back(unlit);
    model.extensionsUsed.push_back("KHR_materials_unlit");
    // The textured materials: their file materials and images, and the value their vertices
    // carry (rho H / pi, rho the material's factor; under a specular layer the viewer's texture
    // tints the layer's share of rho too, a few per cent of the light).
    std::vector<int> bakedMaterial;
    std::vector<std::vector<glm::vec3>> texturedValues;
    if (textures) {
        const Scene& scene = textures->scene;
        bakedMaterial.assign(scene.materials.size(), 0);
        texturedValues.resize(scene.materials.size());
        std::vector<int> image(scene.images.size(), -1);
        // Vertex colours multiply the texture per vertex, which one value per lit.glb vertex and
        // material cannot carry: a material on a surface with them is baked whole, texture and all.
        std::vector<bool> coloured(scene.materials.size(), false);
        for (const Surface& surface : scene.surfaces)
            if (!surface.colors.empty())
                for (const int m : surface.triangleMaterial) coloured[static_cast<std::size_t>(m)] = true;
        for (std::size_t m = 0; m < scene.materials.size(); ++m) {
            const Material& material = scene.materials[m];
            if (!keepsTexture(material) || coloured[m]) continue;
            const auto source = static_cast<std::size_t>(material.baseColorTexture.image);
            if (image[source] < 0) image[source] = addPngImage(model, scene.images[source]);
            bakedMaterial[m] = addTexturedMaterial(model, material, image[source]);
            texturedValues[m].reserve(textures->vertexIrradiance.size());
            for (const glm::vec3& h : textures->vertexIrradiance)
                texturedValues[m].push_back(material.reflectance * h / static_cast<float>(kPi));
        }
    }
    for (std::size_t side = 0; side < mesh.surfaces.size(); ++side)
        addSide(model, mesh, side, elements, vertices, vertexRadiance, textures, bakedMaterial, texturedValues);

    writeGlb(path, model);
}

}  // namespace rad
