#pragma once
// What the program says on stderr besides its results.

#include <cstdio>

#include "scene/scene.h"

namespace rad {

inline void printWarnings(const Scene& scene) {
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "radiosity: warning: %s: %s\n", scene.path.c_str(), w.c_str());
}

}  // namespace rad
