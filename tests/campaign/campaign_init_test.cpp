// `scenfuzz campaign init DIR FILES...`, through the real executable: the campaign.toml it writes
// is accepted by parse_campaign_config and lists FILES relative to DIR; it never overwrites one,
// and refuses files that cannot be seeds without writing anything.
#include "fuzz/campaign/campaign_init.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_config.hpp"
#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;

class CampaignInitTest : public CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    fs::create_directories(dir_ / "seeds" / "folder");
    write("seeds/a.avu", "// a\n");
    write("seeds/folder/b.sdl", "# b\n");
    write("seeds/folder/c.avu", "// c\n");
  }

  std::string seed(const std::string& name) const { return (dir_ / "seeds" / name).string(); }

  CampaignConfigResult parse(const fs::path& toml) const {
    return parse_campaign_config(slurp(toml), toml.string());
  }
};

TEST_F(CampaignInitTest, WritesACampaignTheParserAccepts) {
  const fs::path campaign = dir_ / "nightly";
  const Outcome run =
      scenfuzz({"campaign", "init", campaign.string(), seed("a.avu"), seed("folder")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("wrote " + (campaign / "campaign.toml").string() + " (3 seed scenarios)"),
            std::string::npos)
      << run.out;
  const CampaignConfigResult result = parse(campaign / "campaign.toml");
  ASSERT_TRUE(result.config) << format_diagnostics(
      SourceFile((campaign / "campaign.toml").string(), slurp(campaign / "campaign.toml")),
      result.diagnostics);
  const CampaignConfig& config = *result.config;
  EXPECT_EQ(config.name, "nightly");
  EXPECT_EQ(config.seed_entries, (std::vector<std::string>{"../seeds/a.avu", "../seeds/folder/"}));
  EXPECT_EQ(config.seed_files, (std::vector<std::string>{"../seeds/a.avu", "../seeds/folder/b.sdl",
                                                         "../seeds/folder/c.avu"}));
  EXPECT_EQ(config.ego_version, kReferenceEgoVersion);
  EXPECT_EQ(config.budget_simulations, 5000u);
  EXPECT_EQ(config.search.algorithm, "ga");
  EXPECT_TRUE(result.diagnostics.all().empty());
  // Commented: every table says what it is for.
  const std::string text = slurp(campaign / "campaign.toml");
  EXPECT_NE(text.find("# The ego under test"), std::string::npos);
  // The commented-out [[seed]] example names a file (the first), not the folder.
  EXPECT_NE(text.find("# [[seed]]\n# path = \"../seeds/a.avu\"\n"), std::string::npos) << text;
  // Uncommented, the example is accepted too.
  std::string uncommented = text;
  for (const char* line : {"# [[seed]]\n", "# path = ", "# budget_share = ", "# algo = "})
    uncommented.replace(uncommented.find(line), 2, "");
  const fs::path edited = campaign / "edited.toml";
  std::ofstream(edited) << uncommented;
  const CampaignConfigResult with_seed = parse(edited);
  ASSERT_TRUE(with_seed.config) << uncommented;
  ASSERT_EQ(with_seed.config->seed_overrides.size(), 1u);
  EXPECT_EQ(with_seed.config->seed_overrides[0].algorithm, "nlopt:GN_ISRES");
}

TEST_F(CampaignInitTest, SeedsInAnotherTreeAreNamedAbsolutely) {
  // A seed in a folder that shares nothing but the root with the campaign's: under /var/tmp when
  // the campaign is under /tmp, else under /tmp.
  const fs::path campaign_root = *dir_.begin() / *std::next(dir_.begin());
  const fs::path other_root = campaign_root == "/var" ? "/tmp" : "/var/tmp";
  const fs::path other = other_root / dir_.filename();
  fs::create_directories(other);
  const fs::path elsewhere = other / "elsewhere.avu";
  fs::copy_file(source_file("corpora/avunit/cut_in_straight.avu"), elsewhere,
                fs::copy_options::overwrite_existing);
  const fs::path campaign = dir_ / "nightly";
  const Outcome run =
      scenfuzz({"campaign", "init", campaign.string(), elsewhere.string(), seed("a.avu")});
  std::error_code ignored;
  const CampaignConfigResult result = parse(campaign / "campaign.toml");
  fs::remove_all(other, ignored);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(result.config);
  EXPECT_EQ(result.config->seed_files,
            (std::vector<std::string>{elsewhere.lexically_normal().string(), "../seeds/a.avu"}));
}

TEST_F(CampaignInitTest, WithoutFilesWritesNothing) {
  std::ostringstream out, err;
  EXPECT_EQ(run_campaign_init({(dir_ / "empty").string(), {}}, out, err), 2);
  EXPECT_EQ(err.str(),
            "scenfuzz: error: campaign init needs at least one seed scenario file or "
            "folder\n");
  EXPECT_FALSE(fs::exists(dir_ / "empty"));
}

TEST_F(CampaignInitTest, RelativeFilesAreTakenFromTheWorkingFolder) {
  // The test runs scenfuzz with an absolute DIR but relative FILES, from dir_.
  const std::string command = "cd " + shell_quote(dir_.string()) + " && " +
                              shell_quote(SCENFUZZ_EXECUTABLE) +
                              " campaign init camp seeds/a.avu >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const CampaignConfigResult result = parse(dir_ / "camp" / "campaign.toml");
  ASSERT_TRUE(result.config);
  EXPECT_EQ(result.config->seed_files, (std::vector<std::string>{"../seeds/a.avu"}));
}

TEST_F(CampaignInitTest, EscapesPathsForToml) {
  write("seeds/we\"ird\\name.avu", "// odd\n");
  const fs::path campaign = dir_ / "odd";
  const Outcome run = scenfuzz({"campaign", "init", campaign.string(), seed("we\"ird\\name.avu")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CampaignConfigResult result = parse(campaign / "campaign.toml");
  ASSERT_TRUE(result.config);
  EXPECT_EQ(result.config->seed_files, (std::vector<std::string>{"../seeds/we\"ird\\name.avu"}));
}

TEST_F(CampaignInitTest, NeverOverwritesACampaign) {
  const fs::path campaign = dir_ / "nightly";
  fs::create_directories(campaign);
  write("nightly/campaign.toml", "# mine\n");
  const Outcome run = scenfuzz({"campaign", "init", campaign.string(), seed("a.avu")});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("scenfuzz: error: '" + (campaign / "campaign.toml").string() +
                         "' already exists; campaign init never overwrites it"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(slurp(campaign / "campaign.toml"), "# mine\n");
}

TEST_F(CampaignInitTest, RefusesFilesThatCannotBeSeeds) {
  write("seeds/notes.txt", "notes\n");
  const fs::path campaign = dir_ / "nightly";
  struct Case {
    std::string file, message;
  };
  for (const Case& bad :
       {Case{seed("missing.avu"), "'" + seed("missing.avu") + "' does not exist"},
        Case{seed("notes.txt"), "is not a scenario file: expected a .avu, .scenest or .sdl"}}) {
    SCOPED_TRACE(bad.file);
    const Outcome run = scenfuzz({"campaign", "init", campaign.string(), seed("a.avu"), bad.file});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("scenfuzz: error: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(bad.message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(campaign / "campaign.toml"));
  }
}

TEST_F(CampaignInitTest, UsageErrors) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"campaign"}, std::vector<std::string>{"campaign", "init"},
        std::vector<std::string>{"campaign", "init", (dir_ / "x").string()},
        std::vector<std::string>{"campaign", "frobnicate"}}) {
    const Outcome run = scenfuzz(args);
    EXPECT_EQ(run.exit_code, 2) << args.size();
    EXPECT_NE(run.err.find("scenfuzz: error: "), std::string::npos) << run.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "x"));
}

TEST_F(CampaignInitTest, HelpNamesTheSubcommand) {
  const Outcome run = scenfuzz({"campaign", "init", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("campaign.toml"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace scenfuzz::test
