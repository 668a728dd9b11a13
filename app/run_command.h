#pragma once

#include <functional>
#include <string>
#include <vector>

namespace sedem {
class Observer;
class Simulation;
}  // namespace sedem

namespace sedem::app {

struct RunObservers;

struct RunOptions {
  std::string scene;
  std::string scene_text;  // the scene as TOML text, read when `scene` is empty
  std::string out_dir;     // empty: out/<scene name>
  bool overwrite = false;  // replace the outputs of the run an existing --out holds
  std::string resume_dir;  // set: go on with the interrupted run in this folder
  std::vector<std::string> overrides;
  bool quiet = false;
};

// How a run is steered and looked at by a caller in the same process (the Python module)
// instead of a terminal: the run, its folder and its files stay those of `sedem run`.
struct RunHooks {
  // Polled as the run goes; empty: Ctrl-C and SIGTERM ask (the handlers are installed).
  std::function<bool()> stop_requested;
  // Beside the progress line (which --quiet silences): simulated time (s), particle-steps.
  std::function<void(double simulated_time, double particle_steps)> progress;
  // Observers of the caller's, shown the run too; they must want only times the run's own
  // observers want (a time of their own would stop the engine elsewhere and change the run).
  std::vector<Observer*> observers;
  // Called once the run's own observers watch the simulation, before `observers` are added:
  // simulation.observers().times() are then the times the run stops at.
  std::function<void(const Simulation&)> started;
  // Called once the run ended (complete, stopped or failed after the set-up), its outputs
  // written: what the observers computed, before they go.
  std::function<void(const Simulation&, const RunObservers&)> finished;
};

// `sedem run`: returns the process exit status. Needs a Qt application object.
int run(const RunOptions& options, const RunHooks& hooks = {});

}  // namespace sedem::app
