// SIGINT and SIGTERM (what Ctrl-C, CI time-outs and `timeout` send) ask a search to stop after
// the batch in flight, with everything written; a second one of either ends the process at once.
#pragma once

namespace scenfuzz {

// Installs the handlers for its lifetime; restores the previous ones after.
class StopSignalGuard {
 public:
  StopSignalGuard();
  ~StopSignalGuard();
  StopSignalGuard(const StopSignalGuard&) = delete;
  StopSignalGuard& operator=(const StopSignalGuard&) = delete;

  // Whether a stop was asked for since the guard was made.
  static bool stop_requested();

 private:
  void (*previous_interrupt_)(int);
  void (*previous_terminate_)(int);
};

}  // namespace scenfuzz
