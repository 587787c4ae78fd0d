// glTF's specular layer over diffuse surfaces (scene/material_model.h: SurfaceLayer) and the
// table of its albedo the host and the kernels read (scene/ggx_albedo.h), against quadrature by
// another sampling of the same lobe (tests/optics_reference.h: Walter's microfacet normals, not
// the visible normals the table and the kernels draw).

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "optics_reference.h"
#include "scene/ggx_albedo.h"
#include "scene/material_model.h"

namespace rad {
namespace {

TEST(MaterialLayer, AlbedoTableMatchesAnotherQuadrature) {
    // E1 is the albedo with Schlick's factor at F0 1, E5 at F0 0 (the factor (1 - c)^5 alone).
    // On the table's points and between them (bilinear), at cosines from grazing to normal and
    // roughnesses from a near mirror to 1: within 2e-3 (the reference's own midpoint rule, on
    // 1500 x 1500 points, errs by about 1e-3 near grazing; measured: largest 9.3e-4).
    const GgxAlbedoTable& table = ggxAlbedoTable();
    double largest = 0.0;
    for (const double roughness : {0.1, 10.0 / 31.0, 0.5, 1.0})
        for (const double mu : {0.1, 0.3, 0.8, 1.0}) {
            const double alpha = roughness * roughness;
            const auto e = table.at(mu, roughness);
            const double e1 = test::ggxAlbedo(mu, alpha, 1.0), e5 = test::ggxAlbedo(mu, alpha, 0.0);
            const std::string what = "roughness " + std::to_string(roughness) + ", mu " + std::to_string(mu);
            EXPECT_NEAR(e[0], e1, 2e-3) << what;
            EXPECT_NEAR(e[1], e5, 2e-3) << what;
            EXPECT_LE(e[0], 1.0 + 1e-6) << what;
            largest = std::max({largest, std::fabs(e[0] - e1), std::fabs(e[1] - e5)});
        }
    RecordProperty("largest_difference", std::to_string(largest));
}

// The directional albedo of material m toward cosine mu, per channel k, by quadrature: the
// layer's, F0 E1 + (F90 - F0) E5, and the diffuse part's, its colour times what the dielectric's
// layer leaves it; each lobe scaled by what restores single scattering's loss (ggxEnergyScale,
// with E1 and its mean `e1Average` from the same quadrature).
double albedo(const Material& m, double mu, int k, int n, double e1Average) {
    const SurfaceLayer l = surfaceLayer(m);
    const double alpha = static_cast<double>(l.roughness) * l.roughness;
    const double e1 = test::ggxAlbedo(mu, alpha, 1.0, n), e5 = test::ggxAlbedo(mu, alpha, 0.0, n);
    const double layer = (l.f0[k] * e1 + (l.f90 - l.f0[k]) * e5) * ggxEnergyScale(e1, e1Average, l.f0[k], l.f90);
    const double dielectric = (l.dielectricF0[k] * e1 + (l.dielectricF90 - l.dielectricF0[k]) * e5) *
                              ggxEnergyScale(e1, e1Average, l.dielectricF0[k], l.dielectricF90);
    return layer + l.diffuse[k] * (1.0 - dielectric);
}

TEST(MaterialLayer, RadiosityReflectanceIsTheBrdfsHemisphericalAlbedo) {
    // What the radiosity pass reflects diffusely of a layered surface is what its BRDF reflects of
    // light from every direction, 2 integral a(mu) mu dmu: the layer's light is neither lost nor
    // counted twice. A white non-metal reflects all of it at any roughness. Midpoint rule on 48
    // cosines; within 2e-3 (the table's accuracy, and the energy scale taken at the mean E1 where
    // the BRDF scales by the viewer's).
    Material white;
    white.baseColor = glm::vec3(1.0f);
    white.specular = 1.0f;
    Material paint;  // partly metallic, a weaker and tinted layer, a higher index
    paint.baseColor = glm::vec3(0.8f, 0.2f, 0.1f);
    paint.metallic = 0.3f;
    paint.roughness = 0.45f;
    paint.specular = 0.5f;
    paint.specularColor = glm::vec3(1.0f, 0.5f, 0.8f);
    paint.ior = 1.8f;
    Material varnish;  // a smooth coat over dark wood
    varnish.baseColor = glm::vec3(0.3f, 0.15f, 0.05f);
    varnish.roughness = 0.0f;
    varnish.specular = 1.0f;
    for (Material m : {white, paint, varnish}) {
        m.reflectance = plainReflectance(m);
        const glm::vec3 rho = radiosityReflectance(m);
        ASSERT_TRUE(surfaceLayer(m).present);
        constexpr int kCosines = 48;
        const double alpha = static_cast<double>(surfaceLayer(m).roughness) * surfaceLayer(m).roughness;
        double e1Average = 0.0;
        for (int i = 0; i < kCosines; ++i) {
            const double mu = (i + 0.5) / kCosines;
            e1Average += 2.0 * test::ggxAlbedo(mu, alpha, 1.0, 300) * mu / kCosines;
        }
        for (int k = 0; k < 3; ++k) {
            double integral = 0.0;
            for (int i = 0; i < kCosines; ++i) {
                const double mu = (i + 0.5) / kCosines;
                integral += 2.0 * albedo(m, mu, k, 300, e1Average) * mu / kCosines;
            }
            EXPECT_NEAR(rho[k], integral, 2e-3) << "base " << m.baseColor[k] << ", channel " << k;
            EXPECT_LE(rho[k], 1.0f + 1e-6f);
        }
    }
    EXPECT_NEAR(radiosityReflectance(white).x, 1.0f, 1e-6f);
}

TEST(MaterialLayer, OnlyNonMetalsAndPartlyMetallicSurfacesHaveOne) {
    // Mirrors, rough metals and glass are kinds of their own; a surface with no layer keeps the
    // plain reflectance; metallic alone makes a layer (the metal's part) even with no specular.
    Material plain;
    plain.baseColor = glm::vec3(0.5f);
    plain.reflectance = plainReflectance(plain);
    EXPECT_FALSE(surfaceLayer(plain).present);
    EXPECT_EQ(radiosityReflectance(plain), plain.reflectance);
    Material metal = plain;
    metal.metallic = 1.0f;
    metal.roughness = 0.5f;
    metal.specular = 1.0f;
    EXPECT_FALSE(surfaceLayer(metal).present);
    Material half = plain;
    half.metallic = 0.5f;
    EXPECT_TRUE(surfaceLayer(half).present);
    EXPECT_FLOAT_EQ(surfaceLayer(half).f0.x, 0.25f);
    EXPECT_FLOAT_EQ(surfaceLayer(half).f90, 0.5f);
    Material smooth = plain;
    smooth.specular = 1.0f;
    smooth.roughness = 0.0f;
    EXPECT_FLOAT_EQ(surfaceLayer(smooth).roughness, kSmoothestLayer);
}

}  // namespace
}  // namespace rad
