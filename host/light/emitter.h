#pragma once
// Everything that emits light, behind one interface (docs/architecture.md, "Emitters"). An
// emitter says how much power it emits, how to draw a point and a direction from it, how much of
// it reaches a point, and how the solvers carry its light:
//   - emitters that are scene surfaces give their patches an emitted radiance; the patches then
//     shoot that light like any other (addPatchEmission);
//   - emitters that are not surfaces (point, spot and directional lights, the sky) deliver their
//     direct light to the receivers by shadow rays, and the solvers shoot what the receivers
//     reflect (addDirectLight). Both solve strategies take that light in, so a new
//     kind of light is a new Emitter and its tests, and no solver changes.
// The refinement's direct light on the device (kernels/refine.cl) reads the emitters' direct
// sources (addDirectSources).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "light/light_tree.h"
#include "shared_types.h"

namespace rad {

class ElementMesh;
class PreparedScene;
struct Mesh;
struct PatchTextureMeans;
struct Scene;

// A point on an emitter and a direction light leaves it in, drawn from four uniform numbers.
// `power` is what the sample stands for, per channel: the emitter's power divided by the
// probability density of drawing it, so the mean of `power` over many samples is power().
struct EmissionSample {
    glm::dvec3 position{0.0};   // in the mesh's coordinates (relative to Scene::origin)
    glm::dvec3 normal{0.0};     // the emitting side's unit normal there
    glm::dvec3 direction{0.0};  // unit, on the emitting side
    glm::dvec3 power{0.0};      // W per channel
};

// A polygon (today: an emitting patch, the device's SampleTriangle `triangle`) that the
// device's direct-light kernels sample with shadow rays, with its emitted radiance and area.
struct DirectSource {
    std::uint32_t triangle = 0;
    glm::vec3 radiance{0.0f};  // Le, W / m^2 / sr per channel
    double area = 0.0;         // m^2
};

// Light delivered straight to receivers, before any shot: the power that arrived at each
// element of the receivers (W per channel), the power absorbed by the black backs of
// single-sided faces, and the power that left the scene without arriving anywhere. Empty when
// no emitter delivers direct light.
// How direct light meets mirrors and glass (scene/material_model.h). `follow`, as the
// progressive solve's shots do: shadow rays cross thin panes, the light goes on through them to
// the elements it reaches, and their own elements count only what they keep. `diffuse`, as the
// matrix solvers model them (a mirror a diffuse reflector, glass opaque): light stops at them,
// and their elements count all of it.
enum class SpecularModel { follow, diffuse };

struct DirectLight {
    std::vector<glm::dvec3> arrived;
    // Of `arrived`, what came by way of mirrors or glass (the sky's and the environment's light
    // through a window or off a mirror, kernels/direct_light.cl; the punctual lights' off a
    // mirror or through glass, light/punctual_caustics.h); empty when none did.
    std::vector<glm::dvec3> arrivedBySpecular;
    glm::dvec3 absorbedByBacks{0.0};
    glm::dvec3 escaped{0.0};
    bool empty() const { return arrived.empty(); }
    glm::dvec3 total() const;  // arrived, summed, plus absorbed by backs and escaped
};

class Emitter {
public:
    virtual ~Emitter() = default;

    // For messages and reports: "3 emitting surfaces (12 patches)".
    virtual std::string describe() const = 0;

    // The power it emits, W per channel.
    virtual glm::dvec3 power() const = 0;

    // A point and a direction from u in [0, 1)^4 (see EmissionSample).
    virtual EmissionSample sample(const glm::dvec4& u) const = 0;

    // Irradiance at `point` (unit `normal`) from this emitter, with nothing in the way: W / m^2
    // per channel. Shadow rays, where needed, are the caller's.
    virtual glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal) const = 0;

    // Surfaces: adds their emitted radiance Le to their patches' (indexed by patch).
    virtual void addPatchEmission(std::vector<glm::vec3>& radiance) const { (void)radiance; }

    // The polygons the device samples for direct light (kernels/refine.cl).
    virtual void addDirectSources(std::vector<DirectSource>& sources) const { (void)sources; }

    // Lights no ray can hit, which the device samples by shadow rays (kernels/punctual_light.h):
    // the path tracer's next-event estimation and the refinement's direct light.
    virtual void addPunctualLights(std::vector<PunctualLight>& lights) const { (void)lights; }

    // Emitters the solvers do not shoot: whether they deliver direct light, and adding it
    // (per element of `elements`) to `light`, whose `arrived` has one entry per element, with
    // mirrors and glass as `model` says. Any sampling is keyed by `seed` (the solve's).
    virtual bool deliversDirectLight() const { return false; }
    virtual void addDirectLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t seed,
                                SpecularModel model, DirectLight& light) const {
        (void)scene, (void)elements, (void)seed, (void)model, (void)light;
    }
};

// Where a sample falls in a running sum of shares (a CDF over parts of an emitter): the part k
// with cdf[k - 1] <= x < cdf[k] for x = u * cdf.back(), where its share starts, and its share.
struct CdfPick {
    std::size_t index = 0;
    double start = 0.0, share = 0.0;
};
CdfPick pickByCdf(const std::vector<double>& cdf, double u);

// The scene's emitters.
class Emitters {
public:
    void add(std::unique_ptr<Emitter> emitter) { list_.push_back(std::move(emitter)); }
    const std::vector<std::unique_ptr<Emitter>>& list() const { return list_; }

    glm::dvec3 power() const;  // W per channel, all emitters
    std::vector<DirectSource> directSources() const;
    PunctualLightSet punctualLights() const;  // every emitter's, ordered and with their tree
    // The direct light of every emitter that delivers it, on `elements`; empty when none does.
    DirectLight directLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t seed,
                            SpecularModel model = SpecularModel::follow) const;

private:
    std::vector<std::unique_ptr<Emitter>> list_;
};

// Every emitter the scene holds, of every kind (light/emitters.cpp: one line per kind).
Emitters findEmitters(const Scene& scene, const Mesh& mesh, const PatchTextureMeans& textures);

}  // namespace rad
