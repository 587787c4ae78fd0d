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

// Refuses, before any work, an output file that could not be written: InputError naming
// `option` and `path` when the path is empty, is a folder, or its folder does not exist (and is
// not `folderToBeMade`, one the command makes before it writes).
void checkOutputFile(const std::string& option, const std::string& path, const std::string& folderToBeMade = "");

}  // namespace rad
