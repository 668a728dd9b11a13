#include "app/stop_signals.h"

#include <csignal>

namespace sedem::app {
namespace {

volatile std::sig_atomic_t g_signal = 0;

void on_stop(int sig) {
  g_signal = sig;
  std::signal(sig, SIG_DFL);  // the next one is not caught
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
