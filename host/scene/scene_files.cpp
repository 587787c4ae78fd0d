#include "scene/scene_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

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

namespace {

// A file whose extension names no format the program reads is read as glTF only when it looks
// like glTF (a JSON object, or binary glTF's magic); otherwise a parser error about JSON would
// not say what is wrong.
void refuseUnknownFormat(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".gltf" || ext == ".glb" || isMeshFile(path)) return;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return;  // the loader says what it is instead
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // the glTF loader says why it cannot be read
    std::string head(64, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    if (head.rfind("\xEF\xBB\xBF", 0) == 0) head.erase(0, 3);  // a UTF-8 byte-order mark
    const std::size_t first = head.find_first_not_of(" \t\r\n");
    if (head.rfind("glTF", 0) == 0 || (first != std::string::npos && head[first] == '{')) return;
    const std::string extension = ext.empty() ? std::string("none") : "'" + ext + "'";
    if (head.empty()) throw FileError(path, "is empty");
    throw FileError(path, "is not a scene file the program knows: its extension (" + extension +
                              ") is none of .gltf, .glb, .obj, .stl and .ply, and it does not begin as glTF does");
}

}  // namespace

Scene loadScene(const std::vector<std::string>& paths, const std::string& unit) {
    if (paths.empty()) throw InputError("no scene file given");
    const double scale = metresPerUnit(unit);
    for (const std::string& path : paths) refuseUnknownFormat(path);
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
