// The glTF loader: transforms, formats, primitive modes, materials, and refusal of bad files.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/closed_glass.h"
#include "scene/gltf_loader.h"
#include "scene/material_model.h"
#include "scene/mesh_files.h"
#include "test_support.h"
#include "util/error.h"

namespace rad {
namespace {

using test::sourcePath;
using test::surfaceNamed;

// Positions are stored relative to Scene::origin; these compare world positions.
void expectVertices(const Scene& scene, const Surface& s, std::initializer_list<glm::vec3> expected) {
    ASSERT_EQ(s.triangles.size(), 1u) << s.name;
    std::size_t k = 0;
    for (const glm::vec3& e : expected) {
        const glm::dvec3 p = scene.origin + glm::dvec3(s.positions[s.triangles[0][k++]]);
        EXPECT_NEAR(p.x, e.x, 1e-6) << s.name;
        EXPECT_NEAR(p.y, e.y, 1e-6) << s.name;
        EXPECT_NEAR(p.z, e.z, 1e-6) << s.name;
    }
}

void expectTransforms(const Scene& scene) {
    ASSERT_EQ(scene.surfaces.size(), 3u);
    expectVertices(scene, surfaceNamed(scene, "plain"), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    expectVertices(scene, surfaceNamed(scene, "trs"), {{1, 2, 3}, {1, 4, 3}, {-1, 2, 3}});
    expectVertices(scene, surfaceNamed(scene, "child"), {{10, 5, 0}, {11, 5, 0}, {10, 6, 0}});
    for (const Surface& s : scene.surfaces) EXPECT_NEAR(test::triangleNormal(s, 0).z, 1.0, 1e-9) << s.name;
    EXPECT_NEAR(test::surfaceArea(surfaceNamed(scene, "trs")), 2.0, 1e-6);
}

TEST(GltfLoader, AppliesNodeHierarchyWithMatrixAndTrs) { expectTransforms(loadGltf(sourcePath("tests/data/gltf/transforms.gltf"))); }

TEST(GltfLoader, ReadsBinaryGlb) { expectTransforms(loadGltf(sourcePath("tests/data/gltf/transforms.glb"))); }

TEST(GltfLoader, TriangleStripKeepsConsistentWinding) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/strip.gltf"));
    const Surface& s = surfaceNamed(scene, "strip");
    ASSERT_EQ(s.triangles.size(), 3u);
    for (std::size_t t = 0; t < 3; ++t) EXPECT_NEAR(test::triangleNormal(s, t).z, -1.0, 1e-9) << "triangle " << t;
    EXPECT_NEAR(test::surfaceArea(s), 1.5, 1e-6);
}

TEST(GltfLoader, TriangleFanWithoutIndices) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/fan.gltf"));
    const Surface& s = surfaceNamed(scene, "fan");
    ASSERT_EQ(s.triangles.size(), 3u);
    for (std::size_t t = 0; t < 3; ++t) EXPECT_NEAR(test::triangleNormal(s, t).z, 1.0, 1e-9) << "triangle " << t;
    EXPECT_NEAR(test::surfaceArea(s), 1.5, 1e-6);
}

TEST(GltfLoader, NormalsFollowTheInverseTransposeAndAreUnit) {
    // The node turns 90 degrees about z and stretches x by 4. A normal (0.6, 0, 0.8) becomes
    // R S^-1 (0.6, 0, 0.8) = R (0.15, 0, 0.8) = (0, 0.15, 0.8), normalised; (0, 0, 1) stays.
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/normals-transformed.gltf"));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    const Surface& s = scene.surfaces[0];
    ASSERT_EQ(s.normals.size(), s.positions.size());
    const double length = std::sqrt(0.15 * 0.15 + 0.8 * 0.8);
    EXPECT_NEAR(glm::distance(glm::dvec3(s.normals[0]), glm::dvec3(0, 0, 1)), 0.0, 1e-6);
    EXPECT_NEAR(glm::distance(glm::dvec3(s.normals[1]), glm::dvec3(0, 0.15, 0.8) / length), 0.0, 1e-6);
    EXPECT_NEAR(glm::distance(glm::dvec3(s.normals[2]), glm::dvec3(-0.6, 0, 0.8)), 0.0, 1e-6);
    // Scenes without NORMAL have none: their faces are shaded flat.
    EXPECT_TRUE(loadGltf(sourcePath("tests/data/gltf/fan.gltf")).surfaces[0].normals.empty());
}

TEST(GltfLoader, DoubleSidedMaterial) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/double-sided.gltf"));
    ASSERT_EQ(scene.surfaces.size(), 3u);
    const Surface& plate = surfaceNamed(scene, "plate");
    EXPECT_TRUE(scene.materials[static_cast<std::size_t>(plate.triangleMaterial[0])].doubleSided);
    EXPECT_FALSE(scene.materials[static_cast<std::size_t>(surfaceNamed(scene, "above").triangleMaterial[0])].doubleSided);
}

TEST(GltfLoader, SkipsPointsAndLinesWithWarning) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/points-lines.gltf"));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].triangles.size(), 1u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("2 point or line"), std::string::npos) << scene.warnings[0];
}

TEST(GltfLoader, ExternalBufferRelativeToTheFile) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/external-buffer.gltf"));
    expectVertices(scene, surfaceNamed(scene, "tri"), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
}

TEST(GltfLoader, EmissiveStrengthScalesEmission) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/emissive-strength.gltf"));
    const Material& m = scene.materials[static_cast<std::size_t>(surfaceNamed(scene, "lamp").triangleMaterial[0])];
    EXPECT_FLOAT_EQ(m.emission.x, 2.0f);
    EXPECT_FLOAT_EQ(m.emission.y, 1.0f);
    EXPECT_FLOAT_EQ(m.emission.z, 4.0f);
    EXPECT_FLOAT_EQ(m.reflectance.x, 0.5f);
}

TEST(GltfLoader, MirroringTransformKeepsTheFrontFace) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/mirrored.gltf"));
    EXPECT_NEAR(test::triangleNormal(surfaceNamed(scene, "mirrored"), 0).z, 1.0, 1e-9);
}

// KHR_lights_punctual: photometric intensities over 683 lm/W, placed by their nodes.
TEST(GltfLoader, PointLightOf683CandelaIsOneWattPerSteradian) {
    const Scene scene = loadGltf(sourcePath("tests/data/lights/point-over-plane.gltf"));
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, Light::Type::Point);
    EXPECT_EQ(light.name, "bulb");
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(light.intensity[c], 1.0);
    const glm::dvec3 world = scene.origin + light.position;
    EXPECT_NEAR(world.x, 0.0, 1e-12);
    EXPECT_NEAR(world.y, 1.0, 1e-12);
    EXPECT_NEAR(world.z, 0.0, 1e-12);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(GltfLoader, SpotAndDirectionalLightsShineDownTheirNodesMinusZ) {
    const Scene spot = loadGltf(sourcePath("tests/data/lights/spot-over-plane.gltf"));
    ASSERT_EQ(spot.lights.size(), 1u);
    EXPECT_EQ(spot.lights[0].type, Light::Type::Spot);
    EXPECT_NEAR(spot.lights[0].direction.y, -1.0, 1e-12);
    EXPECT_DOUBLE_EQ(spot.lights[0].innerConeAngle, 0.3);
    EXPECT_DOUBLE_EQ(spot.lights[0].outerConeAngle, 0.6);
    const Scene sun = loadGltf(sourcePath("tests/data/lights/directional-occluder.gltf"));
    ASSERT_EQ(sun.lights.size(), 1u);
    EXPECT_EQ(sun.lights[0].type, Light::Type::Directional);
    EXPECT_NEAR(sun.lights[0].direction.x, 0.5, 1e-12);
    EXPECT_NEAR(sun.lights[0].direction.y, -std::sqrt(0.75), 1e-12);
    EXPECT_NEAR(sun.lights[0].direction.z, 0.0, 1e-12);
}

// The unit triangle's document with its first `from` replaced by `to`.
Scene loadEdited(const std::string& from, const std::string& to) {
    std::string text = test::readText(sourcePath("tests/data/gltf/no-scene-field.gltf"));
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return loadGltfFromMemory(sourcePath("tests/data/gltf/edited.gltf"), text);
}

bool anyWarning(const Scene& scene, const std::string& part) {
    return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

TEST(GltfLoader, LightsItCannotHonourAreNamedInWarnings) {
    const std::string lights = R"("extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "area", "name": "panel"}, {"type": "point", "range": 5.0}]}},
        "extensionsUsed": ["KHR_lights_punctual", "EXT_fancy_thing"], "asset": {)";
    const Scene scene = loadEdited(R"("asset": {)", lights);
    EXPECT_TRUE(scene.lights.empty());  // no node places them
    EXPECT_TRUE(anyWarning(scene, "'area'")) << "unknown light type";
    EXPECT_TRUE(anyWarning(scene, "range")) << "range is ignored";
    EXPECT_TRUE(anyWarning(scene, "EXT_fancy_thing")) << "unknown extension used";
}

// The material model (scene/material_model.h): glTF's defaults, and the diffuse reflectance.
TEST(GltfLoader, AnAbsentMetallicFactorIsOneAndMakesARoughMetal) {
    const Scene scene = loadEdited(R"("metallicFactor": 0.0,)", "");
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.metallic, 1.0f);
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_EQ(specularKind(m), SpecularKind::glossy);
    EXPECT_FLOAT_EQ(m.reflectance.x, 0.5f);  // F0 = baseColor, the matrix solvers' diffuse reflectance
    EXPECT_TRUE(anyWarning(scene, "metallicFactor 1")) << "a metal is named";
    EXPECT_TRUE(anyWarning(scene, "default")) << "and the default that made it one";
}

TEST(GltfLoader, AlphaModesAreReadAndBlendIsAMaskAtOneHalf) {
    const Scene mask = loadEdited(R"("name": "grey",)", R"("name": "grey", "alphaMode": "MASK", "alphaCutoff": 0.25,)");
    EXPECT_EQ(mask.materials[0].alphaMode, Material::AlphaMode::Mask);
    EXPECT_EQ(mask.materials[0].alphaCutoff, 0.25f);
    EXPECT_TRUE(mask.warnings.empty());
    const Scene blend = loadEdited(R"("name": "grey",)", R"("name": "grey", "alphaMode": "BLEND",)");
    EXPECT_EQ(blend.materials[0].alphaMode, Material::AlphaMode::Mask);
    EXPECT_EQ(blend.materials[0].alphaCutoff, 0.5f);
    EXPECT_TRUE(anyWarning(blend, "BLEND"));
    EXPECT_EQ(loadGltf(sourcePath("tests/data/gltf/no-scene-field.gltf")).materials[0].alphaMode,
              Material::AlphaMode::Opaque);
}

TEST(GltfLoader, SmoothMetalsAreMirrorsRoughOnesGlossyAndSmoothTransmittersGlass) {
    // scene/material_model.h: metallic 1 is a mirror up to roughness 0.05 and a GGX reflector
    // above; roughness at most 0.05, metallic 0 and transmission 1 is glass;
    // KHR_materials_volume's thickness says whether it refracts. Partly metallic is diffuse
    // with a specular layer (scene/material_model.h).
    const std::string factors = "\"metallicFactor\": 0.0,\n        \"roughnessFactor\": 1.0";
    const Scene mirror = loadEdited(factors, R"("metallicFactor": 1.0, "roughnessFactor": 0.02)");
    EXPECT_EQ(specularKind(mirror.materials[0]), SpecularKind::mirror);
    EXPECT_TRUE(anyWarning(mirror, "a mirror: the progressive solve"));
    const Scene rough = loadEdited(factors, R"("metallicFactor": 1.0, "roughnessFactor": 0.3)");
    EXPECT_EQ(specularKind(rough.materials[0]), SpecularKind::glossy);
    EXPECT_TRUE(anyWarning(rough, "a rough metal: the progressive solve"));
    const Scene partly = loadEdited(factors, R"("metallicFactor": 0.5, "roughnessFactor": 0.02)");
    EXPECT_EQ(specularKind(partly.materials[0]), SpecularKind::none);
    EXPECT_TRUE(anyWarning(partly, "partly metal: the camera pass and the path tracer draw"));
    const Scene glass = loadEdited(factors, R"("metallicFactor": 0.0, "roughnessFactor": 0.0 }, "extensions": {
        "KHR_materials_transmission": {"transmissionFactor": 1.0}, "KHR_materials_volume": {"thicknessFactor": 0.2})");
    Material m = glass.materials[0];
    EXPECT_FLOAT_EQ(m.thickness, 0.2f);
    EXPECT_EQ(specularKind(m), SpecularKind::glass);
    EXPECT_TRUE(anyWarning(glass, "glass: the progressive solve"));
    m.transmission = 0.9f;
    EXPECT_EQ(specularKind(m), SpecularKind::none);  // partly transmitting: diffuse, as before
    EXPECT_EQ(m.attenuationDistance, 0.0f);           // glTF's default: no attenuation
}

TEST(GltfLoader, AVolumesAttenuationIsReadAndBadValuesAreRefused) {
    // KHR_materials_volume's attenuationColor (0 to 1 per channel) after attenuationDistance
    // metres (> 0) inside the solid; the thickness texture is named in a warning.
    const std::string factors = "\"metallicFactor\": 0.0,\n        \"roughnessFactor\": 1.0";
    const auto volume = [&](const std::string& fields) {
        return loadEdited(factors, R"("metallicFactor": 0.0, "roughnessFactor": 0.0 }, "extensions": {
        "KHR_materials_transmission": {"transmissionFactor": 1.0}, "KHR_materials_volume": {"thicknessFactor": 0.2, )" +
                                       fields + "}");
    };
    const Scene tinted = volume(R"("attenuationDistance": 0.5, "attenuationColor": [0.5, 0.7, 1.0],
        "thicknessTexture": {"index": 0})");
    const Material& m = tinted.materials[0];
    EXPECT_FLOAT_EQ(m.attenuationDistance, 0.5f);
    EXPECT_FLOAT_EQ(m.attenuationColor.x, 0.5f);
    EXPECT_FLOAT_EQ(m.attenuationColor.y, 0.7f);
    EXPECT_FLOAT_EQ(m.attenuationColor.z, 1.0f);
    EXPECT_TRUE(anyWarning(tinted, "thicknessTexture"));
    for (const std::string bad : {R"("attenuationDistance": 0.0)", R"("attenuationDistance": -1.0)",
                                  R"("attenuationColor": [0.5, 1.5, 0.5])", R"("attenuationColor": [0.5, 0.5])"})
        EXPECT_THROW(volume(bad), FileError) << bad;
}

TEST(GltfLoader, TransmissionAndIorAreKeptAndTransmittedLightIsNotReflected) {
    // glTF's defaults give the grey (0.5) material a specular layer: its diffuse part is the base
    // colour times what neither metal nor transmission takes, and the metal's part joins the
    // layer's F0 (scene/material_model.h).
    const Scene scene = loadEdited(R"("metallicFactor": 0.0,)", R"("metallicFactor": 0.25,)");
    const SurfaceLayer partly = surfaceLayer(scene.materials[0]);
    ASSERT_TRUE(partly.present);
    EXPECT_FLOAT_EQ(partly.diffuse.x, 0.375f);              // 0.5 x 0.75
    EXPECT_FLOAT_EQ(partly.f0.x, 0.75f * 0.04f + 0.125f);  // the dielectric's 4 % and the metal's base
    EXPECT_FLOAT_EQ(partly.f90, 1.0f);
    const Scene clear = loadEdited(R"("name": "grey",)", R"("name": "grey", "extensions": {
        "KHR_materials_transmission": {"transmissionFactor": 0.5}, "KHR_materials_ior": {"ior": 1.33}},)");
    const Material& m = clear.materials[0];
    EXPECT_FLOAT_EQ(m.transmission, 0.5f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(surfaceLayer(m).diffuse.x, 0.25f);  // 0.5 x (1 - 0.5)
    EXPECT_TRUE(anyWarning(clear, "transmit"));
}

TEST(GltfLoader, NonMetalsHaveGltfsSpecularLayerUnlessTheFileSaysOtherwise) {
    // glTF gives every non-metal a specular layer (F0 4 % at IOR 1.5, F90 1);
    // KHR_materials_specular weakens it (specularFactor, F90 too) and tints its F0
    // (specularColorFactor, F0 kept at most 1), and 0 turns it off; an unlit material has none.
    const Scene plain = loadEdited(R"("metallicFactor": 0.0,)", R"("metallicFactor": 0.0,)");
    const SurfaceLayer layer = surfaceLayer(plain.materials[0]);
    ASSERT_TRUE(layer.present);
    EXPECT_NEAR(layer.f0.x, 0.04f, 1e-7f);
    EXPECT_FLOAT_EQ(layer.f90, 1.0f);
    EXPECT_GT(plain.materials[0].reflectance.x, 0.5f * layer.diffuseKept.x);  // the layer's light is reflected too
    const Scene tinted = loadEdited(R"("name": "grey",)", R"("name": "grey", "extensions": {
        "KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [1.0, 0.5, 40.0]}},)");
    const SurfaceLayer weak = surfaceLayer(tinted.materials[0]);
    EXPECT_NEAR(weak.dielectricF0.x, 0.02f, 1e-7f);
    EXPECT_NEAR(weak.dielectricF0.y, 0.01f, 1e-7f);
    EXPECT_NEAR(weak.dielectricF0.z, 0.5f, 1e-7f);  // min(0.04 x 40, 1) x 0.5
    EXPECT_FLOAT_EQ(weak.f90, 0.5f);
    const Scene matte = loadEdited(R"("name": "grey",)", R"("name": "grey", "extensions": {
        "KHR_materials_specular": {"specularFactor": 0.0}},)");
    EXPECT_FALSE(surfaceLayer(matte.materials[0]).present);
    EXPECT_FLOAT_EQ(matte.materials[0].reflectance.x, 0.5f);
    const Scene unlit = loadEdited("\"metallicFactor\": 0.0,\n        \"roughnessFactor\": 1.0",
                                   R"("metallicFactor": 0.5, "roughnessFactor": 1.0 }, "extensions": {
        "KHR_materials_unlit": {}, "KHR_materials_specular": {"specularFactor": 1.0})");
    EXPECT_FALSE(surfaceLayer(unlit.materials[0]).present);
    EXPECT_FLOAT_EQ(unlit.materials[0].reflectance.x, 0.5f);
    EXPECT_THROW(loadEdited(R"("name": "grey",)", R"("name": "grey", "extensions": {
        "KHR_materials_specular": {"specularColorFactor": [1.0, -0.5, 1.0]}},)"),
                 FileError);
}

TEST(GltfLoader, DropsDegenerateTrianglesWithCount) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/degenerate.gltf"));
    EXPECT_EQ(surfaceNamed(scene, "mostly_ok").triangles.size(), 1u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("2 degenerate"), std::string::npos) << scene.warnings[0];
}

TEST(GltfLoader, QuantizedPositionsWithStride) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/quantized.gltf"));
    expectVertices(scene, surfaceNamed(scene, "tri"), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
}

TEST(GltfLoader, MorphTargetsTakeTheirDefaultWeights) {
    // tests/data/gltf/morph-targets.gltf: the unit triangle, a target that lifts it by (0, 0, 1)
    // and one that moves corner 1 by (1, 0, 0), at the mesh's weights (0.5, 0): the file's pose
    // is the triangle at z = 0.5, as glTF viewers draw it. A node's weights take the mesh's place.
    const std::string path = sourcePath("tests/data/gltf/morph-targets.gltf");
    const Scene scene = loadGltf(path);
    expectVertices(scene, surfaceNamed(scene, "morphed"), {{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0.5f}});
    std::string text = test::readText(path);
    const std::string node = "\"name\": \"morphed\",";
    ASSERT_NE(text.find(node), std::string::npos);
    text.replace(text.find(node), node.size(), node + " \"weights\": [1.0, 0.5],");
    const Scene posed = loadGltfFromMemory(sourcePath("tests/data/gltf/edited.gltf"), text);
    expectVertices(posed, surfaceNamed(posed, "morphed"), {{0, 0, 1}, {1.5f, 0, 1}, {0, 1, 1}});
}

TEST(GltfLoader, GpuInstancesAreEachASurface) {
    // tests/data/gltf/instanced.gltf: EXT_mesh_gpu_instancing (required) draws the unit triangle
    // three times under a node moved by (0, 0, 1): as it is; doubled and moved by (2, 0, 0);
    // turned a quarter about z and moved by (0, 3, 0). Each instance is a surface of its own.
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/instanced.gltf"));
    ASSERT_EQ(scene.surfaces.size(), 3u);
    expectVertices(scene, surfaceNamed(scene, "instanced#0"), {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
    expectVertices(scene, surfaceNamed(scene, "instanced#1"), {{2, 0, 1}, {4, 0, 1}, {2, 2, 1}});
    expectVertices(scene, surfaceNamed(scene, "instanced#2"), {{0, 3, 1}, {0, 4, 1}, {-1, 3, 1}});
}

TEST(GltfLoader, SkinsPoseTheirMeshesByTheirJoints) {
    // tests/data/gltf/skinned.gltf (scenes/loader_scenes.py: skinned): corners moved by a joint
    // each and one by both at half weight, from two sets of joints, one joint's inverse bind
    // matrix a move; the skinned node's own move by (100, 0, 0) is ignored, as glTF says.
    const std::string path = sourcePath("tests/data/gltf/skinned.gltf");
    const Scene scene = loadGltf(path);
    expectVertices(scene, surfaceNamed(scene, "skinned"), {{0, 0, 1}, {0, 1, 2}, {-0.5f, 0.5f, 1.5f}});
    EXPECT_FALSE(anyWarning(scene, "skin")) << (scene.warnings.empty() ? "" : scene.warnings[0]);
    const std::string text = test::readText(path);
    auto edited = [&](const std::string& from, const std::string& to) {
        std::string t = text;
        EXPECT_NE(t.find(from), std::string::npos) << from;
        if (t.find(from) != std::string::npos) t.replace(t.find(from), from.size(), to);
        return loadGltfFromMemory(sourcePath("tests/data/gltf/edited.gltf"), t);
    };
    // Without the second set the last corner follows the root alone (its weights, 0.5, taken
    // over their sum): (0, 1, 1).
    const Scene oneSet = edited("\"JOINTS_1\"", "\"UNUSED_1\"");
    expectVertices(oneSet, surfaceNamed(oneSet, "skinned"), {{0, 0, 1}, {0, 1, 2}, {0, 1, 1}});
    // A skin whose joints lie outside the scene is not applied, with a warning: the node's move.
    const Scene outside = edited("\"nodes\": [\n        0,\n        2\n      ]", "\"nodes\": [\n        0\n      ]");
    expectVertices(outside, surfaceNamed(outside, "skinned"), {{100, 0, 0}, {101, 0, 0}, {100, 1, 0}});
    EXPECT_TRUE(anyWarning(outside, "not in the scene"));
    // A joint index past the skin's joints, and a skin that does not exist, are refused.
    EXPECT_THROW(edited("\"skin\": 0", "\"skin\": 3"), FileError);
    EXPECT_THROW(edited("\"joints\": [\n        2,\n        1\n      ]", "\"joints\": [\n        2\n      ]"),
                 FileError);
}

TEST(GltfLoader, SolidGlassMakesClosedGlassMeshesSolidAndLeavesPanesThin) {
    // --solid-glass (scene/closed_glass.h): the glass slab (a closed box) with its volume taken
    // away, as Blender's exporter writes glass, becomes a solid again; the thin pane (an open
    // quad) stays thin, named in a warning; a material that is not glass is left alone.
    Scene slab = loadGltf(sourcePath("tests/data/specular/glass-slab.gltf"));
    for (Material& m : slab.materials) m.thickness = 0.0f;
    EXPECT_EQ(solidifyClosedGlass(slab), std::vector<std::string>{"glass"});
    for (const Material& m : slab.materials) EXPECT_EQ(m.thickness > 0.0f, m.name == "glass") << m.name;
    Scene pane = loadGltf(sourcePath("tests/data/specular/thin-pane.gltf"));
    const std::size_t before = pane.warnings.size();
    EXPECT_TRUE(solidifyClosedGlass(pane).empty());
    for (const Material& m : pane.materials) EXPECT_EQ(m.thickness, 0.0f) << m.name;
    EXPECT_EQ(pane.warnings.size(), before + 1);
    EXPECT_TRUE(anyWarning(pane, "not closed"));
}

TEST(GltfLoader, PositionsAreRelativeToTheSceneCentre) {
    const Scene scene = loadGltf(sourcePath("tests/data/gltf/far-from-origin.gltf"));
    // The perpendicular squares moved by (10000, 500, -30000): the origin takes the offset,
    // the float positions keep the unit squares exactly.
    EXPECT_NEAR(scene.origin.x, 10000.5, 1e-9);
    EXPECT_NEAR(scene.origin.y, 500.5, 1e-9);
    EXPECT_NEAR(scene.origin.z, -29999.5, 1e-9);
    const Bounds b = scene.bounds();
    EXPECT_EQ(b.lo, glm::vec3(-0.5f));
    EXPECT_EQ(b.hi, glm::vec3(0.5f));
}

TEST(GltfLoader, FirstSceneWhenNoDefault) {
    EXPECT_EQ(loadGltf(sourcePath("tests/data/gltf/no-scene-field.gltf")).triangleCount(), 1u);
}

TEST(GltfLoader, CornellBox) {
    const Scene scene = loadGltf(sourcePath("scenes/cornell-box.gltf"));
    EXPECT_EQ(scene.surfaces.size(), 8u);
    EXPECT_EQ(scene.triangleCount(), 2u * (6 + 10));
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].name, "cornell");
    EXPECT_NEAR(scene.origin.z + scene.cameras[0].position.z, -0.8, 1e-6);
    // The camera looks down its -Z, which must be world +Z here.
    EXPECT_NEAR(scene.cameras[0].orientation[2].z, -1.0f, 1e-6);
    const Material& light = scene.materials[static_cast<std::size_t>(surfaceNamed(scene, "light").triangleMaterial[0])];
    EXPECT_NEAR(light.emission.x, 17.0f, 1e-4);
    EXPECT_NEAR(light.emission.y, 12.0f, 1e-4);
    EXPECT_NEAR(light.emission.z, 4.0f, 1e-4);
    EXPECT_NEAR(test::triangleNormal(surfaceNamed(scene, "light"), 0).y, -1.0, 1e-9);
    EXPECT_TRUE(scene.warnings.empty());
}

// Every file in tests/data/bad must be refused with a FileError naming the file and the problem.
struct BadFile {
    const char* file;
    const char* mentions;
};

class GltfLoaderRefuses : public ::testing::TestWithParam<BadFile> {};

TEST_P(GltfLoaderRefuses, WithAMessageNamingFileAndProblem) {
    const std::string path = sourcePath(std::string("tests/data/bad/") + GetParam().file);
    try {
        loadGltf(path);
        FAIL() << "loaded " << path;
    } catch (const FileError& e) {
        std::string message = e.what();
        EXPECT_EQ(message.rfind(path, 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        std::transform(message.begin(), message.end(), message.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        EXPECT_NE(message.find(GetParam().mentions), std::string::npos) << message;
    }
}

const BadFile kBadFiles[] = {BadFile{"malformed.gltf", "json"}, BadFile{"deep-nesting.gltf", "deeper than"},
                             BadFile{"not-gltf.glb", "magic"},
                             BadFile{"truncated.glb", "truncated"},
                             BadFile{"missing-buffer.gltf", "does-not-exist.bin"},
                             BadFile{"short-buffer.gltf", "buffer"},
                             BadFile{"accessor-out-of-range.gltf", "accessor"},
                             BadFile{"index-out-of-range.gltf", "index"},
                             BadFile{"nan-position.gltf", "nan"},
                             BadFile{"inf-position.gltf", "inf"},
                             BadFile{"node-cycle.gltf", "cycle"},
                             BadFile{"no-triangles.gltf", "triangle"},
                             BadFile{"empty-scene.gltf", "empty"},
                             BadFile{"nan-transform.gltf", "finite"},
                             BadFile{"bad-mesh-index.gltf", "mesh"},
                             BadFile{"missing-position.gltf", "position"},
                             BadFile{"required-extension.gltf", "khr_texture_basisu"},
                             BadFile{"bad-component-type.gltf", "component"},
                             BadFile{"does-not-exist.gltf", "no such file"},
                             BadFile{"absolute-uri.gltf", "absolute"},
                             BadFile{"parent-uri.gltf", "directory"},
                             BadFile{"scheme-uri.gltf", "scheme"},
                             BadFile{"encoded-parent-image-uri.gltf", "directory"},
                             BadFile{"wrong-type-count.gltf", "count"},
                             BadFile{"wrong-type-children.gltf", "children"},
                             BadFile{"absurd-depth.gltf", "deeper"},
                             BadFile{"absurd-count.gltf", "absurd"},
                             BadFile{"negative-emission.gltf", "negative"},
                             BadFile{"infinite-factor.gltf", "overflow"},
                             BadFile{"gltf-1-version.gltf", "only gltf 2"},
                             BadFile{"no-asset.gltf", "asset"},
                             BadFile{"name-not-string.gltf", "name must be a string"},
                             BadFile{"extensions-not-object.gltf", "extensions must be an object"},
                             BadFile{"fractional-index.gltf", "nodes[0].mesh must be an index"},
                             BadFile{"negative-index.gltf", "material must be an index"},
                             BadFile{"light-negative-intensity.gltf", "intensity"},
                             BadFile{"light-bad-colour.gltf", "color"},
                             BadFile{"light-missing.gltf", "places light 3"},
                             BadFile{"light-without-type.gltf", "no type"},
                             BadFile{"spot-cone-order.gltf", "cone"},
                             BadFile{"spot-without-cone.gltf", "spot"},
                             BadFile{"metallic-not-number.gltf", "metallicfactor"},
                             BadFile{"ior-below-one.gltf", "ior"},
                             BadFile{"bad-alpha-mode.gltf", "alphamode"},
                             BadFile{"texture-out-of-range.gltf", "textures"},
                             BadFile{"extension-texture-extensions-array.gltf", "speculartexture.extensions must be an object"},
                             BadFile{"bad-sampler-wrap.gltf", "wraps"},
                             BadFile{"normal-count.gltf", "normal of mesh 0 ('tri') primitive 0 has 1 entries"},
                             BadFile{"normal-not-finite.gltf", "normal 1 is not finite"}};

// Every file there is in the list (a file nobody tests is a stale file).
TEST(GltfLoaderRefuses, EveryBadFileIsListed) {
    std::set<std::string> listed;
    for (const BadFile& b : kBadFiles) listed.insert(b.file);
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("tests/data/bad"))) {
        const std::string name = entry.path().filename().string();
        // OBJ, STL and PLY files have their own list (MeshFiles.BrokenFilesAreRefusedNamingFileAndProblem).
        if (name != "README.md" && !isMeshFile(name)) EXPECT_TRUE(listed.count(name)) << name << " is not tested";
    }
}

INSTANTIATE_TEST_SUITE_P(BadFiles, GltfLoaderRefuses, ::testing::ValuesIn(kBadFiles),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                             std::string name = info.param.file;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
}  // namespace rad

namespace rad {
namespace {

TEST(GltfLoader, NormalMapsGetTheFilesTangentsOrMikkTSpacesConvention) {
    // tests/data/textures/normal-map-floors.gltf (scenes/texture_scenes.py): floors facing +Y
    // with u along +x or -x and v along +z. Without TANGENT the tangent is the direction of
    // increasing u, and w makes cross(normal, tangent) w point up the image (decreasing v, -z),
    // as glTF defines the bitangent; the file's TANGENT is kept (+z), and under a node that
    // mirrors x turned with it and its sign flipped; the map's scale is read.
    const Scene scene = loadGltf(sourcePath("tests/data/textures/normal-map-floors.gltf"));
    const auto surface = [&](const std::string& name) -> const Surface& {
        for (const Surface& s : scene.surfaces)
            if (s.name == name) return s;
        throw std::runtime_error("no surface " + name);
    };
    struct Frame {
        const char* surface;
        glm::vec4 tangent;
        glm::vec3 up;  // cross(normal, tangent) w
    };
    const Frame expected[] = {{"mapped", {1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}},
                              {"mapped-tangents", {0.0f, 0.0f, 1.0f, 1.0f}, {1.0f, 0.0f, 0.0f}},
                              {"mapped-mirrored", {-1.0f, 0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -1.0f}},
                              {"mapped-under-a-mirror", {-1.0f, 0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -1.0f}}};
    for (const Frame& f : expected) {
        const Surface& s = surface(f.surface);
        ASSERT_EQ(s.tangents.size(), s.positions.size()) << f.surface;
        for (const glm::vec4& t : s.tangents) {
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(t[c], f.tangent[c], 1e-6f) << f.surface << ", component " << c;
            const glm::vec3 up = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(t)) * t.w;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(up[c], f.up[c], 1e-6f) << f.surface << ", bitangent " << c;
        }
    }
    EXPECT_TRUE(surface("turned").tangents.empty());  // no map, no frame
    for (const Material& m : scene.materials) {
        const bool mapped = m.name.find("unmapped") == std::string::npos;
        EXPECT_EQ(m.normalTexture.present(), mapped) << m.name;
        EXPECT_TRUE(!mapped || m.normalTexture.linear) << m.name;
        EXPECT_FLOAT_EQ(m.normalScale, m.name == "matte-scale-0" ? 0.0f : 1.0f) << m.name;
    }
    // a TANGENT that is not VEC4 (here the positions' accessor) is refused, naming it
    std::string text = test::readText(sourcePath("tests/data/textures/normal-map-floors.gltf"));
    const std::size_t at = text.find(R"("TANGENT": 5)");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 12, R"("TANGENT": 3)");
    try {
        loadGltfFromMemory(sourcePath("tests/data/textures/edited.gltf"), text);
        ADD_FAILURE() << "a VEC3 TANGENT was accepted";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("TANGENT of"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rad
