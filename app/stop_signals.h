#pragma once

namespace sedem::app {

// Ctrl-C (SIGINT) and SIGTERM ask the run to stop cleanly instead of killing the process:
// the handler only records the request; the main loop polls it. A second Ctrl-C while
// stopping kills the process as usual; a second SIGTERM changes nothing. A run installs them
// before its set-up, so that a stop asked at any moment ends with a record and a checkpoint.
void install_stop_handlers();
bool stop_requested();
int stop_signal();  // the signal that asked, 0 if none

}  // namespace sedem::app
