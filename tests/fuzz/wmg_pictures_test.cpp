// Issue 24: docs/wmg-semantics.md shows every corpora/wmg scenery as `scenfuzz map FILE --svg`
// draws it; the pictures there must be what this build draws, or the docs show a reading of the
// files that is no longer the program's (scripts/draw-wmg-corpus.sh draws them again).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::slurp;

class WmgPicturesTest : public test::CommandTest {};

TEST_F(WmgPicturesTest, TheDocsShowEveryCorpusSceneryAsThisBuildDrawsIt) {
  const fs::path source = SCENFUZZ_SOURCE_DIR;
  const std::string docs = slurp(source / "docs" / "wmg-semantics.md");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(source / "corpora" / "wmg")) {
    if (entry.path().extension() != ".sdl") continue;
    ++files;
    const std::string name = entry.path().stem().string();
    const fs::path drawn = dir_ / (name + ".svg");
    const Outcome map = scenfuzz({"map", entry.path().string(), "--svg", drawn.string()});
    ASSERT_EQ(map.exit_code, 0) << name << "\n" << map.err;
    const fs::path shown = source / "docs" / "pictures" / "wmg" / (name + ".svg");
    EXPECT_TRUE(slurp(drawn) == slurp(shown))
        << shown << " is not what this build draws: run scripts/draw-wmg-corpus.sh";
    EXPECT_NE(docs.find("(pictures/wmg/" + name + ".svg)"), std::string::npos)
        << "docs/wmg-semantics.md does not show " << name;
  }
  EXPECT_GE(files, 10);
}

}  // namespace
}  // namespace scenfuzz
