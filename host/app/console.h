#pragma once
// What the program says on stderr besides its results: the loader's warnings, and the
// warnings methods and solvers give about their results (also kept for report.json).

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace rad {

// Where warnings go: stderr ("radiosity: warning: ..."), unless a caller that shows them its own
// way (the Python module, as Python warnings) sets a sink.
inline std::function<void(const std::string&)>& warningSink() {
    static std::function<void(const std::string&)> sink;
    return sink;
}

inline void emitWarning(const std::string& warning, std::vector<std::string>* report = nullptr) {
    if (warningSink())
        warningSink()(warning);
    else
        std::fprintf(stderr, "radiosity: warning: %s\n", warning.c_str());
    if (report) report->push_back(warning);
}

inline void printWarnings(const Scene& scene) {
    for (const std::string& w : scene.warnings) emitWarning(scene.path + ": " + w);
}

inline void emitWarnings(const std::vector<std::string>& warnings, std::vector<std::string>* report = nullptr) {
    for (const std::string& w : warnings) emitWarning(w, report);
}

}  // namespace rad
