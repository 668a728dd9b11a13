#include "app/run_record.h"

#include <sys/resource.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/scene/scene_loader.h"
#include "render/atomic_write.h"

namespace sedem::app {

nlohmann::json scene_json(Scene& scene) {
  nlohmann::json out = nlohmann::json::object();
  Schema schema = scene.schema();
  for (const auto& p : schema.params()) {
    std::visit(
        [&](auto* v) {
          using T = std::remove_pointer_t<decltype(v)>;
          if constexpr (std::is_same_v<T, double>) {
            out[p.key] = *v / p.to_si;
          } else if constexpr (std::is_same_v<T, std::vector<double>>) {
            nlohmann::json list = nlohmann::json::array();
            for (double x : *v) list.push_back(x / p.to_si);
            out[p.key] = list;
          } else {
            out[p.key] = *v;
          }
        },
        p.target);
  }
  return out;
}

Scene scene_from_json(const nlohmann::json& keys, const std::string& source) {
  std::vector<std::string> sets;
  // JSON's numbers, booleans, strings and lists of numbers are valid TOML values as dumped.
  for (const auto& [key, value] : keys.items()) sets.push_back(key + "=" + value.dump());
  return parse_scene("", source, sets);
}

std::size_t peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return std::size_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

nlohmann::json run_record_json(const RunRecord& r, Scene& scene) {
  nlohmann::json j;
  j["status"] = r.status;
  if (!r.message.empty()) j["message"] = r.message;
  j["version"] = SEDEM_VERSION;
  j["scene_file"] = r.scene_file;
  j["scene"] = scene_json(scene);
  j["seed"] = r.seed;
  j["particle_count"] = r.particle_count;
  j["steps"] = r.steps;
  j["simulated_time_s"] = r.simulated_time;
  j["wall_time_s"] = r.wall_time;
  j["particle_steps_per_s"] = r.wall_time > 0 ? r.particle_steps / r.wall_time : 0.0;
  j["legs"] = r.legs;
  j["peak_memory_bytes"] = peak_memory_bytes();
  j["results"] = r.results;
  j["warnings"] = r.warnings;
  j["files"] = r.files;
  return j;
}

void write_run_record(const RunRecord& r, Scene& scene, const std::filesystem::path& file) {
  const nlohmann::json j = run_record_json(r, scene);
  write_atomically(file, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

bool write_failed_record_in_place(const RunRecord& r, const std::filesystem::path& file) {
  nlohmann::json j;
  j["status"] = "failed";
  j["message"] = r.message.substr(0, 200);
  std::ofstream out(file, std::ios::trunc);
  out << j.dump() << '\n';
  out.close();
  return bool(out);
}

std::string incomplete_run(const nlohmann::json& record, const std::filesystem::path& dir) {
  const std::string status = record.is_object() ? record.value("status", "") : "";
  if (status == "complete") return {};
  const double reached = record.is_object() ? record.value("simulated_time_s", 0.0) : 0.0;
  std::ostringstream m;
  m << dir.string() << " holds a run that is " << (status.empty() ? "of no status" : status)
    << ", not complete: its files stop at t = " << reached
    << " s and may be partly written. Give --partial to use them anyway";
  if (status != "failed") m << ", or finish the run first: sedem run --resume " << dir.string();
  return m.str();
}

}  // namespace sedem::app
