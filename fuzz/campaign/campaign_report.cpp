// run_campaign_report: opens the database read-only, names the campaign from campaign.toml (the
// folder's name when it has none or cannot be read), loads the data, renders the page and writes
// it where the pictures' relative links resolve.
#include "fuzz/campaign/campaign_report.hpp"

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "fuzz/atomic_file.hpp"
#include "fuzz/campaign/campaign_config.hpp"
#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/campaign_report_data.hpp"
#include "fuzz/campaign/campaign_report_html.hpp"
#include "fuzz/cli.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

// [campaign] name, else the folder's name. A campaign.toml with errors does not stop the report
// (it shows the database); a warning says why the title is the folder's name.
std::string campaign_name(const fs::path& dir, std::ostream& err) {
  const fs::path folder = fs::absolute(dir).lexically_normal();
  std::string fallback = folder.filename().string();
  if (fallback.empty()) fallback = folder.parent_path().filename().string();
  const fs::path toml = dir / "campaign.toml";
  std::ifstream in(toml, std::ios::binary);
  if (!in) return fallback;
  std::ostringstream text;
  text << in.rdbuf();
  const CampaignConfigResult result = parse_campaign_config(text.str(), toml.string());
  if (result.config) return result.config->name;
  err << "scenfuzz: warning: " << toml.string()
      << " has errors (scenfuzz campaign run names them); the report is titled '" << fallback
      << "'\n";
  return fallback;
}

// The campaign folder as seen from the report's folder, '/'-terminated ("" when the same).
std::string campaign_prefix(const fs::path& dir, const fs::path& report) {
  const fs::path from = fs::absolute(report).lexically_normal().parent_path();
  const fs::path relative = fs::absolute(dir).lexically_normal().lexically_relative(from);
  const std::string prefix = relative.generic_string();
  if (prefix.empty() || prefix == "." || prefix == "./") return "";
  return prefix.ends_with('/') ? prefix : prefix + "/";
}

}  // namespace

int run_campaign_report(const CampaignReportOptions& options, std::ostream& out,
                        std::ostream& err) {
  const fs::path dir = options.dir;
  CampaignDbOpening opening = CampaignDb::open_for_reading(dir);
  if (!opening.db) {
    err << "scenfuzz: error: " << opening.error << "\n";
    return kExitBadInput;
  }
  const fs::path report = options.out.empty() ? dir / "report.html" : fs::path(options.out);
  ReportData data;
  try {
    data = load_report_data(*opening.db, dir, campaign_name(dir, err));
  } catch (const CampaignDbError& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return kExitBadInput;
  }
  const ReportPage page{campaign_prefix(dir, report), options.dir, utc_now()};
  if (const std::string problem = write_file_atomically(report, render_report_html(data, page));
      !problem.empty()) {
    err << "scenfuzz: error: " << problem << "\n";
    return kExitBadInput;
  }
  out << "scenfuzz: wrote " << report.string() << " (" << data.runs.size() << " runs, "
      << data.failure_modes.size() << " failure modes)\n";
  return kExitSuccess;
}

}  // namespace scenfuzz
