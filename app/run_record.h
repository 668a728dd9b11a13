#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene/scene.h"

namespace sedem::app {

// run.json: what a run was and how it went. Written with status "running" when the run
// starts and rewritten (atomically) when it ends, so a folder whose run.json does not say
// "complete" is never mistaken for a finished run.
struct RunRecord {
  std::string status = "running";  // running | complete | interrupted | failed
  std::string message;
  std::string scene_file;
  std::int64_t seed = 0;
  std::size_t particle_count = 0;
  std::int64_t steps = 0;
  double simulated_time = 0;
  double wall_time = 0;
  double particle_steps = 0;
  std::int64_t legs = 1;  // the first run and each --resume that went on with it
  nlohmann::json results = nlohmann::json::object();  // each test's error and bias
  // What makes the results doubtful (core/instruments/plausibility.h): {code, message} each.
  nlohmann::json warnings = nlohmann::json::array();
  std::vector<std::string> files;  // what the run wrote into its folder, relative to it
};

// Every scene key with its value in user units, as a JSON object keyed by the dotted name.
nlohmann::json scene_json(Scene& scene);

// The scene back from scene_json (each key given as an override of the defaults).
// Throws SceneError naming `source` and the key.
Scene scene_from_json(const nlohmann::json& scene, const std::string& source);

// Peak resident memory of this process, bytes.
std::size_t peak_memory_bytes();

// What a command that reads a finished run says of a record whose status is not "complete"
// (stopped, failed, or killed while "running"): "" for a complete run, else why its files are
// not a whole test, with the way on (--partial, or finishing it with --resume).
std::string incomplete_run(const nlohmann::json& record, const std::filesystem::path& dir);

// run.json's content: the record, the version, the scene as resolved, the peak memory so far.
nlohmann::json run_record_json(const RunRecord& record, Scene& scene);

// Writes run.json atomically. Throws WriteError.
void write_run_record(const RunRecord& record, Scene& scene, const std::filesystem::path& file);

// A failed run's record when the whole one cannot be written (a full disk): run.json rewritten
// in place, cut to its status and message (its old blocks freed first, so it fits where the
// "running" record was), so that it never stays "running". Best effort: false if even that
// failed.
bool write_failed_record_in_place(const RunRecord& record, const std::filesystem::path& file);

}  // namespace sedem::app
