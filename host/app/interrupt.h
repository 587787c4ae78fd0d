#pragma once
// SIGINT and SIGTERM during a long run ask it to stop at the next safe point (the next batch
// of shots) and still write a complete set of outputs. A second signal ends the program.

namespace rad {

void installInterruptHandlers();
bool interruptRequested();
// Forgets a request, for a process that solves again after one (the Python module).
void clearInterruptRequest();

}  // namespace rad
