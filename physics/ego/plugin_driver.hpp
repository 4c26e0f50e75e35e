// The host side of the ego plugin ABI (ego_plugin.h, docs/ego-plugin.md): one PluginDriver per
// evaluation runs the plugin in a child process of its own, so that a plugin that crashes,
// hangs or fails costs that evaluation an EgoPluginError and nothing else. The child is forked
// (not exec'd): it loads the library, calls scenfuzz_ego_create, then answers each observation
// sent over a socket with the plugin's control until it is told to stop. The child leads a
// process group of its own, and the whole group is killed when the evaluation ends, so that no
// process a plugin forks outlives its evaluation.
#pragma once

#include <sys/types.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "physics/ego/ego_plugin.h"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct PluginOptions {
  std::string library;  // path of the shared library; a bare name found in the current
                        // folder is loaded from there, otherwise dlopen searches for it
  // Wall time from the call (step() or the constructor) to the error when the plugin does not
  // answer; the kill and reap that follow take milliseconds on top.
  double step_timeout = 2.0;    // s the plugin has for one step (and for destroy)
  double start_timeout = 10.0;  // s for starting the process, loading the library and create
};

// The plugin failed this evaluation: it could not be loaded or created, it crashed, hung,
// returned an error or a non-finite control. The message names the library and the step.
class EgoPluginError : public std::runtime_error {
 public:
  EgoPluginError(EgoFailureKind kind, const std::string& message, long step,
                 std::string signal = {})
      : runtime_error(message), kind_(kind), step_(step), signal_(std::move(signal)) {}

  // crash: the process died (a signal or an exit); hang: no answer within the step or start
  // limit; error: cannot load or create, a missing symbol, a non-zero return, a non-finite
  // control (and failures of the host itself: no socket, no fork).
  EgoFailureKind kind() const { return kind_; }
  // The step that failed, from 1; 0 while starting.
  long step() const { return step_; }
  // A crash by a signal: its name ("SIGSEGV"); empty otherwise.
  const std::string& signal() const { return signal_; }

 private:
  EgoFailureKind kind_;
  long step_;
  std::string signal_;
};

// A running plugin for one evaluation. Create it on the thread that runs the evaluation and
// destroy it there: the child is killed when the thread that forked it ends (PR_SET_PDEATHSIG
// follows threads, not processes). Linux only.
class PluginDriver {
 public:
  // Starts the child, which loads the library, checks its three symbols and calls create with
  // `config` (abi_version is set here). Throws EgoPluginError when any of that fails or takes
  // longer than start_timeout, std::invalid_argument for an empty library or a timeout <= 0.
  PluginDriver(const PluginOptions& options, const scenfuzz_ego_config& config);
  // Asks the child to call destroy and exit, waits up to step_timeout for it to, then kills
  // its whole process group (SIGKILL) and reaps it.
  ~PluginDriver();

  PluginDriver(const PluginDriver&) = delete;
  PluginDriver& operator=(const PluginDriver&) = delete;
  PluginDriver(PluginDriver&& other) noexcept;
  PluginDriver& operator=(PluginDriver&& other) noexcept;

  // The plugin's control for this observation, as it returned it (the vehicle model clamps it).
  // Throws EgoPluginError when the plugin crashes, exits, does not answer within step_timeout
  // (the child's group is then killed), returns non-zero or a non-finite control. After an
  // error the driver is spent: every later call throws the same error.
  scenfuzz_control step(const scenfuzz_observation& observation);

  // The child's process id (and its process group's) while it runs, -1 once it has been reaped
  // (after a crash, a hang or a move). For tests and diagnostics.
  pid_t child_process() const { return child_; }
  // Steps sent so far, counting from 1: the number that error messages give.
  long steps() const { return steps_; }

 private:
  [[noreturn]] void fail(const EgoPluginError& error);
  // The error for a child whose end of the socket closed at `when`: it crashed or exited.
  // Ends its group and reaps it.
  EgoPluginError describe_death(const std::string& when);
  // Waits up to `seconds` for the child to end (without reaping it); true if it has.
  bool await_exit(double seconds) const;
  // Kills the child's whole process group and reaps the child; returns its wait status.
  int end_group() noexcept;
  // The graceful end: end of file to the child, up to step_timeout for destroy, then
  // end_group. Closes the descriptors.
  void shut_down() noexcept;
  void close_descriptors() noexcept;

  std::string library_;
  double step_timeout_ = 0;
  pid_t child_ = -1;  // also the id of the child's process group
  int socket_ = -1;
  int child_fd_ = -1;  // a pidfd: readable once the child has ended; -1 where unsupported
  long steps_ = 0;
  std::optional<EgoPluginError> failure_;  // set once the driver is spent
};

}  // namespace scenfuzz
