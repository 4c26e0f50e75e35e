#include "fuzz/progress_report.hpp"

#include <unistd.h>

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fuzz/report_format.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz {

ProgressReport::ProgressReport(const FuzzCommandOptions& options, std::ostream& out,
                               std::ostream& err)
    : options_(options), out_(out), err_(err), terminal_(::isatty(STDERR_FILENO) != 0) {}

void ProgressReport::update(std::size_t judged, const std::vector<double>& best,
                            const std::vector<std::string>& objectives, std::size_t findings,
                            bool force) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double since = std::chrono::duration<double>(Clock::now() - last_).count();
  if (!force && since < (terminal_ ? 0.2 : 5.0)) return;
  last_ = Clock::now();
  double best_value = INFINITY;
  std::string best_name;
  for (std::size_t k = 0; k < best.size(); ++k)
    if (best[k] < best_value) best_value = best[k], best_name = objectives[k];
  const double rate = elapsed > 0 ? static_cast<double>(judged) / elapsed : 0;
  if (options_.json) {
    out_ << nlohmann::json{{"event", "progress"},
                           {"evaluations", judged},
                           {"budget", options_.budget},
                           {"rate", std::round(rate * 100) / 100},
                           {"best", robustness_json(best_value)},
                           {"findings", findings}}
                .dump()
         << "\n"
         << std::flush;
    return;
  }
  if (options_.quiet) return;
  std::ostringstream line;
  line << judged << "/" << options_.budget << " simulations, " << std::fixed << std::setprecision(1)
       << rate << "/s, best "
       << (best_name.empty()
               ? std::string("-")
               : format_number(std::round(best_value * 1000) / 1000) + " (" + best_name + ")")
       << ", " << findings << (findings == 1 ? " finding" : " findings");
  if (terminal_)
    err_ << "\r\033[K" << line.str() << std::flush;
  else
    err_ << line.str() << "\n";
}

void ProgressReport::finish() {
  if (terminal_ && !options_.quiet && !options_.json) err_ << "\n";
}

}  // namespace scenfuzz
