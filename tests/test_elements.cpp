// Elements: the quadtree below each patch, the host's point location, and shading that stays
// continuous where coarse elements meet finer ones (T-vertices).

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <tiny_gltf.h>

#include "io/baked_gltf.h"
#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "mesh/vertices.h"
#include "scene/gltf_loader.h"
#include "shared_math.h"
#include "test_support.h"

namespace rad {
namespace {

double longestEdge(const std::array<glm::vec3, 3>& t) {
    return std::max({glm::distance(t[0], t[1]), glm::distance(t[1], t[2]), glm::distance(t[2], t[0])});
}

glm::dvec3 pointAt(const std::array<glm::vec3, 3>& t, const glm::dvec3& w) {
    return w.x * glm::dvec3(t[0]) + w.y * glm::dvec3(t[1]) + w.z * glm::dvec3(t[2]);
}

// Barycentric weights of `p` on triangle `t` (p in its plane).
glm::dvec3 weightsOf(const std::array<glm::vec3, 3>& t, const glm::dvec3& p) {
    const glm::dvec3 a(t[0]), b(t[1]), c(t[2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double inv = 1.0 / glm::dot(n, n);
    const double u = glm::dot(glm::cross(c - b, p - b), n) * inv;
    const double v = glm::dot(glm::cross(a - c, p - c), n) * inv;
    return {u, v, 1.0 - u - v};
}

struct Floor {
    Scene scene = loadGltf(test::sourcePath("tests/data/solve/occluder.gltf"));
    Mesh mesh = buildMesh(scene, {0.25, 1'000'000});
    std::uint32_t surface = 0;
    Floor() {
        while (mesh.surfaces[surface].name != "floor") ++surface;
    }
};

TEST(ElementMesh, UniformElementsTileEachPatchBelowTheSize) {
    const Floor floor;
    const double size = 0.07;
    const ElementMesh elements = ElementMesh::uniform(floor.mesh, size);
    ASSERT_EQ(elements.elementStart().size(), floor.mesh.patches.size() + 1);
    for (std::uint32_t p = 0; p < floor.mesh.patches.size(); ++p) {
        double area = 0.0;
        for (std::uint32_t e = elements.elementStart()[p]; e < elements.elementStart()[p + 1]; ++e) {
            const Element& element = elements.elements()[e];
            EXPECT_EQ(element.patch, p);
            EXPECT_LE(longestEdge(element.p), size * (1.0 + 1e-6));
            area += element.area;
        }
        EXPECT_NEAR(area, floor.mesh.patches[p].area, 1e-5 * floor.mesh.patches[p].area) << "patch " << p;
    }
    // No finer than needed: halving once more would also pass, so the parents were too big.
    for (const Element& element : elements.elements()) EXPECT_GT(2.0 * longestEdge(element.p), size);
}

TEST(ElementMesh, LocateFindsTheElementHoldingThePoint) {
    const Floor floor;
    ElementMesh elements = ElementMesh::uniform(floor.mesh, 0.0);
    // Uneven trees: split some elements up to three times.
    std::mt19937 random(7);
    for (int round = 0; round < 3; ++round) {
        std::vector<std::uint32_t> some;
        for (std::uint32_t e = 0; e < elements.elements().size(); ++e)
            if (random() % 3 == 0) some.push_back(e);
        elements.split(some, 0.0, 1'000'000);
    }
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const auto patch = static_cast<std::uint32_t>(random() % floor.mesh.patches.size());
        double u = unit(random), v = unit(random);
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        const glm::vec3 onPatch(u, v, 1.0 - u - v);
        glm::vec3 w = onPatch;
        const std::uint32_t e = elements.locate(patch, w);
        ASSERT_GE(e, elements.elementStart()[patch]);
        ASSERT_LT(e, elements.elementStart()[patch + 1]);
        EXPECT_GE(std::min({w.x, w.y, w.z}), -1e-6f);
        EXPECT_NEAR(w.x + w.y + w.z, 1.0f, 1e-6f);
        // Weights in float, three levels down: a few 1e-7 of the patch's 0.25 m.
        const glm::dvec3 expected = pointAt(floor.mesh.patches[patch].p, glm::dvec3(onPatch));
        EXPECT_LT(glm::distance(pointAt(elements.elements()[e].p, glm::dvec3(w)), expected), 1e-6);
    }
}

TEST(ElementMesh, SplitKeepsToTheSmallestEdgeAndTheCap) {
    const Floor floor;
    ElementMesh elements = ElementMesh::uniform(floor.mesh, 0.0);
    const std::size_t patches = elements.elements().size();
    std::vector<std::uint32_t> all(patches);
    for (std::uint32_t e = 0; e < patches; ++e) all[e] = e;
    // Children would be shorter than the smallest edge allowed: nothing splits.
    EXPECT_EQ(elements.split(all, floor.mesh.patchSize, 1'000'000), 0u);
    EXPECT_EQ(elements.elements().size(), patches);
    // The cap: each split adds three elements.
    EXPECT_EQ(elements.split(all, 0.0, patches + 3 * 5), 5u);
    EXPECT_EQ(elements.elements().size(), patches + 15);
    for (const Element& e : elements.elements()) EXPECT_LE(e.level, 1u);
}

// Shading interpolates each element's corner values. Along every element edge, the value seen
// from the element must equal the value seen from whichever element lies on the other side,
// coarse or fine: the T-vertex rule. Without it, a finer neighbour's corner halfway along a
// coarse edge keeps its own average and the shading jumps there.
TEST(Vertices, ShadingIsContinuousAcrossCoarseFineEdges) {
    const Floor floor;
    ElementMesh elements = ElementMesh::uniform(floor.mesh, 0.0);
    std::mt19937 random(11);
    for (int round = 0; round < 4; ++round) {
        std::vector<std::uint32_t> some;
        for (std::uint32_t e = 0; e < elements.elements().size(); ++e)
            if (floor.mesh.patches[elements.elements()[e].patch].surface == floor.surface && random() % 4 == 0)
                some.push_back(e);
        elements.split(some, 0.0, 1'000'000);
    }
    std::uniform_real_distribution<float> value(0.0f, 1.0f);
    std::vector<glm::vec3> perElement(elements.elements().size());
    for (glm::vec3& v : perElement) v = {value(random), value(random), value(random)};
    const MeshVertices vertices = weldVertices(floor.mesh, elements);
    const std::vector<glm::vec3> atVertices = vertexValues(elements, vertices, perElement);
    EXPECT_FALSE(vertices.tVertices.empty());

    std::vector<std::uint32_t> onFloor;
    for (std::uint32_t e = 0; e < elements.elements().size(); ++e)
        if (floor.mesh.patches[elements.elements()[e].patch].surface == floor.surface) onFloor.push_back(e);
    auto shade = [&](std::uint32_t e, const glm::dvec3& w) {
        glm::dvec3 sum(0.0);
        for (int k = 0; k < 3; ++k) sum += w[k] * glm::dvec3(atVertices[vertices.corners[e][k]]);
        return sum;
    };
    std::size_t compared = 0;
    double worst = 0.0;
    for (std::uint32_t e : onFloor) {
        const auto& t = elements.elements()[e].p;
        for (int k = 0; k < 3; ++k)
            for (double s : {0.13, 0.37, 0.5, 0.71, 0.94}) {
                glm::dvec3 w(0.0);
                w[k] = 1.0 - s, w[(k + 1) % 3] = s;
                const glm::dvec3 p = pointAt(t, w);
                const glm::dvec3 here = shade(e, w);
                for (std::uint32_t o : onFloor) {
                    if (o == e) continue;
                    const glm::dvec3 wo = weightsOf(elements.elements()[o].p, p);
                    if (std::min({wo.x, wo.y, wo.z}) < -1e-7) continue;
                    worst = std::max(worst, glm::length(shade(o, wo) - here));
                    ++compared;
                }
            }
    }
    EXPECT_GT(compared, onFloor.size());  // most edges are shared
    // Values in [0, 1] change by up to 1 across a finest element (1.6 cm): float rounding of
    // positions (1e-7 m) and values leaves a few 1e-6.
    EXPECT_LT(worst, 1e-5);
}

// Light that varies linearly is shaded exactly, on any mix of element sizes: each vertex's
// value is a plane fitted to the elements around it. (Averaging the elements' values would be
// off by the gradient times the distance to a coarse neighbour's centroid.)
TEST(Vertices, LinearLightIsShadedExactlyOnMixedSizes) {
    const Floor floor;
    ElementMesh elements = ElementMesh::uniform(floor.mesh, 0.0);
    std::mt19937 random(3);
    for (int round = 0; round < 3; ++round) {
        std::vector<std::uint32_t> some;
        for (std::uint32_t e = 0; e < elements.elements().size(); ++e)
            if (random() % 3 == 0) some.push_back(e);
        elements.split(some, 0.0, 1'000'000);
    }
    // The scene is centred: the floor spans x, z in [-1, 1].
    auto light = [](const glm::dvec3& p) { return 1.0 + 0.3 * p.x + 0.2 * p.z; };
    std::vector<glm::vec3> perElement(elements.elements().size());
    for (std::size_t e = 0; e < perElement.size(); ++e) {  // a linear function's mean is its centroid value
        const auto& p = elements.elements()[e].p;
        perElement[e] = glm::vec3(static_cast<float>(light((glm::dvec3(p[0]) + glm::dvec3(p[1]) + glm::dvec3(p[2])) / 3.0)));
    }
    const MeshVertices vertices = weldVertices(floor.mesh, elements);
    const std::vector<glm::vec3> atVertices = vertexValues(elements, vertices, perElement);
    std::size_t checked = 0;
    for (std::size_t v = 0; v < atVertices.size(); ++v) {
        const glm::dvec3 p(vertices.positions[v]);
        if (vertices.surface[v] != floor.surface) continue;
        EXPECT_NEAR(atVertices[v].x, light(p), 1e-5) << "vertex at " << p.x << ", " << p.z;
        ++checked;
    }
    EXPECT_GT(checked, 1000u);
}

TEST(Vertices, TVerticesTakeTheCoarseEdgesMidpointValue) {
    const Floor floor;
    ElementMesh elements = ElementMesh::uniform(floor.mesh, 0.0);
    elements.split({0}, 0.0, 1'000'000);  // one element split, its neighbours not
    const MeshVertices vertices = weldVertices(floor.mesh, elements);
    ASSERT_FALSE(vertices.tVertices.empty());
    std::vector<glm::vec3> perElement(elements.elements().size());
    for (std::size_t e = 0; e < perElement.size(); ++e) perElement[e] = glm::vec3(static_cast<float>(e));
    const std::vector<glm::vec3> atVertices = vertexValues(elements, vertices, perElement);
    for (const MeshVertices::TVertex& t : vertices.tVertices) {
        const glm::dvec3 mid = 0.5 * (glm::dvec3(vertices.positions[t.a]) + glm::dvec3(vertices.positions[t.b]));
        EXPECT_LT(glm::distance(glm::dvec3(vertices.positions[t.vertex]), mid), 1e-6);
        EXPECT_FLOAT_EQ(atVertices[t.vertex].x, 0.5f * (atVertices[t.a].x + atVertices[t.b].x));
    }
}

// lit.glb of a refined mesh: it loads back through the scene loader, covers each surface's area,
// and has no T-junctions (no vertex strictly inside another triangle's edge): the fans around
// elements with finer neighbours close every crack.
// Vertices the camera pass shades with, for a scene meshed one patch per face.
std::size_t weldedVertices(const std::string& file) {
    const Scene scene = loadGltf(test::sourcePath("tests/data/gltf/" + file));
    const Mesh mesh = buildMesh(scene, {100.0, 1'000'000});
    return weldVertices(mesh, ElementMesh::uniform(mesh, 0.0)).positions.size();
}

TEST(Vertices, TheFilesNormalsSayWhereSurfacesAreSmooth) {
    // An octagonal prism's side: 45 degrees between faces, beyond the 30 degree crease angle.
    // Without normals each face keeps its own four corners; with radial normals the author
    // says it is a cylinder, and the 16 points are shared.
    EXPECT_EQ(weldedVertices("prism-flat.gltf"), 32u);
    EXPECT_EQ(weldedVertices("prism-smooth.gltf"), 16u);
    // A 10 degree fold whose normals are split along it: a hard edge, though within the crease
    // angle (6 points, 8 vertices); the same fold with shared normals at 45 degrees is smooth.
    EXPECT_EQ(weldedVertices("fold-10-split.gltf"), 8u);
    EXPECT_EQ(weldedVertices("fold-45-shared.gltf"), 6u);
    // A 90 degree fold exported with averaged normals stays sharp: averaging light across it
    // would smear one wall's light onto the next.
    EXPECT_EQ(weldedVertices("fold-90-shared.gltf"), 8u);
}

TEST(BakedGltf, TexturedFacesKeepTheirTextureWithTheLightInTheVertexColours) {
    // The checker floor: texture coordinates (4 x, 4 z) in world metres, a 2 x 2 checker,
    // nearest and repeating. The light arriving at a vertex varies across x.
    const Scene scene = loadGltf(test::sourcePath("tests/data/textures/checker-floor.gltf"));
    const Mesh mesh = buildMesh(scene, {0.1, 1'000'000});
    const ElementMesh elements = ElementMesh::uniform(mesh, 0.0);
    const MeshVertices vertices = weldVertices(mesh, elements);
    std::vector<glm::vec3> radiance(vertices.positions.size(), glm::vec3(0.25f)), irradiance;
    for (const glm::vec3& p : vertices.positions) irradiance.push_back(glm::vec3(1.0f + p.x, 2.0f, 3.0f));
    const std::string path = testing::TempDir() + "textured-lit.glb";
    const BakedTextures textures{scene, irradiance};
    writeBakedGltf(path, mesh, elements, vertices, radiance, scene.origin, &textures);

    // Read back by this program's loader: the floor's material shows the same image, filtered
    // and wrapped alike, at the same texture coordinates.
    const Scene baked = loadGltf(path);
    const Surface& floor = test::surfaceNamed(baked, "floor");
    const Material& material = baked.materials[static_cast<std::size_t>(floor.triangleMaterial[0])];
    ASSERT_TRUE(material.baseColorTexture.present());
    EXPECT_TRUE(material.baseColorTexture.nearest);
    EXPECT_EQ(material.baseColorTexture.wrapS, TextureRef::Wrap::Repeat);
    const TextureImage& original = scene.images[0];
    const TextureImage& copy = baked.images[static_cast<std::size_t>(material.baseColorTexture.image)];
    EXPECT_EQ(copy.width, original.width);
    EXPECT_EQ(copy.rgba, original.rgba);
    ASSERT_EQ(floor.texCoords[0].size(), floor.positions.size());
    for (std::size_t v = 0; v < floor.positions.size(); ++v) {
        const glm::dvec3 world = glm::dvec3(floor.positions[v]) + baked.origin;
        EXPECT_NEAR(floor.texCoords[0][v].x, 4.0 * world.x, 1e-5);
        EXPECT_NEAR(floor.texCoords[0][v].y, 4.0 * world.z, 1e-5);
    }
    // The lamp emits: it keeps the plain baked material and its radiance.
    EXPECT_FALSE(baked.materials[static_cast<std::size_t>(test::surfaceNamed(baked, "lamp").triangleMaterial[0])]
                     .baseColorTexture.present());

    // COLOR_0 of the floor: rho H / pi at each vertex (rho the material's factor).
    tinygltf::Model model;
    tinygltf::TinyGLTF reader;
    std::string error, warning;
    ASSERT_TRUE(reader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
    const glm::vec3 rho =
        scene.materials[static_cast<std::size_t>(test::surfaceNamed(scene, "floor").triangleMaterial[0])].reflectance;
    const tinygltf::Primitive* textured = nullptr;
    for (const tinygltf::Mesh& m : model.meshes)
        for (const tinygltf::Primitive& p : m.primitives)
            if (p.attributes.count("TEXCOORD_0")) textured = &p;
    ASSERT_NE(textured, nullptr);
    const auto values = [&](const char* attribute) {
        const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(textured->attributes.at(attribute))];
        const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const auto* data =
            reinterpret_cast<const float*>(model.buffers[0].data.data() + view.byteOffset + a.byteOffset);
        return std::vector<float>(data, data + 3 * a.count);
    };
    const std::vector<float> colours = values("COLOR_0"), positions = values("POSITION");
    ASSERT_GT(colours.size(), 0u);
    for (std::size_t v = 0; v < colours.size() / 3; ++v) {
        const float x = positions[3 * v];  // the file's coordinates are the mesh's
        const glm::vec3 expected = rho * glm::vec3(1.0f + x, 2.0f, 3.0f) / static_cast<float>(kPi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(colours[3 * v + c], expected[c], 1e-5) << v;
    }
}

TEST(BakedGltf, RefinedMeshLoadsBackWithoutTJunctions) {
    const Floor floor;
    ElementMesh elements = ElementMesh::uniform(floor.mesh, 0.0);
    std::mt19937 random(9);
    for (int round = 0; round < 3; ++round) {
        std::vector<std::uint32_t> some;
        for (std::uint32_t e = 0; e < elements.elements().size(); ++e)
            if (random() % 3 == 0) some.push_back(e);
        elements.split(some, 0.0, 1'000'000);
    }
    const MeshVertices vertices = weldVertices(floor.mesh, elements);
    ASSERT_FALSE(vertices.tVertices.empty());
    const std::vector<glm::vec3> radiance =
        vertexValues(elements, vertices, std::vector<glm::vec3>(elements.elements().size(), glm::vec3(0.5f)));
    const std::string path = testing::TempDir() + "refined-lit.glb";
    writeBakedGltf(path, floor.mesh, elements, vertices, radiance, floor.scene.origin);
    const Scene baked = loadGltf(path);
    const Surface& surface = test::surfaceNamed(baked, "floor");
    EXPECT_NEAR(test::surfaceArea(surface), floor.mesh.surfaces[floor.surface].area,
                1e-5 * floor.mesh.surfaces[floor.surface].area);
    std::size_t inside = 0;
    for (const auto& t : surface.triangles)
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a(surface.positions[t[k]]), b(surface.positions[t[(k + 1) % 3]]);
            const glm::dvec3 ab = b - a;
            for (const glm::vec3& q : surface.positions) {
                const double s = glm::dot(glm::dvec3(q) - a, ab) / glm::dot(ab, ab);
                if (s > 1e-4 && s < 1.0 - 1e-4 && glm::length(glm::dvec3(q) - (a + s * ab)) < 1e-6) ++inside;
            }
        }
    EXPECT_EQ(inside, 0u);
}

}  // namespace
}  // namespace rad
