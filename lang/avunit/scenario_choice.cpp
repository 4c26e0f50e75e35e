#include "lang/avunit/scenario_choice.hpp"

#include <algorithm>

namespace scenfuzz::avunit {

namespace {

// Where the command line's choice is named in messages: the option itself.
constexpr const char* kOption = "--scenario";

std::string traces_text(const std::vector<std::string>& traces) {
  std::string text;
  for (const std::string& trace : traces) text += (text.empty() ? "" : ", ") + trace;
  return text;
}

void report_unknown(const std::vector<ScenarioCandidate>& candidates, const std::string& name,
                    Diagnostics& diagnostics) {
  if (candidates.empty()) {
    diagnostics.error(SourceLocation{1, 1, 0, 0}, std::string("there is no scenario '") + name +
                                                      "' (" + kOption +
                                                      "): this file builds no scenario");
    return;
  }
  diagnostics.error(candidates.front().location,
                    std::string("there is no scenario '") + name + "' (" + kOption +
                        "): this file " + (candidates.size() == 1 ? "has only " : "has ") +
                        candidate_list(candidates));
}

void report_several(const std::vector<ScenarioCandidate>& candidates,
                    const ScenarioRequest& request, Diagnostics& diagnostics) {
  const std::string which = std::string(request.executed ? "executes " : "creates ") +
                            std::to_string(candidates.size()) +
                            " scenarios: " + candidate_list(candidates);
  if (request.survey) {
    diagnostics.note(candidates[1].location, "this file " + which + "; `run`, the search and " +
                                                 "`space` take " + kOption + " NAME to choose one");
    return;
  }
  diagnostics.error(candidates[1].location,
                    "this file " + which + ": choose one with " + kOption + " NAME" +
                        (request.executed ? "" : " or with 'Trace trace = EXE(scenario);'"));
}

}  // namespace

std::string candidate_list(const std::vector<ScenarioCandidate>& candidates) {
  std::string text;
  for (const ScenarioCandidate& candidate : candidates) {
    if (!text.empty()) text += ", ";
    text += candidate.name;
    if (!candidate.traces.empty()) text += " (" + traces_text(candidate.traces) + ")";
  }
  return text;
}

std::optional<std::size_t> choose_scenario(const std::vector<ScenarioCandidate>& candidates,
                                           const ScenarioRequest& request,
                                           Diagnostics& diagnostics) {
  if (!request.name.empty()) {
    auto found = std::find_if(candidates.begin(), candidates.end(),
                              [&](const ScenarioCandidate& c) { return c.name == request.name; });
    if (found != candidates.end()) return static_cast<std::size_t>(found - candidates.begin());
    report_unknown(candidates, request.name, diagnostics);
    return std::nullopt;
  }
  if (candidates.empty()) return std::nullopt;
  if (candidates.size() > 1) {
    report_several(candidates, request, diagnostics);
    if (!request.survey) return std::nullopt;
  }
  return 0;
}

}  // namespace scenfuzz::avunit
