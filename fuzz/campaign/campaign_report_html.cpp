// render_report_html: the page is built as one string, section by section. Every text that comes
// from the database or the file system goes through `text()` or `attribute()` (escaped), every
// path into href/src through url_path() as well.
#include "fuzz/campaign/campaign_report_html.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include "fuzz/campaign/campaign_report_svg.hpp"
#include "physics/map/svg_writing.hpp"

namespace scenfuzz {

namespace {

// The page's look: readable at a glance, printable, no web fonts (nothing fetched).
constexpr const char* kStyle = R"css(
:root { --ink: #1f2a30; --muted: #5f6f78; --line: #dde3e7; --band: #f6f8f9; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: #fff;
  font: 15px/1.5 system-ui, -apple-system, "Segoe UI", "DejaVu Sans", Roboto, sans-serif; }
main { max-width: 1360px; margin: 0 auto; padding: 28px 32px 64px; }
header { border-bottom: 3px solid #263238; margin-bottom: 8px; padding-bottom: 12px; }
h1 { font-size: 28px; margin: 0 0 4px; }
h2 { font-size: 21px; margin: 40px 0 10px; padding-bottom: 4px; border-bottom: 1px solid var(--line); }
h3 { font-size: 15px; margin: 0 0 6px; word-break: break-all; }
p { margin: 6px 0 12px; }
.muted { color: var(--muted); }
.count { display: inline-block; min-width: 28px; padding: 0 8px; margin-left: 8px; border-radius: 14px;
  background: #eceff1; color: #263238; font-size: 15px; text-align: center; vertical-align: 2px; }
.tiles { display: flex; flex-wrap: wrap; gap: 12px; margin: 16px 0; }
.tile { border: 1px solid var(--line); border-radius: 8px; padding: 10px 16px; min-width: 112px; background: var(--band); }
.tile b { display: block; font-size: 24px; }
.tile span { color: var(--muted); font-size: 13px; }
.tile.new b { color: #c62828; } .tile.regressed b { color: #ef6c00; } .tile.fixed b { color: #2e7d32; }
table { border-collapse: collapse; width: 100%; margin: 8px 0 16px; }
th, td { text-align: left; vertical-align: top; padding: 8px 10px; border-bottom: 1px solid var(--line); }
th { background: var(--band); font-size: 13px; color: #455a64; }
td.number, th.number { text-align: right; font-variant-numeric: tabular-nums; }
tr:hover td { background: #fafbfc; }
code { font: 13px/1.4 "DejaVu Sans Mono", Menlo, Consolas, monospace; background: #f1f3f4;
  padding: 2px 5px; border-radius: 4px; word-break: break-all; }
.signature { display: block; color: var(--muted); font-size: 13px; margin-top: 2px; word-break: break-word; }
/* Fixed columns: long signatures and commands wrap inside their cells, never widen the page. */
table.failure-modes { table-layout: fixed; }
table.failure-modes td { overflow-wrap: break-word; }
col.picture { width: 222px; } col.seed { width: 14%; } col.responsibility { width: 116px; }
col.seen { width: 176px; } col.replay { width: 22%; }
.thumb img { width: 200px; height: auto; border: 1px solid var(--line); border-radius: 4px; display: block; }
.badge { display: inline-block; padding: 1px 9px; border-radius: 10px; font-size: 13px; font-weight: 600; }
.badge.ego { background: #fdecea; color: #b71c1c; } .badge.other { background: #eceff1; color: #37474f; }
.badge.shared { background: #fff3e0; color: #e65100; } .badge.none { color: var(--muted); font-weight: 400; }
.none-found { color: var(--muted); font-style: italic; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(540px, 1fr)); gap: 18px; }
figure { margin: 0; border: 1px solid var(--line); border-radius: 8px; padding: 12px 14px; }
figcaption { color: var(--muted); font-size: 13px; margin-bottom: 4px; }
svg.chart { width: 100%; height: auto; display: block; font-family: inherit; }
.trend svg.chart { max-width: 960px; }
.empty { border: 1px dashed #b0bec5; border-radius: 8px; padding: 16px 20px; background: var(--band); }
)css";

std::string text(std::string_view raw) {
  std::string escaped;
  append_escaped(escaped, raw);
  return escaped;
}

// A path that may break after each '/' when its column is narrow, never inside a name.
std::string path_text(std::string_view path) {
  std::string html;
  for (const char c : path) {
    append_escaped(html, std::string_view(&c, 1));
    if (c == '/') html += "<wbr>";
  }
  return html;
}

std::string cell(const std::string& html, const char* css_class = nullptr) {
  return css_class ? std::string("<td class=\"") + css_class + "\">" + html + "</td>"
                   : "<td>" + html + "</td>";
}

std::string robustness_text(double value) {
  if (std::isinf(value)) return value < 0 ? "-inf" : "inf";
  return number_text(value, 4);
}

// "2026-11-27T02:00:00Z" as people read it in a table: "2026-11-27 02:00".
std::string short_time(const std::string& iso) {
  if (iso.size() < 16 || iso[10] != 'T') return iso;
  return iso.substr(0, 10) + " " + iso.substr(11, 5);
}

// First and last seen in one cell: "run 1 → run 3", then when each of those runs started.
std::string seen_text(const ReportFailureMode& shown) {
  const CampaignFailureMode& mode = shown.mode;
  std::string html = "run " + std::to_string(mode.first_seen_run) + " → run " +
                     std::to_string(mode.last_seen_run) + "<span class=\"signature\">";
  if (!shown.first_seen_started.empty())
    html += "first " + text(short_time(shown.first_seen_started));
  if (!shown.last_seen_started.empty())
    html += "<br>last " + text(short_time(shown.last_seen_started));
  return html + "</span>";
}

// "1 search", "3 searches".
std::string counted(std::size_t count, const std::string& one, const std::string& many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

std::string responsibility_badge(const std::string& responsibility) {
  if (responsibility == "ego" || responsibility == "other" || responsibility == "shared")
    return "<span class=\"badge " + responsibility + "\">" + responsibility + "</span>";
  if (responsibility.empty()) return "<span class=\"badge none\">none</span>";
  return "<span class=\"badge none\">" + text(responsibility) + "</span>";
}

std::string thumbnail(const ReportFailureMode& mode, const ReportPage& page) {
  if (mode.picture.empty()) return "<span class=\"muted\">no picture</span>";
  const std::string href = text(url_path(page.campaign_prefix + mode.picture));
  return "<a class=\"thumb\" href=\"" + href + "\"><img src=\"" + href +
         "\" alt=\"bird's-eye picture of failure mode " + std::to_string(mode.mode.id) + "\"></a>";
}

std::string failure_mode_row(const ReportFailureMode& shown, const ReportPage& page) {
  const FailureModeRecord& mode = shown.mode.record;
  std::string scenario;
  if (!mode.scenario_file.empty())
    scenario = "<span class=\"signature\">scenario: <a href=\"" +
               text(url_path(page.campaign_prefix + mode.scenario_file)) + "\">" +
               text(mode.scenario_file) + "</a></span>";
  if (!shown.minimised.empty())
    scenario += "<span class=\"signature\"><a href=\"" +
                text(url_path(page.campaign_prefix + shown.minimised)) + "\">minimised</a></span>";
  return "<tr>" + cell(thumbnail(shown, page)) +
         cell("<b>" + text(mode.spec) + "</b><span class=\"signature\">" + text(mode.signature) +
              "</span>") +
         cell(shown.seed_path.empty()
                  ? "<span class=\"muted\">seed " + std::to_string(mode.seed_id) + "</span>"
                  : path_text(shown.seed_path)) +
         cell(responsibility_badge(mode.responsibility)) + cell(seen_text(shown)) +
         cell("<code>" + text(mode.replay_command) + "</code>" + scenario) + "</tr>\n";
}

struct StatusSection {
  FailureModeStatus status;
  const char* id;
  const char* heading;
  const char* meaning;
};

// The failure-mode sections, in the order the issue asks for: what needs attention first.
constexpr std::array<StatusSection, 5> kStatusSections{{
    {FailureModeStatus::new_mode, "new", "New failure modes",
     "Found for the first time, for their seed; no later run has replayed them yet."},
    {FailureModeStatus::regressed, "regressed", "Regressed failure modes",
     "Fixed once, failing again."},
    {FailureModeStatus::still_failing, "still-failing", "Still failing",
     "Known from an earlier run and found (or replayed as failing) again."},
    {FailureModeStatus::flaky, "flaky", "Flaky failure modes",
     "The regression replay failed with some perception seeds and passed with others."},
    {FailureModeStatus::fixed, "fixed", "Fixed failure modes",
     "The regression replay no longer fails with any perception seed."},
}};

std::string failure_mode_section(const ReportData& data, const StatusSection& section,
                                 const ReportPage& page) {
  std::string rows;
  std::size_t count = 0;
  for (const ReportFailureMode& mode : data.failure_modes)
    if (mode.mode.status == section.status) {
      rows += failure_mode_row(mode, page);
      ++count;
    }
  std::string html = "<section id=\"" + std::string(section.id) + "\">\n<h2>" + section.heading +
                     "<span class=\"count\">" + std::to_string(count) +
                     "</span></h2>\n<p class=\"muted\">" + section.meaning + "</p>\n";
  if (count == 0) return html + "<p class=\"none-found\">None.</p>\n</section>\n";
  return html +
         "<table class=\"failure-modes\">\n<colgroup><col class=\"picture\"><col class=\"mode\">"
         "<col class=\"seed\"><col class=\"responsibility\"><col class=\"seen\">"
         "<col class=\"replay\"></colgroup>\n<thead><tr><th>Picture</th><th>Failure mode</th>"
         "<th>Seed</th><th>Responsibility</th><th>First → last seen</th>"
         "<th>Replay (from the campaign folder)</th></tr></thead>\n<tbody>\n" +
         rows + "</tbody>\n</table>\n</section>\n";
}

std::string tile(std::size_t value, const char* label, const char* css_class = "") {
  return "<div class=\"tile " + std::string(css_class) + "\"><b>" + std::to_string(value) +
         "</b><span>" + label + "</span></div>";
}

std::size_t with_status(const ReportData& data, FailureModeStatus status) {
  std::size_t count = 0;
  for (const ReportFailureMode& mode : data.failure_modes) count += mode.mode.status == status;
  return count;
}

std::string runs_table(const ReportData& data) {
  std::string html =
      "<table class=\"runs\">\n<thead><tr><th>Run</th><th>Started (UTC)</th><th>Ended (UTC)</th>"
      "<th>Ego version</th><th class=\"number\">Searches</th><th class=\"number\">Simulations</th>"
      "<th class=\"number\">New</th><th class=\"number\">Failing</th>"
      "<th class=\"number\">Regressed</th><th class=\"number\">Fixed</th></tr></thead>\n<tbody>\n";
  for (const ReportRun& run : data.runs)
    html +=
        "<tr>" + cell(std::to_string(run.run.id)) + cell(text(short_time(run.run.started))) +
        cell(run.run.ended.empty() ? "<span class=\"muted\">not ended (running, or killed)</span>"
                                   : text(short_time(run.run.ended))) +
        cell("<code>" + text(run.run.ego_version) + "</code>") +
        cell(std::to_string(run.searches), "number") +
        cell(std::to_string(run.simulations), "number") +
        cell(std::to_string(run.modes_first_seen), "number") +
        cell(std::to_string(run.modes_seen), "number") +
        cell(std::to_string(run.regressed), "number") + cell(std::to_string(run.fixed), "number") +
        "</tr>\n";
  return html + "</tbody>\n</table>\n";
}

// "run 4", "runs 1 to 3", "runs 1, 3, 5", "12 runs, 1 to 40".
std::string run_ids_text(const std::vector<std::int64_t>& ids) {
  if (ids.size() == 1) return "run " + std::to_string(ids.front());
  const bool consecutive = ids.back() - ids.front() + 1 == static_cast<std::int64_t>(ids.size());
  if (consecutive)
    return "runs " + std::to_string(ids.front()) + " to " + std::to_string(ids.back());
  if (ids.size() > 6)
    return std::to_string(ids.size()) + " runs, " + std::to_string(ids.front()) + " to " +
           std::to_string(ids.back());
  std::string listed = "runs ";
  for (std::size_t i = 0; i < ids.size(); ++i)
    listed += (i == 0 ? "" : ", ") + std::to_string(ids[i]);
  return listed;
}

// "Ego versions: <code>a</code> (runs 1-3), <code>b</code> (run 4)", in the order first run.
std::string ego_versions(const ReportData& data) {
  std::vector<std::pair<std::string, std::vector<std::int64_t>>> versions;
  for (const ReportRun& run : data.runs) {
    auto known = std::find_if(versions.begin(), versions.end(), [&](const auto& entry) {
      return entry.first == run.run.ego_version;
    });
    if (known == versions.end()) known = versions.insert(versions.end(), {run.run.ego_version, {}});
    known->second.push_back(run.run.id);
  }
  std::string html = "<p>Ego versions: ";
  for (std::size_t i = 0; i < versions.size(); ++i) {
    const std::vector<std::int64_t>& ids = versions[i].second;
    html += (i == 0 ? "" : ", ") + std::string("<code>") + text(versions[i].first) + "</code> (" +
            run_ids_text(ids) + ")";
  }
  return html + "</p>\n";
}

std::string summary_section(const ReportData& data, const ReportPage& page) {
  std::string html = "<section id=\"summary\">\n<h2>Summary</h2>\n";
  if (data.runs.empty())
    return html + "<p class=\"empty\">This campaign has no runs yet: <code>scenfuzz campaign run " +
           text(page.campaign_folder) + "</code> starts the first.</p>\n</section>\n";
  std::size_t searches = 0, simulations = 0;
  for (const ReportRun& run : data.runs) {
    searches += run.searches;
    simulations += run.simulations;
  }
  html += "<div class=\"tiles\">" + tile(data.runs.size(), "runs") +
          tile(data.seeds.size(), "seeds") + tile(searches, "searches") +
          tile(simulations, "simulations") +
          tile(with_status(data, FailureModeStatus::new_mode), "new", "new") +
          tile(with_status(data, FailureModeStatus::regressed), "regressed", "regressed") +
          tile(with_status(data, FailureModeStatus::still_failing), "still failing") +
          tile(with_status(data, FailureModeStatus::flaky), "flaky") +
          tile(with_status(data, FailureModeStatus::fixed), "fixed", "fixed") + "</div>\n";
  return html + ego_versions(data) + runs_table(data) + "</section>\n";
}

std::string seed_row(const ReportSeed& seed) {
  const std::string best = seed.best.empty() ? "<span class=\"muted\">none judged</span>"
                                             : robustness_text(seed.best.back().best);
  return "<tr>" + cell(path_text(seed.seed.path)) +
         cell("<code>" + text(seed.seed.content_hash) + "</code>") +
         cell(std::to_string(seed.searches), "number") +
         cell(std::to_string(seed.simulations), "number") +
         cell(std::to_string(seed.judged), "number") + cell(best, "number") +
         cell(std::to_string(seed.failure_modes), "number") +
         cell(std::to_string(seed.features), "number") + "</tr>\n";
}

std::string seeds_section(const ReportData& data) {
  std::string html =
      "<section id=\"seeds\">\n<h2>Seeds<span class=\"count\">" +
      std::to_string(data.seeds.size()) +
      "</span></h2>\n<p class=\"muted\">Per seed scenario, over all its searches in all runs: the "
      "lowest robustness reached so far against the simulations spent (below zero a spec is "
      "violated), the failure modes found, and the behaviour-coverage features its searches "
      "reached (docs/coverage.md; the corpus's total counts each feature once).</p>\n";
  if (data.seeds.empty()) return html + "<p class=\"none-found\">None yet.</p>\n</section>\n";
  html +=
      "<table class=\"seeds\">\n<thead><tr><th>Seed</th><th>Content hash</th>"
      "<th class=\"number\">Searches</th><th class=\"number\">Simulations</th>"
      "<th class=\"number\">Judged</th><th class=\"number\">Best robustness</th>"
      "<th class=\"number\">Failure modes</th><th class=\"number\">Features covered</th>"
      "</tr></thead>\n<tbody>\n";
  for (const ReportSeed& seed : data.seeds) html += seed_row(seed);
  // The corpus's features are a union, not the column's sum: a foot row of its own.
  html += "</tbody>\n<tfoot><tr><th colspan=\"7\">Corpus</th>" +
          cell(std::to_string(data.corpus_features), "number corpus-features") +
          "</tr></tfoot>\n</table>\n<div class=\"charts\">\n";
  for (const ReportSeed& seed : data.seeds)
    html += "<figure>\n<h3>" + text(seed.seed.path) + "</h3>\n<figcaption>" +
            counted(seed.simulations, "simulation", "simulations") + " in " +
            counted(seed.searches, "search", "searches") + "; " +
            counted(seed.failure_modes, "failure mode", "failure modes") + "</figcaption>\n" +
            robustness_chart_svg(seed, "Best robustness so far of " + seed.seed.path) +
            "</figure>\n";
  return html + "</div>\n</section>\n";
}

std::string trend_section(const ReportData& data) {
  return "<section id=\"trend\" class=\"trend\">\n<h2>Trend across runs</h2>\n<p class=\"muted\">"
         "Per run: failure modes failing in it (first seen in it, regressed in it, still "
         "failing), and those fixed by it.</p>\n" +
         trend_chart_svg(data.runs) + "</section>\n";
}

}  // namespace

std::string url_path(const std::string& path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string encoded;
  for (const char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    const bool plain = (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z') ||
                       (byte >= '0' && byte <= '9') || c == '-' || c == '.' || c == '_' ||
                       c == '~' || c == '/';
    if (plain) {
      encoded += c;
    } else {
      encoded += '%';
      encoded += kHex[byte >> 4];
      encoded += kHex[byte & 0xF];
    }
  }
  return encoded;
}

std::string render_report_html(const ReportData& data, const ReportPage& page) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      text(data.name) + " · scenfuzz campaign report</title>\n<style>" + kStyle +
      "</style>\n</head>\n<body>\n<main>\n<header>\n<h1>Campaign " + text(data.name) +
      "</h1>\n<p class=\"muted\">scenfuzz campaign report of <code>" + text(page.campaign_folder) +
      "</code>, written " + text(page.written) + "</p>\n</header>\n";
  html += summary_section(data, page);
  for (const StatusSection& section : kStatusSections)
    html += failure_mode_section(data, section, page);
  html += seeds_section(data) + trend_section(data);
  return html + "</main>\n</body>\n</html>\n";
}

}  // namespace scenfuzz
