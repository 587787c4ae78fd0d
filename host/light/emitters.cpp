#include "light/emissive_surfaces.h"
#include "light/emitter.h"

namespace rad {

Emitters findEmitters(const Scene& scene, const Mesh& mesh) {
    Emitters emitters;
    // One line per kind of emitter a scene can hold.
    if (auto surfaces = EmissiveSurfaces::find(scene, mesh)) emitters.add(std::move(surfaces));
    return emitters;
}

}  // namespace rad
