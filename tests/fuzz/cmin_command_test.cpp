// `scenfuzz cmin` through the executable, with real behaviour coverage: planted duplicates of
// corpus files are dropped and exactly the originals kept; a second run into the same folder
// reuses every seed's coverage and ends with the same output.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using scenfuzz::test::Outcome;
using scenfuzz::test::slurp;
using CminCommandTest = scenfuzz::test::CommandTest;

// The scenario files directly in `folder`, by name.
std::set<std::string> scenario_files(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".avu") names.insert(entry.path().filename().string());
  return names;
}

TEST_F(CminCommandTest, PlantedDuplicatesAreDroppedAndTheOriginalsKept) {
  const fs::path source = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit";
  const fs::path corpus = dir_ / "corpus";
  fs::create_directories(corpus);
  // Three seeds with different behaviour, and copies that sort after them (a tie between equal
  // files goes to the first path).
  for (const char* name : {"cut_in_straight", "roundabout_entry", "jaywalker_night_rain"}) {
    fs::copy_file(source / (std::string(name) + ".avu"),
                  corpus / ("a_" + std::string(name) + ".avu"));
    fs::copy_file(source / (std::string(name) + ".avu"),
                  corpus / ("z_" + std::string(name) + ".avu"));
  }
  fs::copy_file(source / "cut_in_straight.avu", corpus / "zz_cut_in_straight_again.avu");
  const fs::path out = dir_ / "out";
  const Outcome run = scenfuzz({"cmin", corpus.string(), "-o", out.string(), "-j", "2"});
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(scenario_files(out),
            (std::set<std::string>{"a_cut_in_straight.avu", "a_jaywalker_night_rain.avu",
                                   "a_roundabout_entry.avu"}))
      << run.out;
  // Kept files are copied unchanged.
  EXPECT_EQ(slurp(out / "a_roundabout_entry.avu"), slurp(source / "roundabout_entry.avu"));
  const nlohmann::json table = nlohmann::json::parse(slurp(out / "cmin.json"));
  EXPECT_NE(table.dump().find("z_roundabout_entry.avu"), std::string::npos) << "dropped, listed";

  // Run again into the same folder: every seed's coverage comes from the control file, and the
  // output is the same.
  const std::string first_table = slurp(out / "cmin.json");
  const Outcome again = scenfuzz({"cmin", corpus.string(), "-o", out.string(), "-j", "1"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(slurp(out / "cmin.json"), first_table);
  EXPECT_EQ(scenario_files(out).size(), 3u);
}

TEST_F(CminCommandTest, BadOptionsAndFoldersAreExitTwo) {
  const std::string seed =
      (fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit" / "cut_in_straight.avu").string();
  EXPECT_EQ(scenfuzz({"cmin", seed}).exit_code, 2) << "-o is required";
  EXPECT_EQ(scenfuzz({"cmin", seed, "-o", (dir_ / "o").string(), "-j", "-1"}).exit_code, 2);
  const std::string file = write("not-a-folder", "x");
  const Outcome onto_file = scenfuzz({"cmin", seed, "-o", file});
  EXPECT_EQ(onto_file.exit_code, 2);
  EXPECT_NE(onto_file.err.find("not-a-folder"), std::string::npos) << onto_file.err;
}

}  // namespace
}  // namespace scenfuzz
