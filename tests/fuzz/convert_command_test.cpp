// `scenfuzz convert --to sdl2` and the `.sdl` dispatch of `check` and `space`, run as a user would
// run them: a level-1 corpus file becomes level-2 text that the level-2 parser reads back.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "command_runner.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/wmg.hpp"

namespace {

namespace fs = std::filesystem;

using ConvertCommandTest = scenfuzz::test::CommandTest;

std::string corpus(const std::string& name) {
  return (fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "wmg" / name).string();
}

TEST_F(ConvertCommandTest, LevelOneFileBecomesLevelTwoTextThatParsesBack) {
  const auto run = scenfuzz({"convert", "--to", "sdl2", corpus("motorway_cut_in_level1.sdl")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const scenfuzz::SourceFile converted("converted.sdl", run.out);
  EXPECT_EQ(scenfuzz::wmg::detect_wmg_level(converted), 2);
  const scenfuzz::wmg::Level2ParseResult tree = scenfuzz::wmg::parse_level2(converted);
  EXPECT_TRUE(tree.file.has_value())
      << scenfuzz::format_diagnostics(converted, tree.diagnostics) << run.out;
  const scenfuzz::wmg::ParseResult scenario = scenfuzz::wmg::parse(converted);
  EXPECT_TRUE(scenario.ok()) << scenfuzz::format_diagnostics(converted, scenario.diagnostics);
  EXPECT_FALSE(scenario.scenario.parameters.empty());
}

TEST_F(ConvertCommandTest, LevelTwoFileIsPrintedCanonically) {
  const auto run = scenfuzz({"convert", "--to", "sdl2", corpus("cut_in.sdl")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("SCENERY ELEMENTS"), std::string::npos);
  // Canonical text has no comments: the corpus file's own header is gone.
  EXPECT_EQ(run.out.find("# Cut-in"), std::string::npos);
  const auto again = scenfuzz({"convert", "--to", "sdl2", write("canonical.sdl", run.out)});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, run.out);
}

TEST_F(ConvertCommandTest, BadInputExitsTwoWithFileLineAndColumn) {
  const std::string path = write("bad.sdl",
                                 "VERSION: 1.0\nAUTHOR: 'a'\n\nThere is no junction present.\n"
                                 "R1 is a wobbly road.\n");
  const auto run = scenfuzz({"convert", "--to", "sdl2", path});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_NE(run.err.find(path + ":5:"), std::string::npos) << run.err;
}

TEST_F(ConvertCommandTest, UnknownTargetIsAUsageError) {
  const auto run = scenfuzz({"convert", "--to", "avunit", corpus("cut_in.sdl")});
  EXPECT_EQ(run.exit_code, 2);
}

TEST_F(ConvertCommandTest, CheckAndSpaceReadWmgFiles) {
  const auto check = scenfuzz({"check", corpus("signalised_junction.sdl")});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  const auto space = scenfuzz({"space", corpus("cut_in.sdl")});
  EXPECT_EQ(space.exit_code, 0) << space.err;
  EXPECT_NE(space.out.find("Cutter.phase2.duration"), std::string::npos) << space.out;
  std::string text = scenfuzz::test::slurp(corpus("cut_in.sdl"));
  text.replace(text.find("in [R1.L3]"), 10, "in [R1.L7]");
  const std::string broken = write("broken.sdl", text);
  const auto bad = scenfuzz({"check", broken});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown lane 'R1.L7'"), std::string::npos) << bad.err;
}

}  // namespace
