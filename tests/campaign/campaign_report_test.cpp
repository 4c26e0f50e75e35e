// `scenfuzz campaign report DIR`, through the real executable: exit 2 without a campaign.db, a
// valid page for a campaign without runs, text from the database escaped, pictures linked
// relative to wherever --out puts the page, and a report written while a run holds the campaign.
#include "fuzz/campaign/campaign_report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz/campaign/campaign_db.hpp"
#include "tests/campaign/report_campaign.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t found = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++found;
  return found;
}

class CampaignReportTest : public ReportCampaignTest {
 protected:
  fs::path campaign() const { return dir_ / "nightly"; }

  // A campaign of one run: `seed_name` (copied from a corpus seed) searched for spec1.
  CampaignSearchResult one_run(const std::string& seed_name, const std::string& ego_version) {
    fs::create_directories(campaign() / "seeds");
    const std::string seed = "seeds/" + seed_name;
    fs::copy_file(source_file("corpora/avunit/pedestrian_step_out.avu"), campaign() / seed);
    CampaignDbOpening opening = CampaignDb::open(campaign());
    EXPECT_TRUE(opening.db) << opening.error;
    const std::int64_t run = opening.db->begin_run(ego_version);
    const std::int64_t seed_id = opening.db->upsert_seed(seed, "0123456789abcdef");
    CampaignSearchResult result =
        search(*opening.db, campaign(), run, seed_id, seed, "spec1", 30, 1);
    opening.db->end_run(run);
    return result;
  }
};

TEST_F(CampaignReportTest, AFolderWithoutACampaignDatabaseIsExitTwoWithTheReason) {
  fs::create_directories(campaign());
  const Outcome run = scenfuzz({"campaign", "report", campaign().string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "scenfuzz: error: '" + campaign().string() +
                         "' is not a campaign folder: it has no campaign.db\n");
  EXPECT_FALSE(fs::exists(campaign() / "report.html"));
  EXPECT_FALSE(fs::exists(campaign() / "campaign.db"));  // nothing created
  const Outcome missing = scenfuzz({"campaign", "report", (dir_ / "nowhere").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("has no campaign.db"), std::string::npos) << missing.err;
}

TEST_F(CampaignReportTest, ACampaignWithoutRunsGetsAPageThatSaysSo) {
  { ASSERT_TRUE(CampaignDb::open(campaign()).db); }
  const Outcome run = scenfuzz({"campaign", "report", campaign().string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "scenfuzz: wrote " + (campaign() / "report.html").string() +
                         " (0 runs, 0 failure modes)\n");
  const std::string page = slurp(campaign() / "report.html");
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>\n"));
  EXPECT_TRUE(page.ends_with("</html>\n"));
  EXPECT_NE(page.find("<title>nightly · scenfuzz campaign report</title>"), std::string::npos);
  EXPECT_NE(page.find("This campaign has no runs yet"), std::string::npos);
  EXPECT_EQ(count(page, "<p class=\"none-found\">None.</p>"), 5u);  // one per status
  EXPECT_NE(page.find("no runs yet"), std::string::npos);           // the trend chart
  EXPECT_EQ(page.find("<table"), std::string::npos);
}

TEST_F(CampaignReportTest, TextFromTheDatabaseIsEscaped) {
  const CampaignSearchResult result = one_run("<b>cut & co.avu", "v<2> & \"x\"");
  ASSERT_FALSE(result.modes.empty());
  const Outcome run = scenfuzz({"campaign", "report", campaign().string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = slurp(campaign() / "report.html");
  EXPECT_EQ(page.find("<b>cut"), std::string::npos);
  EXPECT_EQ(page.find("v<2>"), std::string::npos);
  // In the tables, the chart's heading and title, and every failure mode's row.
  EXPECT_GE(count(page, "&lt;b&gt;cut &amp; co.avu"), 3 + result.modes.size());
  EXPECT_NE(page.find("<code>v&lt;2&gt; &amp; &quot;x&quot;</code>"), std::string::npos);
}

TEST_F(CampaignReportTest, PicturesAreLinkedRelativeToTheReportWhereverItIs) {
  const CampaignSearchResult result = one_run("step_out.avu", "v1");
  ASSERT_FALSE(result.modes.empty());
  const fs::path out = dir_ / "published" / "nightly report.html";
  fs::create_directories(out.parent_path());
  const Outcome run = scenfuzz({"campaign", "report", campaign().string(), "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(fs::exists(campaign() / "report.html"));
  const std::string page = slurp(out);
  for (const FailureModeRecord& mode : result.modes) {
    const std::string picture =
        "../nightly/" + fs::path(mode.scenario_file).replace_extension(".svg").string();
    ASSERT_TRUE(fs::exists(out.parent_path() / picture)) << picture;
    EXPECT_NE(page.find("<img src=\"" + picture + "\""), std::string::npos) << picture;
    EXPECT_NE(page.find("<a href=\"../nightly/" + mode.scenario_file + "\">"), std::string::npos);
  }
}

TEST_F(CampaignReportTest, AReportIsWrittenWhileARunHoldsTheCampaign) {
  one_run("step_out.avu", "v1");
  CampaignDbOpening running = CampaignDb::open(campaign());
  ASSERT_TRUE(running.db) << running.error;
  running.db->begin_run("v2");
  const Outcome run = scenfuzz({"campaign", "report", campaign().string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = slurp(campaign() / "report.html");
  EXPECT_NE(page.find("not ended (running, or killed)"), std::string::npos);
  EXPECT_NE(page.find("<code>v2</code> (run 2)"), std::string::npos);
}

TEST_F(CampaignReportTest, TheTitleIsTheCampaignsName) {
  fs::create_directories(campaign());
  std::ofstream(campaign() / "a.avu") << "// a\n";
  std::ofstream(campaign() / "campaign.toml")
      << "seeds = [\"a.avu\"]\n[campaign]\nname = \"nightly <main>\"\n[budget]\nsimulations = 10\n";
  { ASSERT_TRUE(CampaignDb::open(campaign()).db); }
  const Outcome run = scenfuzz({"campaign", "report", campaign().string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_NE(slurp(campaign() / "report.html").find("<h1>Campaign nightly &lt;main&gt;</h1>"),
            std::string::npos);
  // A campaign.toml with an error: the folder's name, and a warning.
  std::ofstream(campaign() / "campaign.toml") << "seeds = [\"missing.avu\"]\n";
  const Outcome broken = scenfuzz({"campaign", "report", campaign().string()});
  ASSERT_EQ(broken.exit_code, 0) << broken.err;
  EXPECT_NE(broken.err.find("warning: " + (campaign() / "campaign.toml").string() + " has errors"),
            std::string::npos)
      << broken.err;
  EXPECT_NE(slurp(campaign() / "report.html").find("<h1>Campaign nightly</h1>"), std::string::npos);
}

}  // namespace
}  // namespace scenfuzz::test
