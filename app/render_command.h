#pragma once

#include <string>
#include <vector>

namespace sedem::app {

struct RenderOptions {
  std::vector<std::string> run_dirs;
  std::string out_dir = "out/figures";  // where figures shared by several runs go
  bool quiet = false;
  bool partial = false;  // redraw a run that did not complete (its files stop where it did)
};

// `sedem render RUN_DIR...`: takes every reading and draws every figure and frame again from
// a run's saved particle series and run.json, without simulating. With several runs it also
// draws the figures they share, one panel per run, into out_dir, each panel and legend entry
// labelled by what differs between the runs (run_labels). Returns the exit status.
int render_runs(const RenderOptions& options);

}  // namespace sedem::app
