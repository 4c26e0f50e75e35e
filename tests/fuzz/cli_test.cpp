// End-to-end tests of the scenfuzz executable: exit codes and output of its subcommands, run as a
// user would run them, on scenario and map files written to a temporary folder (and the shared
// sample maps, when they are there).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "tests/support/apollo_text_maps.hpp"
#include "tests/support/shared_dir.hpp"

namespace {

namespace fs = std::filesystem;

// A small logical scenario: npc1 starts 20 m ahead of the ego at a speed in [5, 10] m/s.
constexpr const char* kValidScenario = R"(map_name = "san_francisco";
ego_init_state = ("lane_39"->10);
ego_target_state = ("lane_39"->100);
ego_vehicle = AV(ego_init_state, ego_target_state);
npc1_init_state = ("lane_39"->30, , range(5, 10));
npc1 = Vehicle(npc1_init_state);
time = 12:00;
weather = {rain: 0.5};
evn = Environment(time, weather);
scenario0 = CreateScenario{load(map_name);
    ego_vehicle;
    {npc1};
    {};
    {};
    evn;
};
Trace trace = EXE(scenario0);
trace |= G (dis(trace[ego], trace[truth][npc1]) >= 1.0);
)";
constexpr int kRangeLine = 5;

// The same scenario without a range: a concrete scenario.
std::string concrete_scenario() {
  std::string text = kValidScenario;
  text.replace(text.find("range(5, 10)"), 12, "7.5");
  return text;
}

// A syntax error on line 2: the lane position has no arc length.
constexpr const char* kBadScenario = R"(map_name = "san_francisco";
ego_init_state = ("lane_39"->);
)";

using scenfuzz::test::Outcome;
using scenfuzz::test::slurp;

using CliTest = scenfuzz::test::CommandTest;

TEST_F(CliTest, VersionPrintsNameAndVersion) {
  const Outcome run = scenfuzz({"--version"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "scenfuzz " SCENFUZZ_VERSION "\n");
  EXPECT_EQ(run.err, "");
}

TEST_F(CliTest, HelpListsTheSubcommands) {
  const Outcome run = scenfuzz({"--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("check"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("space"), std::string::npos) << run.out;
}

TEST_F(CliTest, EverySubcommandHasHelp) {
  const Outcome check = scenfuzz({"check", "--help"});
  EXPECT_EQ(check.exit_code, 0);
  EXPECT_NE(check.out.find("FILE"), std::string::npos) << check.out;
  const Outcome space = scenfuzz({"space", "--help"});
  EXPECT_EQ(space.exit_code, 0);
  EXPECT_NE(space.out.find("--json"), std::string::npos) << space.out;
}

TEST_F(CliTest, UsageErrorsExitWithTwo) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {}, {"frobnicate"}, {"check"}, {"space"}, {"space", "--bogus", "x.avu"}}) {
    const Outcome run = scenfuzz(args);
    EXPECT_EQ(run.exit_code, 2) << "args: " << ::testing::PrintToString(args);
    EXPECT_NE(run.err.find("scenfuzz: error:"), std::string::npos) << run.err;
  }
}

TEST_F(CliTest, CheckIsSilentOnAValidFile) {
  const std::string path = write("valid.avu", kValidScenario);
  const Outcome run = scenfuzz({"check", path});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "");
}

TEST_F(CliTest, CheckReportsErrorsWithFileLineAndColumn) {
  const std::string path = write("bad.avu", kBadScenario);
  const Outcome run = scenfuzz({"check", path});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_TRUE(std::regex_search(run.err, std::regex("bad\\.avu:2:[0-9]+: error: "))) << run.err;
  // The offending line is shown under the message.
  EXPECT_NE(run.err.find("ego_init_state = (\"lane_39\"->);"), std::string::npos) << run.err;
}

// CH-Scenario files are read and checked; the accident formalism is read and checked but not
// simulated yet: a clear error, never a file read as AVUnit.
TEST_F(CliTest, CheckReadsCHScenarioAndReportsItsMistakes) {
  const std::string good = write("good.chs",
                                 "import from MAP\n  length: 200\n  width: 20\n"
                                 "road r\n  left boundary: (0, 17) (200, 17)\n"
                                 "  centre line: (0, 10) (200, 10)\n"
                                 "  right boundary: (0, 3) (200, 3)\n"
                                 "Entity\n  DynamicEntity1\n    name: car\n    speed: 40\n");
  Outcome run = scenfuzz({"check", good});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::string no_ego = write("no_ego.chs", "map: san_francisco\ncloudiness: 0.5\n");
  run = scenfuzz({"check", no_ego});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no_ego.chs:1:1: error: the file has no dynamic entity that is a vehicle"),
            std::string::npos)
      << run.err;
  const std::string bad = write("bad.chs", "map: san_francisco\ncloudiness: 5\n");
  run = scenfuzz({"check", bad});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.chs:2:13: error: the cloudiness must be from 0 to 1"),
            std::string::npos)
      << run.err;
  // An accident description's mistakes are located; a good one checks clean.
  run = scenfuzz({"check", write("crash.acc", "STATIC [ ROAD [ KIND = crosroad; ] ]")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("crash.acc:1:24: error:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("crossroad"), std::string::npos) << run.err;
  run = scenfuzz(
      {"check", std::string(SCENFUZZ_SOURCE_DIR) + "/corpora/accident/carsim_crossroad_tree.acc"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

TEST_F(CliTest, CheckGoesOnAfterAFailingFile) {
  const std::string bad = write("bad.avu", kBadScenario);
  const std::string missing = (dir_ / "missing.avu").string();
  const std::string good = write("good.avu", kValidScenario);
  const Outcome run = scenfuzz({"check", bad, missing, good});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.avu:2:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("cannot read '" + missing + "'"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("good.avu"), std::string::npos) << "a clean file prints nothing";
}

TEST_F(CliTest, CheckReportsAnUnreadableFile) {
  const std::string missing = (dir_ / "missing.avu").string();
  const Outcome run = scenfuzz({"check", missing});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "scenfuzz: error: cannot read '" + missing + "': No such file or directory\n");

  const Outcome directory = scenfuzz({"check", dir_.string()});
  EXPECT_EQ(directory.exit_code, 2);
  EXPECT_EQ(directory.err,
            "scenfuzz: error: cannot read '" + dir_.string() + "': Is a directory\n");
}

TEST_F(CliTest, SpacePrintsATable) {
  const std::string path = write("valid.avu", kValidScenario);
  const Outcome run = scenfuzz({"space", path});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  std::istringstream lines(run.out);
  std::string header, row, extra;
  ASSERT_TRUE(std::getline(lines, header));
  ASSERT_TRUE(std::getline(lines, row));
  EXPECT_FALSE(std::getline(lines, extra)) << "one row per dimension";
  EXPECT_TRUE(std::regex_search(header, std::regex("^name +kind +lower +upper +unit +line$")))
      << header;
  EXPECT_TRUE(std::regex_search(
      row, std::regex("^npc1\\.init\\.speed +continuous +5 +10 +\\S+ +5:[0-9]+$")))
      << row;
  // Columns are aligned: each header word starts where its value does.
  EXPECT_EQ(header.find("kind"), row.find("continuous"));
  EXPECT_EQ(header.find("line"), row.rfind(' ') + 1);
}

TEST_F(CliTest, SpacePrintsJson) {
  const std::string path = write("valid.avu", kValidScenario);
  const Outcome run = scenfuzz({"space", path, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  EXPECT_EQ(document.at("file"), path);
  const nlohmann::json& dimensions = document.at("dimensions");
  ASSERT_TRUE(dimensions.is_array());
  ASSERT_EQ(dimensions.size(), 1u);
  const nlohmann::json& speed = dimensions[0];
  EXPECT_EQ(speed.at("name"), "npc1.init.speed");
  EXPECT_EQ(speed.at("kind"), "continuous");
  EXPECT_EQ(speed.at("lower"), 5.0);
  EXPECT_EQ(speed.at("upper"), 10.0);
  EXPECT_TRUE(speed.at("unit").is_string());
  EXPECT_FALSE(speed.contains("choices")) << "only discrete dimensions list choices";
  EXPECT_EQ(speed.at("line"), kRangeLine);
  const std::string range_line = "npc1_init_state = (\"lane_39\"->30, , range(5, 10));";
  EXPECT_EQ(speed.at("column"), range_line.find("range(") + 1) << "the range construct";
}

TEST_F(CliTest, SpaceOfAConcreteScenarioIsDerivedAroundItsValues) {
  const std::string path = write("concrete.avu", concrete_scenario());
  const Outcome table = scenfuzz({"space", path});
  EXPECT_EQ(table.exit_code, 0) << table.err;
  EXPECT_EQ(table.out.rfind("derived: ", 0), 0u) << table.out;
  EXPECT_NE(table.out.find("npc1.init.speed"), std::string::npos) << table.out;
  const Outcome json = scenfuzz({"space", "--json", "--mutate", "speed=2", path});
  EXPECT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json document = nlohmann::json::parse(json.out);
  EXPECT_EQ(document.at("derived"), true);
  const nlohmann::json* speed = nullptr;
  for (const nlohmann::json& dimension : document.at("dimensions"))
    if (dimension.at("name") == "npc1.init.speed") speed = &dimension;
  ASSERT_NE(speed, nullptr) << json.out;
  EXPECT_EQ(speed->at("value"), 7.5);
  EXPECT_EQ(speed->at("lower"), 5.5);
  EXPECT_EQ(speed->at("upper"), 9.5);
  // With every kind kept as written, nothing is left to search.
  std::vector<std::string> none = {"space"};
  for (const char* kind :
       {"position", "waypoint", "lateral", "heading", "speed", "weather", "time"})
    none.insert(none.end(), {"--mutate", std::string(kind) + "=0"});
  none.push_back(path);
  const Outcome kept = scenfuzz(none);
  EXPECT_EQ(kept.exit_code, 0) << kept.err;
  EXPECT_EQ(kept.out,
            "no parameters: the scenario is concrete and none of its values is mutated "
            "(--mutate)\n");
  const Outcome bad = scenfuzz({"space", "--mutate", "speed=fast", path});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--mutate speed=fast"), std::string::npos) << bad.err;
}

TEST_F(CliTest, SpaceOfABadFileReportsErrorsAndPrintsNoSpace) {
  const std::string path = write("bad.avu", kBadScenario);
  for (const bool json : {false, true}) {
    const Outcome run = json ? scenfuzz({"space", "--json", path}) : scenfuzz({"space", path});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find("bad.avu:2:"), std::string::npos) << run.err;
  }
  const Outcome missing = scenfuzz({"space", (dir_ / "missing.avu").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos) << missing.err;
}

// Real-world files written for other tools: whatever the front end makes of them, `check` ends
// with 0 or 2, never a crash.
TEST_F(CliTest, CheckNeverCrashesOnTheSharedExamples) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  std::vector<std::string> files;
  for (const char* folder : {"examples/avunit", "examples/scenest"}) {
    const fs::path dir = scenfuzz::test::shared_dir() / folder;
    if (!fs::is_directory(dir)) continue;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path().string());
  }
  ASSERT_FALSE(files.empty()) << "no examples under " << scenfuzz::test::shared_dir();
  for (const std::string& file : files) {
    const Outcome run = scenfuzz({"check", file});
    EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 2) << file << "\n" << run.err;
  }
}

// ---- scenfuzz map ----

const std::vector<std::string> kBuiltinMaps = {"straight",   "curve",      "t_junction",
                                               "crossroads", "roundabout", "merge"};

// The value of one line of the map summary ("lanes       32 (...)" -> "32 (...)"), or
// std::nullopt when the summary has no such line.
std::optional<std::string> summary_field(const std::string& summary, const std::string& key) {
  std::istringstream lines(summary);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with(key + " ")) continue;
    return line.substr(line.find_first_not_of(' ', key.size()));
  }
  return std::nullopt;
}

// Sets an environment variable for the scenfuzz runs of one test, and puts the old value back.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_value_ = old;
    ::setenv(name_, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (old_value_)
      ::setenv(name_, old_value_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_value_;
};

bool has_leftover_temporary_file(const fs::path& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".tmp.") != std::string::npos) return true;
  return false;
}

class CliMapTest : public CliTest {
 protected:
  std::string write_map(const std::string& folder, const std::string& text) {
    fs::create_directories(dir_ / folder);
    return write(folder + "/base_map.txt", text);
  }
};

TEST_F(CliMapTest, ListShowsEveryBuiltinMapWithItsParameters) {
  const Outcome run = scenfuzz({"map", "--list"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  // A map per unindented line, its parameters indented below it.
  std::vector<std::string> maps;
  std::vector<int> parameter_counts;
  std::istringstream lines(run.out);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("  ")) {
      maps.push_back(line.substr(0, line.find(':')));
      parameter_counts.push_back(0);
    } else {
      ASSERT_FALSE(maps.empty()) << "a parameter before any map: " << line;
      ++parameter_counts.back();
    }
  }
  EXPECT_EQ(maps, kBuiltinMaps);
  for (std::size_t i = 0; i < maps.size() && i < parameter_counts.size(); ++i)
    EXPECT_GT(parameter_counts[i], 0) << maps[i] << " lists no parameters";
  // Name, default, range, unit and what it does.
  EXPECT_NE(run.out.find("  lanes = 2 [1, 6]  lanes in each direction\n"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("  length = 500 [10, 10000] m  length of the road\n"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("  ring_radius = 20 [5, 100] m "), std::string::npos) << run.out;
}

TEST_F(CliMapTest, SummaryOfABuiltinMap) {
  const Outcome run = scenfuzz({"map", "crossroads"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_EQ(summary_field(run.out, "map"), "crossroads");
  EXPECT_EQ(summary_field(run.out, "source"), "built-in");
  // 16 arm lanes (4 arms, 2 lanes each way) and 16 junction connectors.
  const std::string lanes = summary_field(run.out, "lanes").value_or("");
  EXPECT_TRUE(lanes.starts_with("32 (")) << run.out;
  EXPECT_NE(lanes.find("16 in junctions"), std::string::npos) << run.out;
  EXPECT_EQ(summary_field(run.out, "junctions"), "1");
  EXPECT_EQ(summary_field(run.out, "signals"), "4");
  EXPECT_EQ(summary_field(run.out, "stop signs"), "0");
  EXPECT_EQ(summary_field(run.out, "yield signs"), "0");
  EXPECT_EQ(summary_field(run.out, "crosswalks"), "4");
  EXPECT_TRUE(summary_field(run.out, "bounds").has_value()) << run.out;

  const Outcome one_lane = scenfuzz({"map", "crossroads?lanes=1&crosswalks=0"});
  ASSERT_EQ(one_lane.exit_code, 0) << one_lane.err;
  EXPECT_TRUE(summary_field(one_lane.out, "lanes").value_or("").starts_with("20 ("))
      << one_lane.out;
  EXPECT_EQ(summary_field(one_lane.out, "crosswalks"), "0");
}

TEST_F(CliMapTest, SummaryOfAnApolloMap) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::string apollo = (scenfuzz::test::shared_dir() / "maps" / "apollo").string();
  // --map-path before the name as well as after it.
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"map", "san_francisco", "--map-path", apollo},
                                             {"map", "--map-path", apollo, "san_francisco"}}) {
    const Outcome run = scenfuzz(args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(summary_field(run.out, "map"), "san_francisco");
    EXPECT_EQ(summary_field(run.out, "source"), apollo + "/san_francisco/base_map.bin");
    EXPECT_TRUE(summary_field(run.out, "projection").value_or("").starts_with("+proj=utm"))
        << run.out;
    EXPECT_TRUE(summary_field(run.out, "lanes").value_or("").starts_with("1524 (")) << run.out;
    EXPECT_EQ(summary_field(run.out, "junctions"), "91");
    EXPECT_EQ(summary_field(run.out, "signals"), "201");
    EXPECT_EQ(summary_field(run.out, "stop signs"), "9");
    EXPECT_EQ(summary_field(run.out, "crosswalks"), "43");
  }
}

TEST_F(CliMapTest, JsonOfAnApolloMap) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::string apollo = (scenfuzz::test::shared_dir() / "maps" / "apollo").string();
  const Outcome run = scenfuzz({"map", "san_francisco", "--map-path", apollo, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  EXPECT_EQ(document.at("name"), "san_francisco");
  const nlohmann::json& counts = document.at("counts");
  EXPECT_EQ(counts.at("lanes"), 1524);
  EXPECT_EQ(counts.at("junctions"), 91);
  EXPECT_EQ(counts.at("signals"), 201);
  EXPECT_EQ(counts.at("stop_signs"), 9);
  EXPECT_EQ(counts.at("crosswalks"), 43);
  const nlohmann::json& lanes = document.at("lanes");
  ASSERT_TRUE(lanes.is_array());
  EXPECT_EQ(lanes.size(), 1524u);
  const auto lane_540 = std::find_if(lanes.begin(), lanes.end(), [](const nlohmann::json& lane) {
    return lane.at("id") == "lane_540";
  });
  ASSERT_NE(lane_540, lanes.end());
  EXPECT_GT(lane_540->at("length").get<double>(), 0);
  EXPECT_TRUE(lane_540->at("successors").is_array());
}

TEST_F(CliMapTest, JsonOfABuiltinMap) {
  const Outcome run = scenfuzz({"map", "--json", "crossroads"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  EXPECT_EQ(document.at("counts"), nlohmann::json({{"lanes", 32},
                                                   {"junctions", 1},
                                                   {"signals", 4},
                                                   {"stop_signs", 0},
                                                   {"yield_signs", 0},
                                                   {"crosswalks", 4}}));
  const nlohmann::json& lanes = document.at("lanes");
  ASSERT_EQ(lanes.size(), 32u);
  const auto in_junction =
      std::count_if(lanes.begin(), lanes.end(),
                    [](const nlohmann::json& lane) { return !lane.at("junction").is_null(); });
  EXPECT_EQ(in_junction, 16);
  EXPECT_NE(std::find_if(lanes.begin(), lanes.end(),
                         [](const nlohmann::json& lane) { return lane.at("id") == "north_in_0"; }),
            lanes.end());
}

TEST_F(CliMapTest, SvgDrawing) {
  const fs::path plain = dir_ / "plain.svg", labelled = dir_ / "labelled.svg";
  const Outcome run = scenfuzz({"map", "crossroads", "--svg", plain.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(summary_field(run.out, "map"), "crossroads") << "the summary is printed as well";
  const std::string svg = slurp(plain);
  EXPECT_TRUE(svg.starts_with("<?xml") || svg.starts_with("<svg")) << svg.substr(0, 100);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  EXPECT_EQ(svg.find("north_in_0"), std::string::npos) << "lane ids only with --labels";

  const Outcome with_labels =
      scenfuzz({"map", "crossroads", "--svg", labelled.string(), "--labels"});
  ASSERT_EQ(with_labels.exit_code, 0) << with_labels.err;
  const std::string labelled_svg = slurp(labelled);
  EXPECT_TRUE(labelled_svg.ends_with("</svg>\n"));
  EXPECT_NE(labelled_svg.find(">north_in_0<"), std::string::npos);
  EXPECT_FALSE(has_leftover_temporary_file(dir_));
}

TEST_F(CliMapTest, SvgThatCannotBeWritten) {
  const fs::path missing_folder = dir_ / "missing";
  const std::string into_missing = (missing_folder / "out.svg").string();
  const Outcome run = scenfuzz({"map", "crossroads", "--svg", into_missing});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("cannot write '" + into_missing + "'"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(missing_folder));

  // A folder where the drawing should go: the temporary file written beside it is removed.
  const fs::path folder = dir_ / "drawing.svg";
  fs::create_directories(folder);
  const Outcome onto_folder = scenfuzz({"map", "crossroads", "--svg", folder.string()});
  EXPECT_EQ(onto_folder.exit_code, 2);
  EXPECT_NE(onto_folder.err.find(folder.string()), std::string::npos) << onto_folder.err;
  EXPECT_TRUE(fs::is_empty(folder));
  EXPECT_FALSE(has_leftover_temporary_file(dir_));
}

TEST_F(CliMapTest, UnknownMapName) {
  const Outcome run = scenfuzz({"map", "atlantis", "--map-path", dir_.string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("'atlantis' not found"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(dir_.string()), std::string::npos) << "the searched folders";
  EXPECT_NE(run.err.find("crossroads"), std::string::npos) << "the built-in maps";

  // --svg draws nothing for a map that is not there.
  const Outcome with_svg = scenfuzz({"map", "atlantis", "--svg", (dir_ / "a.svg").string()});
  EXPECT_EQ(with_svg.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "a.svg"));
}

TEST_F(CliMapTest, BadParametersExitWithTwo) {
  const Outcome out_of_range = scenfuzz({"map", "straight?lanes=9"});
  EXPECT_EQ(out_of_range.exit_code, 2);
  EXPECT_NE(out_of_range.err.find("parameter 'lanes'"), std::string::npos) << out_of_range.err;

  const Outcome not_a_number = scenfuzz({"map", "straight?lanes=abc"});
  EXPECT_EQ(not_a_number.exit_code, 2);
  EXPECT_NE(not_a_number.err.find("'abc'"), std::string::npos) << not_a_number.err;

  write_map("town", scenfuzz::test::one_lane_map("lane_1"));
  const Outcome apollo = scenfuzz({"map", "town?lanes=2", "--map-path", dir_.string()});
  EXPECT_EQ(apollo.exit_code, 2);
  EXPECT_NE(apollo.err.find("only built-in maps take parameters"), std::string::npos) << apollo.err;
}

TEST_F(CliMapTest, MalformedMapFileNamesFileAndLine) {
  const std::string file = write_map("broken", scenfuzz::test::kBrokenMap);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"map", file}, {"map", "broken", "--map-path", dir_.string()}}) {
    const Outcome run = scenfuzz(args);
    EXPECT_EQ(run.exit_code, 2) << ::testing::PrintToString(args);
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find(file + ":5:"), std::string::npos) << run.err;
  }
}

TEST_F(CliMapTest, MapPathOrderAndEnvironment) {
  write_map("first/town", scenfuzz::test::one_lane_map("lane_first"));
  write_map("second/town", scenfuzz::test::one_lane_map("lane_second"));
  write_map("second/hamlet", scenfuzz::test::one_lane_map("lane_hamlet"));
  const std::string first = (dir_ / "first").string(), second = (dir_ / "second").string();

  const Outcome first_wins =
      scenfuzz({"map", "town", "--map-path", first, "--map-path", second, "--json"});
  ASSERT_EQ(first_wins.exit_code, 0) << first_wins.err;
  EXPECT_EQ(nlohmann::json::parse(first_wins.out).at("lanes").at(0).at("id"), "lane_first");
  const Outcome second_wins =
      scenfuzz({"map", "town", "--map-path", second, "--map-path", first, "--json"});
  ASSERT_EQ(second_wins.exit_code, 0) << second_wins.err;
  EXPECT_EQ(nlohmann::json::parse(second_wins.out).at("lanes").at(0).at("id"), "lane_second");

  const ScopedEnvironment environment("SCENFUZZ_MAP_PATH",
                                      (dir_ / "nowhere").string() + ":" + second);
  const Outcome from_environment = scenfuzz({"map", "hamlet", "--json"});
  ASSERT_EQ(from_environment.exit_code, 0) << from_environment.err;
  EXPECT_EQ(nlohmann::json::parse(from_environment.out).at("lanes").at(0).at("id"), "lane_hamlet");
  // --map-path comes before SCENFUZZ_MAP_PATH.
  const Outcome command_line_first = scenfuzz({"map", "town", "--map-path", first, "--json"});
  ASSERT_EQ(command_line_first.exit_code, 0) << command_line_first.err;
  EXPECT_EQ(nlohmann::json::parse(command_line_first.out).at("lanes").at(0).at("id"), "lane_first");
}

TEST_F(CliMapTest, MissingNameOrBadOptionsExitWithOne) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"map"},
                                             {"map", "--svg"},
                                             {"map", "--map-path"},
                                             {"map", "--bogus", "crossroads"},
                                             {"map", "crossroads", "straight"}}) {
    const Outcome run = scenfuzz(args);
    EXPECT_EQ(run.exit_code, 2) << "args: " << ::testing::PrintToString(args);
    EXPECT_NE(run.err.find("scenfuzz: error:"), std::string::npos) << run.err;
  }
}

TEST_F(CliMapTest, Help) {
  const Outcome top = scenfuzz({"--help"});
  EXPECT_NE(top.out.find("map"), std::string::npos) << top.out;
  const Outcome run = scenfuzz({"map", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option : {"--map-path", "--svg", "--labels", "--json", "--list"})
    EXPECT_NE(run.out.find(option), std::string::npos) << option << "\n" << run.out;
}

}  // namespace

class CliRunTest : public CliTest {
 protected:
  static std::string corpus_file(const std::string& name) {
    return (fs::path(SCENFUZZ_TEST_DATA_DIR).parent_path().parent_path().parent_path() / "corpora" /
            "avunit" / name)
        .string();
  }
};

TEST_F(CliRunTest, RunsALogicalScenarioAtTheMiddleAndWritesItsOutputs) {
  const fs::path out = dir_ / "run";
  // The corpus seed with a clearance to oncoming traffic of 3 m, more than two lanes side by side
  // leave: violated wherever the cars pass, the middle of the space among them. (The seeds
  // themselves are violated at few points, their middles none.)
  std::string text = slurp(corpus_file("overtaking_oncoming.avu"));
  const std::string clearance = "G (dis_car >= 1.0 & dis_bus >= 1.0)";
  ASSERT_NE(text.find(clearance), std::string::npos);
  text.replace(text.find(clearance), clearance.size(), "G (dis_car >= 3.0 & dis_bus >= 1.0)");
  const fs::path strict = dir_ / "oncoming_strict.avu";
  std::ofstream(strict) << text;
  const Outcome run = scenfuzz({"run", strict.string(), "--at", "mid", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.out.find("spec spec1: robustness -"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("violated by 'dis_car >= 3.0' ("), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("map straight"), std::string::npos) << run.out;
  // The report names the point as the concrete scenario's header does: by the value of what the
  // file writes, not by the draw of a range inside it.
  EXPECT_NE(run.out.find("\n  car.waypoint[0].position.x = 150 m, where range(-30, 30) & "
                         "(-1.0, 0.0) drew 0 ("),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("simulated "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("ego reached its target: "), std::string::npos) << run.out;
  for (const char* name : {"trace.csv", "trace.json", "trace.svg", "scenario.avu"})
    EXPECT_TRUE(fs::exists(out / name)) << name;
  EXPECT_TRUE(slurp(out / "trace.csv").starts_with("time,actor,"));
  EXPECT_TRUE(slurp(out / "trace.svg").ends_with("</svg>\n"));
  const std::string concrete = slurp(out / "scenario.avu");
  // The header names a dimension inside an expression by the value of what the file writes
  // (a position, 150 + the draw of the offset) and where the draw came from.
  EXPECT_NE(concrete.find("\n//   car.waypoint[0].position.x = 150 m, where range(-30, 30) & "
                          "(-1.0, 0.0) drew 0 ("),
            std::string::npos)
      << concrete;
  std::size_t body = concrete.find('\n') + 1;  // after the header's lines, one per dimension
  while (concrete.compare(body, 5, "//   ") == 0) body = concrete.find('\n', body) + 1;
  EXPECT_EQ(concrete.find("range(", body), std::string::npos) << "every range replaced";
  EXPECT_FALSE(has_leftover_temporary_file(out));

  // The concrete scenario it wrote runs as it is, and gives the same outcome.
  const Outcome again =
      scenfuzz({"run", (out / "scenario.avu").string(), "--out", (dir_ / "again").string()});
  ASSERT_EQ(again.exit_code, 1) << again.err;
  EXPECT_EQ(slurp(out / "trace.csv"), slurp(dir_ / "again" / "trace.csv"));
  auto verdict_line = [](const std::string& printed) {
    const std::size_t start = printed.find("spec spec1:");
    return printed.substr(start, printed.find(" at ", start) - start);
  };
  EXPECT_EQ(verdict_line(run.out), verdict_line(again.out));
}

TEST_F(CliRunTest, JsonSummary) {
  const Outcome run = scenfuzz({"run", corpus_file("stationary_obstacle_in_lane.avu"), "--at",
                                "random", "--seed", "7", "--json", "--out", (dir_ / "o").string()});
  ASSERT_NE(run.exit_code, 2) << run.err;
  const auto summary = nlohmann::json::parse(run.out);
  ASSERT_EQ(summary["specs"].size(), 1u);
  const auto& spec = summary["specs"][0];
  EXPECT_EQ(spec["name"], "spec1");
  EXPECT_EQ(spec["violated"], run.exit_code == 1);
  EXPECT_EQ(spec["violated"], spec["robustness"].get<double>() < 0);
  EXPECT_TRUE(spec["atom_location"].get<std::string>().ends_with(":45:19") || !spec["violated"]);
  EXPECT_EQ(summary["map"], "straight");
  EXPECT_EQ(summary["seed"], 7);
  EXPECT_TRUE(summary["collisions"].is_array());
  EXPECT_TRUE(summary["parameters"].is_object());
  EXPECT_EQ(summary["files"].size(), 4u);
}

// Issue 24: a file whose actors never come near the ego (here a car three lanes away) cannot fail
// whatever the search tries; run and the search say so instead of reporting "0 findings" as a pass.
TEST_F(CliRunTest, ActorsThatNeverComeNearTheEgoAreWarnedOf) {
  const std::string text = R"(ego_vehicle = AV(("east_0"->20, , 10), ("east_0"->200));
npc = Vehicle(("east_3"->30, , NPC_SPEED));
scenario = CreateScenario{load("straight?lanes=4"); ego_vehicle; {npc}; {}; {};};
Trace trace = EXE(scenario);
)";
  auto with_speed = [&](const std::string& speed) {
    std::string file = text;
    file.replace(file.find("NPC_SPEED"), 9, speed);
    return file;
  };
  const std::string far = write("far.avu", with_speed("10"));
  const Outcome run = scenfuzz({"run", far, "--out", (dir_ / "o").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("warning: the scenario's actors never come within 3 m of the ego's "
                         "path (nearest: npc 7 m at 0 s)"),
            std::string::npos)
      << run.err;
  const Outcome json = scenfuzz({"run", far, "--json"});
  const auto summary = nlohmann::json::parse(json.out);
  EXPECT_EQ(summary["interaction"]["actors_interact"], false);
  EXPECT_EQ(summary["interaction"]["nearest_to_ego_path"][0]["actor"], "npc");

  const std::string logical = write("far_logical.avu", with_speed("range(5, 15)"));
  const Outcome search = scenfuzz({"--budget", "4", logical, "--out", (dir_ / "search").string()});
  ASSERT_EQ(search.exit_code, 0) << search.err;
  EXPECT_NE(search.err.find("warning: at the centre of the space, the scenario's actors never "
                            "come within 3 m"),
            std::string::npos)
      << search.err;

  // The same car in the ego's own lane ahead: no warning.
  std::string near = with_speed("10");
  near.replace(near.find("east_3"), 6, "east_0");
  const Outcome near_run =
      scenfuzz({"run", write("near.avu", near), "--out", (dir_ / "n").string()});
  EXPECT_EQ(near_run.err.find("never come within"), std::string::npos) << near_run.err;
}

// A concrete point of corpora/wmg/oblique_crossroads.sdl that a search reported as the ego's
// fault ("left the car no room to stop"): an oncoming car turning left on the same green drove
// into the ego going straight. The turner gives way, also when it is the one that runs into the
// other. An ego that holds its speed (the reference driver brakes and misses the turner).
TEST_F(CliRunTest, AnOncomingLeftTurnerDrivingIntoTheEgoGoingStraightIsAtFault) {
  const fs::path file = fs::path(SCENFUZZ_TEST_DATA_DIR) / "left_turner_into_ego.sdl";
  const std::string steady = std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/libsteady.so";
  const Outcome run = scenfuzz({"run", file.string(), "--seed", "1", "--ego-plugin", steady,
                                "--out", (dir_ / "o").string()});
  ASSERT_NE(run.exit_code, 2) << run.err;
  EXPECT_NE(run.out.find("collision at 11.25 s: Ego left / Car front"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("responsibility: other: the other turned left without giving way to the "
                         "oncoming ego going straight: "),
            std::string::npos)
      << run.out;
}

// Issue 24: `scenfuzz map FILE` draws the map a scenario builds, and says which arm each road of a
// WMG scenery became (the stem R3 of corpora/wmg/give_way_t_junction.sdl is the south arm).
TEST_F(CliRunTest, MapOfAScenarioFileSaysWhichArmEachRoadBecame) {
  const fs::path file =
      fs::path(corpus_file("x")).parent_path().parent_path() / "wmg" / "give_way_t_junction.sdl";
  const Outcome map =
      scenfuzz({"map", file.string(), "--svg", (dir_ / "scenery.svg").string(), "--labels"});
  ASSERT_EQ(map.exit_code, 0) << map.err;
  EXPECT_NE(map.out.find("map         t_junction"), std::string::npos) << map.out;
  // R3.L1 leads into the junction (R3.L1 -> R1.L2 + R2.L1), R3.L2 out of it.
  EXPECT_NE(map.out.find("road R3     the south arm (R3.L1 south_in_0, R3.L2 south_out_0)"),
            std::string::npos)
      << map.out;
  EXPECT_NE(map.out.find("road R1     the west arm"), std::string::npos) << map.out;
  const std::string svg = slurp(dir_ / "scenery.svg");
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  // The picture marks the actors where the run starts them, and the roads' names.
  EXPECT_NE(svg.find(">Ego (ego)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">Car (FSL of Ego)</text>"), std::string::npos);
  for (const std::string road : {"R1", "R2", "R3"})
    EXPECT_NE(svg.find(">" + road + "</text>"), std::string::npos) << road;
  std::size_t bodies = 0;
  for (std::size_t at = svg.find("class=\"mark-body\""); at != std::string::npos;
       at = svg.find("class=\"mark-body\"", at + 1))
    ++bodies;
  EXPECT_EQ(bodies, 2u) << "the ego's and the car's";
  const Outcome broken = scenfuzz({"map", write("broken.sdl", "VERSION: 1.0\nnonsense\n")});
  EXPECT_EQ(broken.exit_code, 2);
  EXPECT_NE(broken.err.find("broken.sdl:"), std::string::npos) << broken.err;
}

TEST_F(CliRunTest, ALogicalScenarioNeedsAPoint) {
  const Outcome run = scenfuzz({"run", corpus_file("stationary_obstacle_in_lane.avu")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--at mid"), std::string::npos) << run.err;
}

TEST_F(CliRunTest, AnEgoPluginThatCannotLoadIsABadInput) {
  const Outcome run =
      scenfuzz({"run", corpus_file("stationary_obstacle_in_lane.avu"), "--at", "mid",
                "--ego-plugin", (dir_ / "missing.so").string(), "--out", (dir_ / "o").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("missing.so"), std::string::npos) << run.err;
}

TEST_F(CliRunTest, AScenarioWithAnUnknownLaneNamesItsPlace) {
  const std::string path = write("bad_lane.avu", R"(ego = AV(("nowhere"->10), ("east_0"->100));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
)");
  const Outcome run = scenfuzz({"run", path, "--out", (dir_ / "o").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad_lane.avu:1:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nowhere"), std::string::npos) << run.err;
}

// ---- option checks: every bad value is a usage error naming the option, before any work ----

namespace {

struct BadOption {
  std::vector<std::string> args;
  std::string option;  // what the message must name
};

// Options `run` and the search both take.
const std::vector<BadOption> kBadSharedOptions = {
    {{"--dt", "0"}, "--dt"},
    {{"--dt", "-1"}, "--dt"},
    {{"--dt", "nan"}, "--dt"},
    {{"--dt", "1.5"}, "--dt"},
    {{"--duration", "nan"}, "--duration"},
    {{"--duration", "1e9"}, "--duration"},
    {{"--duration", "1e300"}, "--duration"},
    {{"--duration", "0"}, "--duration"},
    {{"--duration", "inf"}, "--duration"},
    // Each value is fine on its own; together they are 10,010,000 steps.
    {{"--duration", "1001", "--dt", "0.0001"}, "--duration"},
    {{"--ego-step-timeout", "0"}, "--ego-step-timeout"},
    {{"--ego-step-timeout", "nan"}, "--ego-step-timeout"},
    {{"--ego-step-timeout", "3601"}, "--ego-step-timeout"},
    {{"--ego-start-timeout", "-1"}, "--ego-start-timeout"},
    {{"--ego-start-timeout", "inf"}, "--ego-start-timeout"},
    {{"--seed", "-1"}, "--seed"},
    {{"--seed", "18446744073709551616"}, "--seed"},
};

// The search's own options.
const std::vector<BadOption> kBadSearchOptions = {
    {{"--budget", "-1"}, "--budget"},
    {{"--budget=-1"}, "--budget"},
    {{"--budget", "18446744073709551616"}, "--budget"},
    {{"--budget", "0"}, "--budget"},
    {{"--budget", "1000000001"}, "--budget"},
    {{"--budget", "2.5"}, "--budget"},
    {{"-j", "-1"}, "--jobs"},
    {{"-j", "1000000"}, "--jobs"},
    {{"--time-limit", "-1"}, "--time-limit"},
    {{"--time-limit", "nan"}, "--time-limit"},
    {{"--time-limit", "0"}, "--time-limit"},
};

// A concrete scenario on the built-in straight road whose spec (keep clear of the wreck) holds
// for the first seconds whatever drives the ego.
constexpr const char* kSafeScenario = R"(ego = AV(("east_0"->10), ("east_0"->200));
wreck = Obstacle("east_0"->150, (box, 4.5, 1.9, 1.5));
scenario = CreateScenario{load("straight"); ego; {}; {}; {wreck};};
Trace trace = EXE(scenario);
trace |= G (dis(trace[ego], trace[truth][wreck]) > 1.0);
)";

void expect_usage_error(const Outcome& run, const BadOption& bad, const std::string& command) {
  const std::string what = command + " " + ::testing::PrintToString(bad.args);
  EXPECT_EQ(run.exit_code, 2) << what << "\n" << run.err;
  EXPECT_NE(run.err.find("scenfuzz: error: "), std::string::npos) << what << "\n" << run.err;
  EXPECT_NE(run.err.find(bad.option), std::string::npos) << what << "\n" << run.err;
  EXPECT_EQ(run.out, "") << what;
}

}  // namespace

TEST_F(CliRunTest, TheSearchRejectsBadOptionValues) {
  const std::string scenario = corpus_file("stationary_obstacle_in_lane.avu");
  std::vector<BadOption> cases = kBadSharedOptions;
  cases.insert(cases.end(), kBadSearchOptions.begin(), kBadSearchOptions.end());
  for (const BadOption& bad : cases) {
    const fs::path out = dir_ / "search";
    std::vector<std::string> args = bad.args;
    // Should a value get through, the search is short (an option given twice would be a usage
    // error of its own, so only the options a case does not give).
    const std::string given = ::testing::PrintToString(bad.args);
    if (given.find("--budget") == std::string::npos) args.insert(args.end(), {"--budget", "2"});
    if (given.find("--time-limit") == std::string::npos)
      args.insert(args.end(), {"--time-limit", "60"});
    args.insert(args.end(), {"--out", out.string(), scenario});
    expect_usage_error(scenfuzz(args), bad, "scenfuzz");
    EXPECT_FALSE(fs::exists(out)) << "nothing written for " << ::testing::PrintToString(bad.args);
  }
}

TEST_F(CliRunTest, RunRejectsBadOptionValues) {
  const std::string scenario = corpus_file("stationary_obstacle_in_lane.avu");
  for (const BadOption& bad : kBadSharedOptions) {
    const fs::path out = dir_ / "run";
    std::vector<std::string> args = {"run", scenario, "--at", "mid", "--out", out.string()};
    args.insert(args.end(), bad.args.begin(), bad.args.end());
    expect_usage_error(scenfuzz(args), bad, "scenfuzz run");
    EXPECT_FALSE(fs::exists(out)) << "nothing written for " << ::testing::PrintToString(bad.args);
  }
}

// The scenario's own duration is checked against --dt once the scenario is read.
TEST_F(CliRunTest, RunRejectsAStepTooSmallForTheScenariosDuration) {
  const std::string path = write("safe.avu", kSafeScenario);
  const Outcome run = scenfuzz({"run", path, "--dt", "1e-300", "--out", (dir_ / "o").string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--dt"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the scenario's duration"), std::string::npos) << run.err;
}

TEST_F(CliRunTest, BoundaryValuesAreAccepted) {
  const std::string path = write("safe.avu", kSafeScenario);
  const Outcome run =
      scenfuzz({"run", path, "--dt", "1", "--duration", "2", "--seed", "18446744073709551615",
                "--ego-step-timeout", "3600", "--out", (dir_ / "o").string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json summary = nlohmann::json::parse(run.out);
  EXPECT_EQ(summary.at("dt"), 1.0);
  EXPECT_EQ(summary.at("seed"), 18446744073709551615ull);
}

TEST_F(CliRunTest, HelpStatesEveryBoundAndDefault) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--help"}, {"run", "--help"}}) {
    const Outcome help = scenfuzz(args);
    ASSERT_EQ(help.exit_code, 0);
    for (const char* text :
         {"--dt S ", "(0 < S <= 1; default 0.05)", "(0 < S <= 43200; default the scenario's",
          "--ego-step-timeout S", "(0 < S <= 3600; default 2)", "--ego-start-timeout S",
          "(0 < S <= 3600; default 10)", "--continue-after-collision", "--map-path DIR",
          "--ego-plugin LIB", "--seed N"})
      EXPECT_NE(help.out.find(text), std::string::npos) << text << "\n" << help.out;
  }
  const Outcome search = scenfuzz({"--help"});
  for (const char* text : {"(1 <= N <= 1000000000; default 500)", "(0 <= N <= 1024; default all",
                           "--time-limit S", "(S > 0; default none)", "--resume", "--force"})
    EXPECT_NE(search.out.find(text), std::string::npos) << text << "\n" << search.out;
}

#ifdef SCENFUZZ_TEST_PLUGIN_DIR

// A plugin that crashes is a finding: exit 1, with what happened, even though every spec holds.
TEST_F(CliRunTest, ACrashingEgoPluginIsAFinding) {
  const std::string path = write("safe.avu", kSafeScenario);
  const std::string plugin = std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/libcrashing.so";
  const Outcome run =
      scenfuzz({"run", path, "--ego-plugin", plugin, "--out", (dir_ / "o").string()});
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("spec spec1: robustness "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(satisfied)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("ended: ego_failure"), std::string::npos) << run.out;
  // The plugin dereferences NULL on its third step, at 0.1 s.
  EXPECT_TRUE(std::regex_search(run.out, std::regex("ego failure.*SIGSEGV.*step 3")) &&
              std::regex_search(run.out, std::regex("ego failure.* t = 0\\.1 s")))
      << run.out;

  const Outcome json =
      scenfuzz({"run", path, "--ego-plugin", plugin, "--out", (dir_ / "j").string(), "--json"});
  EXPECT_EQ(json.exit_code, 1) << json.err;
  const nlohmann::json failure = nlohmann::json::parse(json.out).at("ego_failure");
  ASSERT_TRUE(failure.is_object()) << failure;
  EXPECT_NE(failure.at("reason").get<std::string>().find("SIGSEGV"), std::string::npos);
  EXPECT_DOUBLE_EQ(failure.at("time").get<double>(), 0.1);
  // Filled in when the simulation records the kind of failure (Trace::ego_failure).
  if (!failure.at("kind").is_null()) {
    EXPECT_EQ(failure.at("kind"), "ego_crash");
    EXPECT_EQ(failure.at("signal"), "SIGSEGV");
    EXPECT_EQ(failure.at("step"), 3);
  }
}

// --ego-step-timeout reaches the simulation: a plugin that never answers is a hang after it.
TEST_F(CliRunTest, AHangingEgoPluginIsAFindingAfterTheStepTimeout) {
  const std::string path = write("safe.avu", kSafeScenario);
  const std::string plugin = std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/libhanging.so";
  const Outcome run = scenfuzz({"run", path, "--ego-plugin", plugin, "--ego-step-timeout", "0.2",
                                "--out", (dir_ / "o").string(), "--json"});
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  const nlohmann::json failure = nlohmann::json::parse(run.out).at("ego_failure");
  EXPECT_NE(failure.at("reason").get<std::string>().find("0.2 s"), std::string::npos) << failure;
}

TEST_F(CliRunTest, AnEgoPluginWithoutItsFunctionsIsABadInput) {
  const std::string not_a_plugin = write("not_a_plugin.so", "not a shared library\n");
  const Outcome run = scenfuzz({"run", write("safe.avu", kSafeScenario), "--ego-plugin",
                                not_a_plugin, "--out", (dir_ / "o").string()});
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.err.find("not_a_plugin.so"), std::string::npos) << run.err;
  EXPECT_EQ(run.out, "");
}

#endif  // SCENFUZZ_TEST_PLUGIN_DIR
