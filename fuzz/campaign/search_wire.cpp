// JSON (nlohmann) as the wire format: a few kilobytes per search besides the pictures, read
// once per search, so its cost is nothing beside the simulations. Robustness may be ±infinity,
// which JSON has no number for: it travels as the strings "inf" and "-inf".
#include "fuzz/campaign/search_wire.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fuzz/atomic_file.hpp"
#include "fuzz/campaign/mode_files.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

double read_number(const json& value) {
  if (value.is_string())
    return (value.get<std::string>() == "inf" ? 1 : -1) * std::numeric_limits<double>::infinity();
  return value.get<double>();
}

json optional_number(const std::optional<double>& value) {
  return value ? number(*value) : json(nullptr);
}

std::optional<double> read_optional_number(const json& value) {
  if (value.is_null()) return std::nullopt;
  return read_number(value);
}

json summary_json(const SearchSummary& summary) {
  return {{"evaluations", summary.evaluations},
          {"judged", summary.judged},
          {"failed", summary.failed},
          {"infeasible", summary.infeasible},
          {"wall_seconds", summary.wall_seconds},
          {"stop", static_cast<int>(summary.stop)}};
}

SearchSummary read_summary(const json& value) {
  SearchSummary summary;
  summary.evaluations = value.at("evaluations").get<std::size_t>();
  summary.judged = value.at("judged").get<std::size_t>();
  summary.failed = value.at("failed").get<std::size_t>();
  summary.infeasible = value.at("infeasible").get<std::size_t>();
  summary.wall_seconds = value.at("wall_seconds").get<double>();
  summary.stop = static_cast<StopReason>(value.at("stop").get<int>());
  return summary;
}

}  // namespace

std::string encode_task(const CampaignSearchTask& task) {
  return json{{"arm", task.arm},         {"budget", task.budget}, {"seed", task.seed},
              {"threads", task.threads}, {"folder", task.folder}, {"time_limit", task.time_limit}}
      .dump();
}

CampaignSearchTask decode_task(const std::string& bytes) {
  const json value = json::parse(bytes);
  CampaignSearchTask task;
  task.arm = value.at("arm").get<std::size_t>();
  task.budget = value.at("budget").get<std::uint64_t>();
  task.seed = value.at("seed").get<std::uint64_t>();
  task.threads = value.at("threads").get<std::size_t>();
  task.folder = value.at("folder").get<std::string>();
  task.time_limit = value.at("time_limit").get<double>();
  return task;
}

std::string encode_result(const CampaignSearchResult& result, const std::vector<WireFile>& files) {
  json evaluations = json::array();
  for (const CampaignEvaluation& evaluation : result.evaluations)
    evaluations.push_back(
        {evaluation.index, optional_number(evaluation.robustness), evaluation.finding});
  json modes = json::array();
  for (const FoundMode& mode : result.modes)
    modes.push_back({{"signature", mode.signature},
                     {"spec", mode.spec},
                     {"responsibility", mode.responsibility},
                     {"finding_file", mode.finding_file},
                     {"seed", mode.seed}});
  json sent = json::array();
  for (const WireFile& file : files) sent.push_back({file.path, file.content});
  return json{{"interrupted", result.interrupted},
              {"error", result.error},
              {"summary", summary_json(result.summary)},
              {"evaluations", std::move(evaluations)},
              {"modes", std::move(modes)},
              {"best", optional_number(result.best)},
              {"coverage", result.coverage},
              {"files", std::move(sent)}}
      .dump();
}

CampaignSearchResult decode_result(const std::string& bytes, std::vector<WireFile>& files) {
  const json value = json::parse(bytes);
  CampaignSearchResult result;
  result.interrupted = value.at("interrupted").get<bool>();
  result.error = value.at("error").get<std::string>();
  result.summary = read_summary(value.at("summary"));
  for (const json& row : value.at("evaluations"))
    result.evaluations.push_back(
        {row.at(0).get<std::int64_t>(), read_optional_number(row.at(1)), row.at(2).get<bool>()});
  for (const json& mode : value.at("modes"))
    result.modes.push_back(
        {mode.at("signature").get<std::string>(), mode.at("spec").get<std::string>(),
         mode.at("responsibility").get<std::string>(), mode.at("finding_file").get<std::string>(),
         mode.at("seed").get<std::uint64_t>()});
  result.best = read_optional_number(value.at("best"));
  result.coverage = value.at("coverage").get<std::vector<std::string>>();
  files.clear();
  for (const json& file : value.at("files"))
    files.push_back({file.at(0).get<std::string>(), file.at(1).get<std::string>()});
  return result;
}

std::vector<WireFile> finding_files(const CampaignSearchResult& result, std::string& error) {
  std::vector<WireFile> files;
  for (const FoundMode& mode : result.modes) {
    const fs::path finding = mode.finding_file;
    for (const char* suffix : kModeSidecars) {
      const fs::path sidecar = finding.parent_path() / (finding.stem().string() + suffix);
      WireFile file{sidecar.generic_string(), ""};
      if (read_whole_file(sidecar, file.content)) files.push_back(std::move(file));
    }
    WireFile file{finding.generic_string(), ""};
    if (!read_whole_file(finding, file.content)) {
      error = "cannot read the finding '" + file.path + "'";
      return {};
    }
    files.push_back(std::move(file));
  }
  return files;
}

std::string place_files(const std::vector<WireFile>& files) {
  for (const WireFile& file : files) {
    std::error_code failure;
    if (fs::exists(file.path, failure)) continue;  // a shared disk: the worker's own copy
    fs::create_directories(fs::path(file.path).parent_path(), failure);
    if (std::string error = write_file_atomically(file.path, file.content); !error.empty())
      return error;
  }
  return "";
}

}  // namespace scenfuzz
