// The campaign report as one self-contained HTML page: inline CSS, inline SVG charts, no script
// and nothing fetched but the failure modes' pictures, linked by relative paths so the report and
// the campaign folder can be copied or served statically together. Sections in the order an
// engineer reads them: summary, new, regressed, still failing, flaky and fixed failure modes,
// seeds with their charts, the trend across runs. Every text from the database is escaped.
#pragma once

#include <string>

#include "fuzz/campaign/campaign_report_data.hpp"

namespace scenfuzz {

struct ReportPage {
  // The campaign folder as seen from the report's folder ("" when the report is inside it, else
  // e.g. "../nightly/"), prefixed to the pictures' and scenario files' paths.
  std::string campaign_prefix;
  std::string campaign_folder;  // as the user named it, for the replay instructions
  std::string written;          // when the report was written, UTC
};

std::string render_report_html(const ReportData& data, const ReportPage& page);

// `path` (generic form, '/'-separated) as a URL path: every byte but letters, digits, '-', '.',
// '_', '~' and '/' percent-encoded, so a file name with a space, '#', '?' or '%' still links.
std::string url_path(const std::string& path);

}  // namespace scenfuzz
