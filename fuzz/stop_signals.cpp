#include "fuzz/stop_signals.hpp"

#include <atomic>
#include <csignal>

namespace scenfuzz {

namespace {

std::atomic<bool> stop_requested_flag{false};

extern "C" void on_stop_signal(int) {
  stop_requested_flag.store(true);
  // The second signal of either kind ends the process at once.
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

}  // namespace

StopSignalGuard::StopSignalGuard() {
  stop_requested_flag.store(false);
  previous_interrupt_ = std::signal(SIGINT, on_stop_signal);
  previous_terminate_ = std::signal(SIGTERM, on_stop_signal);
}

StopSignalGuard::~StopSignalGuard() {
  std::signal(SIGINT, previous_interrupt_);
  std::signal(SIGTERM, previous_terminate_);
}

bool StopSignalGuard::stop_requested() { return stop_requested_flag.load(); }

}  // namespace scenfuzz
