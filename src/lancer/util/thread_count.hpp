// How many threads a stage runs on: the --threads a user asked for, or every hardware thread for 0,
// the same rule for the kd-tree build and the renderer.
#pragma once

namespace lancer {

// `requested` > 0 as it is; 0 (or less): std::thread::hardware_concurrency(), at least 1.
int resolveThreadCount(int requested);

}  // namespace lancer
