#pragma once
// Everything that emits light, behind one interface (docs/architecture.md, "Emitters"): a
// description. An emitter says how much power it emits, how to draw a point and a direction
// from it, how much of it reaches a point with nothing in the way, and what it gives the device:
//   - emitters that are scene surfaces give their patches an emitted radiance; the patches then
//     shoot that light like any other (addPatchEmission), and the kernels sample the emitting
//     patches (addDirectSources);
//   - emitters that are not surfaces (point, spot and directional lights, the sky, a map) say how
//     their direct light reaches the receivers (delivery), which the solver's direct-light service
//     computes (solver/direct_light.h) before the first shot; the solvers shoot what the
//     receivers reflect. Punctual lights list their device records (addPunctualLights).
// Nothing here touches the device.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "light/light_tree.h"
#include "shared_types.h"

namespace rad {

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

// How an emitter's light reaches the receivers first. Surfaces' patches shoot it (`none`); the
// others' direct light is delivered to every element before the first shot by the solver's
// direct-light service (solver/direct_light.h), from what they describe:
//   punctual     shadow rays to the punctual lights they list (addPunctualLights), on the device,
//                and rays drawn from them (sample) for their light by way of mirrors and glass;
//   environment  the light from outside, the scene's sky or map (Scene::sky, Scene::environment),
//                by rays that leave the scene, on the device;
//   unoccluded   irradiance() at each element's centroid, with nothing in the way.
enum class DirectDelivery { none, punctual, environment, unoccluded };

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

    // How its light reaches the receivers first (none: it is a surface, its patches shoot it).
    virtual DirectDelivery delivery() const { return DirectDelivery::none; }
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

private:
    std::vector<std::unique_ptr<Emitter>> list_;
};

// Every emitter the scene holds, of every kind (light/emitters.cpp: one line per kind).
Emitters findEmitters(const Scene& scene, const Mesh& mesh, const PatchTextureMeans& textures);

}  // namespace rad
