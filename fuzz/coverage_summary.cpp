// coverage_summary_json: the counts per family next to the sorted names (a std::set is sorted).
#include "fuzz/coverage_summary.hpp"

#include "lang/demand.hpp"

namespace scenfuzz {

nlohmann::json coverage_summary_json(const std::set<std::string>& features) {
  nlohmann::json by_family = nlohmann::json::object();
  for (const char* family : kCoverageFamilies) by_family[family] = 0;
  nlohmann::json names = nlohmann::json::array();
  for (const std::string& feature : features) {
    const std::string family = feature.substr(0, feature.find('.'));
    // behaviour_coverage and law_coverage name no other family.
    SCENFUZZ_DEMAND(by_family.contains(family));
    by_family[family] = by_family[family].get<std::size_t>() + 1;
    names.push_back(feature);
  }
  return {{"features", features.size()}, {"names", names}, {"by_family", by_family}};
}

}  // namespace scenfuzz
