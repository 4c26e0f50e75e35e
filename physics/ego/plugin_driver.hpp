// The host side of the ego plugin ABI (ego_plugin.h, docs/ego-plugin.md): one PluginDriver per
// evaluation runs the plugin in a child process of its own, so that a plugin that crashes,
// hangs or fails costs that evaluation an EgoPluginError and nothing else. The child is forked
// (not exec'd): it loads the library, calls scenfuzz_ego_create, then answers each observation
// sent over a socket with the plugin's control until it is told to stop.
#pragma once

#include <sys/types.h>

#include <stdexcept>
#include <string>

#include "physics/ego/ego_plugin.h"

namespace scenfuzz {

struct PluginOptions {
  std::string library;          // path of the shared library; a bare name found in the current
                                // folder is loaded from there, otherwise dlopen searches for it
  double step_timeout = 2.0;    // s of wall time the plugin has for one step (and for destroy)
  double start_timeout = 10.0;  // s of wall time for loading the library and create
};

// The plugin failed this evaluation: it could not be loaded or created, it crashed, hung,
// returned an error or a non-finite control. The message names the library and the step.
class EgoPluginError : public std::runtime_error {
 public:
  using runtime_error::runtime_error;
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
  // Asks the child to call destroy and exit, kills it (SIGKILL) if it has not within
  // step_timeout, and always reaps it.
  ~PluginDriver();

  PluginDriver(const PluginDriver&) = delete;
  PluginDriver& operator=(const PluginDriver&) = delete;
  PluginDriver(PluginDriver&& other) noexcept;
  PluginDriver& operator=(PluginDriver&& other) noexcept;

  // The plugin's control for this observation, as it returned it (the vehicle model clamps it).
  // Throws EgoPluginError when the plugin crashes, exits, does not answer within step_timeout
  // (the child is then killed), returns non-zero or a non-finite control. After an error the
  // driver is spent: every later call throws the same error.
  scenfuzz_control step(const scenfuzz_observation& observation);

  // The child's process id while it runs, -1 once it has been reaped (after a crash, a hang or
  // a move). For tests and diagnostics.
  pid_t child_process() const { return child_; }
  // Steps sent so far, counting from 1: the number that error messages give.
  long steps() const { return steps_; }

 private:
  [[noreturn]] void fail(const std::string& what);
  // The message for a child that has gone (crashed or exited) at `when`; reaps it.
  std::string describe_death(const std::string& when);
  void shut_down() noexcept;

  std::string library_;
  double step_timeout_ = 0;
  pid_t child_ = -1;
  int socket_ = -1;
  long steps_ = 0;
  std::string failure_;  // set once the driver is spent
};

}  // namespace scenfuzz
