// The lightmap's layout on a scene (host/lightmap/lightmap_layout.h) and lightmapped.glb
// (host/io/lightmapped_gltf.h): the scene's triangles come back unchanged with the lightmap's
// UVs on TEXCOORD_1 and the lightmap as their emissive texture; the scene's own TEXCOORD_1 is
// used where it can be and refused, with the reason, where not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <tiny_gltf.h>

#include "io/lightmapped_gltf.h"
#include "lightmap/lightmap_layout.h"
#include "render/tone_map.h"
#include "scene/gltf_loader.h"
#include "test_support.h"
#include "util/error.h"

namespace rad {
namespace {

TEST(LightmappedGltf, LoadsBackWithTheScenesTrianglesAndItsLightmapOnTexcoord1) {
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    const Mesh mesh = buildMesh(scene, MeshOptions{0.1, 10'000'000});
    LightmapOptions options;
    options.texelSize = 0.004;
    options.pageSize = 256;
    const LightmapLayout layout = layoutLightmap(scene, mesh, options);
    ASSERT_FALSE(layout.fromScene);
    ASSERT_GE(layout.pages, 2u);  // materials on more than one page: a primitive per (material, page)
    // Each page a ramp across x in red and down y in green, blue its number, so the texel a UV
    // read back points to can be checked.
    std::vector<Image> pages(layout.pages);
    for (std::size_t p = 0; p < pages.size(); ++p) {
        pages[p].width = pages[p].height = 256;
        for (int y = 0; y < 256; ++y)
            for (int x = 0; x < 256; ++x)
                pages[p].pixels.push_back(
                    glm::vec3((x + 0.5f) / 256.0f * 2.0f, (y + 0.5f) / 256.0f * 2.0f, static_cast<float>(p)));
    }
    const std::string path = (std::filesystem::temp_directory_path() / "radiosity-test-lightmapped.glb").string();
    writeLightmappedGltf(path, scene, mesh, layout, pages, 2.0);
    const Scene back = loadGltf(path);
    // A strength of at most 1 goes in the emissive factor (no extension needed).
    writeLightmappedGltf(path, scene, mesh, layout, pages, 0.25);
    const Scene weak = loadGltf(path);
    std::remove(path.c_str());
    for (const Material& m : weak.materials) EXPECT_EQ(m.emission, glm::vec3(0.25f)) << m.name;

    ASSERT_EQ(back.surfaces.size(), scene.surfaces.size());
    ASSERT_EQ(back.cameras.size(), scene.cameras.size());
    EXPECT_LT(glm::length(back.cameras[0].position - scene.cameras[0].position), 1e-5f);
    std::size_t firstFace = 0;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface &a = scene.surfaces[s], &b = back.surfaces[s];
        ASSERT_EQ(a.triangles.size(), b.triangles.size()) << a.name;
        ASSERT_FALSE(b.texCoords[1].empty()) << a.name;
        // The file groups triangles by (material, page): match each input triangle to the one
        // read back at the same corners, then compare its lightmap UVs with the layout's.
        std::vector<bool> used(b.triangles.size(), false);
        for (std::size_t t = 0; t < a.triangles.size(); ++t) {
            std::size_t match = b.triangles.size();
            for (std::size_t u = 0; u < b.triangles.size() && match == b.triangles.size(); ++u) {
                bool same = !used[u];
                for (std::size_t k = 0; k < 3 && same; ++k)
                    same = glm::length(a.positions[a.triangles[t][k]] - b.positions[b.triangles[u][k]]) < 1e-5f;
                if (same) match = u;
            }
            ASSERT_LT(match, b.triangles.size()) << a.name << " triangle " << t << " is not in the file";
            used[match] = true;
            const std::size_t f = firstFace + t;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::vec2 uv = b.texCoords[1][b.triangles[match][k]];
                EXPECT_NEAR(uv.x * 256.0, layout.texels[f][k].x, 1e-3) << a.name;
                EXPECT_NEAR(uv.y * 256.0, layout.texels[f][k].y, 1e-3) << a.name;
            }
            const Material& m = back.materials[static_cast<std::size_t>(b.triangleMaterial[match])];
            EXPECT_EQ(m.reflectance, glm::vec3(0.0f));
            EXPECT_EQ(m.emission, glm::vec3(2.0f));  // the emissive strength
            ASSERT_TRUE(m.emissiveTexture.present());
            EXPECT_EQ(m.emissiveTexture.texCoord, 1);
            // The texel under the triangle's centre, as the UVs read back point to it (u across,
            // v down from the image's top) in the image the material reads: its red and green
            // are its column and row, its blue the page the layout put the face on.
            const TextureImage& image = back.images[static_cast<std::size_t>(m.emissiveTexture.image)];
            const glm::vec2 centre = (b.texCoords[1][b.triangles[match][0]] + b.texCoords[1][b.triangles[match][1]] +
                                      b.texCoords[1][b.triangles[match][2]]) /
                                     3.0f * 256.0f;
            const int x = std::min(255, static_cast<int>(centre.x)), y = std::min(255, static_cast<int>(centre.y));
            const std::uint8_t* texel = &image.rgba[(static_cast<std::size_t>(y) * 256 + x) * 4];
            auto encoded = [](float linear) { return static_cast<int>(std::lround(255.0f * srgb(linear))); };
            EXPECT_EQ(texel[0], encoded((x + 0.5f) / 256.0f)) << a.name;
            EXPECT_EQ(texel[1], encoded((y + 0.5f) / 256.0f)) << a.name;
            EXPECT_EQ(texel[2], encoded(static_cast<float>(layout.pageOf[f]) / 2.0f)) << a.name;
        }
        firstFace += a.triangles.size();
    }
}

// glTF numbers a primitive's UV sets from 0 without a gap (specification 3.7.2.1); viewers
// read them so (Blender's importer stops at the first one missing and then shows no lightmap).
// The Cornell box has no UV set of its own.
TEST(LightmappedGltf, NumbersItsUvSetsFromZeroWithoutAGap) {
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    ASSERT_TRUE(scene.surfaces[0].texCoords[0].empty());
    const Mesh mesh = buildMesh(scene, MeshOptions{0.1, 10'000'000});
    LightmapOptions options;
    options.pageSize = 64;
    const LightmapLayout layout = layoutLightmap(scene, mesh, options);
    std::vector<Image> pages(layout.pages);
    for (Image& page : pages) {
        page.width = page.height = 64;
        page.pixels.assign(64 * 64, glm::vec3(0.5f));
    }
    const std::string path = (std::filesystem::temp_directory_path() / "radiosity-test-uv-sets.glb").string();
    writeLightmappedGltf(path, scene, mesh, layout, pages, 1.0);
    tinygltf::Model model;
    tinygltf::TinyGLTF reader;
    std::string error, warning;
    const bool read = reader.LoadBinaryFromFile(&model, &error, &warning, path);
    std::remove(path.c_str());
    ASSERT_TRUE(read) << error;
    std::size_t primitives = 0;
    for (const tinygltf::Mesh& m : model.meshes)
        for (const tinygltf::Primitive& p : m.primitives) {
            ++primitives;
            int sets = 0;
            while (p.attributes.count("TEXCOORD_" + std::to_string(sets))) ++sets;
            for (const auto& [name, accessor] : p.attributes)
                if (name.rfind("TEXCOORD_", 0) == 0) EXPECT_LT(std::stoi(name.substr(9)), sets) << name << " after a gap";
            EXPECT_EQ(sets, 2) << m.name;
            // The lightmap's UVs, which the emissive texture reads, on both.
            EXPECT_EQ(p.attributes.at("TEXCOORD_0"), p.attributes.at("TEXCOORD_1")) << m.name;
        }
    EXPECT_GT(primitives, 0u);
}

TEST(LightmapLayout, UsesTheScenesTexcoord1WhereItCanAndSaysWhyNot) {
    Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    const Mesh mesh = buildMesh(scene, MeshOptions{0.1, 10'000'000});
    // A made atlas's UVs given back as the scene's TEXCOORD_1: usable, and used as they are.
    LightmapOptions made;
    made.texelSize = 0.005;
    made.pageSize = 512;
    const LightmapLayout atlas = layoutLightmap(scene, mesh, made);
    ASSERT_EQ(atlas.pages, 1u);
    std::size_t firstFace = 0;
    for (Surface& s : scene.surfaces) {
        s.texCoords[1].assign(s.positions.size(), glm::vec2(0.0f));
        // A vertex shared by faces in two charts cannot hold both places: split every corner.
        std::vector<glm::vec3> positions;
        std::vector<glm::vec2> uv;
        for (std::size_t t = 0; t < s.triangles.size(); ++t)
            for (std::size_t k = 0; k < 3; ++k) {
                positions.push_back(s.positions[s.triangles[t][k]]);
                uv.push_back(glm::vec2(atlas.texels[firstFace + t][k] / 512.0));
                s.triangles[t][k] = static_cast<std::uint32_t>(positions.size() - 1);
            }
        firstFace += s.triangles.size();
        s.positions = positions;
        s.texCoords[0].clear();
        s.texCoords[1] = uv;
        s.normals.clear();
    }
    const Mesh split = buildMesh(scene, MeshOptions{0.1, 10'000'000});
    LightmapOptions fromScene;
    fromScene.pageSize = 512;
    fromScene.uv = LightmapOptions::Uv::scene;
    const LightmapLayout used = layoutLightmap(scene, split, fromScene);
    EXPECT_TRUE(used.fromScene);
    EXPECT_EQ(used.charts, atlas.charts);
    EXPECT_NEAR(used.texelSize, 0.005, 1e-6);
    for (std::size_t f = 0; f < split.faces.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(used.texels[f][k].x, atlas.texels[f][k].x, 1e-3);

    // One triangle moved onto another's place: refused under Uv::scene, replaced under automatic.
    scene.surfaces[0].texCoords[1][0] = scene.surfaces[1].texCoords[1][0];
    scene.surfaces[0].texCoords[1][1] = scene.surfaces[1].texCoords[1][1];
    scene.surfaces[0].texCoords[1][2] = scene.surfaces[1].texCoords[1][2];
    const Mesh moved = buildMesh(scene, MeshOptions{0.1, 10'000'000});
    try {
        layoutLightmap(scene, moved, fromScene);
        ADD_FAILURE() << "an overlapping TEXCOORD_1 was used";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("overlapping"), std::string::npos) << e.what();
    }
    LightmapOptions automatic = fromScene;
    automatic.uv = LightmapOptions::Uv::automatic;
    automatic.texelSize = 0.01;
    const LightmapLayout replaced = layoutLightmap(scene, moved, automatic);
    EXPECT_FALSE(replaced.fromScene);
    EXPECT_NE(replaced.note.find("overlapping"), std::string::npos) << replaced.note;
    // Coordinates outside [0, 1] are refused too.
    scene.surfaces[0].texCoords[1][0] = glm::vec2(1.5f, 0.5f);
    EXPECT_THROW(layoutLightmap(scene, buildMesh(scene, MeshOptions{0.1, 10'000'000}), fromScene), InputError);
}

TEST(LightmapLayout, AGivenTexelSizeTakesTheSmallestPageThatHoldsItAndNoneIsRefusedByName) {
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    const Mesh mesh = buildMesh(scene, MeshOptions{0.1, 10'000'000});
    LightmapOptions options;
    options.uv = LightmapOptions::Uv::atlas;
    options.texelSize = 0.01;
    const LightmapLayout chosen = layoutLightmap(scene, mesh, options);
    EXPECT_EQ(chosen.pages, 1u);
    EXPECT_EQ(chosen.texelSize, 0.01);
    ASSERT_GE(chosen.pageSize, 64u);
    ASSERT_LE(chosen.pageSize, 4096u);
    EXPECT_EQ(chosen.pageSize & (chosen.pageSize - 1), 0u) << "a power of two";
    if (chosen.pageSize > 64) {  // half the page: more pages, or a face that does not fit one
        options.pageSize = chosen.pageSize / 2;
        try {
            EXPECT_GT(layoutLightmap(scene, mesh, options).pages, 1u);
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("larger than a page"), std::string::npos) << e.what();
        }
    }
    // Texels so small that a face spans more than the largest page searched.
    options.pageSize = 0;
    options.texelSize = 1e-5;
    try {
        layoutLightmap(scene, mesh, options);
        ADD_FAILURE() << "a face of more than 4096 texels was laid on a page";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("cornell-box.gltf"), std::string::npos) << message;
        EXPECT_NE(message.find("of surface '"), std::string::npos) << message;
        EXPECT_NE(message.find("larger than a page of 4096"), std::string::npos) << message;
    }
    // No texel size: the one that puts the atlas on the one page given.
    options.texelSize = 0.0;
    options.pageSize = 256;
    const LightmapLayout onePage = layoutLightmap(scene, mesh, options);
    EXPECT_EQ(onePage.pages, 1u);
    EXPECT_EQ(onePage.pageSize, 256u);
    EXPECT_GT(onePage.texelSize, 0.0);
}

}  // namespace
}  // namespace rad
