#include "light/emissive_surfaces.h"
#include "light/emitter.h"
#include "light/environment_light.h"
#include "light/punctual_lights.h"

namespace rad {

Emitters findEmitters(const Scene& scene, const Mesh& mesh, const PatchTextureMeans& textures) {
    Emitters emitters;
    // One line per kind of emitter a scene can hold.
    if (auto surfaces = EmissiveSurfaces::find(scene, mesh, textures)) emitters.add(std::move(surfaces));
    if (auto lights = PunctualLights::find(scene)) emitters.add(std::move(lights));
    if (auto outside = EnvironmentLight::find(scene)) emitters.add(std::move(outside));
    return emitters;
}

}  // namespace rad
