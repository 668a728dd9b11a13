#include "app/run_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// The folders a run writes its series, frames and figures into.
const std::set<std::string> kOutputFolders{"particles", "fields",  "hydrometer", "frames",
                                           "figures",   "columns", "replay"};

bool is_temporary(const fs::path& p) {
  return p.extension() == ".tmp";
}

std::string first_component(const fs::path& relative) {
  return relative.empty() ? std::string() : relative.begin()->string();
}

}  // namespace

bool is_run_output(const fs::path& relative) {
  const std::string top = first_component(relative);
  if (std::distance(relative.begin(), relative.end()) > 1) return kOutputFolders.count(top) > 0;
  const fs::path name(top);
  const std::string ext = name.extension().string();
  return kOutputFolders.count(top) > 0 || top == "run.json" || top == "checkpoint.bin" ||
         top == "checkpoint.json" || top == "report.html" || top == "sedem.pvsm" || ext == ".pvd" ||
         ext == ".csv" || ext == ".tmp";
}

std::vector<std::string> run_files(const fs::path& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file()) continue;
    const fs::path relative = it->path().lexically_relative(dir);
    if (relative == "run.json" || is_temporary(relative)) continue;
    files.push_back(relative.generic_string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string safe_folder_name(const std::string& name) {
  std::string out;
  for (const unsigned char c : name) {
    const bool keep = std::isalnum(c) || std::strchr("._-=,+", c) != nullptr;
    out += keep && c != 0 ? char(c) : '_';
  }
  if (out.empty() || out.front() == '.') out.insert(out.begin(), '_');
  return out;
}

RunFolder::RunFolder(fs::path dir, bool resuming, bool overwrite) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_))
    throw Error("cannot write to the output folder " + dir_.string() + ": " +
                (ec ? ec.message() : std::string("not a folder")));
  // The lock is on the folder itself: nothing is added to it, and the kernel drops the lock
  // when the process ends, however it ends.
  lock_fd_ = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (lock_fd_ < 0)
    throw Error("cannot write to the output folder " + dir_.string() + ": " + std::strerror(errno));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw Error("another sedem run is writing into " + dir_.string() +
                "; wait for it to end or choose another --out");
  }
  if (resuming) return;

  std::vector<fs::path> entries;
  for (const auto& e : fs::directory_iterator(dir_)) entries.push_back(e.path());
  if (entries.empty()) return;
  const bool old_run = fs::exists(dir_ / "run.json");
  std::ifstream record(dir_ / "run.json");
  const std::string text{std::istreambuf_iterator<char>(record), {}};
  // A run killed before its first checkpoint (still "running", its lock free, as it is now
  // ours): nothing of it can be resumed, and its outputs are taken over as --overwrite would.
  const bool killed_early = text.find("\"status\": \"running\"") != std::string::npos &&
                            !fs::exists(dir_ / "checkpoint.bin") &&
                            !fs::exists(dir_ / "checkpoint.json");
  if (!overwrite && !killed_early) {
    if (text.find("\"status\": \"interrupted\"") != std::string::npos)
      throw Error(dir_.string() + " holds an interrupted run: go on with it with sedem run " +
                  "--resume " + dir_.string() + ", or give --overwrite to replace it");
    throw Error(dir_.string() + (old_run ? " holds another run" : " is not empty") +
                "; choose another --out, or give --overwrite to replace " +
                (old_run ? "that run" : "the run outputs in it"));
  }
  // --overwrite: what a run writes goes; anything else stays and stops the run, so that a
  // mistyped --out never deletes the user's own files and the folder still holds one run only.
  std::vector<std::string> foreign;
  for (const auto& p : entries) {
    const fs::path relative = p.filename();
    // A series folder is one whose .pvd sits beside it (particles/ and particles.pvd).
    const bool series = fs::is_directory(p) && fs::exists(p.string() + ".pvd");
    if (is_run_output(relative) || series)
      fs::remove_all(p);
    else
      foreign.push_back(relative.string());
  }
  if (!foreign.empty()) {
    std::sort(foreign.begin(), foreign.end());
    throw Error(dir_.string() + " holds " + foreign.front() +
                (foreign.size() > 1 ? " and " + std::to_string(foreign.size() - 1) + " more" : "") +
                ", which no sedem run writes: --overwrite replaces a run's outputs only; move " +
                "them or choose another --out");
  }
}

RunFolder::~RunFolder() {
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

}  // namespace sedem::app
