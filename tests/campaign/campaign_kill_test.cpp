// `scenfuzz campaign run` through the real executable, interrupted the ways a nightly job is:
// kill -9 at random moments (seeded, so the moments are the same each time) and SIGTERM, each
// followed by runs until one completes, must leave exactly the database and modes/ of an
// uninterrupted run (with [search] tmin = true too); and a second run on the same folder at once
// is refused, naming the first.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "fuzz/cli.hpp"
#include "tests/campaign/campaign_fixture.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// `scenfuzz campaign run DIR -j 2` started in the background, its output in files.
class Background {
 public:
  Background(const fs::path& dir, const fs::path& out, const fs::path& err) {
    const std::vector<std::string> args = {SCENFUZZ_EXECUTABLE, "campaign", "run",
                                           dir.string(),        "-j",       "2"};
    std::vector<char*> argv;
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ == 0) {
      const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(out_fd, 1);
      ::dup2(err_fd, 2);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
  }
  ~Background() {
    if (pid_ > 0 && !done_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }

  pid_t pid() const { return pid_; }

  // Whether it has ended by itself; its wait status in `status`.
  bool ended(int& status) {
    done_ = done_ || ::waitpid(pid_, &status_, WNOHANG) == pid_;
    status = status_;
    return done_;
  }

  // Sends `signal` and waits for the end; the wait status.
  int stop(int signal) {
    if (!done_) {
      ::kill(pid_, signal);
      ::waitpid(pid_, &status_, 0);
      done_ = true;
    }
    return status_;
  }

 private:
  pid_t pid_ = -1;
  bool done_ = false;
  int status_ = 0;
};

// Waits (a minute at most) until the file at `path` holds `text` or `process` has ended.
void wait_for_output(Background& process, const fs::path& path, const std::string& text) {
  const Clock::time_point start = Clock::now();
  int status = 0;
  while (slurp(path).find(text) == std::string::npos && !process.ended(status) &&
         Clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

class CampaignKillTest : public CommandTest {
 protected:
  // `more`: lines for campaign.toml's [search] table.
  fs::path campaign(const std::string& name, const std::string& more = "") {
    fs::create_directories(dir_ / name);
    write(name + "/campaign.toml",
          campaign_toml(small_campaign_seeds(), "simulations = 320", more));
    return dir_ / name;
  }

  // The uninterrupted run's dump, and how long it took.
  std::string uninterrupted(double& seconds, const std::string& more = "") {
    const fs::path folder = campaign("whole", more);
    const Clock::time_point start = Clock::now();
    const Outcome outcome = scenfuzz({"campaign", "run", folder.string(), "-j", "2"});
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_EQ(outcome.exit_code, kExitViolated) << outcome.err;
    return canonical_dump(folder);
  }

  // Kills runs of the campaign in `folder` until one ends by itself (then completes it if a kill
  // came after the run ended, before the process did); how many were killed. Even kills come
  // at a moment after the start (while the seeds load, the database opens, the run begins or
  // continues); odd ones after the run has said which run it is; both up to `spread` seconds
  // later, so that together they reach every part of the run, its end included.
  int kill_until_it_ends(const fs::path& folder, double spread, std::mt19937& random) {
    std::uniform_real_distribution<double> moment(0.0, spread);
    int kills = 0;
    bool ended = false;
    while (kills < 100 && !ended) {
      Background run(folder, dir_ / "out.txt", dir_ / "err.txt");
      if (kills % 2 == 1) wait_for_output(run, dir_ / "out.txt", "run 1");
      std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
      int status = 0;
      if (run.ended(status)) {
        EXPECT_TRUE(WIFEXITED(status)) << status;
        return kills;
      }
      // It may end by itself between that check and the kill: then the kill found a zombie.
      const int stopped = run.stop(SIGKILL);
      if (WIFEXITED(stopped)) return kills;
      EXPECT_TRUE(WIFSIGNALED(stopped)) << stopped;
      ++kills;
      // Killed after the run was recorded as ended, before the process exited: the next
      // `campaign run` would begin run 2, which an uninterrupted run never does.
      ended = canonical_dump(folder).find("run 1 reference ended") != std::string::npos;
    }
    if (!ended) complete(folder);
    return kills;
  }

  // Runs the campaign once more to its end: the run it continues ends.
  void complete(const fs::path& folder) {
    const Outcome outcome = scenfuzz({"campaign", "run", folder.string(), "-j", "2"});
    EXPECT_TRUE(outcome.exit_code == kExitViolated || outcome.exit_code == kExitSuccess)
        << outcome.err;
    EXPECT_NE(outcome.out.find("continuing run 1"), std::string::npos) << outcome.out;
  }
};

TEST_F(CampaignKillTest, KilledAtRandomMomentsItEndsAsAnUninterruptedRun) {
  double seconds = 0;
  const std::string expected = uninterrupted(seconds);
  ASSERT_NE(expected.find("\nmode "), std::string::npos) << expected;
  ASSERT_NE(expected.find("  covers "), std::string::npos) << expected;
  std::mt19937 random(20261126);
  // Until eight kills or more hit one run: the machine's speed changes under other loads, so a
  // sequence that lets the run end sooner is followed by one with moments half as far apart.
  int kills = 0;
  for (int sequence = 0; sequence < 4 && kills < 8; ++sequence) {
    const fs::path folder = campaign("killed-" + std::to_string(sequence));
    kills = kill_until_it_ends(folder, seconds / (6 << sequence), random);
    const std::string dump = canonical_dump(folder);
    EXPECT_TRUE(dump == expected) << first_difference(dump, expected);
  }
  EXPECT_GE(kills, 8);
}

// With [search] tmin = true the minimised files (compared by content) are the same too: a kill
// during a minimisation leaves the search unrecorded and the file unwritten, and the continued run
// records and minimises it.
TEST_F(CampaignKillTest, WithTminKilledAtRandomMomentsItEndsAsAnUninterruptedRun) {
  double seconds = 0;
  const std::string expected = uninterrupted(seconds, "tmin = true\n");
  ASSERT_NE(expected.find(".min.avu "), std::string::npos) << expected;
  std::mt19937 random(20261127);
  int kills = 0;
  for (int sequence = 0; sequence < 3 && kills < 6; ++sequence) {
    const fs::path folder = campaign("killed-" + std::to_string(sequence), "tmin = true\n");
    kills = kill_until_it_ends(folder, seconds / (6 << sequence), random);
    const std::string dump = canonical_dump(folder);
    EXPECT_TRUE(dump == expected) << first_difference(dump, expected);
  }
  EXPECT_GE(kills, 6);
}

TEST_F(CampaignKillTest, SigtermStopsWithEverythingRecordedAndTheNextRunContinues) {
  double seconds = 0;
  const std::string expected = uninterrupted(seconds);
  const fs::path folder = campaign("stopped");
  {
    Background run(folder, dir_ / "out.txt", dir_ / "err.txt");
    // Once the first search is recorded (a stop before would have nothing to keep).
    wait_for_output(run, dir_ / "out.txt", "round 0: ");
    const int status = run.stop(SIGTERM);
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_TRUE(WEXITSTATUS(status) == kExitSuccess || WEXITSTATUS(status) == kExitViolated);
  }
  const std::string err = slurp(dir_ / "err.txt");
  if (err.find("interrupted") != std::string::npos) {
    // Stopped half-way: the run is not over, and what is recorded stays.
    const std::string partial = canonical_dump(folder);
    EXPECT_NE(partial.find("\nsearch 1 "), std::string::npos) << partial;
    EXPECT_NE(partial.find("run 1 reference open"), std::string::npos) << partial;
    complete(folder);
  }
  const std::string dump = canonical_dump(folder);
  EXPECT_TRUE(dump == expected) << first_difference(dump, expected);
}

TEST_F(CampaignKillTest, ASecondRunAtOnceIsRefusedNamingTheFirst) {
  const fs::path folder = dir_ / "busy";
  fs::create_directories(folder);
  write("busy/campaign.toml", campaign_toml(small_campaign_seeds(), "simulations = 1000000"));
  Background first(folder, dir_ / "out.txt", dir_ / "err.txt");
  // Until the first has the campaign (it says so once its run has begun).
  wait_for_output(first, dir_ / "out.txt", "run 1");
  const Outcome second = scenfuzz({"campaign", "run", folder.string()});
  EXPECT_EQ(second.exit_code, kExitBadInput);
  EXPECT_NE(second.err.find("is in use by another run (process " + std::to_string(first.pid())),
            std::string::npos)
      << second.err;
  first.stop(SIGKILL);
}

}  // namespace
}  // namespace scenfuzz::test
