#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace sedem::app {

// A run's folder holds one run only. Before a run writes anything, RunFolder takes the folder
// for itself: it creates it, locks it (a second run into the same folder stops at once) and
// checks that it is empty, or, with `overwrite`, removes the outputs of the run it held
// before. A resumed run goes on in the folder of its own interrupted run. At the end,
// run_files() lists what the run wrote, for run.json.
class RunFolder {
 public:
  struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  // Throws Error with a message for the user when the folder cannot be taken.
  RunFolder(std::filesystem::path dir, bool resuming, bool overwrite);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  int lock_fd_ = -1;
};

// Every file in a run folder, relative to it ('/' separated, sorted), but run.json and the
// temporary files of an atomic write: what run.json lists as the run's files.
std::vector<std::string> run_files(const std::filesystem::path& dir);

// Whether `relative` (a path inside a run folder) is one of the files a run writes: its series,
// readings, figures, frames, checkpoint, report.html. --overwrite removes these and nothing else.
bool is_run_output(const std::filesystem::path& relative);

// A name usable as one folder inside an output folder: characters other than letters, digits
// and . _ - = , + become '_', and a name that is empty or starts with '.' gets a leading '_',
// so that no scene or sweep name can point outside the output folder ("../x", "/etc").
std::string safe_folder_name(const std::string& name);

}  // namespace sedem::app
