// End-to-end tests of what a search leaves on disk when it does not end well, run as a user or a
// nightly job runs it: kill -9 at several points and --resume gives exactly the uninterrupted
// search; an earlier search in --out is refused, resumed or replaced; two searches never write
// into one folder; SIGTERM stops like SIGINT; a full disk stops the search with the file named
// and the folder consistent; a search that judged nothing exits 2 with the reason.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::slurp;

const std::string kCutIn = test::source_file("corpora/avunit/cut_in_straight.avu");

// A search's result, for comparing two runs: evaluations.csv without its wall times, the
// findings of summary.json without their folder, and every finding file with the folder's name
// taken out.
std::string search_result(const fs::path& out) {
  // Fields are compared as read (quoted ones may hold commas), all but the wall time.
  const auto rows = test::read_csv(slurp(out / "evaluations.csv"));
  const auto& header = rows.front();
  const auto wall = static_cast<std::size_t>(
      std::find(header.begin(), header.end(), "wall_seconds") - header.begin());
  std::string result;
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i)
      if (i != wall || &row == &rows.front()) result += row[i] + "\x1f";
    result += "\n";
  }
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  nlohmann::json findings = summary["findings"];
  for (auto& finding : findings) finding.erase("file");
  result += findings.dump() + "\n";
  // The behaviour coverage reached: replayed evaluations bring theirs from the journal.
  result += summary["coverage"].dump() + "\n";
  for (const auto& entry : fs::directory_iterator(out / "findings")) {
    std::string text = slurp(entry.path());
    for (std::size_t at = text.find(out.string()); at != std::string::npos;
         at = text.find(out.string(), at))
      text.replace(at, out.string().size(), "OUT");
    result += entry.path().filename().string() + ":" + text + "\n";
  }
  return result;
}

std::size_t line_count(const fs::path& path) {
  const std::string text = slurp(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

bool has_temporary_files(const fs::path& out) {
  for (const fs::path& folder : {out, out / "findings"})
    if (fs::is_directory(folder))
      for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename().string().find(".tmp.") != std::string::npos) return true;
  return false;
}

class OutputJournalTest : public test::CommandTest {
 protected:
  // Starts a search in a child process, its output into dir_/child.txt.
  pid_t start(const std::vector<std::string>& args) {
    const pid_t child = ::fork();
    if (child != 0) return child;
    const std::string log = (dir_ / "child.txt").string();
    std::freopen(log.c_str(), "a", stdout);
    std::freopen(log.c_str(), "a", stderr);
    std::vector<char*> argv = {const_cast<char*>(SCENFUZZ_EXECUTABLE)};
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    ::execv(SCENFUZZ_EXECUTABLE, argv.data());
    std::_Exit(127);
  }

  // Waits (at most 60 s) until `path` has at least `lines` lines; false if the child ended first.
  bool wait_for_lines(pid_t child, const fs::path& path, std::size_t lines) {
    std::uintmax_t size = 0;
    for (int i = 0; i < 60000; ++i) {
      std::error_code error;
      const std::uintmax_t now = fs::file_size(path, error);
      if (!error && now != size && line_count(path) >= lines) return true;
      if (!error) size = now;
      int status = 0;
      if (::waitpid(child, &status, WNOHANG) == child) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }

  std::vector<std::string> search_args(const fs::path& out, const std::string& jobs) {
    return {"--budget", "1500",    "--seed", "4",          "-j",
            jobs,       "--quiet", "--out",  out.string(), kCutIn};
  }
};

TEST_F(OutputJournalTest, KillNineAndResumeGiveTheUninterruptedSearch) {
  const fs::path reference = dir_ / "reference";
  ASSERT_EQ(scenfuzz(search_args(reference, "2")).exit_code, 1);
  const std::string expected = search_result(reference);

  // Killed after the first rows, in the middle, and killed again while resuming; resumed with
  // another thread count each time.
  const fs::path out = dir_ / "killed";
  for (std::size_t rows : {2u, 700u, 1100u}) {
    SCOPED_TRACE("killed at " + std::to_string(rows) + " rows");
    std::vector<std::string> args = search_args(out, rows == 700 ? "2" : "1");
    if (rows != 2) args.push_back("--resume");
    const pid_t child = start(args);
    ASSERT_TRUE(wait_for_lines(child, out / "evaluations.csv", rows))
        << "the search ended before it could be killed";
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    ASSERT_EQ(::waitpid(child, nullptr, 0), child);
    // What is on disk is consistent: every finding in summary.json has its files, and every
    // evaluation it counts is in the journal.
    if (fs::exists(out / "summary.json")) {
      const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
      EXPECT_EQ(summary["complete"], false);
      EXPECT_LE(summary["evaluations"].get<std::size_t>() + 1, line_count(out / "evaluations.csv"));
      for (const auto& finding : summary["findings"])
        EXPECT_TRUE(fs::exists(finding["file"].get<std::string>())) << finding.dump();
    }
  }
  std::vector<std::string> args = search_args(out, "1");
  args.push_back("--resume");
  const Outcome resumed = scenfuzz(args);
  ASSERT_EQ(resumed.exit_code, 1) << resumed.err;
  EXPECT_FALSE(has_temporary_files(out));
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "summary.json"))["complete"], true);
  EXPECT_GT(nlohmann::json::parse(slurp(out / "summary.json"))["coverage"]["features"], 0);
  EXPECT_EQ(search_result(out), expected);
}

TEST_F(OutputJournalTest, AnEarlierSearchIsRefusedResumedOrReplaced) {
  const fs::path out = dir_ / "out";
  auto args = [&](std::vector<std::string> extra, const std::string& seed = "2",
                  const std::string& budget = "40") {
    std::vector<std::string> all = {"--budget", budget,  "--seed",     seed,
                                    "--quiet",  "--out", out.string(), "--all-collisions"};
    all.insert(all.end(), extra.begin(), extra.end());
    all.push_back(kCutIn);
    return all;
  };
  ASSERT_EQ(scenfuzz(args({})).exit_code, 1);
  const std::string first = search_result(out);

  Outcome run = scenfuzz(args({}));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("holds an earlier search"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--resume"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--force"), std::string::npos) << run.err;
  EXPECT_EQ(search_result(out), first);

  // Resuming a finished search changes nothing; resuming with another seed is refused.
  EXPECT_EQ(scenfuzz(args({"--resume"})).exit_code, 1);
  EXPECT_EQ(search_result(out), first);
  run = scenfuzz(args({"--resume"}, "3"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("its seed was 2, now 3"), std::string::npos) << run.err;

  // A search killed before its journal had a header resumes from nothing.
  fs::remove(out / "evaluations.csv");
  EXPECT_EQ(scenfuzz(args({"--resume"})).exit_code, 1);
  EXPECT_EQ(search_result(out), first);

  // --force replaces it: no finding of the first search is left beside the new ones.
  run = scenfuzz(args({"--force"}, "3", "10"));
  EXPECT_NE(run.exit_code, 2) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["seed"], 3);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(out / "findings")) ++files;
  EXPECT_EQ(files, 3 * summary["findings"].size());
}

TEST_F(OutputJournalTest, TwoSearchesNeverShareAFolderAndSigtermStopsCleanly) {
  const fs::path out = dir_ / "out";
  const pid_t first =
      start({"--budget", "10000000", "--algo", "random", "--out", out.string(), "--quiet", kCutIn});
  ASSERT_TRUE(wait_for_lines(first, out / "evaluations.csv", 20));

  const Outcome second = scenfuzz({"--budget", "10", "--out", out.string(), "--resume", kCutIn});
  EXPECT_EQ(second.exit_code, 2);
  EXPECT_NE(second.err.find("in use by another search (process " + std::to_string(first)),
            std::string::npos)
      << second.err;

  ASSERT_EQ(::kill(first, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(first, &status, 0), first);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by SIGTERM instead of stopping";
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["complete"], true);
  EXPECT_EQ(summary["stop"], "interrupted");
  EXPECT_GT(summary["wall_seconds"].get<double>(), 0);
  EXPECT_EQ(WEXITSTATUS(status), summary["findings"].empty() ? 0 : 1);
  EXPECT_EQ(line_count(out / "evaluations.csv"), 1 + summary["evaluations"].get<std::size_t>());
}

// The checks after a write failed: exit 2 naming the file, a consistent folder, and a resume
// (with room again) that ends as the uninterrupted search does.
void expect_stopped_consistently(const Outcome& run, const fs::path& out, const std::string& why) {
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("cannot write '" + out.string()), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(why), std::string::npos) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["stop"], "error");
  EXPECT_NE(summary["error"].get<std::string>().find(why), std::string::npos);
  for (const auto& finding : summary["findings"])
    EXPECT_TRUE(fs::exists(finding["file"].get<std::string>())) << finding.dump();
  EXPECT_LE(summary["evaluations"].get<std::size_t>() + 1, line_count(out / "evaluations.csv"));
}

TEST_F(OutputJournalTest, AFileSizeLimitStopsTheSearchWithTheFileNamed) {
  const fs::path out = dir_ / "out";
  const fs::path reference = dir_ / "reference";
  ASSERT_EQ(scenfuzz(search_args(reference, "2")).exit_code, 1);
  // Files may not grow past 40 KB: a finding's trace or the journal hits it soon.
  const std::string log = (dir_ / "limited.txt").string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::freopen(log.c_str(), "w", stderr);
    std::signal(SIGXFSZ, SIG_IGN);  // write() then fails with EFBIG instead of killing
    const rlimit limit = {40000, 40000};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::vector<std::string> args = search_args(out, "2");
    std::vector<char*> argv = {const_cast<char*>(SCENFUZZ_EXECUTABLE)};
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    ::execv(SCENFUZZ_EXECUTABLE, argv.data());
    std::_Exit(127);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  Outcome limited;
  limited.exit_code = WEXITSTATUS(status);
  limited.err = slurp(log);
  expect_stopped_consistently(limited, out, "File too large");

  std::vector<std::string> args = search_args(out, "1");
  args.push_back("--resume");
  ASSERT_EQ(scenfuzz(args).exit_code, 1);
  EXPECT_EQ(search_result(out), search_result(reference));
}

TEST_F(OutputJournalTest, AFullDiskStopsTheSearchWithTheFileNamed) {
  const fs::path mount = dir_ / "small";
  fs::create_directories(mount);
  if (::geteuid() != 0 || ::mount("tmpfs", mount.c_str(), "tmpfs", 0, "size=192k") != 0)
    GTEST_SKIP() << "needs root to mount a small tmpfs (AFileSizeLimit... covers the same path)";
  const fs::path out = mount / "out";
  const Outcome run = scenfuzz(search_args(out, "2"));
  expect_stopped_consistently(run, out, "No space left on device");
  ::umount(mount.c_str());
}

TEST_F(OutputJournalTest, ASearchThatJudgedNothingExitsTwoWithTheReason) {
  const std::string unknown_lane =
      write("lane.avu",
            "ego = AV((\"no_such_lane\"->range(20, 60), , 10), (\"east_0\"->300));\n"
            "s = CreateScenario{load(\"straight\"); ego; {}; {}; {};};\n");
  Outcome run =
      scenfuzz({"--budget", "10", "--quiet", "--out", (dir_ / "a").string(), unknown_lane});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no evaluation could be judged"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("lane.avu:1:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("'no_such_lane'"), std::string::npos) << run.err;

  // WMG map ranges that the generator cannot build: every point is infeasible.
  std::string sdl = slurp(test::source_file("corpora/wmg/cut_in.sdl"));
  const std::string radius = "curvature radius of [S1: 1000 to 4000]";
  ASSERT_NE(sdl.find(radius), std::string::npos);
  sdl.replace(sdl.find(radius), radius.size(), "curvature radius of [S1: 1 to 5]");
  run = scenfuzz(
      {"--budget", "5", "--quiet", "--out", (dir_ / "c").string(), write("tight.sdl", sdl)});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no evaluation could be judged"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("is outside its range 20..10000 m"), std::string::npos) << run.err;

  run = scenfuzz({"--budget", "10", "--quiet", "--out", (dir_ / "b").string(), "--ego-plugin",
                  (dir_ / "no_such_plugin.so").string(), kCutIn});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no evaluation could be judged: 10 proposed, 0 infeasible, 10 failed"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("no_such_plugin.so"), std::string::npos) << run.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / "b" / "summary.json"))["complete"], true);
}

}  // namespace
}  // namespace scenfuzz
