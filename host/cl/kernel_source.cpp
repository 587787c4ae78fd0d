#include "cl/kernel_source.h"

#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "util/error.h"

namespace rad {

// Defined in the file the build generates from kernels/.
const std::map<std::string, std::string_view>& embeddedKernelFiles();

namespace {

void expand(const std::string& name, std::set<std::string>& included, std::string& out) {
    const auto& files = embeddedKernelFiles();
    const auto file = files.find(name);
    if (file == files.end()) throw RuntimeFailure("kernel file '" + name + "' is not embedded in this build");
    if (!included.insert(name).second) return;
    std::istringstream lines{std::string(file->second)};
    std::string line;
    int number = 0;
    out += "#line 1 \"" + name + "\"\n";
    while (std::getline(lines, line)) {
        ++number;
        const auto first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
            const auto open = line.find('"'), close = line.rfind('"');
            if (open != std::string::npos && close > open) {
                expand(line.substr(open + 1, close - open - 1), included, out);
                out += "#line " + std::to_string(number + 1) + " \"" + name + "\"\n";
                continue;
            }
        }
        out += line;
        out += '\n';
    }
}

}  // namespace

std::string kernelSource(const std::string& mainFile) {
    std::set<std::string> included;
    std::string out;
    expand(mainFile, included, out);
    return out;
}

}  // namespace rad
