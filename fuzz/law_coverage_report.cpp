// law_coverage_json / law_coverage_text: the law specs' sub-violations grouped per spec, each
// reached one with its formula printed as AVUnit (what the user can read and search for).
#include "fuzz/law_coverage_report.hpp"

#include "lang/avunit/avunit.hpp"

namespace scenfuzz {

namespace {

// The indices into `subs` of each law spec's sub-violations, in the scenario's order of specs.
std::map<std::size_t, std::vector<std::size_t>> by_spec(const std::vector<LawSubViolation>& subs) {
  std::map<std::size_t, std::vector<std::size_t>> groups;
  for (std::size_t j = 0; j < subs.size(); ++j) groups[subs[j].spec].push_back(j);
  return groups;
}

}  // namespace

void note_first_reached(const std::vector<std::string>& coverage, std::size_t index,
                        FirstReached& first) {
  for (const std::string& feature : coverage)
    if (feature.starts_with("law.")) first.emplace(feature, index);
}

nlohmann::json law_coverage_json(const ScenarioTemplate& scenario,
                                 const std::vector<LawSubViolation>& subs,
                                 const FirstReached& first) {
  nlohmann::json specs = nlohmann::json::array();
  for (const auto& [spec, members] : by_spec(subs)) {
    nlohmann::json reached = nlohmann::json::array(), unreached = nlohmann::json::array();
    for (std::size_t j : members) {
      const auto found = first.find(subs[j].name);
      if (found == first.end()) {
        unreached.push_back(subs[j].name);
        continue;
      }
      reached.push_back(
          {{"name", subs[j].name},
           {"formula", avunit::print_formula(scenario, scenario.specs[spec], subs[j].formula)},
           {"first_evaluation", found->second}});
    }
    specs.push_back({{"spec", scenario.specs[spec].name},
                     {"covered", reached.size()},
                     {"of", members.size()},
                     {"reached", reached},
                     {"unreached", unreached}});
  }
  return specs;
}

std::string law_coverage_text(const ScenarioTemplate& scenario,
                              const std::vector<LawSubViolation>& subs, const FirstReached& first) {
  std::string text;
  for (const auto& [spec, members] : by_spec(subs)) {
    std::string lines;
    std::size_t covered = 0;
    for (std::size_t j : members) {
      const auto found = first.find(subs[j].name);
      if (found == first.end()) continue;
      ++covered;
      lines += "  " + subs[j].name + " (evaluation " + std::to_string(found->second) +
               "): " + avunit::print_formula(scenario, scenario.specs[spec], subs[j].formula) +
               "\n";
    }
    text += "law coverage of " + scenario.specs[spec].name + ": " + std::to_string(covered) +
            " of " + std::to_string(members.size()) + " sub-violations" +
            (covered > 0 ? ":\n" : "\n") + lines;
  }
  return text;
}

}  // namespace scenfuzz
