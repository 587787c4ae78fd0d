#pragma once
// What the program says on stderr besides its results: the loader's warnings, and the
// warnings methods and solvers give about their results (also kept for report.json).

#include <cstdio>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace rad {

inline void printWarnings(const Scene& scene) {
    for (const std::string& w : scene.warnings)
        std::fprintf(stderr, "radiosity: warning: %s: %s\n", scene.path.c_str(), w.c_str());
}

inline void emitWarning(const std::string& warning, std::vector<std::string>* report = nullptr) {
    std::fprintf(stderr, "radiosity: warning: %s\n", warning.c_str());
    if (report) report->push_back(warning);
}

inline void emitWarnings(const std::vector<std::string>& warnings, std::vector<std::string>* report = nullptr) {
    for (const std::string& w : warnings) emitWarning(w, report);
}

}  // namespace rad
