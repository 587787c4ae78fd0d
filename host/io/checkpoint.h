#pragma once
// Solver checkpoints: a SolverState in a binary file, with the fingerprint of the problem it
// belongs to (scene bytes, mesh, options that steer the solve) and a checksum. Written
// atomically, so a crash while saving leaves the previous checkpoint intact.

#include <cstdint>
#include <string>

#include "solver/solver_state.h"

namespace rad {

void writeCheckpoint(const std::string& path, const SolverState& state, std::uint64_t fingerprint);

// Throws FileError when the file is missing, damaged (checksum), of another format version, or
// of another problem (fingerprint).
SolverState readCheckpoint(const std::string& path, std::uint64_t fingerprint);

}  // namespace rad
