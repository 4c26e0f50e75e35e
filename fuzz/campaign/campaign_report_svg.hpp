// The campaign report's charts, drawn as inline SVG by our own code (no JavaScript, no library,
// nothing fetched), so the report reads offline and in any browser: a seed's best robustness so
// far against the simulations spent, and the failure modes of each run. Every text is escaped.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_report_data.hpp"

namespace scenfuzz {

// Tick values for an axis from `low` to `high` (low < high): about `wanted` round numbers (1, 2
// or 5 times a power of ten apart) within the range, ends included when round.
std::vector<double> axis_ticks(double low, double high, int wanted);

// A step line of the seed's best robustness so far against its simulations, the zero line (below
// it a spec is violated) marked, each run's start marked, axes with ticks and labels. `title`
// names the chart for screen readers.
std::string robustness_chart_svg(const ReportSeed& seed, const std::string& title);

// Per run, a stacked bar of the failure modes seen (first seen in the run, regressed in it, the
// rest still failing) and a bar of those fixed by it, with a legend.
std::string trend_chart_svg(const std::vector<ReportRun>& runs);

}  // namespace scenfuzz
