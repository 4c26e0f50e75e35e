// The search's progress report: a line rewritten in place on a terminal, a plain line every few
// seconds otherwise, JSON lines with --json, nothing with --quiet.
#pragma once

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"

namespace scenfuzz {

class ProgressReport {
 public:
  ProgressReport(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err);

  // Reports unless the last report is too recent (0.2 s on a terminal, 5 s otherwise) and
  // `force` is false.
  void update(std::size_t judged, const std::vector<double>& best,
              const std::vector<std::string>& objectives, std::size_t findings, bool force);

  // Ends the line rewritten in place, so that what follows starts on a line of its own.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;

  const FuzzCommandOptions& options_;
  std::ostream& out_;
  std::ostream& err_;
  bool terminal_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_{};
};

}  // namespace scenfuzz
