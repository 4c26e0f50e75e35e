// What a failing or forking ego plugin costs: no process of its group outlives the evaluation,
// whatever way the evaluation ends, and a plugin that hangs costs its time limit and no more.
// The time limits are the behaviour here, so these tests measure wall time, with bounds loose
// enough for a loaded two-core machine.
#include <dirent.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "physics/ego/plugin_driver.hpp"

#ifndef SCENFUZZ_TEST_PLUGIN_DIR
#error "tests/CMakeLists.txt passes the plugins' folder"
#endif

namespace scenfuzz {
namespace {

using Clock = std::chrono::steady_clock;

std::string test_plugin(const std::string& name) {
  return std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

scenfuzz_ego_config config_with_seed(std::uint64_t seed) {
  scenfuzz_ego_config config{};
  config.dt = 0.1;
  config.seed = seed;
  config.vehicle = {4.93, 1.86, 2.85, 40.0, 3.0, 8.0, 0.6};
  config.target_x = std::nan("");
  config.target_y = std::nan("");
  return config;
}

scenfuzz_observation still_observation() {
  scenfuzz_observation observation{};
  observation.light = SCENFUZZ_LIGHT_NONE;
  return observation;
}

struct ProcessStat {
  char state = 0;  // 0: no such process
  pid_t group = -1;
};

// From /proc/<pid>/stat: "pid (comm) state ppid pgrp ...", where comm may hold spaces.
ProcessStat stat_of(pid_t pid) {
  ProcessStat stat;
  std::ifstream file("/proc/" + std::to_string(pid) + "/stat");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (close == std::string::npos) return stat;
  std::istringstream fields(text.substr(close + 1));
  pid_t parent = 0;
  fields >> stat.state >> parent >> stat.group;
  return stat;
}

bool running(pid_t pid) {
  const char state = stat_of(pid).state;
  return state != 0 && state != 'Z' && state != 'X';
}

// The processes of group `group` that still run. A killed orphan stays a zombie until init
// reaps it, which some inits (this machine's) do only every second or two, so
// kill(-group, 0) alone would count processes that no longer run.
std::vector<pid_t> running_members(pid_t group) {
  std::vector<pid_t> members;
  DIR* proc = opendir("/proc");
  if (proc == nullptr) return members;
  while (const dirent* entry = readdir(proc)) {
    const auto pid = static_cast<pid_t>(std::atoi(entry->d_name));
    if (pid > 0 && stat_of(pid).group == group && running(pid)) members.push_back(pid);
  }
  closedir(proc);
  return members;
}

// Waits up to `seconds` for `sleeper` and every process of `group` to have stopped running.
bool all_end_within(pid_t sleeper, pid_t group, double seconds) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    const bool group_gone = (kill(-group, 0) == -1 && errno == ESRCH) ||  // zombies reaped too
                            running_members(group).empty();
    if (group_gone && !running(sleeper)) return true;
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The plugin forks a sleeper in create and ends its second step as its seed says.
enum class Ending { normal = 0, crash = 1, hang = 2, error = 3 };

struct Ended {
  pid_t group = -1;
  pid_t sleeper = -1;
  std::string error;  // empty: no error
};

Ended run_forking_plugin(Ending ending) {
  PluginOptions options;
  options.library = test_plugin("forking");
  options.step_timeout = 0.3;
  Ended ended;
  PluginDriver driver(options, config_with_seed(static_cast<std::uint64_t>(ending)));
  ended.group = driver.child_process();
  ended.sleeper = static_cast<pid_t>(driver.step(still_observation()).acceleration);
  try {
    driver.step(still_observation());
  } catch (const EgoPluginError& error) {
    ended.error = error.what();
  }
  return ended;
}

TEST(PluginTeardown, TheSleeperAPluginForksRunsWhileTheEvaluationDoes) {
  PluginOptions options;
  options.library = test_plugin("forking");
  PluginDriver driver(options, config_with_seed(0));
  const auto sleeper = static_cast<pid_t>(driver.step(still_observation()).acceleration);
  EXPECT_TRUE(running(sleeper));
  EXPECT_EQ(stat_of(sleeper).group, driver.child_process())
      << "the plugin and its sleeper are in the plugin's own process group";
}

TEST(PluginTeardown, NoProcessOfTheGroupOutlivesANormalEnd) {
  const Ended ended = run_forking_plugin(Ending::normal);
  EXPECT_EQ(ended.error, "");
  EXPECT_TRUE(all_end_within(ended.sleeper, ended.group, 2.0))
      << "sleeper " << ended.sleeper << ", group " << ended.group;
}

TEST(PluginTeardown, NoProcessOfTheGroupOutlivesACrashAndTheCrashIsSeenAsOne) {
  const Ended ended = run_forking_plugin(Ending::crash);
  // The sleeper holds the socket open, so the crash is seen from the process, not the socket.
  EXPECT_NE(ended.error.find("crashed (SIGSEGV) at step 2"), std::string::npos) << ended.error;
  EXPECT_TRUE(all_end_within(ended.sleeper, ended.group, 2.0))
      << "sleeper " << ended.sleeper << ", group " << ended.group;
}

TEST(PluginTeardown, NoProcessOfTheGroupOutlivesAHang) {
  const Ended ended = run_forking_plugin(Ending::hang);
  EXPECT_NE(ended.error.find("did not answer within 0.3 s at step 2"), std::string::npos)
      << ended.error;
  EXPECT_TRUE(all_end_within(ended.sleeper, ended.group, 2.0))
      << "sleeper " << ended.sleeper << ", group " << ended.group;
}

TEST(PluginTeardown, NoProcessOfTheGroupOutlivesAnError) {
  const Ended ended = run_forking_plugin(Ending::error);
  EXPECT_NE(ended.error.find("returned error 5 at step 2"), std::string::npos) << ended.error;
  EXPECT_TRUE(all_end_within(ended.sleeper, ended.group, 2.0))
      << "sleeper " << ended.sleeper << ", group " << ended.group;
}

TEST(PluginTeardown, ANormalEndDoesNotWaitForTheSleeper) {
  // The sleeper keeps the socket open: waiting for the socket to close would cost the whole
  // step limit at every evaluation.
  PluginOptions options;
  options.library = test_plugin("forking");
  options.step_timeout = 1.0;
  auto driver = std::make_unique<PluginDriver>(options, config_with_seed(0));
  driver->step(still_observation());
  const auto start = Clock::now();
  driver.reset();
  EXPECT_LT(seconds_since(start), 0.5);
}

TEST(PluginTeardown, AHangingStepCostsItsLimit) {
  PluginOptions options;
  options.library = test_plugin("hanging");
  options.step_timeout = 0.3;
  PluginDriver driver(options, config_with_seed(0));
  const auto start = Clock::now();
  EXPECT_THROW(driver.step(still_observation()), EgoPluginError);
  const double elapsed = seconds_since(start);
  EXPECT_GE(elapsed, 0.3);
  EXPECT_LE(elapsed, 1.1 * 0.3 + 0.15);
}

TEST(PluginTeardown, AHangingStepOfAForkingPluginCostsItsLimit) {
  PluginOptions options;
  options.library = test_plugin("forking");
  options.step_timeout = 0.3;
  PluginDriver driver(options, config_with_seed(static_cast<std::uint64_t>(Ending::hang)));
  driver.step(still_observation());
  const auto start = Clock::now();
  EXPECT_THROW(driver.step(still_observation()), EgoPluginError);
  const double elapsed = seconds_since(start);
  EXPECT_GE(elapsed, 0.3);
  EXPECT_LE(elapsed, 1.1 * 0.3 + 0.15);
}

TEST(PluginTeardown, AHangingCreateCostsTheStartLimit) {
  PluginOptions options;
  options.library = test_plugin("hanging_create");
  options.step_timeout = 0.3;
  options.start_timeout = 0.5;
  const auto start = Clock::now();
  try {
    PluginDriver driver(options, config_with_seed(0));
    ADD_FAILURE() << "the hang went unnoticed";
  } catch (const EgoPluginError& error) {
    EXPECT_NE(std::string(error.what()).find("did not start within 0.5 s (killed)"),
              std::string::npos)
        << error.what();
    EXPECT_EQ(error.kind(), EgoFailureKind::hang);
    EXPECT_EQ(error.step(), 0);
  }
  const double elapsed = seconds_since(start);
  EXPECT_GE(elapsed, 0.5);
  EXPECT_LE(elapsed, 1.1 * 0.5 + 0.15);
}

}  // namespace
}  // namespace scenfuzz
