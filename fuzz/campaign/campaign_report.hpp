// `scenfuzz campaign report DIR [--out FILE]`: writes the campaign's static HTML report (one
// self-contained file; the failure modes' pictures are linked from DIR/modes/) from its database,
// read without the run lock, so a report can be written while a run runs.
#pragma once

#include <ostream>
#include <string>

namespace scenfuzz {

struct CampaignReportOptions {
  std::string dir;  // DIR: the campaign folder
  std::string out;  // --out FILE; empty: DIR/report.html
};

// Writes the report (atomically) and says where on `out`. kExitBadInput, with the reason on
// `err`, when DIR has no campaign.db or it cannot be read, or the report cannot be written.
int run_campaign_report(const CampaignReportOptions& options, std::ostream& out, std::ostream& err);

}  // namespace scenfuzz
