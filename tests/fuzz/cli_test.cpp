// End-to-end tests of the scenfuzz executable: exit codes and output of its subcommands, run as a
// user would run them, on scenario files written to a temporary folder.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/shared_dir.hpp"

#ifndef SCENFUZZ_EXECUTABLE
#error "SCENFUZZ_EXECUTABLE must name the scenfuzz binary (see tests/CMakeLists.txt)"
#endif

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

struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

std::string quote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scenfuzz_cli_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  // Runs scenfuzz with `args`, capturing its exit code, stdout and stderr.
  Outcome scenfuzz(const std::vector<std::string>& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    std::string command = quote(SCENFUZZ_EXECUTABLE);
    for (const std::string& arg : args) command += " " + quote(arg);
    command += " </dev/null >" + quote(out.string()) + " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    Outcome run;
    if (status != -1 && WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
    run.out = slurp(out);
    run.err = slurp(err);
    return run;
  }

  fs::path dir_;
};

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

TEST_F(CliTest, UsageErrorsExitWithOne) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {}, {"frobnicate"}, {"check"}, {"space"}, {"space", "--bogus", "x.avu"}}) {
    const Outcome run = scenfuzz(args);
    EXPECT_EQ(run.exit_code, 1) << "args: " << ::testing::PrintToString(args);
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

TEST_F(CliTest, SpaceOfAConcreteScenario) {
  const std::string path = write("concrete.avu", concrete_scenario());
  const Outcome table = scenfuzz({"space", path});
  EXPECT_EQ(table.exit_code, 0) << table.err;
  EXPECT_EQ(table.out, "no parameters: the scenario is concrete\n");
  const Outcome json = scenfuzz({"space", "--json", path});
  EXPECT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json document = nlohmann::json::parse(json.out);
  EXPECT_EQ(document.at("dimensions"), nlohmann::json::array());
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

}  // namespace
