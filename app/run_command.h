#pragma once

#include <string>
#include <vector>

namespace sedem::app {

struct RunOptions {
  std::string scene;
  std::string out_dir;     // empty: out/<scene name>
  bool overwrite = false;  // replace the outputs of the run an existing --out holds
  std::string resume_dir;  // set: go on with the interrupted run in this folder
  std::vector<std::string> overrides;
  bool quiet = false;
};

// `sedem run`: returns the process exit status. Needs a Qt application object.
int run(const RunOptions& options);

}  // namespace sedem::app
