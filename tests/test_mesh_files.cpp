// OBJ, STL and PLY files: the same coordinates give the same scene as the glTF file that holds
// them, bit for bit; units scale; materials come from the MTL; broken files are refused.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scene/gltf_loader.h"
#include "scene/material_model.h"
#include "scene/mesh_files.h"
#include "scene/polygon_split.h"
#include "scene/scene_files.h"
#include "test_support.h"
#include "util/error.h"

namespace rad {
namespace {

using test::sourcePath;

std::string meshData(const char* name) { return sourcePath(std::string("tests/data/meshes/") + name); }

// Every surface's triangles by world position (and, with `normals`, their vertex normals),
// compared bit for bit.
void expectSameGeometry(const Scene& expected, const Scene& got, bool normals = false) {
    ASSERT_EQ(expected.surfaces.size(), got.surfaces.size());
    EXPECT_EQ(std::memcmp(&expected.origin, &got.origin, sizeof expected.origin), 0);
    for (std::size_t s = 0; s < expected.surfaces.size(); ++s) {
        const Surface& a = expected.surfaces[s];
        const Surface& b = got.surfaces[s];
        EXPECT_EQ(a.name, b.name);
        ASSERT_EQ(a.triangles.size(), b.triangles.size()) << a.name;
        for (std::size_t t = 0; t < a.triangles.size(); ++t)
            for (int c = 0; c < 3; ++c) {
                const glm::vec3 pa = a.positions[a.triangles[t][c]], pb = b.positions[b.triangles[t][c]];
                EXPECT_EQ(std::memcmp(&pa, &pb, sizeof pa), 0) << a.name << " triangle " << t << " corner " << c;
                if (!normals) continue;
                ASSERT_FALSE(a.normals.empty() || b.normals.empty()) << a.name;
                const glm::vec3 na = a.normals[a.triangles[t][c]], nb = b.normals[b.triangles[t][c]];
                EXPECT_EQ(std::memcmp(&na, &nb, sizeof na), 0) << a.name << " normal, triangle " << t << " corner " << c;
            }
    }
}

TEST(MeshFiles, ObjStlAndPlyHoldTheSameSceneAsGltf) {
    const Scene gltf = loadGltf(meshData("room-plain.gltf"));
    expectSameGeometry(gltf, loadMeshFiles({meshData("room.obj")}));
    expectSameGeometry(gltf, loadMeshFiles({meshData("floor.stl"), meshData("panel.stl"), meshData("lamp.stl")}));
    expectSameGeometry(gltf, loadMeshFiles({meshData("floor.ply"), meshData("panel.ply"), meshData("lamp.ply")}));
}

TEST(MeshFiles, ObjNormalsAndMaterialsAreTheGltfFiles) {
    const Scene gltf = loadGltf(meshData("room.gltf"));
    const Scene obj = loadMeshFiles({meshData("room.obj")});
    expectSameGeometry(gltf, obj, true);  // with the vertex normals (vn, NORMAL)
    for (std::size_t s = 0; s < obj.surfaces.size(); ++s) {
        ASSERT_EQ(gltf.surfaces[s].triangleMaterial.size(), obj.surfaces[s].triangleMaterial.size());
        for (std::size_t t = 0; t < obj.surfaces[s].triangleMaterial.size(); ++t) {
            const Material& a = gltf.materials[static_cast<std::size_t>(gltf.surfaces[s].triangleMaterial[t])];
            const Material& b = obj.materials[static_cast<std::size_t>(obj.surfaces[s].triangleMaterial[t])];
            EXPECT_EQ(a.name, b.name);
            EXPECT_EQ(a.reflectance, b.reflectance) << a.name;
            EXPECT_EQ(a.emission, b.emission) << a.name;
            EXPECT_EQ(a.doubleSided, b.doubleSided) << a.name;
        }
    }
    EXPECT_TRUE(obj.anyEmissiveSurface());
    // STL and PLY have no materials: glTF's default, white and single-sided.
    const Scene stl = loadMeshFiles({meshData("floor.stl")});
    const Material& m = stl.materials[static_cast<std::size_t>(stl.surfaces[0].triangleMaterial[0])];
    EXPECT_EQ(m.reflectance, glm::vec3(1.0f));
    EXPECT_FALSE(m.doubleSided);
    EXPECT_FALSE(stl.anyEmissiveSurface());
}

TEST(MeshFiles, UnitsScaleTheCoordinates) {
    const Scene metres = loadMeshFiles({meshData("room.obj")});
    const Scene millimetres = loadScene({meshData("room.obj")}, "mm");
    EXPECT_NEAR(millimetres.bounds().diagonal(), 1e-3 * metres.bounds().diagonal(), 1e-9);
    EXPECT_NEAR(millimetres.origin.x, 1e-3 * metres.origin.x, 1e-9);
    const Scene inches = loadScene({meshData("floor.ply")}, "in");
    EXPECT_NEAR(inches.bounds().diagonal(), 0.0254 * loadScene({meshData("floor.ply")}).bounds().diagonal(), 1e-7);
}

// Writes `text` to a file of this name in a fresh temporary directory; returns its path.
std::string temporaryFile(const std::string& name, const std::string& text) {
    const auto directory = std::filesystem::temp_directory_path() / ("radiosity-mesh-files-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory);
    const std::string path = (directory / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(MeshFiles, AsciiStlMayHoldSeveralSolidsOrEndWithoutEndsolid) {
    const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    const std::string moved = "facet normal 0 0 1\nouter loop\nvertex 2 0 0\nvertex 3 0 0\nvertex 2 1 0\nendloop\nendfacet\n";
    const Scene two = loadMeshFiles({temporaryFile("two.stl", "solid a\n" + facet + "endsolid a\nsolid b\n" + moved + "endsolid b\n")});
    ASSERT_EQ(two.surfaces.size(), 1u);  // the file is the surface
    EXPECT_EQ(two.surfaces[0].triangles.size(), 2u);
    EXPECT_EQ(two.surfaces[0].name, "two");
    const Scene open = loadMeshFiles({temporaryFile("open.stl", "solid a\n" + facet)});
    EXPECT_EQ(open.surfaces[0].triangles.size(), 1u);
    ASSERT_FALSE(open.warnings.empty());
    EXPECT_NE(open.warnings[0].find("endsolid"), std::string::npos) << open.warnings[0];
    // Cut inside a facet it is broken, not merely unfinished.
    EXPECT_THROW(loadMeshFiles({temporaryFile("cut.stl", "solid a\n" + facet.substr(0, 40))}), FileError);
}

TEST(MeshFiles, SameNamesAreMadeUnique) {
    const Scene twice = loadMeshFiles({meshData("floor.stl"), meshData("floor.ply")});
    ASSERT_EQ(twice.surfaces.size(), 2u);
    EXPECT_EQ(twice.surfaces[0].name, "floor");
    EXPECT_EQ(twice.surfaces[1].name, "floor@2");
}

TEST(MeshFiles, GltfIsReadAloneAndInMetres) {
    EXPECT_THROW(loadScene({meshData("room.gltf"), meshData("floor.stl")}), FileError);
    EXPECT_THROW(loadScene({meshData("room.gltf")}, "mm"), FileError);
    EXPECT_THROW(loadScene({meshData("room.obj")}, "furlong"), InputError);
}

// Twice the signed area, about +z, of the polygon through `points` (the shoelace formula).
double shoelace(const std::vector<glm::dvec3>& points) {
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 &a = points[i], &b = points[(i + 1) % points.size()];
        sum += a.x * b.y - b.x * a.y;
    }
    return sum;
}

// Checks that `triangles` over `points` (a simple polygon facing +z) keep its winding and
// cover exactly its area: a triangle outside it adds area, one turned over takes it away.
void expectCovers(const std::vector<glm::dvec3>& points, const std::vector<std::array<std::size_t, 3>>& triangles,
                  const std::string& what) {
    ASSERT_EQ(triangles.size(), points.size() - 2) << what;
    double covered = 0.0;
    for (const auto& t : triangles) {
        const double twice = shoelace({points[t[0]], points[t[1]], points[t[2]]});
        EXPECT_GT(twice, 0.0) << what << ": a triangle turned over";
        covered += std::fabs(twice);
    }
    EXPECT_NEAR(covered, shoelace(points), 1e-9 * covered) << what;
}

std::vector<glm::dvec3> star(std::size_t corners, double x0) {  // as scenes/mesh_scenes.py's polygons_obj
    std::vector<glm::dvec3> points;
    for (std::size_t k = 0; k < corners; ++k) {
        const double r = k % 3 == 0 ? 1.0 : 0.5, a = 2.0 * M_PI * static_cast<double>(k) / static_cast<double>(corners);
        points.emplace_back(x0 + r * std::cos(a), r * std::sin(a), 0.0);
    }
    return points;
}

TEST(MeshFiles, PolygonsAreSplitIntoTrianglesInsideThem) {
    // A convex polygon: the fan from its first corner, as before.
    const std::vector<glm::dvec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0.5, 0}};
    const auto fan = splitPolygon(square);
    ASSERT_EQ(fan.size(), 3u);
    for (std::size_t c = 0; c < fan.size(); ++c) EXPECT_EQ(fan[c], (std::array<std::size_t, 3>{0, c + 1, c + 2}));
    // An L-shaped panel: its first corner's fan covers its notch.
    const std::vector<glm::dvec3> notch{{6, 1, 0}, {5, 1, 0}, {5, -1, 0}, {7, -1, 0}, {7, 0, 0}, {6, 0, 0}};
    expectCovers(notch, splitPolygon(notch), "L-shaped panel");
    expectCovers(star(600, 0.0), splitPolygon(star(600, 0.0)), "star");
    // large, but simple: ear clipping finishes it (only a polygon that crosses itself is fanned)
    expectCovers(star(12000, 0.0), splitPolygon(star(12000, 0.0)), "star of 12,000 corners");
    // Turned to face -z (its corners in the other order) and upright (facing +y, its x along z):
    // the same cover, each triangle facing the polygon's way.
    std::vector<glm::dvec3> below(notch.rbegin(), notch.rend()), upright;
    for (const glm::dvec3& p : notch) upright.emplace_back(p.y, 2.0, p.x);
    const std::pair<std::vector<glm::dvec3>, glm::dvec3> turned[] = {{below, {0, 0, -1}}, {upright, {0, 1, 0}}};
    for (const auto& [points, facing] : turned) {
        double covered = 0.0;
        for (const auto& t : splitPolygon(points)) {
            const glm::dvec3 n = glm::cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
            EXPECT_GT(glm::dot(n, facing), 0.0) << facing.y;
            covered += glm::length(n);
        }
        EXPECT_NEAR(covered, 6.0, 1e-9) << facing.y;  // twice the area, 3
    }
}

TEST(MeshFiles, ObjAndPlyPolygonsOfAnyCornerCountKeepTheirArea) {
    const Scene scene = loadMeshFiles({meshData("polygons.obj")});
    const std::vector<glm::dvec3> notch{{6, 1, 0}, {5, 1, 0}, {5, -1, 0}, {7, -1, 0}, {7, 0, 0}, {6, 0, 0}};
    std::vector<glm::dvec3> disc;
    for (int k = 0; k < 300; ++k) disc.emplace_back(std::cos(2 * M_PI * k / 300), std::sin(2 * M_PI * k / 300), 0.0);
    const std::map<std::string, std::pair<std::size_t, double>> expected{
        {"disc", {300, shoelace(disc) / 2}}, {"star", {600, shoelace(star(600, 3.0)) / 2}}, {"notch", {6, 3.0}}};
    ASSERT_EQ(scene.surfaces.size(), expected.size());
    for (const Surface& s : scene.surfaces) {
        const auto& [corners, area] = expected.at(s.name);
        EXPECT_EQ(s.triangles.size(), corners - 2) << s.name;
        double sum = 0.0;
        for (const auto& t : s.triangles) {
            const glm::dvec3 n = glm::cross(glm::dvec3(s.positions[t[1]] - s.positions[t[0]]),
                                            glm::dvec3(s.positions[t[2]] - s.positions[t[0]]));
            EXPECT_GT(n.z, 0.0) << s.name;
            sum += glm::length(n) / 2;
        }
        EXPECT_NEAR(sum, area, 2e-5 * area) << s.name;  // the file's six decimals
    }
    // PLY: the same L-shaped panel, with a NaN normal as scans leave them: read, the faces
    // around it shaded flat, and said so.
    std::string ply = "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
                      "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n";
    for (std::size_t k = 0; k < notch.size(); ++k)
        ply += std::to_string(notch[k].x) + " " + std::to_string(notch[k].y) + (k == 4 ? " 0 nan nan nan\n" : " 0 0 0 1\n");
    ply += "6 0 1 2 3 4 5\n";
    const Scene panel = loadMeshFiles({temporaryFile("notch.ply", ply)});
    ASSERT_EQ(panel.surfaces.size(), 1u);
    double sum = 0.0;
    for (const auto& t : panel.surfaces[0].triangles)
        sum += glm::length(glm::cross(glm::dvec3(panel.surfaces[0].positions[t[1]] - panel.surfaces[0].positions[t[0]]),
                                      glm::dvec3(panel.surfaces[0].positions[t[2]] - panel.surfaces[0].positions[t[0]]))) /
               2;
    EXPECT_NEAR(sum, 3.0, 1e-6);
    ASSERT_FALSE(panel.warnings.empty());
    EXPECT_NE(panel.warnings[0].find("not finite"), std::string::npos) << panel.warnings[0];
}

TEST(MeshFiles, ObjMaterialsTakeTheirSpecularPartAsBlenderReadsIt) {
    // Blender 5.0.1's OBJ importer read these MTL materials as (metallic, roughness, specular IOR
    // level): "gold", as Blender's exporter writes a gold metal of roughness 0.3, (1, 0.3, 0.5);
    // "phong", as older tools write a plastic, (0, 0.9, 0.2); "pbr", with the PBR extension's Pr
    // beside Ns, (0, 0.7, -); "half", illum 3 with Ka 0.5, (0.5, 0.553, 0.5). A level of 0.5 is
    // glTF's default layer (F0 4 % at IOR 1.5), so the F0 tint is twice the level here. Kd alone
    // stays a plain diffuse surface, as before.
    const std::string mtl = "newmtl gold\nNs 490\nKa 1 1 1\nKd 0.9 0.6 0.2\nKs 0.5 0.5 0.5\nNi 1.5\nd 1\nillum 3\n"
                            "newmtl phong\nNs 10\nKa 1 1 1\nKd 0.5 0.5 0.5\nKs 0.2 0.2 0.2\nNi 0\nillum 2\n"
                            "newmtl pbr\nNs 900\nKd 0.5 0.5 0.5\nPr 0.7\nNi 1.33\n"
                            "newmtl half\nNs 200\nKa 0.5 0.5 0.5\nKd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nillum 3\n"
                            "newmtl plain\nKd 0.5 0.5 0.5\nKa 1 1 1\nillum 2\n";
    temporaryFile("specular.mtl", mtl);
    std::string obj = "mtllib specular.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (const char* name : {"gold", "phong", "pbr", "half", "plain"}) obj += std::string("g ") + name + "\nusemtl " + name + "\nf 1 2 3\n";
    Scene scene = loadMeshFiles({temporaryFile("specular.obj", obj)});
    // The same file with old Mac line ends (\r alone) gives the same materials: the keys given
    // are found per material as tinyobjloader reads the lines.
    std::string mac = mtl;
    std::replace(mac.begin(), mac.end(), '\n', '\r');
    temporaryFile("specular.mtl", mac);
    const Scene fromMac = loadMeshFiles({temporaryFile("specular.obj", obj)});
    ASSERT_EQ(fromMac.materials.size(), scene.materials.size());
    for (std::size_t k = 0; k < scene.materials.size(); ++k) {
        EXPECT_EQ(fromMac.materials[k].name, scene.materials[k].name);
        EXPECT_EQ(fromMac.materials[k].reflectance, scene.materials[k].reflectance) << scene.materials[k].name;
        EXPECT_EQ(fromMac.materials[k].metallic, scene.materials[k].metallic) << scene.materials[k].name;
    }
    std::map<std::string, const Material*> byName;
    for (const Material& m : scene.materials) byName[m.name] = &m;
    ASSERT_EQ(byName.size(), 5u);
    struct Expected {
        const char* name;
        float metallic, roughness, specular, tint, ior;
    };
    for (const Expected& e : {Expected{"gold", 1.0f, 0.3f, 1.0f, 1.0f, 1.5f}, Expected{"phong", 0.0f, 0.9f, 1.0f, 0.4f, 1.5f},
                              Expected{"pbr", 0.0f, 0.7f, 1.0f, 1.0f, 1.33f},
                              Expected{"half", 0.5f, 1.0f - std::sqrt(0.2f), 1.0f, 1.0f, 1.5f},
                              Expected{"plain", 0.0f, 1.0f, 0.0f, 1.0f, 1.5f}}) {
        const Material& m = *byName.at(e.name);
        EXPECT_NEAR(m.metallic, e.metallic, 1e-6f) << e.name;
        EXPECT_NEAR(m.roughness, e.roughness, 1e-6f) << e.name;
        EXPECT_NEAR(m.specular, e.specular, 1e-6f) << e.name;
        EXPECT_NEAR(m.specularColor.x, e.tint, 1e-6f) << e.name;
        EXPECT_NEAR(m.ior, e.ior, 1e-6f) << e.name;
        EXPECT_EQ(m.reflectance, radiosityReflectance(m)) << e.name;  // the layer's light reflected too
    }
    EXPECT_EQ(byName.at("plain")->reflectance, glm::vec3(0.5f));
    EXPECT_GT(byName.at("phong")->reflectance.x, 0.5f * (1.0f - 0.05f));  // the base less the layer, plus the layer
}

TEST(MeshFiles, ObjNormalAndMetalRoughnessMapsAreReadAsBlenderWritesThem) {
    // tests/data/meshes/blender.obj (scenes/mesh_scenes.py: blender_obj): Blender's OBJ exporter
    // writes a normal map as map_Bump -bm STRENGTH, a roughness texture as map_Ns and a metallic
    // one as map_refl, and its importer reads them back so. They become glTF's normalTexture (with
    // tangents generated for it) and metallicRoughnessTexture (green roughness, blue metal, the
    // metal's one texel taken at every roughness texel), factors 1. A grey height map given as bump
    // is not a normal map: not read, with a warning. The PBR extension's map_Pm beside Pr keeps
    // the roughness factor (the texture's green is 1).
    const Scene scene = loadMeshFiles({meshData("blender.obj")});
    std::map<std::string, const Material*> byName;
    for (const Material& m : scene.materials) byName[m.name] = &m;
    const Material& blender = *byName.at("blender");
    ASSERT_TRUE(blender.normalTexture.present());
    EXPECT_TRUE(blender.normalTexture.linear);
    EXPECT_FLOAT_EQ(blender.normalScale, 0.7f);
    ASSERT_TRUE(blender.metallicRoughnessTexture.present());
    EXPECT_TRUE(blender.metallicRoughnessTexture.linear && blender.metallicRoughnessTextured);
    EXPECT_EQ(blender.metallic, 1.0f);
    EXPECT_EQ(blender.roughness, 1.0f);
    const TextureImage& both = scene.images[static_cast<std::size_t>(blender.metallicRoughnessTexture.image)];
    ASSERT_EQ(both.width, 2);
    ASSERT_EQ(both.height, 1);
    EXPECT_EQ(both.rgba[1], 64);   // roughness, texel 0
    EXPECT_EQ(both.rgba[5], 192);  // roughness, texel 1
    EXPECT_EQ(both.rgba[2], 200);  // the metal's one texel
    EXPECT_EQ(both.rgba[6], 200);
    const Material& height = *byName.at("height");
    EXPECT_FALSE(height.normalTexture.present());
    EXPECT_TRUE(std::any_of(scene.warnings.begin(), scene.warnings.end(), [](const std::string& w) {
        return w.find("height.png") != std::string::npos && w.find("not a normal map") != std::string::npos;
    }));
    // A roughness map wider than 46,341 texels (where x times the width passes 2^31) is taken
    // whole, the metal's texel at each of its texels.
    const Material& wide = *byName.at("wide");
    ASSERT_TRUE(wide.metallicRoughnessTexture.present());
    const TextureImage& long_ = scene.images[static_cast<std::size_t>(wide.metallicRoughnessTexture.image)];
    ASSERT_EQ(long_.width, 50000);
    EXPECT_EQ(long_.rgba[4 * 49999 + 1], 249);
    EXPECT_EQ(long_.rgba[4 * 49999 + 2], 200);
    const Material& pbr = *byName.at("pbr");
    ASSERT_TRUE(pbr.metallicRoughnessTexture.present());
    EXPECT_FLOAT_EQ(pbr.roughness, 0.4f);
    EXPECT_EQ(pbr.metallic, 1.0f);
    const TextureImage& metalOnly = scene.images[static_cast<std::size_t>(pbr.metallicRoughnessTexture.image)];
    EXPECT_EQ(metalOnly.rgba[1], 255);
    EXPECT_EQ(metalOnly.rgba[2], 200);
    // The normal-mapped quad has a tangent frame at its corners: along +x (its u), w = +1.
    for (const Surface& s : scene.surfaces) {
        if (s.name != "blender") continue;
        ASSERT_EQ(s.tangents.size(), s.positions.size());
        for (const glm::vec4& t : s.tangents) {
            EXPECT_NEAR(t.x, 1.0f, 1e-6f);
            EXPECT_NEAR(t.w, 1.0f, 1e-6f);
        }
    }
}

TEST(MeshFiles, PlyAndObjVertexColoursAreReadAsSrgb) {
    // Scanners and MeshLab write vertex colours as sRGB values: a PLY's red, green and blue (uchar
    // over 255, float as it is) and an OBJ's "v x y z r g b" become the surface's colours, linear,
    // which multiply the base colour as glTF's COLOR_0 does. A file without them has none.
    const double half = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);  // sRGB 128
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nproperty uchar red\nproperty uchar green\nproperty float blue\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const Scene ply = loadMeshFiles(
        {temporaryFile("coloured.ply", header + "0 0 0 255 0 1\n1 0 0 0 128 0.5\n0 1 0 0 0 0\n3 0 1 2\n")});
    const Scene obj = loadMeshFiles({temporaryFile(
        "coloured.obj", "v 0 0 0 1 0 1\nv 1 0 0 0 0.50196 0.5\nv 0 1 0 0 0 0\nf 1 2 3\n")});
    for (const Scene* scene : {&ply, &obj}) {
        ASSERT_EQ(scene->surfaces.size(), 1u);
        const Surface& s = scene->surfaces[0];
        ASSERT_EQ(s.colors.size(), s.positions.size());
        for (std::size_t v = 0; v < s.positions.size(); ++v) {
            const glm::vec3 p = s.positions[v] + glm::vec3(scene->origin);
            const glm::dvec3 expected = p.x > 0.5f ? glm::dvec3(0.0, half, 0.214041)
                                        : p.y > 0.5f ? glm::dvec3(0.0)
                                                     : glm::dvec3(1.0, 0.0, 1.0);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.colors[v][c], expected[c], 2e-5) << "vertex " << v << ", " << c;
        }
    }
    EXPECT_TRUE(loadMeshFiles({meshData("floor.ply")}).surfaces.at(0).colors.empty());
    EXPECT_TRUE(loadMeshFiles({meshData("room.obj")}).surfaces.at(0).colors.empty());
}

TEST(MeshFiles, PlyFaceColoursColourTheirFaces) {
    // A PLY whose faces carry colours (as trimesh, Open3D and segmentation tools write them): two
    // triangles sharing an edge, red (255, 0, 0) and grey (128, 128, 128), sRGB. Each face's
    // corners take its colour, linear, the shared vertices made twice; over the vertices' own
    // colours, with a warning.
    const double half = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);  // sRGB 128
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                               "property float z\n";
    const std::string faces = "element face 2\nproperty list uchar int vertex_indices\nproperty uchar red\n"
                              "property uchar green\nproperty uchar blue\nend_header\n";
    const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
    const Scene plain = loadMeshFiles({temporaryFile("faces.ply", header + faces + vertices +
                                                                      "3 0 1 2 255 0 0\n3 0 2 3 128 128 128\n")});
    ASSERT_EQ(plain.surfaces.size(), 1u);
    const Surface& s = plain.surfaces[0];
    ASSERT_EQ(s.triangles.size(), 2u);
    ASSERT_EQ(s.positions.size(), 6u);  // corners 0 and 2 made once for each colour
    ASSERT_EQ(s.colors.size(), s.positions.size());
    for (std::size_t t = 0; t < 2; ++t)
        for (std::uint32_t v : s.triangles[t]) {
            const glm::dvec3 expected = t == 0 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(half);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.colors[v][c], expected[c], 1e-6) << "triangle " << t;
        }
    const Scene both = loadMeshFiles({temporaryFile(
        "both.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "property uchar red\nproperty uchar green\nproperty uchar blue\n" +
                        faces + "0 0 0 0 255 0\n1 0 0 0 255 0\n1 1 0 0 255 0\n0 1 0 0 255 0\n3 0 1 2 255 0 0\n3 0 2 3 255 0 0\n")});
    for (std::uint32_t v : both.surfaces.at(0).triangles[1]) EXPECT_NEAR(both.surfaces[0].colors[v].x, 1.0, 1e-6);
    EXPECT_TRUE(std::any_of(both.warnings.begin(), both.warnings.end(),
                            [](const std::string& w) { return w.find("faces' colours") != std::string::npos; }));
}

TEST(MeshFiles, BrokenFilesAreRefusedNamingFileAndProblem) {
    const std::pair<const char*, const char*> cases[] = {
        {"truncated.stl", "neither binary STL"}, {"bad-number.stl", "line 4"},
        {"not-stl.stl", "ASCII STL"},            {"no-end-header.ply", "end_header"},
        {"face-out-of-range.ply", "vertex 9"},   {"short.ply", "end of the file"},
        {"index-out-of-range.obj", "vertex 7"},  {"only-points.obj", "no triangles"},
        {"inf-vertex.ply", "finite"},            {"nan-vertex.obj", "line 2"},
        {"two-vertex-elements.ply", "two vertex elements"}};
    std::set<std::string> listed;
    for (const auto& [file, problem] : cases) listed.insert(file);
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("tests/data/bad"))) {
        const std::string name = entry.path().filename().string();
        if (isMeshFile(name)) EXPECT_TRUE(listed.count(name)) << name << " is not tested";
    }
    for (const auto& [file, problem] : cases) {
        try {
            loadMeshFiles({sourcePath(std::string("tests/data/bad/") + file)});
            ADD_FAILURE() << file << " was read";
        } catch (const FileError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(file), std::string::npos) << message;
            EXPECT_NE(message.find(problem), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace rad
