// Textures (scene/texture_sampling.h, mesh/patch_textures.h, kernels/texture.h): sRGB decoding,
// what a patch's reflectance and emission become, and the camera pass showing the texture at
// pixel resolution.

#include <algorithm>
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <webp/encode.h>
#include <nlohmann/json.hpp>

#include "solver/direct_light.h"
#include "device_fixture.h"
#include "mesh/vertices.h"
#include "device/specular_faces.h"
#include "render/path_tracer.h"
#include "render/renderer.h"
#include "render/view.h"
#include "scene/gltf_loader.h"
#include "scene/mesh_files.h"
#include "scene/material_model.h"
#include "scene/texture_sampling.h"
#include "shared_math.h"
#include "util/error.h"
#include "solver/progressive_solver.h"

namespace rad {
namespace {

using test::sharedCompute;
using test::TestScene;

TEST(Textures, SrgbDecodingIsTheStandardsCurve) {
    for (int i = 0; i < 256; ++i) {
        const double c = i / 255.0;
        const double linear = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        EXPECT_EQ(srgbToLinear(static_cast<std::uint8_t>(i)), static_cast<float>(linear)) << i;
    }
    EXPECT_EQ(srgbToLinear(0), 0.0f);
    EXPECT_EQ(srgbToLinear(255), 1.0f);
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
        const std::size_t taken = std::min<std::size_t>(3, bytes.size() - i);  // 1 to 3 bytes: 2 to 4 digits
        for (std::size_t k = 0; k < 4; ++k) out += k <= taken ? digits[(n >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

TEST(Textures, ExtTextureWebpImagesAreDecoded) {
    // EXT_texture_webp: the texture names a WebP image in its extension, the image a
    // glTF-Transform or Squoosh pipeline writes. A lossless 2 x 2 WebP of four distinct texels
    // decodes to exactly them, whether the texture has a PNG fallback as its source or none
    // (the extension then required).
    const std::uint8_t texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 128, 64, 32, 255};
    std::uint8_t* encoded = nullptr;
    const std::size_t size = WebPEncodeLosslessRGBA(texels, 2, 2, 8, &encoded);
    ASSERT_GT(size, 0u);
    const std::string webp(reinterpret_cast<const char*>(encoded), size);
    WebPFree(encoded);
    for (const bool fallback : {false, true}) {
        // (with a fallback, a WebP that does not decode leaves the fallback, below)
        auto json = nlohmann::json::parse(test::readText(test::sourcePath("tests/data/textures/uniform-texture.gltf")));
        json["images"].push_back(
            {{"name", "webp"}, {"mimeType", "image/webp"}, {"uri", "data:application/octet-stream;base64," + base64(webp)}});
        json["textures"][0]["extensions"]["EXT_texture_webp"] = {{"source", 1}};
        if (!fallback) json["textures"][0].erase("source");
        json["extensionsUsed"].push_back("EXT_texture_webp");
        if (!fallback) json["extensionsRequired"] = {"EXT_texture_webp"};
        const Scene scene = loadGltfFromMemory(test::sourcePath("tests/data/textures/edited.gltf"), json.dump());
        const TextureRef& ref = scene.materials.at(0).baseColorTexture;
        ASSERT_TRUE(ref.present()) << fallback;
        const TextureImage& image = scene.images.at(static_cast<std::size_t>(ref.image));
        ASSERT_EQ(image.width, 2);
        ASSERT_EQ(image.height, 2);
        EXPECT_TRUE(std::equal(image.rgba.begin(), image.rgba.end(), texels)) << fallback;
        if (!fallback) continue;
        json["images"][1]["uri"] = "data:application/octet-stream;base64," + base64(webp.substr(0, 20));
        const Scene broken = loadGltfFromMemory(test::sourcePath("tests/data/textures/edited.gltf"), json.dump());
        const TextureRef& kept = broken.materials.at(0).baseColorTexture;
        ASSERT_TRUE(kept.present());
        EXPECT_EQ(broken.images.at(static_cast<std::size_t>(kept.image)).width, 4);  // the 4 x 4 PNG
    }
}

TEST(Textures, TextureTransformAndWrapModesFollowTheSpecification) {
    // KHR_texture_transform: uv' = T R S uv with R = [[cos, sin], [-sin, cos]] (the extension's
    // rows), and the sampler's wrap modes; checked on a 2 x 2 texture read nearest.
    auto json = nlohmann::json::parse(test::readText(test::sourcePath("tests/data/textures/uniform-texture.gltf")));
    auto& info = json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"];
    info["extensions"]["KHR_texture_transform"] = {{"offset", {0.1, 0.2}}, {"rotation", 0.5}, {"scale", {2.0, 3.0}}};
    const Scene scene = loadGltfFromMemory(test::sourcePath("tests/data/textures/edited.gltf"), json.dump());
    const TextureRef& ref = scene.materials[0].baseColorTexture;
    ASSERT_TRUE(ref.present());
    const double c = std::cos(0.5), s = std::sin(0.5);
    for (const glm::vec2 uv : {glm::vec2(0.3f, 0.7f), glm::vec2(-1.5f, 2.25f)}) {
        const glm::vec2 t = transformedUv(ref, uv);
        EXPECT_NEAR(t.x, c * 2.0 * uv.x + s * 3.0 * uv.y + 0.1, 1e-6);
        EXPECT_NEAR(t.y, -s * 2.0 * uv.x + c * 3.0 * uv.y + 0.2, 1e-6);
    }
    // Texels 0 (top-left) .. 3 (bottom-right) of distinct grey levels, read nearest.
    TextureImage image;
    image.width = image.height = 2;
    image.rgba = {0, 0, 0, 255, 85, 85, 85, 255, 170, 170, 170, 255, 255, 255, 255, 255};
    TextureRef plain;
    plain.image = 0;
    plain.nearest = true;
    auto texel = [&](const TextureRef& r, glm::vec2 uv) {
        const float v = sampleTexture(image, r, uv).x;
        for (int k = 0; k < 4; ++k)
            if (v == srgbToLinear(static_cast<std::uint8_t>(85 * k))) return k;
        return -1;
    };
    EXPECT_EQ(texel(plain, {0.25f, 0.25f}), 0);
    EXPECT_EQ(texel(plain, {0.75f, 0.25f}), 1);
    EXPECT_EQ(texel(plain, {0.25f, 0.75f}), 2);  // v grows downwards: rows from the top
    EXPECT_EQ(texel(plain, {1.25f, 0.25f}), 0);  // repeat
    TextureRef clamped = plain, mirrored = plain;
    clamped.wrapS = clamped.wrapT = TextureRef::Wrap::ClampToEdge;
    mirrored.wrapS = mirrored.wrapT = TextureRef::Wrap::MirroredRepeat;
    EXPECT_EQ(texel(clamped, {1.25f, 0.25f}), 1);
    EXPECT_EQ(texel(clamped, {-3.0f, 5.0f}), 2);
    EXPECT_EQ(texel(mirrored, {1.25f, 0.25f}), 1);  // the second period runs backwards
    EXPECT_EQ(texel(mirrored, {1.75f, 0.25f}), 0);
    EXPECT_EQ(texel(plain, {std::nanf(""), 0.25f}), 0);  // a coordinate that is not finite reads texel 0
}

TEST(Textures, LoadedFromDataUrisAndFromGlbBufferViews) {
    for (const char* file : {"tests/data/textures/uniform-texture.gltf", "tests/data/textures/uniform-texture.glb"}) {
        const Scene scene = loadGltf(test::sourcePath(file));
        ASSERT_EQ(scene.images.size(), 1u) << file;
        EXPECT_EQ(scene.images[0].width, 4);
        EXPECT_EQ(scene.images[0].height, 4);
        ASSERT_TRUE(scene.materials[0].baseColorTexture.present()) << file;
        EXPECT_EQ(scene.surfaces[0].texCoords[0].size(), scene.surfaces[0].positions.size());
        EXPECT_TRUE(scene.surfaces[0].texCoords[1].empty());
        EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
    }
}

TEST(Textures, AJpegBesideTheGltfFileIsReadByItsBytes) {
    // A 16 x 16 JPEG of one sRGB colour, written here, referenced by a .gltf beside it (its
    // extension says nothing: the decoder goes by the bytes). JPEG is lossy, but a block of one
    // colour keeps only its quantised mean: each channel within 2 levels of what was written.
    const std::string dir = testing::TempDir();
    std::vector<unsigned char> rgb;
    for (int i = 0; i < 16 * 16; ++i) rgb.insert(rgb.end(), {200, 100, 50});
    std::string jpeg;
    ASSERT_TRUE(stbi_write_jpg_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<char*>(data), size);
        },
        &jpeg, 16, 16, 3, rgb.data(), 100));
    std::ofstream(dir + "colour.data", std::ios::binary) << jpeg;
    nlohmann::json doc =
        nlohmann::json::parse(test::readText(test::sourcePath("tests/data/textures/uniform-texture.gltf")));
    doc["images"][0] = {{"uri", "colour.data"}, {"mimeType", "image/jpeg"}};
    std::ofstream(dir + "jpeg-texture.gltf") << doc.dump();
    const Scene scene = loadGltf(dir + "jpeg-texture.gltf");
    ASSERT_EQ(scene.images.size(), 1u);
    const TextureImage& image = scene.images[0];
    ASSERT_EQ(image.width, 16);
    ASSERT_EQ(image.height, 16);
    for (std::size_t t = 0; t < image.rgba.size(); t += 4) {
        EXPECT_NEAR(image.rgba[t], 200, 2);
        EXPECT_NEAR(image.rgba[t + 1], 100, 2);
        EXPECT_NEAR(image.rgba[t + 2], 50, 2);
        EXPECT_EQ(image.rgba[t + 3], 255);
    }
}

TEST(Textures, AUniformTextureGivesEveryPatchItsDecodedValueTimesTheFactor) {
    // 4 x 4 texels of sRGB 128 under baseColorFactor (1, 0.5, 0.25).
    const TestScene s("tests/data/textures/uniform-texture.gltf", 0.1);
    const float grey = srgbToLinear(128);
    EXPECT_NEAR(grey, 0.2158605f, 1e-7f);
    for (const glm::vec3& rho : s.patches().reflectance) {
        EXPECT_FLOAT_EQ(rho.x, grey);
        EXPECT_FLOAT_EQ(rho.y, 0.5f * grey);
        EXPECT_FLOAT_EQ(rho.z, 0.25f * grey);
    }
}

TEST(Textures, ATexturedMetalTakesItsF0FromTheTextureAndAPaintedOneIsLayered) {
    // The uniform texture on a metal: as a rough metal (roughness 0.3) or a mirror (0), its F0 is
    // the factor times the decoded texel (the patches' mean), not the factor alone. The same
    // material with a metallicRoughnessTexture (the factors are glTF's defaults in real assets,
    // and the texture says where the surface is metal) is diffuse with a specular layer that reads
    // the texture, with a warning; glass, whose factors no texture can change, stays glass.
    nlohmann::json doc =
        nlohmann::json::parse(test::readText(test::sourcePath("tests/data/textures/uniform-texture.gltf")));
    auto& pbr = doc["materials"][0]["pbrMetallicRoughness"];
    pbr["metallicFactor"] = 1.0;
    const float grey = srgbToLinear(128);
    for (const double roughness : {0.3, 0.0}) {
        pbr["roughnessFactor"] = roughness;
        const TestScene s(loadGltfFromMemory(test::sourcePath("tests/data/textures/edited.gltf"), doc.dump()), 0.1);
        ASSERT_EQ(specularKind(s.scene().materials[0]), roughness > 0.0 ? SpecularKind::glossy : SpecularKind::mirror);
        const SpecularFaceTable table = buildSpecularFaces(s.scene(), s.mesh(), &s.patches().reflectance);
        ASSERT_TRUE(table.any);
        for (const SpecularFace& face : table.faces) {
            EXPECT_NEAR(face.colour[0], grey, 1e-6f) << roughness;
            EXPECT_NEAR(face.colour[1], 0.5f * grey, 1e-6f) << roughness;
            EXPECT_NEAR(face.colour[2], 0.25f * grey, 1e-6f) << roughness;
        }
    }
    pbr.erase("metallicFactor");
    pbr.erase("roughnessFactor");
    pbr["metallicRoughnessTexture"] = {{"index", 0}};
    const Scene painted = loadGltfFromMemory(test::sourcePath("tests/data/textures/edited.gltf"), doc.dump());
    EXPECT_EQ(painted.materials[0].metallic, 1.0f);
    EXPECT_EQ(specularKind(painted.materials[0]), SpecularKind::none);
    EXPECT_TRUE(std::any_of(painted.warnings.begin(), painted.warnings.end(), [](const std::string& w) {
        return w.find("draw the metal where the texture says") != std::string::npos;
    }));
    ASSERT_TRUE(painted.materials[0].metallicRoughnessTexture.present());
    EXPECT_TRUE(painted.materials[0].metallicRoughnessTexture.linear);
    EXPECT_TRUE(surfaceLayer(painted.materials[0]).present);
    // A texture only scales the factors down: metallic 0 and smooth stay so, and glass stays glass.
    Material glass = painted.materials[0];
    glass.metallic = 0.0f;
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    EXPECT_EQ(specularKind(glass), SpecularKind::glass);
}

TEST(Textures, KhrMaterialsSpecularTexturesSetEachPatchsReflectance) {
    // tests/data/textures/specular-texture-floor.gltf: the specularTexture's alpha is 0 where
    // x < 0.5 and 128/255 beyond, the specularColorTexture white where z < 0.5 and sRGB
    // (255, 128, 0) beyond. The radiosity pass reflects each patch by the layer its textures'
    // means give: the base colour alone on the bare half, the layer's albedo and the base's share
    // it leaves on the others; the file reads without a warning.
    const TestScene s("tests/data/textures/specular-texture-floor.gltf", 0.125);
    const Material& m = s.scene().materials.at(0);
    EXPECT_TRUE(s.scene().warnings.empty()) << s.scene().warnings.front();
    const glm::vec3 base(0.9f, 0.7f, 0.4f);
    const float strength = 128.0f / 255.0f;
    const glm::vec4 white(1.0f, 1.0f, 1.0f, strength), tinted(1.0f, srgbToLinear(128), 0.0f, strength);
    const glm::vec3 whiteLayer = radiosityReflectance(m, glm::vec3(1.0f), glm::vec3(1.0f), white);
    const glm::vec3 tintedLayer = radiosityReflectance(m, glm::vec3(1.0f), glm::vec3(1.0f), tinted);
    // the layers differ from the bare base and from each other (what the textures change)
    EXPECT_GT(glm::length(whiteLayer - base), 0.01f);
    EXPECT_GT(glm::length(whiteLayer - tintedLayer), 0.005f);
    int counted[3] = {0, 0, 0};
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        const Patch& patch = s.mesh().patches[p];
        const glm::vec3 centre = (patch.p[0] + patch.p[1] + patch.p[2]) / 3.0f + glm::vec3(s.scene().origin);
        const int part = centre.x < 0.5f ? 0 : (centre.z < 0.5f ? 1 : 2);
        const glm::vec3 expected = part == 0 ? base : (part == 1 ? whiteLayer : tintedLayer);
        const glm::vec3 rho = s.patches().reflectance[p];
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rho[c], expected[c], 1e-6f) << "patch " << p << ", part " << part;
        ++counted[part];
    }
    EXPECT_GT(counted[0], 0);
    EXPECT_GT(counted[1], 0);
    EXPECT_GT(counted[2], 0);
}

TEST(Textures, KhrMaterialsSpecularTexturesReadTheirSetAndTransformAndRefuseABadIndex) {
    // The extension's texture references are read as the core's are: texCoord, and
    // KHR_texture_transform's offset and set; an index past the textures is refused, naming it.
    const std::string path = test::sourcePath("tests/data/textures/edited.gltf");
    nlohmann::json doc =
        nlohmann::json::parse(test::readText(test::sourcePath("tests/data/textures/specular-texture-floor.gltf")));
    auto& layer = doc["materials"][0]["extensions"]["KHR_materials_specular"];
    layer["specularTexture"]["texCoord"] = 1;
    layer["specularColorTexture"]["extensions"]["KHR_texture_transform"] = {{"offset", {0.25, 0.5}}, {"texCoord", 1}};
    const Scene scene = loadGltfFromMemory(path, doc.dump());
    const Material& m = scene.materials.at(0);
    EXPECT_EQ(m.specularTexture.texCoord, 1);
    EXPECT_TRUE(m.specularTexture.linear);
    EXPECT_EQ(m.specularColorTexture.texCoord, 1);
    EXPECT_FALSE(m.specularColorTexture.linear);
    EXPECT_FLOAT_EQ(m.specularColorTexture.transform[2][0], 0.25f);
    EXPECT_FLOAT_EQ(m.specularColorTexture.transform[2][1], 0.5f);
    // on glass the layer is the ior's: the textures are dropped, with a warning
    nlohmann::json glass = doc;
    glass["materials"][0]["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1.0}};
    glass["extensionsUsed"].push_back("KHR_materials_transmission");
    const Scene pane = loadGltfFromMemory(path, glass.dump());
    EXPECT_FALSE(pane.materials.at(0).specularTexture.present());
    EXPECT_TRUE(std::any_of(pane.warnings.begin(), pane.warnings.end(), [](const std::string& w) {
        return w.find("textures are not read on glass") != std::string::npos;
    }));
    layer["specularTexture"]["index"] = 99;
    try {
        loadGltfFromMemory(path, doc.dump());
        FAIL() << "a specularTexture naming texture 99 was read";
    } catch (const FileError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find("specularTexture"), std::string::npos) << message;
    }
}

TEST(Textures, VertexColoursMultiplyTheBaseColourOfEachPatch) {
    // tests/data/textures/vertex-colour-floor.gltf: base colour (0.9, 0.7, 0.4), unlit (plain
    // diffuse); COLOR_0 as normalized bytes (VEC4) going from white at x = 0 to black at x = 1
    // where z < 0.5, as floats (VEC3) of (0.2, 0.6, 1.0) where z > 0.5. glTF multiplies the base
    // colour by them: each patch reflects the base colour times COLOR_0's mean over it, which is
    // linear, so 1 - x at its centre on the gradient.
    const TestScene s("tests/data/textures/vertex-colour-floor.gltf", 0.125);
    EXPECT_TRUE(s.scene().warnings.empty()) << s.scene().warnings.front();
    const glm::vec3 base(0.9f, 0.7f, 0.4f), blue(0.2f, 0.6f, 1.0f);
    int counted[2] = {0, 0};
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        const Patch& patch = s.mesh().patches[p];
        const glm::vec3 centre = (patch.p[0] + patch.p[1] + patch.p[2]) / 3.0f + glm::vec3(s.scene().origin);
        const int part = centre.z < 0.5f ? 0 : 1;
        const glm::vec3 expected = part == 0 ? base * (1.0f - centre.x) : base * blue;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(s.patches().reflectance[p][c], expected[c], 1e-5f) << "patch " << p << ", part " << part;
        ++counted[part];
    }
    EXPECT_GT(counted[0], 4);
    EXPECT_GT(counted[1], 4);
    // A signed or integer (not normalized) COLOR_0 is not one glTF allows: refused, naming it.
    const std::string path = test::sourcePath("tests/data/textures/edited.gltf");
    nlohmann::json doc =
        nlohmann::json::parse(test::readText(test::sourcePath("tests/data/textures/vertex-colour-floor.gltf")));
    for (const auto& [type, normalized] : {std::pair{5120, true}, std::pair{5121, false}}) {
        doc["accessors"][0]["componentType"] = type;
        doc["accessors"][0]["normalized"] = normalized;
        try {
            loadGltfFromMemory(path, doc.dump());
            ADD_FAILURE() << "COLOR_0 of component type " << type << " was read";
        } catch (const FileError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path), std::string::npos) << message;
            EXPECT_NE(message.find("COLOR_0"), std::string::npos) << message;
        }
    }
}

TEST(Textures, ObjMapKdMultipliesKdInTheObjsTextureCoordinates) {
    // tests/data/meshes/textured.obj: a unit quad facing +z whose vt are its (x, y), Kd (0.5, 0.6,
    // 0.7) times map_Kd -clamp .\stripes.png (a backslash, as Windows programs write; 2 x 2
    // texels, the top row white, the bottom black).
    // OBJ counts v from the image's bottom, so the quad is white at the top: with bilinear
    // filtering each patch reflects Kd times the texture's mean over it, 1 where y > 0.75, 0
    // where y < 0.25, 0.5 over the quad. Beside it a quad whose map_Kd names no file keeps its Kd,
    // and a warning names the file.
    Scene scene = loadMeshFiles({test::sourcePath("tests/data/meshes/textured.obj")});
    ASSERT_EQ(scene.images.size(), 3u);  // stripes.png for 'stripes', and for 'leaf' with its mask.png
    EXPECT_TRUE(std::any_of(scene.warnings.begin(), scene.warnings.end(), [](const std::string& w) {
        return w.find("missing.png") != std::string::npos && w.find("'lost'") != std::string::npos;
    }));
    const TestScene s(std::move(scene), 0.125);
    const glm::vec3 kd(0.5f, 0.6f, 0.7f);
    double sum = 0.0, area = 0.0;
    int white = 0, black = 0;
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        const Patch& patch = s.mesh().patches[p];
        const glm::vec3 rho = s.patches().reflectance[p];
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& corner : patch.p) {
            lo = glm::min(lo, corner + glm::vec3(s.scene().origin));
            hi = glm::max(hi, corner + glm::vec3(s.scene().origin));
        }
        if (lo.x > 3.5f) continue;  // the cut-outs, below
        if (lo.x > 1.5f) {  // the quad without its image
            for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(rho[c], 0.3f);
            continue;
        }
        const double shade = rho.x / kd.x;
        for (int c = 1; c < 3; ++c) EXPECT_NEAR(rho[c] / kd[c], shade, 1e-5) << "patch " << p;
        if (lo.y >= 0.75f) {
            EXPECT_NEAR(shade, 1.0, 1e-5) << "patch " << p << " at the top";
            ++white;
        }
        if (hi.y <= 0.25f) {
            EXPECT_NEAR(shade, 0.0, 1e-5) << "patch " << p << " at the bottom";
            ++black;
        }
        sum += shade * patch.area;
        area += patch.area;
    }
    EXPECT_GT(white, 2);
    EXPECT_GT(black, 2);
    EXPECT_NEAR(sum / area, 0.5, 0.01);
    // map_d mask.png (white left, black right) cuts 'leaf' as glTF's alpha MASK: its base colour
    // texture's alpha is the mask's grey; 'window' (d 0.3) is cut everywhere, with a warning.
    const Scene& read = s.scene();
    const auto material = [&](const char* name) -> const Material& {
        return *std::find_if(read.materials.begin(), read.materials.end(),
                             [&](const Material& m) { return m.name == name; });
    };
    const Material& leaf = material("leaf");
    EXPECT_EQ(leaf.alphaMode, Material::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(leaf.alpha, 1.0f);
    ASSERT_TRUE(leaf.baseColorTexture.present());
    const TextureImage& cut = read.images.at(static_cast<std::size_t>(leaf.baseColorTexture.image));
    for (int texel = 0; texel < 4; ++texel) {
        EXPECT_EQ(cut.rgba[4 * texel + 3], texel % 2 == 0 ? 255 : 0) << texel;  // alpha: the mask
        EXPECT_EQ(cut.rgba[4 * texel], texel < 2 ? 255 : 0) << texel;           // colour: the stripes
    }
    const Material& window = material("window");
    EXPECT_EQ(window.alphaMode, Material::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(window.alpha, 0.3f);
    EXPECT_TRUE(std::any_of(read.warnings.begin(), read.warnings.end(), [](const std::string& w) {
        return w.find("'window'") != std::string::npos && w.find("cut-out") != std::string::npos;
    }));
}

TEST(Textures, PlyTextureFileAndPerCornerCoordinatesAreRead) {
    // tests/data/meshes/textured.ply: the unit quad as MeshLab writes a textured scan ("comment
    // TextureFile stripes.png", texcoord per face corner, v from the bottom): white at the top,
    // black below, as the OBJ's (the same image, unclamped here: bilinear wrapping blends the
    // rows at the very top and bottom, so only patches within y 0.3 to 0.7 are checked against
    // the gradient between the rows' centres).
    const TestScene s(loadMeshFiles({test::sourcePath("tests/data/meshes/textured.ply")}), 0.1);
    ASSERT_EQ(s.scene().images.size(), 1u);
    ASSERT_TRUE(s.scene().materials.at(0).baseColorTexture.present());
    int checked = 0;
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        const Patch& patch = s.mesh().patches[p];
        const glm::vec3 centre = (patch.p[0] + patch.p[1] + patch.p[2]) / 3.0f + glm::vec3(s.scene().origin);
        float lo = 1.0f, hi = 0.0f;
        for (const glm::vec3& corner : patch.p) {
            lo = std::min(lo, corner.y + static_cast<float>(s.scene().origin.y));
            hi = std::max(hi, corner.y + static_cast<float>(s.scene().origin.y));
        }
        if (lo < 0.3f || hi > 0.7f) continue;
        // texel rows' centres at image v 0.25 (white) and 0.75 (black): y = 1 - v
        EXPECT_NEAR(s.patches().reflectance[p].x, std::clamp((centre.y - 0.25) / 0.5, 0.0, 1.0), 0.05) << p;
        ++checked;
    }
    EXPECT_GT(checked, 4);
}

TEST(Textures, APatchsReflectanceIsTheTexturesMeanOverIt) {
    // A black-and-white checker (nearest, repeated 4 times across): the floor's mean is 0.5.
    // Each patch's mean is the midpoint rule with at least four points per texel it covers;
    // only points within half their spacing of a checker edge can be misjudged, so the
    // area-weighted mean over the floor is within 1% of 0.5, and patches wholly inside one
    // texel read exactly 0 or 1.
    const TestScene s("tests/data/textures/checker-floor.gltf", 0.05);
    const std::size_t floor = s.surface("floor");
    double sum = 0.0, area = 0.0;
    int pure = 0, mixed = 0;
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        if (s.mesh().patches[p].surface != floor) continue;
        const double rho = s.patches().reflectance[p].x;
        sum += rho * s.patches().area[p];
        area += s.patches().area[p];
        EXPECT_GE(rho, 0.0);
        EXPECT_LE(rho, 1.0);
        (rho == 0.0 || rho == 1.0 ? pure : mixed) += 1;
    }
    EXPECT_NEAR(sum / area, 0.5, 0.005);
    EXPECT_GT(pure, 100);  // patches 1/20 m across, texels 1/8 m: most lie inside one
    EXPECT_GT(mixed, 10);
}

TEST(Textures, AnEmissiveTextureScalesTheEmittedPower) {
    // Half of the unit lamp's emissive texture is black: it emits pi x 0.5 W per channel.
    const TestScene s("tests/data/textures/half-lit-lamp.gltf", 0.05);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.emitters().power()[c], 0.5 * kPi, 0.005 * kPi);
}

// The light of a solve as the camera pass reads it: radiance B / pi and irradiance H at the
// vertices.
struct Shaded {
    MeshVertices vertices;
    std::vector<glm::vec3> radiance, irradiance;
};

Shaded solveAndShade(const TestScene& s, std::uint64_t rays) {
    ProgressiveOptions options;
    options.rays = rays;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    Shaded out{weldVertices(s.mesh(), s.elements), {}, {}};
    out.radiance = vertexValues(s.elements, out.vertices, r.radiosity);
    for (glm::vec3& v : out.radiance) v /= static_cast<float>(kPi);
    std::vector<glm::vec3> h(r.incident.size());
    for (std::size_t e = 0; e < h.size(); ++e) h[e] = r.incident[e] / s.elements.elements()[e].area;
    out.irradiance = vertexValues(s.elements, out.vertices, h);
    return out;
}

TEST(Textures, TheCameraPassShowsRhoOfUvTimesTheIrradiance) {
    // A uniform texture under a sky: rho(uv) is the patches' rho everywhere, so the textured
    // path, rho(uv) H / pi, shows what the plain path, B / pi, shows, to float rounding.
    Scene scene = loadGltf(test::sourcePath("tests/data/textures/uniform-texture.gltf"));
    scene.sky = glm::vec3(1.0f, 2.0f, 3.0f);
    const TestScene s(std::move(scene), 0.1);
    const Shaded shaded = solveAndShade(s, 100'000);
    const View view = chooseView(s.scene(), "");
    const DeviceElements elements(sharedCompute(), s.elements);
    const Image textured =
        renderView(s, elements, shaded.vertices, shaded.radiance, view, {48, 48, 1}, &shaded.irradiance);
    const Image plain = renderView(s, elements, shaded.vertices, shaded.radiance, view, {48, 48, 1});
    int floor = 0;
    for (std::size_t i = 0; i < plain.pixels.size(); ++i) {
        if (plain.pixels[i] == glm::vec3(1.0f, 2.0f, 3.0f)) continue;  // the sky
        ++floor;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(textured.pixels[i][c], plain.pixels[i][c], 1e-5 * plain.pixels[i][c]) << i;
    }
    EXPECT_GT(floor, 100);
}

TEST(Textures, TheCameraPassShowsTheTextureAtPixelResolution) {
    // Straight down at the checker floor, 8 pixels per texel: pixels inside black texels are
    // exactly black, pixels inside white ones show H / pi, at least what the patch means show.
    const TestScene s("tests/data/textures/checker-floor.gltf", 0.05);
    const Shaded shaded = solveAndShade(s, 200'000);
    const View view = chooseView(s.scene(), "plan");
    const DeviceElements elements(sharedCompute(), s.elements);
    const int size = 64;
    const Image textured =
        renderView(s, elements, shaded.vertices, shaded.radiance, view, {size, size, 1}, &shaded.irradiance);
    const Image plain = renderView(s, elements, shaded.vertices, shaded.radiance, view, {size, size, 1});
    int black = 0, white = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (x % 8 == 0 || x % 8 == 7 || y % 8 == 0 || y % 8 == 7) continue;  // near a texel edge
            const glm::vec3 t = textured.pixels[static_cast<std::size_t>(y * size + x)];
            const glm::vec3 p = plain.pixels[static_cast<std::size_t>(y * size + x)];
            if (t.x == 0.0f) {
                ++black;
                continue;
            }
            ++white;
            EXPECT_GE(t.x, p.x * (1.0f - 1e-5f)) << x << ", " << y;
            EXPECT_EQ(t.x, t.y);
        }
    // 8 x 8 texels, half of each colour, 36 inner pixels each.
    EXPECT_EQ(black, 32 * 36);
    EXPECT_EQ(white, 32 * 36);
}

TEST(AlphaMasks, AMaskedQuadPassesTheUnmaskedFractionOfTheLight) {
    // 1 W/m^2 straight down through a quad whose texture is clear on its half x > 0.5: the floor
    // below receives exactly 0.5 W; elements wholly on one side get 0 or 1 W/m^2. The midpoint
    // rule errs only on the elements the edge x = 0.5 crosses (1/62 m wide, a few % of the
    // floor), each by at most a sixteenth of its power: 0.005 W bounds it.
    const TestScene s("tests/data/textures/masked-quad.gltf", 0.025);
    const DirectLight direct = directLight(s, s.elements, 1);
    const std::size_t floor = s.surface("floor");
    double total = 0.0;
    int dark = 0, lit = 0;
    for (std::size_t e = 0; e < direct.arrived.size(); ++e) {
        const Element& element = s.elements.elements()[e];
        if (s.mesh().patches[element.patch].surface != floor) continue;
        total += direct.arrived[e].x;
        double lo = 1e9, hi = -1e9;
        for (const glm::vec3& p : element.p) {
            const double x = s.scene().origin.x + p.x;
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
        const double mean = direct.arrived[e].x / element.area;
        if (hi < 0.5 - 1e-6) {
            EXPECT_EQ(mean, 0.0) << e;
            ++dark;
        }
        if (lo > 0.5 + 1e-6) {
            EXPECT_NEAR(mean, 1.0, 1e-6) << e;
            ++lit;
        }
    }
    EXPECT_NEAR(total, 0.5, 0.005);
    EXPECT_GT(dark, 100);
    EXPECT_GT(lit, 100);
    // The screen itself receives the light only where it is opaque: 0.5 W in all.
    const std::size_t screen = s.surface("screen");
    double onScreen = 0.0;
    for (std::size_t e = 0; e < direct.arrived.size(); ++e)
        if (s.mesh().patches[s.elements.elements()[e].patch].surface == screen) onScreen += direct.arrived[e].x;
    EXPECT_NEAR(onScreen, 0.5, 0.005);
}

TEST(AlphaMasks, AQuadClearEverywhereLetsAllOfTheLightThrough) {
    // baseColorFactor alpha 0.3 under cutoff 0.5, no texture: the quad is not there for rays, and
    // receives nothing itself (light that arrived on it would be light twice).
    const TestScene s("tests/data/textures/clear-quad.gltf", 0.05);
    const DirectLight direct = directLight(s, s.elements, 1);
    const std::size_t floor = s.surface("floor"), screen = s.surface("screen");
    double onFloor = 0.0, onScreen = 0.0;
    for (std::size_t e = 0; e < direct.arrived.size(); ++e) {
        const std::size_t surface = s.mesh().patches[s.elements.elements()[e].patch].surface;
        if (surface == floor) onFloor += direct.arrived[e].x;
        if (surface == screen) onScreen += direct.arrived[e].x;
    }
    EXPECT_NEAR(onFloor, 1.0, 1e-5);
    EXPECT_EQ(onScreen, 0.0);
    EXPECT_EQ(direct.absorbedByBacks.x, 0.0);  // the floor's back faces away; the screen's is clear
}

TEST(Textures, ThePathTracerReadsTexturesAtTheHit) {
    // Straight down at the checker floor under a sky, one reflection, 4 pixels per texel: pixels
    // inside black texels are black, inside white ones lit (a face's mean would show neither).
    Scene scene = loadGltf(test::sourcePath("tests/data/textures/checker-floor.gltf"));
    scene.sky = glm::vec3(1.0f);
    const TestScene s(std::move(scene), 10.0);
    PathTraceOptions o;
    o.width = 32;
    o.height = 32;
    o.samples = 4;
    o.maxBounces = 1;
    const PathTraceResult r = pathTrace(s, chooseView(s.scene(), "plan"), o);
    int black = 0, lit = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            if (x % 4 == 0 || x % 4 == 3 || y % 4 == 0 || y % 4 == 3) continue;  // near a texel edge
            const float v = r.image.pixels[static_cast<std::size_t>(y * o.width + x)].x;
            (v == 0.0f ? black : lit) += 1;
        }
    EXPECT_EQ(black, 32 * 4);
    EXPECT_EQ(lit, 32 * 4);
}

TEST(AlphaMasks, TheCameraSeesThroughTheClearTexels) {
    // From above, orthographic, direct light only: where the quad is opaque (x < 0.5) the
    // camera sees it, rho 0.2 under E = 1: 0.2 / pi; where it is clear, the floor, rho 0.5:
    // 0.5 / pi. The path tracer's camera and shadow rays both pass the clear texels.
    const TestScene s("tests/data/textures/masked-quad.gltf", 10.0);
    const View v = test::topDownView(s.scene(), glm::dvec3(0.5, 2.0, 0.5), 0.5f);
    PathTraceOptions o;
    o.width = 16;
    o.height = 16;
    o.samples = 1;
    o.maxBounces = 1;
    const PathTraceResult r = pathTrace(s, v, o);
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            if (x == 7 || x == 8) continue;  // jittered samples may fall on either side of x = 0.5
            const double expected = (x < 8 ? 0.2 : 0.5) / kPi;
            EXPECT_NEAR(r.image.pixels[static_cast<std::size_t>(y * o.width + x)].x, expected, 1e-5) << x << ", " << y;
        }
}

}  // namespace
}  // namespace rad
