#include "app/stop_signals.h"

#include <csignal>

namespace sedem::app {
namespace {

volatile std::sig_atomic_t g_signal = 0;

void on_stop(int sig) {
  if (g_signal == 0) g_signal = sig;
  // A second Ctrl-C is a person who will not wait: it kills. A second SIGTERM is a program
  // repeating its request (coreutils timeout sends two): the run still stops cleanly.
  if (sig == SIGINT) std::signal(sig, SIG_DFL);
}

}  // namespace

void install_stop_handlers() {
  std::signal(SIGINT, on_stop);
  std::signal(SIGTERM, on_stop);
}

bool stop_requested() {
  return g_signal != 0;
}
int stop_signal() {
  return g_signal;
}

}  // namespace sedem::app
