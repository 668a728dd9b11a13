#pragma once

#include <string>

namespace sedem::app {

struct ParaviewOptions {
  std::string run_dir;
  std::string pvpython;    // ParaView's Python; empty: SEDEM_PVPYTHON, then pvpython on PATH
  std::string time;        // the time shown, s; empty: the last
  std::string screenshot;  // also a PNG of the layout there
  bool quiet = false;
};

// `sedem paraview RUN_DIR`: writes RUN_DIR/sedem.pvsm, a ParaView state that opens the run as
// the paper shows it, by running the built-in macro (docs/sedem_paraview.py) with ParaView's
// own pvpython. A state file is ParaView's own format, of the ParaView that reads it: it is
// written by that ParaView, on demand, rather than by every run. Returns the exit status.
int paraview_state(const ParaviewOptions& options);

}  // namespace sedem::app
