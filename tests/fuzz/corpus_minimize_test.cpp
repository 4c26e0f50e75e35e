// `scenfuzz cmin` without cover_seed: the greedy set cover and its tie-breaks, then
// minimize_corpus on corpora whose coverage is planted in the seed files themselves (a line
// "features a b c", optionally "steps N" or "error WHY"), so that what must be kept is known:
// planted duplicates dropped, the same output for any -j, a control file cut short by a kill (and
// real kills of a child process) resumed to the output of an uninterrupted run, errors listed
// without stopping the run, an edited seed covered again.
#include "fuzz/corpus_minimize.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/cmin_control_file.hpp"
#include "fuzz/cmin_table.hpp"
#include "fuzz/folder_lock.hpp"
#include "fuzz/set_cover.hpp"
#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

SeedCoverage planted(const std::string& path, std::vector<std::string> features,
                     std::uintmax_t size = 100, std::uint64_t steps = 10) {
  SeedCoverage coverage;
  coverage.path = path;
  coverage.features = std::move(features);
  coverage.file_size = size;
  coverage.simulated_steps = steps;
  return coverage;
}

std::vector<std::string> kept_paths(const SetCover& cover, const std::vector<SeedCoverage>& seeds) {
  std::vector<std::string> paths;
  for (std::size_t k : cover.kept) paths.push_back(seeds[k].path);
  return paths;
}

using Paths = std::vector<std::string>;

TEST(GreedySetCover, TheSeedWithTheMostNewFeaturesFirstThenWhatStillAddsSome) {
  const std::vector<SeedCoverage> seeds = {planted("a", {"f1", "f2"}),
                                           planted("b", {"f1", "f2", "f3"}),
                                           planted("c", {"f3", "f4"}), planted("d", {"f2"})};
  const SetCover cover = greedy_set_cover(seeds);
  EXPECT_EQ(kept_paths(cover, seeds), (Paths{"b", "c"}));
  EXPECT_EQ(cover.features, 4u);
  EXPECT_EQ(cover.new_features[1], (Paths{"f1", "f2", "f3"}));
  EXPECT_EQ(cover.new_features[2], (Paths{"f4"}));
  EXPECT_TRUE(cover.new_features[0].empty());
  // Dropped: who covers their features.
  EXPECT_EQ(cover.covered_by[0], (std::vector<std::size_t>{1}));
  EXPECT_EQ(cover.covered_by[3], (std::vector<std::size_t>{1}));
}

TEST(GreedySetCover, AFeatureOnlyOneSeedHasKeepsThatSeed) {
  // Greedy takes the big one first, then needs both small ones for their own features.
  const std::vector<SeedCoverage> seeds = {planted("big", {"1", "2", "3", "4"}),
                                           planted("left", {"1", "2", "5"}),
                                           planted("right", {"3", "4", "6"})};
  const SetCover cover = greedy_set_cover(seeds);
  EXPECT_EQ(kept_paths(cover, seeds), (Paths{"big", "left", "right"}));
  EXPECT_EQ(cover.new_features[1], (Paths{"5"}));
}

TEST(GreedySetCover, TiesGoToTheSmallerFileThenTheCheaperSeedThenThePath) {
  {
    const std::vector<SeedCoverage> seeds = {planted("a", {"x"}, 200, 1),
                                             planted("b", {"x"}, 100, 99)};
    EXPECT_EQ(kept_paths(greedy_set_cover(seeds), seeds), (Paths{"b"}));
  }
  {
    const std::vector<SeedCoverage> seeds = {planted("a", {"x"}, 100, 50),
                                             planted("b", {"x"}, 100, 20)};
    EXPECT_EQ(kept_paths(greedy_set_cover(seeds), seeds), (Paths{"b"}));
  }
  {
    const std::vector<SeedCoverage> seeds = {planted("b", {"x"}), planted("a", {"x"})};
    EXPECT_EQ(kept_paths(greedy_set_cover(seeds), seeds), (Paths{"a"}));
  }
  {
    // More new features beat a smaller file.
    const std::vector<SeedCoverage> seeds = {planted("small", {"x"}, 10),
                                             planted("large", {"x", "y"}, 1000)};
    EXPECT_EQ(kept_paths(greedy_set_cover(seeds), seeds), (Paths{"large"}));
  }
}

TEST(GreedySetCover, SeedsWithErrorsOrNoFeaturesAreNotKept) {
  std::vector<SeedCoverage> seeds = {planted("bad", {"x", "y"}), planted("empty", {}),
                                     planted("good", {"x"})};
  seeds[0].error = "bad:1:1: error: expected a scenario";
  const SetCover cover = greedy_set_cover(seeds);
  EXPECT_EQ(kept_paths(cover, seeds), (Paths{"good"}));
  EXPECT_EQ(cover.features, 1u);
  EXPECT_TRUE(cover.covered_by[1].empty());
}

// Coverage planted in the seed file: "features a b c", "steps N", "error WHY" lines. It counts
// its calls, by path, and can be made slow.
class PlantedCover {
 public:
  explicit PlantedCover(std::chrono::milliseconds delay = std::chrono::milliseconds(0))
      : delay_(delay) {}

  SeedCoverage operator()(const std::string& path) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++calls_[path];
    }
    if (delay_.count() > 0) std::this_thread::sleep_for(delay_);
    SeedCoverage coverage;
    coverage.path = path;
    coverage.simulations = 1;
    std::istringstream text(slurp(path));
    for (std::string line; std::getline(text, line);) {
      std::istringstream words(line);
      std::string key;
      words >> key;
      if (key == "features")
        for (std::string feature; words >> feature;) coverage.features.push_back(feature);
      if (key == "steps") words >> coverage.simulated_steps;
      if (key == "error") coverage.error = path + ":1:1: error:" + line.substr(5);
    }
    std::sort(coverage.features.begin(), coverage.features.end());
    return coverage;
  }

  CoverFunction function() {
    return [this](const std::string& path) { return (*this)(path); };
  }

  std::size_t calls() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t total = 0;
    for (const auto& [path, count] : calls_) total += count;
    return total;
  }

  std::map<std::string, int> calls_by_path() {
    std::lock_guard<std::mutex> lock(mutex_);
    return calls_;
  }

 private:
  std::chrono::milliseconds delay_;
  std::mutex mutex_;
  std::map<std::string, int> calls_;
};

class CorpusMinimizeTest : public CommandTest {
 protected:
  std::string seed(const std::string& name, const std::string& text) {
    fs::create_directories((dir_ / name).parent_path());
    return write(name, text);
  }

  // Five originals, each with a feature of its own, and planted duplicates: exact copies (in
  // zz-copies/, whose paths sort later), a larger copy with the same features, and seeds whose
  // features the originals already have; one seed without features.
  void planted_corpus() {
    seed("corpus/a.avu", "features common a\n");
    seed("corpus/b.avu", "features common b\nsteps 5\n");
    seed("corpus/c.scenest", "features c\n");
    seed("corpus/sub/d.avu", "features d common\n");
    seed("corpus/sub/e.sdl", "features e a\n");
    seed("corpus/zz-copies/a.avu", "features common a\n");
    seed("corpus/zz-copies/d.avu", "features d common\n");
    seed("corpus/larger-b.avu", "features common b\nsteps 5\n# the same, only longer\n");
    seed("corpus/subset.avu", "features a\n");
    seed("corpus/union.avu", "features a c e\n");
    seed("corpus/empty.avu", "# nothing happens\n");
    seed("corpus/notes.txt", "not a scenario: never looked at\n");
  }

  CminOptions options(const std::string& out, std::size_t jobs = 1) {
    CminOptions cmin;
    cmin.inputs = {(dir_ / "corpus").string()};
    cmin.out_dir = (dir_ / out).string();
    cmin.jobs = jobs;
    cmin.identity = "planted 1";
    return cmin;
  }

  nlohmann::json table(const std::string& out) {
    return nlohmann::json::parse(slurp(dir_ / out / kCminTableFileName));
  }

  // Every file in `out` but the lock (which names the process holding it) with its bytes; paths
  // into the test folder made relative, so that two output folders compare.
  std::string dump(const std::string& out) {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir_ / out))
      if (entry.is_regular_file() && entry.path().filename() != "cmin.lock")
        files.push_back(entry.path().lexically_relative(dir_ / out).generic_string());
    std::sort(files.begin(), files.end());
    std::string text;
    for (const std::string& file : files) text += "== " + file + "\n" + slurp(dir_ / out / file);
    const std::string folder = dir_.string();
    for (std::size_t at; (at = text.find(folder)) != std::string::npos;)
      text.replace(at, folder.size(), "DIR");
    return text;
  }

  std::string corpus(const std::string& name) { return (dir_ / "corpus" / name).string(); }
};

TEST_F(CorpusMinimizeTest, PlantedDuplicatesAreDroppedAndExactlyTheOriginalsKept) {
  planted_corpus();
  PlantedCover cover;
  const CminResult result = minimize_corpus(options("out"), cover.function());
  ASSERT_EQ(result.problem, CminProblem::none) << result.message;
  std::vector<std::string> kept;
  for (std::size_t k : result.kept) kept.push_back(result.seeds[k].output);
  std::sort(kept.begin(), kept.end());
  // union.avu (a c e) is taken first, the three seeds it makes redundant never are.
  EXPECT_EQ(kept, (Paths{"b.avu", "sub/d.avu", "union.avu"}));
  EXPECT_EQ(result.features, 6u);
  EXPECT_EQ(result.seeds.size(), 11u);
  EXPECT_EQ(cover.calls(), 11u);
  // The kept files are copied byte for byte; nothing else is.
  EXPECT_EQ(slurp(dir_ / "out/sub/d.avu"), slurp(corpus("sub/d.avu")));
  EXPECT_EQ(slurp(dir_ / "out/union.avu"), slurp(corpus("union.avu")));
  EXPECT_FALSE(fs::exists(dir_ / "out/a.avu"));
  EXPECT_FALSE(fs::exists(dir_ / "out/zz-copies"));

  const nlohmann::json json = table("out");
  EXPECT_EQ(json["kept"].size(), 3u);
  EXPECT_EQ(json["kept"][0]["path"], corpus("union.avu"));
  EXPECT_EQ(json["kept"][0]["new_features"], (Paths{"a", "c", "e"}));
  std::map<std::string, std::string> reasons;
  for (const auto& dropped : json["dropped"]) reasons[dropped["path"]] = dropped["reason"];
  EXPECT_EQ(reasons.size(), 8u);
  EXPECT_EQ(reasons[corpus("zz-copies/a.avu")],
            "covered by " + corpus("union.avu") + ", " + corpus("sub/d.avu"));
  // Its "common" was first covered by sub/d.avu, chosen before b.avu.
  EXPECT_EQ(reasons[corpus("larger-b.avu")],
            "covered by " + corpus("sub/d.avu") + ", " + corpus("b.avu"));
  EXPECT_EQ(reasons[corpus("empty.avu")], "no features");
  EXPECT_TRUE(json["errors"].empty());
}

TEST_F(CorpusMinimizeTest, TheOutputIsTheSameForAnyNumberOfJobs) {
  planted_corpus();
  for (int i = 0; i < 30; ++i)
    seed("corpus/many/" + std::to_string(i) + ".avu",
         "features m" + std::to_string(i % 7) + " common\nsteps " + std::to_string(i % 3) + "\n");
  PlantedCover cover;
  ASSERT_EQ(minimize_corpus(options("one", 1), cover.function()).problem, CminProblem::none);
  ASSERT_EQ(minimize_corpus(options("four", 4), cover.function()).problem, CminProblem::none);
  ASSERT_EQ(minimize_corpus(options("cores", 0), cover.function()).problem, CminProblem::none);
  const std::string one = dump("one");
  EXPECT_NE(one.find("== many/"), std::string::npos);
  EXPECT_EQ(dump("four"), one);
  EXPECT_EQ(dump("cores"), one);
}

TEST_F(CorpusMinimizeTest, KeptFilesKeepTheirPlaceUnderTheirInputAndCollisionsAreRenamed) {
  seed("one/x.avu", "features p\n");
  seed("one/deep/y.avu", "features q\n");
  seed("two/x.avu", "features r\n");
  const std::string single = seed("single/y.avu", "features s\n");
  seed("three/deep/y.avu", "features t\n");
  CminOptions cmin = options("out");
  cmin.inputs = {(dir_ / "one").string(), (dir_ / "two").string() + "/", single,
                 (dir_ / "three").string()};
  PlantedCover cover;
  const CminResult result = minimize_corpus(cmin, cover.function());
  ASSERT_EQ(result.problem, CminProblem::none) << result.message;
  std::map<std::string, std::string> outputs;
  for (const CminSeed& seed : result.seeds) outputs[seed.path] = seed.output;
  EXPECT_EQ(outputs[(dir_ / "one/x.avu").string()], "x.avu");
  EXPECT_EQ(outputs[(dir_ / "one/deep/y.avu").string()], "deep/y.avu");
  EXPECT_EQ(outputs[(dir_ / "two/x.avu").string()], "x-2.avu");
  EXPECT_EQ(outputs[single], "y.avu");
  EXPECT_EQ(outputs[(dir_ / "three/deep/y.avu").string()], "deep/y-2.avu");
  EXPECT_EQ(slurp(dir_ / "out/x-2.avu"), "features r\n");
  EXPECT_EQ(slurp(dir_ / "out/deep/y-2.avu"), "features t\n");
}

TEST_F(CorpusMinimizeTest, SeedsWithErrorsAreListedAndTheRunGoesOn) {
  planted_corpus();
  seed("corpus/broken.avu", "features z\nerror expected a scenario\n");
  seed("corpus/zz-broken.avu", "error nothing to cover\n");
  CminOptions cmin = options("out");
  cmin.inputs.push_back((dir_ / "missing").string());
  cmin.inputs.push_back((dir_ / "corpus/notes.txt").string());
  PlantedCover cover;
  const CminResult result = minimize_corpus(cmin, cover.function());
  ASSERT_EQ(result.problem, CminProblem::none) << result.message;
  EXPECT_EQ(result.kept.size(), 3u);  // z of the broken seed counts for nothing
  EXPECT_EQ(result.features, 6u);
  const nlohmann::json json = table("out");
  std::map<std::string, std::string> errors;
  for (const auto& error : json["errors"]) errors[error["path"]] = error["error"];
  EXPECT_EQ(errors.size(), 4u);
  EXPECT_EQ(errors[corpus("broken.avu")],
            corpus("broken.avu") + ":1:1: error: expected a scenario");
  EXPECT_EQ(errors[(dir_ / "missing").string()],
            "'" + (dir_ / "missing").string() + "' does not exist");
  EXPECT_NE(errors[corpus("notes.txt")].find("is not a scenario file"), std::string::npos);

  std::ostringstream out, err;
  print_cmin_report(result, cmin.out_dir, out, err);
  EXPECT_EQ(cmin_exit_status(result), kExitSuccess);
  EXPECT_NE(err.str().find("warning: " + corpus("broken.avu") + " is left out: " +
                           corpus("broken.avu") + ":1:1: error: expected a scenario"),
            std::string::npos)
      << err.str();
  EXPECT_NE(out.str().find("error    " + corpus("zz-broken.avu")), std::string::npos);
  EXPECT_NE(out.str().find("dropped  " + corpus("empty.avu") + ": no features"), std::string::npos);
  EXPECT_NE(out.str().find("cmin: kept 3 of 15 seeds (8 dropped, 4 with errors), covering 6"),
            std::string::npos)
      << out.str();
}

TEST_F(CorpusMinimizeTest, WhenNoSeedCanBeCoveredTheStatusIsTwo) {
  seed("corpus/a.avu", "error no scenario\n");
  PlantedCover cover;
  const CminResult result = minimize_corpus(options("out"), cover.function());
  EXPECT_EQ(result.problem, CminProblem::nothing_covered);
  EXPECT_EQ(cmin_exit_status(result), kExitBadInput);
  std::ostringstream out, err;
  print_cmin_report(result, options("out").out_dir, out, err);
  EXPECT_NE(err.str().find("error: no seed could be covered"), std::string::npos) << err.str();
}

TEST_F(CorpusMinimizeTest, AnOutputFolderThatIsNotCminsOrOverlapsAnInputIsRefused) {
  planted_corpus();
  seed("taken/mine.txt", "the user's own file\n");
  PlantedCover cover;
  CminResult result = minimize_corpus(options("taken"), cover.function());
  EXPECT_EQ(result.problem, CminProblem::output_folder);
  EXPECT_NE(result.message.find("is not empty and was not made by cmin"), std::string::npos);
  EXPECT_EQ(cmin_exit_status(result), kExitBadInput);
  EXPECT_EQ(cover.calls(), 0u);

  result = minimize_corpus(options("corpus/min"), cover.function());
  EXPECT_EQ(result.problem, CminProblem::output_folder);
  EXPECT_NE(result.message.find("is inside the input"), std::string::npos) << result.message;
  EXPECT_FALSE(fs::exists(dir_ / "corpus/min"));

  CminOptions around = options("corpus/..");
  around.out_dir = dir_.string();
  result = minimize_corpus(around, cover.function());
  EXPECT_EQ(result.problem, CminProblem::output_folder);

  seed("file-out", "");
  result = minimize_corpus(options("file-out"), cover.function());
  EXPECT_EQ(result.problem, CminProblem::output_folder);
  EXPECT_NE(result.message.find("is not a folder"), std::string::npos) << result.message;
  std::ostringstream out, err;
  print_cmin_report(result, "file-out", out, err);
  EXPECT_NE(err.str().find("scenfuzz: error: the output folder"), std::string::npos);
}

TEST_F(CorpusMinimizeTest, AnOutputFolderInUseByAnotherRunIsRefused) {
  planted_corpus();
  FolderLock other;
  FolderLockRefusal refusal;
  ASSERT_TRUE(other.acquire(dir_ / "out", "cmin.lock", refusal)) << refusal.error;
  PlantedCover cover;
  const CminResult result = minimize_corpus(options("out"), cover.function());
  EXPECT_EQ(result.problem, CminProblem::output_folder);
  EXPECT_NE(result.message.find("is in use by another run (process " + std::to_string(::getpid())),
            std::string::npos)
      << result.message;
  EXPECT_EQ(cover.calls(), 0u);
}

// The control file of a run killed after `lines` records: the records in the order a parallel
// run wrote them and half of the next line, and nothing else in the output folder.
void cut_short(const fs::path& out, std::size_t lines) {
  const std::string whole = slurp(out / kCminControlFileName);
  std::vector<std::string> records;
  std::istringstream in(whole);
  std::string header;
  std::getline(in, header);
  for (std::string line; std::getline(in, line);) records.push_back(line);
  std::reverse(records.begin(), records.end());
  std::string text = header + "\n";
  for (std::size_t i = 0; i < lines; ++i) text += records[i] + "\n";
  text += records[lines].substr(0, records[lines].size() / 2);
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / kCminControlFileName, std::ios::binary) << text;
}

TEST_F(CorpusMinimizeTest, AControlFileCutShortByAKillIsResumedToTheSameOutput) {
  planted_corpus();
  PlantedCover whole_cover;
  ASSERT_EQ(minimize_corpus(options("whole"), whole_cover.function()).problem, CminProblem::none);
  const std::string expected = dump("whole");
  EXPECT_NE(expected.find("== cmin.control\n"), std::string::npos);

  for (std::size_t lines : {0u, 1u, 4u, 10u}) {
    fs::copy(dir_ / "whole", dir_ / "killed", fs::copy_options::recursive);
    cut_short(dir_ / "killed", lines);
    PlantedCover cover;
    const CminResult result = minimize_corpus(options("killed", 2), cover.function());
    ASSERT_EQ(result.problem, CminProblem::none) << result.message;
    EXPECT_EQ(cover.calls(), 11 - lines) << lines;
    EXPECT_EQ(result.covered_now, 11 - lines);
    EXPECT_EQ(dump("killed"), expected) << lines;
    fs::remove_all(dir_ / "killed");
  }
}

TEST_F(CorpusMinimizeTest, AStopRequestFinishesTheSeedsInFlightAndTheNextRunContinues) {
  planted_corpus();
  PlantedCover whole_cover;
  ASSERT_EQ(minimize_corpus(options("whole"), whole_cover.function()).problem, CminProblem::none);

  PlantedCover cover;
  const CminResult stopped =
      minimize_corpus(options("out", 2), cover.function(), [&cover] { return cover.calls() >= 4; });
  EXPECT_EQ(stopped.problem, CminProblem::interrupted);
  EXPECT_EQ(cmin_exit_status(stopped), kExitBadInput);
  EXPECT_FALSE(fs::exists(dir_ / "out" / kCminTableFileName));
  const std::size_t first = cover.calls();
  EXPECT_GE(first, 4u);
  EXPECT_LT(first, 11u);
  std::ostringstream out, err;
  print_cmin_report(stopped, "out", out, err);
  EXPECT_NE(err.str().find("run the same command again to continue"), std::string::npos);

  const CminResult resumed = minimize_corpus(options("out", 2), cover.function());
  ASSERT_EQ(resumed.problem, CminProblem::none) << resumed.message;
  EXPECT_EQ(cover.calls(), 11u);  // every seed covered once over the two runs
  EXPECT_EQ(dump("out"), dump("whole"));
}

TEST_F(CorpusMinimizeTest, AnEditedSeedIsCoveredAgainAndOnlyIt) {
  planted_corpus();
  {
    PlantedCover cover;
    ASSERT_EQ(minimize_corpus(options("out"), cover.function()).problem, CminProblem::none);
  }
  // subset.avu now covers a feature of its own: it is kept, with its new bytes.
  seed("corpus/subset.avu", "features a novel\n");
  PlantedCover cover;
  const CminResult result = minimize_corpus(options("out"), cover.function());
  ASSERT_EQ(result.problem, CminProblem::none) << result.message;
  EXPECT_EQ(cover.calls_by_path(), (std::map<std::string, int>{{corpus("subset.avu"), 1}}));
  std::ostringstream out, err;
  print_cmin_report(result, "out", out, err);
  EXPECT_NE(out.str().find("kept 4 of 11 seeds (7 dropped, 0 with errors), covering 7 features, "
                           "in 'out' (the table: cmin.json); 10 seeds' coverage read from "
                           "cmin.control"),
            std::string::npos)
      << out.str();
  EXPECT_EQ(slurp(dir_ / "out/subset.avu"), "features a novel\n");
  // The same as a run from scratch on the edited corpus.
  PlantedCover fresh;
  ASSERT_EQ(minimize_corpus(options("fresh"), fresh.function()).problem, CminProblem::none);
  EXPECT_EQ(dump("out"), dump("fresh"));
}

TEST_F(CorpusMinimizeTest, ACopyTheNewResultNoLongerKeepsIsRemoved) {
  planted_corpus();
  PlantedCover cover;
  ASSERT_EQ(minimize_corpus(options("out"), cover.function()).problem, CminProblem::none);
  ASSERT_TRUE(fs::exists(dir_ / "out/union.avu"));
  fs::remove(dir_ / "corpus/union.avu");
  ASSERT_EQ(minimize_corpus(options("out"), cover.function()).problem, CminProblem::none);
  EXPECT_FALSE(fs::exists(dir_ / "out/union.avu"));
  PlantedCover fresh;
  ASSERT_EQ(minimize_corpus(options("fresh"), fresh.function()).problem, CminProblem::none);
  EXPECT_EQ(dump("out"), dump("fresh"));
}

TEST_F(CorpusMinimizeTest, RecordsMadeWithOtherCoverageOptionsAreNotReused) {
  planted_corpus();
  PlantedCover cover;
  ASSERT_EQ(minimize_corpus(options("out"), cover.function()).problem, CminProblem::none);
  CminOptions other = options("out");
  other.identity = "planted 2";
  const CminResult result = minimize_corpus(other, cover.function());
  ASSERT_EQ(result.problem, CminProblem::none) << result.message;
  EXPECT_EQ(cover.calls(), 22u);
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_NE(result.notes[0].find("other coverage options"), std::string::npos);
}

TEST(CminControlFile, ARecordReadsBackAsWrittenAndBrokenLinesAreSkipped) {
  const fs::path path = fs::temp_directory_path() /
                        ("scenfuzz_cmin_control_" + std::to_string(::getpid()) + ".control");
  CminRecord record;
  record.hash = "0123456789abcdef";
  record.coverage = planted("dir/a b.avu", {"ego.turn_left", "x"}, 123, 456);
  record.coverage.simulations = 3;
  record.coverage.logical = true;
  CminRecord failed = record;
  failed.coverage.path = "bad.avu";
  failed.coverage.features.clear();
  failed.coverage.error = "bad.avu:2:3: error: expected ';'\n  x\n    ^\n";
  const std::string line = cmin_control_line(record);
  std::ofstream(path, std::ios::binary) << cmin_control_header("id") << line << "{\"path\": 1}\n"
                                        << cmin_control_line(failed) << line.substr(0, 20);
  const CminControlContents contents = read_cmin_control(path, "id");
  EXPECT_TRUE(contents.existed);
  EXPECT_FALSE(contents.other_identity);
  EXPECT_EQ(contents.unreadable_lines, 2u);
  ASSERT_EQ(contents.records.size(), 2u);
  const CminRecord& back = contents.records.at("dir/a b.avu");
  EXPECT_EQ(back.hash, record.hash);
  EXPECT_EQ(back.coverage.features, record.coverage.features);
  EXPECT_EQ(back.coverage.file_size, 123u);
  EXPECT_EQ(back.coverage.simulated_steps, 456u);
  EXPECT_EQ(back.coverage.simulations, 3u);
  EXPECT_TRUE(back.coverage.logical);
  EXPECT_EQ(contents.records.at("bad.avu").coverage.error, failed.coverage.error);
  EXPECT_TRUE(read_cmin_control(path, "other").other_identity);
  fs::remove(path);
  EXPECT_FALSE(read_cmin_control(path, "id").existed);
}

// Real kills: a child process runs minimize_corpus with a slow cover and is killed with SIGKILL
// once its control file holds a given number of records (or, for the last, after it has
// finished covering); a run in this process then completes the work. Each must end with the
// output of an uninterrupted run.
TEST_F(CorpusMinimizeTest, KilledWithSigkillAtSeveralPointsItEndsAsAnUninterruptedRun) {
  planted_corpus();
  for (int i = 0; i < 24; ++i)
    seed("corpus/many/" + std::to_string(i) + ".avu",
         "features m" + std::to_string(i % 9) + "\nsteps " + std::to_string(i % 4) + "\n");
  PlantedCover whole_cover;
  ASSERT_EQ(minimize_corpus(options("whole"), whole_cover.function()).problem, CminProblem::none);
  const std::string expected = dump("whole");
  const std::size_t seeds = 35;

  for (const std::size_t records : std::vector<std::size_t>{0, 3, 12, 30, seeds}) {
    const std::string out = "killed-" + std::to_string(records);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      PlantedCover slow(std::chrono::milliseconds(40));
      minimize_corpus(options(out, 2), slow.function());
      ::_exit(0);
    }
    // Waits (a minute at most) for the control file to hold `records` lines after its header.
    const fs::path control = dir_ / out / kCminControlFileName;
    const Clock::time_point start = Clock::now();
    int status = 0;
    bool ended = false;
    while (!ended && Clock::now() - start < std::chrono::seconds(60)) {
      const std::string text = fs::exists(control) ? slurp(control) : "";
      const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
      if (!text.empty() && lines >= records + 1) break;
      ended = ::waitpid(child, &status, WNOHANG) == child;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    // Before every seed is covered, the kill must find it still running.
    if (records < seeds) {
      EXPECT_FALSE(ended) << records;
    }
    if (!ended) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
    }
    PlantedCover cover;
    const CminResult result = minimize_corpus(options(out, 2), cover.function());
    ASSERT_EQ(result.problem, CminProblem::none) << result.message;
    EXPECT_LE(cover.calls(), seeds - records) << records;
    if (records < seeds) {
      EXPECT_GE(cover.calls(), 1u) << records;
    }
    EXPECT_EQ(dump(out), expected) << records;
  }
}

}  // namespace
}  // namespace scenfuzz::test
