#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace dynanav {
namespace {

std::atomic<int> g_signal{0};

extern "C" void onSignal(int signal_number) {
  g_signal.store(signal_number);
  std::signal(signal_number, SIG_DFL);  // the next one of its kind ends the process
}

}  // namespace

void installInterruptHandlers() {
  for (int s : {SIGINT, SIGTERM, SIGHUP}) std::signal(s, onSignal);
  std::signal(SIGPIPE, SIG_IGN);
}

bool interruptRequested() {
  return g_signal.load() != 0;
}

int interruptSignal() {
  return g_signal.load();
}

void requestInterrupt(int signal_number) {
  g_signal.store(signal_number);
}

}  // namespace dynanav
