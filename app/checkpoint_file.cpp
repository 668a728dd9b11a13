#include "app/checkpoint_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <omp.h>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/run_record.h"
#include "core/run/stage_setups.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      h ^= static_cast<unsigned char>(data[i]);
      h *= 1099511628211ull;
    }
  }
  void add(const std::string& s) {
    add(s.data(), s.size());
    add("\0", 1);
  }
  std::string hex() const {
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
  }
};

std::string errno_text(int e) {
  return e ? std::strerror(e) : "unknown error";
}

// Flushes a file to the disk, so that a rename after it never exposes an empty file after a
// power cut.
void sync_file(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY);
  if (fd < 0) throw std::runtime_error("cannot open " + file.string() + ": " + errno_text(errno));
  const int r = ::fsync(fd);
  const int e = errno;
  ::close(fd);
  if (r != 0) throw std::runtime_error("cannot flush " + file.string() + ": " + errno_text(e));
}

void sync_dir(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

nlohmann::json to_json(const CheckpointRecord& r) {
  return {{"identity", r.identity},     {"content", r.content}, {"time_s", r.time},
          {"wall_time_s", r.wall_time}, {"legs", r.legs},       {"scene_file", r.scene_file}};
}

std::optional<CheckpointRecord> from_json(const nlohmann::json& j) {
  if (!j.is_object()) return std::nullopt;
  try {
    CheckpointRecord r;
    r.identity = j.at("identity").get<std::string>();
    r.content = j.at("content").get<std::string>();
    r.time = j.at("time_s").get<double>();
    r.wall_time = j.at("wall_time_s").get<double>();
    r.legs = j.at("legs").get<std::int64_t>();
    r.scene_file = j.value("scene_file", "");
    if (!std::isfinite(r.wall_time) || r.wall_time < 0 || r.legs < 1) return std::nullopt;
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string run_identity(Scene& scene) {
  Fnv f;
  f.add(scene_json(scene).dump());
  f.add(std::to_string(scene.sample.seed));
  if (!takes_local_steps(engine_setup(scene))) {
    const auto threads = scene.integrator.threads > 0 ? std::int64_t(scene.integrator.threads)
                                                      : std::int64_t(omp_get_max_threads());
    f.add(std::to_string(threads));
  }
  f.add(SEDEM_VERSION);
  return f.hex();
}

std::string file_hash(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  Fnv f;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    f.add(buffer, std::size_t(in.gcount()));
  }
  return f.hex();
}

void write_checkpoint(const fs::path& dir,
                      const std::function<void(const std::string&)>& write_engine,
                      CheckpointRecord record) {
  const fs::path bin = dir / kCheckpointFile, json = dir / kCheckpointRecordFile;
  fs::path bin_tmp = bin, json_tmp = json;
  bin_tmp += ".tmp";
  json_tmp += ".tmp";
  try {
    write_engine(bin_tmp.string());
    sync_file(bin_tmp);
    record.content = file_hash(bin_tmp);
    nlohmann::json j = to_json(record);
    // The checkpoint.bin in place until the rename below: a kill between the two renames
    // leaves it beside this record, which still accepts it.
    std::ifstream old_in(json);
    if (old_in) {
      const auto old = nlohmann::json::parse(old_in, nullptr, false);
      if (!old.is_discarded() && old.contains("current"))
        j = {{"current", j}, {"previous", old["current"]}};
      else
        j = {{"current", j}};
    } else {
      j = {{"current", j}};
    }
    {
      std::ofstream out(json_tmp);
      out << j.dump(2) << '\n';
      out.flush();
      if (!out) throw std::runtime_error("cannot write " + json_tmp.string());
    }
    sync_file(json_tmp);
    fs::rename(json_tmp, json);
    fs::rename(bin_tmp, bin);
    sync_dir(dir);
  } catch (...) {
    std::error_code ec;
    fs::remove(bin_tmp, ec);
    fs::remove(json_tmp, ec);
    throw;
  }
}

CheckpointRecord read_checkpoint_record(const fs::path& dir, const std::string& identity) {
  const fs::path bin = dir / kCheckpointFile, json = dir / kCheckpointRecordFile;
  std::ifstream in(json);
  if (!in)
    throw CheckpointError(json.string() +
                          ": missing; a checkpoint without it cannot prove which run it belongs "
                          "to");
  const auto j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("current"))
    throw CheckpointError(json.string() + ": not a sedem checkpoint record");
  const std::string content = file_hash(bin);
  for (const char* which : {"current", "previous"}) {
    if (!j.contains(which)) continue;
    const auto r = from_json(j[which]);
    if (!r) throw CheckpointError(json.string() + ": damaged (" + which + " entry)");
    if (r->content != content) continue;
    if (r->identity != identity)
      throw CheckpointError(
          bin.string() +
          " was written by another run (another scene, seed or version, or, without local "
          "steps, thread count) than the one run.json describes; it cannot be resumed");
    return *r;
  }
  throw CheckpointError(bin.string() + " does not match " + json.string() +
                        ": it is damaged or was replaced");
}

void remove_checkpoint(const fs::path& dir) {
  std::error_code ec;
  for (const char* f : {kCheckpointFile, kCheckpointRecordFile}) {
    fs::remove(dir / f, ec);
    auto tmp = dir / f;
    tmp += ".tmp";
    fs::remove(tmp, ec);
  }
}

}  // namespace sedem::app
