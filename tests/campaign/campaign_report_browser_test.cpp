// The campaign report in a real browser: headless Chromium loads a report of a small campaign
// built from real searches (three runs, two seeds, every failure-mode status) and the test checks
// from the DOM Chromium built that the tables have their rows and the charts their paths, that
// no console message was logged, that every picture loaded and every chart has a size, and saves
// a screenshot. A deliberately broken page proves the checks see errors.
//
// The screenshot and the report (with its pictures) are kept in
// <test binary's folder>/test-output/campaign_report/ (report.png, report.html); the test prints
// the path.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

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

// The text of the element that starts with `start` up to the next `end`; empty when absent.
std::string between(const std::string& text, const std::string& start, const std::string& end) {
  const std::size_t from = text.find(start);
  if (from == std::string::npos) return {};
  const std::size_t to = text.find(end, from);
  return text.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

// Rows of the table body inside the section with this id (0 without a table).
std::size_t body_rows(const std::string& dom, const std::string& section_id) {
  const std::string section = between(dom, "<section id=\"" + section_id + "\"", "</section>");
  return count(between(section, "<tbody>", "</tbody>"), "<tr>");
}

// What Chromium made of a page.
struct BrowserRun {
  int exit_code = -1;
  std::string dom;                   // --dump-dom: the DOM after loading, serialised
  std::vector<std::string> console;  // every console message (the report has no script)
};

// Chromium's console messages in its log: `...:INFO:CONSOLE:12] "message", source: ...`.
std::vector<std::string> console_lines(const std::string& log) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    const std::string line = log.substr(start, end - start);
    if (line.find(":CONSOLE") != std::string::npos) lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

// Loads `page` in headless Chromium, dumping the DOM; with `screenshot`, saves one too.
BrowserRun load_in_chromium(const fs::path& page, const fs::path& scratch,
                            const fs::path& screenshot = {}) {
  const fs::path dom = scratch / "dom.html", log = scratch / "chromium.log";
  std::string command =
      "timeout 60 chromium --headless=new --no-sandbox --disable-gpu --enable-logging=stderr "
      "--v=0 --hide-scrollbars --dump-dom";
  if (!screenshot.empty())
    command += " --window-size=1280,2000 --screenshot=" + shell_quote(screenshot.string());
  command += " " + shell_quote("file://" + fs::absolute(page).string()) + " >" +
             shell_quote(dom.string()) + " 2>" + shell_quote(log.string());
  BrowserRun run;
  const int status = std::system(command.c_str());
  if (status != -1 && WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  run.dom = slurp(dom);
  run.console = console_lines(slurp(log));
  return run;
}

// A copy of `page` beside it with a script that, once everything has loaded, logs a console
// error for every picture that did not load and every chart without a size, and writes what it
// checked into <body data-probe="...">. The report itself has no script; the probe is the test's.
fs::path with_probe(const fs::path& page) {
  const std::string probe = R"html(<script>
window.addEventListener('load', () => {
  const images = [...document.images];
  for (const image of images)
    if (!(image.complete && image.naturalWidth > 0))
      console.error('picture not loaded: ' + image.getAttribute('src'));
  const charts = [...document.querySelectorAll('svg.chart')];
  for (const chart of charts) {
    const box = chart.getBoundingClientRect();
    if (box.width < 100 || box.height < 50) console.error('chart without a size: ' + chart.classList);
  }
  document.body.dataset.probe = 'images=' + images.length + ' charts=' + charts.length;
});
</script>
)html";
  std::string text = slurp(page);
  const std::size_t body_end = text.rfind("</body>");
  EXPECT_NE(body_end, std::string::npos);
  text.insert(body_end, probe);
  fs::path probed = page;
  probed.replace_filename("probe-" + page.filename().string());
  std::ofstream(probed, std::ios::binary) << text;
  return probed;
}

// Where the screenshot and the report are kept after the test.
fs::path test_output() {
  return fs::read_symlink("/proc/self/exe").parent_path() / "test-output" / "campaign_report";
}

class CampaignReportBrowserTest : public ReportCampaignTest {
 protected:
  void SetUp() override {
    ReportCampaignTest::SetUp();
    ASSERT_TRUE(have_chromium())
        << "chromium is not installed: run scripts/install-deps.sh (Debian's chromium package)";
  }
};

TEST_F(CampaignReportBrowserTest, TheChecksSeeAScriptErrorAMissingPictureAndAnEmptyChart) {
  const fs::path page = dir_ / "broken.html";
  std::ofstream(page) << "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>broken</title>"
                         "</head><body><table><tbody><tr><td>a</td></tr></tbody></table>"
                         "<img src=\"missing.svg\" alt=\"\">"
                         "<svg class=\"chart\" width=\"0\" height=\"0\"></svg>"
                         "<script>notDefinedAnywhere();</script></body></html>\n";
  const BrowserRun run = load_in_chromium(with_probe(page), dir_);
  ASSERT_EQ(run.exit_code, 0);
  EXPECT_NE(run.dom.find("data-probe=\"images=1 charts=1\""), std::string::npos) << run.dom;
  std::string console;
  for (const std::string& line : run.console) console += line + "\n";
  ASSERT_EQ(run.console.size(), 3u) << console;
  EXPECT_NE(console.find("notDefinedAnywhere is not defined"), std::string::npos) << console;
  EXPECT_NE(console.find("picture not loaded: missing.svg"), std::string::npos) << console;
  EXPECT_NE(console.find("chart without a size"), std::string::npos) << console;
}

// Three runs. Run 1 (ego v1) searches both seeds: the first seed's failure modes are new. Run 2
// (ego v2) replays them (one fixed, one flaky, two still failing) and searches the second seed
// again. Run 3 (v2) is still replaying: the fixed mode fails again (regressed), a still failing
// one is now fixed.
TEST_F(CampaignReportBrowserTest, TheReportRendersItsTablesAndChartsWithoutAnError) {
  const fs::path campaign = dir_ / "nightly";
  fs::create_directories(campaign / "seeds");
  // A seed whose name would break a page that did not escape it.
  const std::string step_out = "seeds/step_out.avu", cut_in = "seeds/cut <in> & \"co\".avu";
  fs::copy_file(source_file("corpora/avunit/pedestrian_step_out.avu"), campaign / step_out);
  fs::copy_file(source_file("corpora/avunit/pedestrian_step_out.avu"), campaign / cut_in);
  {
    CampaignDbOpening opening = CampaignDb::open(campaign);
    ASSERT_TRUE(opening.db) << opening.error;
    CampaignDb& db = *opening.db;
    const std::int64_t run1 = db.begin_run("v1");
    const std::int64_t a = db.upsert_seed(step_out, content_hash(slurp(campaign / step_out)));
    const std::int64_t b = db.upsert_seed(cut_in, content_hash(slurp(campaign / cut_in)) + "-b");
    const CampaignSearchResult first = search(db, campaign, run1, a, step_out, "spec1", 40, 1);
    search(db, campaign, run1, b, cut_in, "slow_near_child", 20, 8);
    db.end_run(run1);
    ASSERT_GE(first.modes.size(), 4u);
    const std::vector<CampaignFailureMode> known = db.list_failure_modes();

    const std::int64_t run2 = db.begin_run("v2");
    db.record_replay(run2, known[0].id, {3, 0, ""});  // fixed
    db.record_replay(run2, known[1].id, {3, 1, ""});  // flaky
    db.upsert_failure_mode(run2, known[2].record);
    db.upsert_failure_mode(run2, known[3].record);
    search(db, campaign, run2, b, cut_in, "slow_near_child", 20, 7);
    db.end_run(run2);

    const std::int64_t run3 = db.begin_run("v2");
    db.upsert_failure_mode(run3, known[0].record);    // fixed, failing again: regressed
    db.record_replay(run3, known[3].id, {3, 0, ""});  // fixed
  }
  const Outcome report = scenfuzz({"campaign", "report", campaign.string()});
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const fs::path page = campaign / "report.html";

  // What the page should show, counted from the database.
  CampaignDbOpening reading = CampaignDb::open_for_reading(campaign);
  ASSERT_TRUE(reading.db) << reading.error;
  std::map<FailureModeStatus, std::size_t> by_status;
  for (const CampaignFailureMode& mode : reading.db->list_failure_modes()) ++by_status[mode.status];
  std::set<std::string> corpus_features;
  for (const CampaignSearch& search : reading.db->list_searches())
    for (const std::string& feature : reading.db->list_coverage(search.id))
      corpus_features.insert(feature);
  EXPECT_GE(corpus_features.size(), 3u);
  for (FailureModeStatus status :
       {FailureModeStatus::new_mode, FailureModeStatus::regressed, FailureModeStatus::still_failing,
        FailureModeStatus::flaky, FailureModeStatus::fixed})
    EXPECT_GE(by_status[status], 1u) << status_name(status);

  const fs::path kept = test_output();
  fs::remove_all(kept);
  fs::create_directories(kept);
  const fs::path screenshot = kept / "report.png";
  const BrowserRun run = load_in_chromium(page, dir_, screenshot);
  ASSERT_EQ(run.exit_code, 0);
  std::string console;
  for (const std::string& line : run.console) console += line + "\n";
  EXPECT_TRUE(run.console.empty()) << console;

  // The tables, as Chromium parsed them: a row per failure mode of each status, per seed, per run.
  EXPECT_EQ(body_rows(run.dom, "new"), by_status[FailureModeStatus::new_mode]);
  EXPECT_EQ(body_rows(run.dom, "regressed"), by_status[FailureModeStatus::regressed]);
  EXPECT_EQ(body_rows(run.dom, "still-failing"), by_status[FailureModeStatus::still_failing]);
  EXPECT_EQ(body_rows(run.dom, "flaky"), by_status[FailureModeStatus::flaky]);
  EXPECT_EQ(body_rows(run.dom, "fixed"), by_status[FailureModeStatus::fixed]);
  EXPECT_EQ(body_rows(run.dom, "seeds"), 2u);
  // The corpus's coverage in the seeds table's foot.
  EXPECT_NE(run.dom.find("<td class=\"number corpus-features\">" +
                         std::to_string(corpus_features.size()) + "</td>"),
            std::string::npos);
  EXPECT_EQ(body_rows(run.dom, "summary"), 3u);
  // The seed's name is text, not markup.
  EXPECT_EQ(run.dom.find("<in>"), std::string::npos);
  EXPECT_GE(count(run.dom, "cut &lt;in&gt; &amp; \"co\".avu"), 3u);
  // The charts: one per seed, each with its step line and zero line, and the trend's bars.
  EXPECT_EQ(count(run.dom, "<svg class=\"chart robustness-chart\""), 2u);
  EXPECT_EQ(count(run.dom, "<path class=\"best-so-far\" d=\"M"), 2u);
  EXPECT_EQ(count(run.dom, "class=\"zero-line\""), 2u);
  EXPECT_EQ(count(run.dom, "<svg class=\"chart trend-chart\""), 1u);
  EXPECT_GE(count(run.dom, "<rect class=\"bar "), 4u);

  // Every picture loaded and every chart has a size.
  const BrowserRun probed = load_in_chromium(with_probe(page), dir_);
  ASSERT_EQ(probed.exit_code, 0);
  std::string probe_console;
  for (const std::string& line : probed.console) probe_console += line + "\n";
  EXPECT_TRUE(probed.console.empty()) << probe_console;
  std::size_t with_picture = 0;
  for (const CampaignFailureMode& mode : reading.db->list_failure_modes())
    with_picture +=
        fs::exists(campaign / fs::path(mode.record.scenario_file).replace_extension(".svg"));
  EXPECT_GE(with_picture, 3u);
  EXPECT_NE(probed.dom.find("data-probe=\"images=" + std::to_string(with_picture) + " charts=3\""),
            std::string::npos)
      << between(probed.dom, "<body", ">");

  // The screenshot: a PNG of the window's size with something drawn in it.
  const std::string png = slurp(screenshot);
  ASSERT_GE(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto big_endian = [&](std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = at; i < at + 4; ++i)
      value = (value << 8) | static_cast<unsigned char>(png[i]);
    return value;
  };
  EXPECT_EQ(big_endian(16), 1280u);  // IHDR width
  EXPECT_EQ(big_endian(20), 2000u);  // IHDR height
  EXPECT_GT(png.size(), 60'000u);    // a blank page of this size is a few kilobytes
  fs::copy_file(page, kept / "report.html");
  fs::copy(campaign / "modes", kept / "modes");
  std::cout << "screenshot: " << screenshot.string() << "\n";
  RecordProperty("screenshot", screenshot.string());
}

}  // namespace
}  // namespace scenfuzz::test
