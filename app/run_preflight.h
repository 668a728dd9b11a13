#pragma once

// Checks made before a run starts simulating, so that it fails in seconds with the reason
// rather than hours later: the memory it will need against the machine's, and whether every
// place it writes to can be written.

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/scene/scene.h"

namespace sedem::app {

// An estimate of a run's peak memory, bytes: the particles (engine, sample, snapshots in
// flight), the voidage grid of the drag and the instruments' layers. `key` is set to the
// scene key that dominates it.
std::size_t estimate_run_bytes(const Scene& scene, std::string* key = nullptr);

// Memory this process may still use: the smaller of the memory available on the machine and
// what the address-space limit (ulimit -v) leaves, bytes.
std::size_t usable_memory_bytes();

// Empty if the run fits; else the message, with the estimate and the machine's memory.
std::string memory_refusal(const Scene& scene);

// Creates the output folder and the sub-folders the run writes to, and writes and removes a
// probe file in each. Returns an empty string, or the first place that fails with the
// system's reason.
std::string check_writable(const std::filesystem::path& out, const Scene& scene);

// Removes the temporary files (*.tmp) a failed run leaves in `out` and its sub-folders.
void remove_temporary_files(const std::filesystem::path& out);

}  // namespace sedem::app
