#pragma once
// The OpenCL sources under kernels/, embedded into the binary at build time
// (cmake/EmbedKernels.cmake), so the program runs from any directory.

#include <string>

namespace rad {

// The text of kernels/<mainFile> with every `#include "name"` of another kernels/ file
// replaced by that file's text (each file once). Throws RuntimeFailure for an unknown name.
std::string kernelSource(const std::string& mainFile);

}  // namespace rad
