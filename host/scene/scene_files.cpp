#include "scene/scene_files.h"

#include "scene/gltf_loader.h"
#include "scene/mesh_files.h"
#include "util/error.h"

namespace rad {

double metresPerUnit(const std::string& unit) {
    if (unit == "m") return 1.0;
    if (unit == "cm") return 0.01;
    if (unit == "mm") return 0.001;
    if (unit == "in") return 0.0254;
    if (unit == "ft") return 0.3048;
    throw InputError("unknown length unit '" + unit + "' (m, cm, mm, in or ft)");
}

Scene loadScene(const std::vector<std::string>& paths, const std::string& unit) {
    if (paths.empty()) throw InputError("no scene file given");
    const double scale = metresPerUnit(unit);
    bool allMeshes = true;
    for (const std::string& path : paths) allMeshes = allMeshes && isMeshFile(path);
    if (allMeshes) return loadMeshFiles(paths, scale);
    for (const std::string& path : paths)
        if (!isMeshFile(path) && paths.size() > 1)
            throw FileError(path, "a glTF scene is read alone: only OBJ, STL and PLY files can be given together");
    if (unit != "m")
        throw FileError(paths.front(), "glTF is in metres by definition: --unit applies to OBJ, STL and PLY files");
    return loadGltf(paths.front());
}

}  // namespace rad
