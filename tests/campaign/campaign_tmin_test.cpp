// [search] tmin = true: a campaign minimises the representative of each failure mode new to its
// seed into DIR/modes/<hash>.min.avu, which keeps the mode's failure when replayed; the database
// and modes/ (minimised files' contents included) are the same for any -j; a later run minimises
// nothing more for the modes it finds again; the report links the minimised file.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_run.hpp"
#include "fuzz/campaign/mode_files.hpp"
#include "fuzz/cli.hpp"
#include "tests/campaign/campaign_fixture.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBudget = "simulations = 320";

// "failure mode: ..." of a file's header.
std::string mode_line(const std::string& text) {
  const std::size_t at = text.find("failure mode: ");
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

// A mode without its atom: the spec's name and the fields after the atom (canonical AVUnit, which
// tmin writes, spells an atom out in full: "dis_ped <= 1.0" is "dis(...) <= 1" there).
std::string beyond_atom(const std::string& mode) {
  std::vector<std::string> fields;
  for (std::size_t from = 0;;) {
    const std::size_t bar = mode.find(" | ", from);
    fields.push_back(mode.substr(from, bar - from));
    if (bar == std::string::npos) break;
    from = bar + 3;
  }
  std::string text = mode.substr(0, mode.find(": ", std::string("failure mode: ").size()));
  // A mode has at least four fields after its atom (actor, responsibility, manoeuvre, road; and
  // for a collision the sides): the last four are past the atom, whatever the atom holds.
  for (std::size_t i = fields.size() - std::min<std::size_t>(4, fields.size() - 1);
       i < fields.size(); ++i)
    text += " | " + fields[i];
  return text;
}

std::size_t minimised_count(const fs::path& folder) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(folder / "modes"))
    count += entry.path().string().ends_with(".min.avu") ? 1 : 0;
  return count;
}

class CampaignTminTest : public CommandTest {
 protected:
  fs::path campaign(const std::string& name, bool tmin = true) {
    fs::create_directories(dir_ / name);
    write(name + "/campaign.toml",
          campaign_toml(small_campaign_seeds(), kBudget, tmin ? "tmin = true\n" : ""));
    return dir_ / name;
  }

  int run(const fs::path& folder, std::uint64_t jobs) {
    out_.str("");
    err_.str("");
    return run_campaign({folder.string(), jobs, "", false}, {}, out_, err_);
  }

  std::ostringstream out_, err_;
};

TEST_F(CampaignTminTest, EachNewModeHasItsMinimisedScenarioWhichKeepsTheFailure) {
  const fs::path folder = campaign("c");
  ASSERT_EQ(run(folder, 2), kExitViolated) << err_.str();
  EXPECT_EQ(err_.str().find("not minimised"), std::string::npos) << err_.str();
  CampaignDbOpening opening = CampaignDb::open(folder);
  ASSERT_TRUE(opening.db) << opening.error;
  const std::vector<CampaignFailureMode> modes = opening.db->list_failure_modes();
  opening.db.reset();
  ASSERT_FALSE(modes.empty());
  for (const CampaignFailureMode& mode : modes) {
    const std::string minimised = minimised_mode_file(mode.record.scenario_file);
    ASSERT_TRUE(fs::exists(folder / minimised)) << minimised;
    const std::string text = slurp(folder / minimised);
    const std::string finding_mode = mode_line(slurp(folder / mode.record.scenario_file));
    ASSERT_FALSE(finding_mode.empty());
    EXPECT_EQ(beyond_atom(mode_line(text)), beyond_atom(finding_mode)) << text;
    EXPECT_NE(text.find("// replay: scenfuzz run " + minimised + " --seed "), std::string::npos)
        << text;
    // tmin replays it and refuses it unless it fails as its header's mode says.
    const Outcome again =
        scenfuzz({"tmin", (folder / minimised).string(), "-o", (dir_ / "again.avu").string()});
    EXPECT_EQ(again.exit_code, 0) << minimised << ": " << again.err;
    EXPECT_EQ(mode_line(again.out), mode_line(text)) << again.out;
  }
  EXPECT_EQ(minimised_count(folder), modes.size());

  // The report links each one.
  const Outcome report = scenfuzz({"campaign", "report", folder.string()});
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string page = slurp(folder / "report.html");
  EXPECT_NE(page.find(">minimised</a>"), std::string::npos);
  EXPECT_NE(page.find(minimised_mode_file(modes.front().record.scenario_file)), std::string::npos);

  // A second run finds known modes again: only new ones are minimised. Whether it also finds a
  // new mode (exit 1) or none (exit 0) depends on the search, not on what is tested here.
  const int second = run(folder, 2);
  ASSERT_TRUE(second == 0 || second == kExitViolated) << second << ": " << err_.str();
  EXPECT_NE(out_.str().find("still_failing"), std::string::npos) << out_.str();
  opening = CampaignDb::open(folder);
  ASSERT_TRUE(opening.db) << opening.error;
  EXPECT_EQ(minimised_count(folder), opening.db->list_failure_modes().size());
}

TEST_F(CampaignTminTest, TheMinimisedFilesAreTheSameForAnyNumberOfJobs) {
  const fs::path one = campaign("one"), two = campaign("two");
  ASSERT_EQ(run(one, 1), kExitViolated) << err_.str();
  ASSERT_EQ(run(two, 2), kExitViolated) << err_.str();
  const std::string dump = canonical_dump(one);
  EXPECT_NE(dump.find(".min.avu "), std::string::npos) << dump;
  const std::string other = canonical_dump(two);
  EXPECT_TRUE(dump == other) << first_difference(dump, other);
}

TEST_F(CampaignTminTest, WithoutTminNothingIsMinimised) {
  const fs::path folder = campaign("c", false);
  ASSERT_EQ(run(folder, 2), kExitViolated) << err_.str();
  EXPECT_EQ(minimised_count(folder), 0u);
}

}  // namespace
}  // namespace scenfuzz::test
