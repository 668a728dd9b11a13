#pragma once

// A checkpoint that proves what it belongs to. The engine writes its state to
// checkpoint.bin; beside it, checkpoint.json records the run's identity (a hash of the
// resolved scene, the seed, the thread count and the version), a hash of checkpoint.bin's
// bytes, the simulated time and the wall time spent so far. Both are written to temporary
// files, flushed to the disk and renamed, so that a kill or a power cut at any moment leaves
// either the previous checkpoint or the new one, never half of one; checkpoint.json keeps the
// previous checkpoint's record too, for a kill between the two renames. --resume refuses a
// checkpoint whose identity or bytes do not match.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/scene/scene.h"

namespace sedem::app {

inline constexpr const char* kCheckpointFile = "checkpoint.bin";
inline constexpr const char* kCheckpointRecordFile = "checkpoint.json";

// A checkpoint that does not belong to the run or is damaged.
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What a checkpoint records beside the engine's state.
struct CheckpointRecord {
  std::string identity;    // run_identity() of the run that wrote it
  std::string content;     // hash of checkpoint.bin's bytes
  double time = 0;         // simulated time, s
  double wall_time = 0;    // wall time of every leg up to the checkpoint, s
  std::int64_t legs = 1;   // how many runs (the first and each resume) led to it
  std::string scene_file;  // the scene file of the first leg
};

// The hash of everything that decides a run's results: the resolved scene (seed included),
// sedem's version, and the number of worker threads where it changes the bits (not with local
// steps, which give the same results on any count: a run stopped on one machine goes on on
// another with more or fewer cores).
std::string run_identity(Scene& scene);

// 64-bit FNV-1a of a file's bytes, as 16 hex digits.
std::string file_hash(const std::filesystem::path& file);

// Writes a checkpoint into `dir`: `write_engine` saves the engine's state to the path it is
// given (a temporary file), then the record. Throws std::runtime_error with the cause.
void write_checkpoint(const std::filesystem::path& dir,
                      const std::function<void(const std::string&)>& write_engine,
                      CheckpointRecord record);

// The record of the checkpoint in `dir`, checked against `identity` and against the bytes of
// checkpoint.bin. Throws CheckpointError naming the file and what does not match.
CheckpointRecord read_checkpoint_record(const std::filesystem::path& dir,
                                        const std::string& identity);

// Removes a checkpoint and its record (a run that completed, or a new run into the folder).
void remove_checkpoint(const std::filesystem::path& dir);

}  // namespace sedem::app
