#pragma once
// Outputs are written whole or not at all: into a temporary file beside the target, renamed
// over it only once complete.

#include <functional>
#include <ostream>
#include <string>

namespace rad {

// Calls write(stream) on a temporary file next to `path`, then renames it to `path`. On any
// failure the temporary file is removed and RuntimeFailure names the path and the problem.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace rad
