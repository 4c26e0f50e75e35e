// parse_campaign_config: the only file that includes toml++. The document is parsed whole, then
// each table is read with its keys checked against the ones it may have; every problem becomes a
// diagnostic at the place toml++ recorded for the key or value, and reading goes on, so a user
// sees all of a file's problems at once.
#include "fuzz/campaign/campaign_config.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <stdexcept>
#include <string_view>

#include "fuzz/evaluator.hpp"
#include "fuzz/options.hpp"
#include "fuzz/search_strategy.hpp"
#include "fuzz/seed_paths.hpp"
#include "lang/number_format.hpp"
#include "lang/source_file.hpp"
#include "sampler/mutation_space.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

// The place toml++ recorded, as a SourceLocation into `file` (offset and length too, so that the
// caret line underlines a value on one line).
std::uint32_t offset_of(const SourceFile& file, std::uint32_t line, std::uint32_t column) {
  const std::string_view text = file.line_text(line);
  if (text.empty()) return 0;
  std::size_t i = 0;
  // Columns count code points: a byte that is not a UTF-8 continuation byte starts one.
  for (std::uint32_t at = 1; i < text.size() && at < column; ++at) {
    ++i;
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  }
  return static_cast<std::uint32_t>(text.data() - file.text().data() + i);
}

SourceLocation location_of(const SourceFile& file, const toml::source_region& region) {
  SourceLocation at;
  at.line = std::max<std::uint32_t>(region.begin.line, 1);
  at.column = std::max<std::uint32_t>(region.begin.column, 1);
  at.offset = offset_of(file, at.line, at.column);
  if (region.end.line == region.begin.line && region.end.column > region.begin.column) {
    const std::uint32_t end = offset_of(file, at.line, region.end.column);
    if (end > at.offset) at.length = end - at.offset;
  }
  return at;
}

std::string type_text(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date or time";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::none: break;
  }
  return "nothing";
}

// A number as the user wrote it, for "found ..." in messages.
std::string value_text(const toml::node& node) {
  if (const auto* integer = node.as_integer()) return std::to_string(integer->get());
  if (const auto* number = node.as_floating_point()) {
    const double value = number->get();
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return format_number(value);
  }
  return type_text(node);
}

// Whether `algorithm` names a search strategy. The strategy factory is the one authority on the
// names --algo accepts, so it is asked (with a one-dimensional space) rather than copied.
std::string algorithm_problem(const std::string& algorithm) {
  const SearchDimension dimension{"x", GeneKind::continuous, 0, "", ""};
  try {
    (void)make_search_strategy(algorithm, std::span(&dimension, 1), 0, 1);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return {};
}

// Reads one campaign.toml into `config`, reporting into `diagnostics`.
struct Reader {
  const SourceFile& source;
  Diagnostics& diagnostics;
  CampaignConfig& config;

  void error(const toml::source_region& where, std::string message) {
    diagnostics.error(location_of(source, where), std::move(message));
  }
  void error_at_start(std::string message) {
    diagnostics.error(SourceLocation{1, 1, 0, 0}, std::move(message));
  }

  // Every key of `table` that is not in `known` is an error naming the ones that are.
  void check_keys(const toml::table& table, const std::string& table_name,
                  std::initializer_list<std::string_view> known) {
    for (const auto& [key, node] : table) {
      (void)node;
      bool found = false;
      for (std::string_view name : known) found = found || key.str() == name;
      if (found) continue;
      std::string names;
      for (std::string_view name : known) names += (names.empty() ? "" : ", ") + std::string(name);
      error(key.source(), "unknown key '" + std::string(key.str()) + "' in " + table_name +
                              "; expected one of: " + names);
    }
  }

  // The table `name` of `parent`, nullptr when absent or (with an error) not a table.
  const toml::table* table(const toml::table& parent, std::string_view name) {
    const toml::node* node = parent.get(name);
    if (node == nullptr) return nullptr;
    if (const toml::table* found = node->as_table()) return found;
    error(node->source(), "'" + std::string(name) + "': expected a table ([" + std::string(name) +
                              "]), found " + type_text(*node));
    return nullptr;
  }

  std::optional<std::string> string(const toml::node& node, const std::string& key) {
    if (const auto* text = node.as_string()) return text->get();
    error(node.source(), "'" + key + "': expected a string, found " + type_text(node));
    return std::nullopt;
  }

  std::optional<std::string> non_empty_string(const toml::node& node, const std::string& key) {
    std::optional<std::string> text = string(node, key);
    if (text && text->empty()) {
      error(node.source(), "'" + key + "': expected a non-empty string");
      return std::nullopt;
    }
    return text;
  }

  // A whole number in [lowest, highest].
  std::optional<std::int64_t> integer(const toml::node& node, const std::string& key,
                                      std::int64_t lowest, std::int64_t highest) {
    const auto* integer = node.as_integer();
    const std::string expected = "'" + key + "': expected a whole number from " +
                                 std::to_string(lowest) + " to " + std::to_string(highest);
    if (integer == nullptr) {
      error(node.source(), expected + ", found " + value_text(node));
      return std::nullopt;
    }
    const std::int64_t value = integer->get();
    if (value < lowest || value > highest) {
      error(node.source(), expected + ", found " + value_text(node));
      return std::nullopt;
    }
    return value;
  }

  // A finite number > 0, whole or not.
  std::optional<double> positive_number(const toml::node& node, const std::string& key) {
    std::optional<double> value;
    if (const auto* integer = node.as_integer()) value = static_cast<double>(integer->get());
    if (const auto* number = node.as_floating_point()) value = number->get();
    if (!value || !std::isfinite(*value) || *value <= 0) {
      error(node.source(),
            "'" + key + "': expected a finite number greater than 0, found " + value_text(node));
      return std::nullopt;
    }
    return value;
  }

  std::optional<std::string> algorithm(const toml::node& node, const std::string& key) {
    std::optional<std::string> name = string(node, key);
    if (!name) return std::nullopt;
    const std::string problem = algorithm_problem(*name);
    if (problem.empty()) return name;
    error(node.source(), "'" + key + "': " + problem);
    return std::nullopt;
  }

  // An array of strings; nullopt (with errors) when it is not one.
  std::optional<std::vector<std::pair<std::string, const toml::node*>>> strings(
      const toml::node& node, const std::string& key) {
    const toml::array* array = node.as_array();
    if (array == nullptr) {
      error(node.source(), "'" + key + "': expected an array of strings ([\"...\", ...]), found " +
                               type_text(node));
      return std::nullopt;
    }
    std::vector<std::pair<std::string, const toml::node*>> items;
    bool ok = true;
    for (const toml::node& item : *array) {
      std::optional<std::string> text = non_empty_string(item, key + " item");
      if (text) items.emplace_back(*text, &item);
      ok = ok && text.has_value();
    }
    if (!ok) return std::nullopt;
    return items;
  }

  void read_campaign(const toml::table& root) {
    const toml::table* campaign = table(root, "campaign");
    if (campaign == nullptr) return;
    check_keys(*campaign, "[campaign]", {"name"});
    if (const toml::node* name = campaign->get("name")) {
      if (auto text = non_empty_string(*name, "campaign.name")) config.name = *text;
    }
  }

  void read_seeds(const toml::table& root) {
    const toml::node* node = root.get("seeds");
    if (node == nullptr) {
      error_at_start(
          "no seeds: expected `seeds = [\"FILE.avu\", \"FOLDER/\", ...]` before the first table");
      return;
    }
    auto entries = strings(*node, "seeds");
    if (!entries) return;
    if (entries->empty()) error(node->source(), "'seeds': expected at least one file or folder");
    std::set<std::string> seen;
    for (const auto& [entry, item] : *entries) {
      config.seed_entries.push_back(entry);
      const SeedExpansion expansion = expand_seed_entry(config.folder, entry);
      if (!expansion.error.empty()) error(item->source(), "'seeds': " + expansion.error);
      for (const std::string& file : expansion.files)
        if (seen.insert(file).second) config.seed_files.push_back(file);
    }
  }

  void read_ego(const toml::table& root) {
    const toml::table* ego = table(root, "ego");
    if (ego == nullptr) {
      config.ego_version = kReferenceEgoVersion;
      return;
    }
    check_keys(*ego, "[ego]", {"plugin", "version"});
    if (const toml::node* plugin = ego->get("plugin")) {
      if (auto text = non_empty_string(*plugin, "ego.plugin")) config.ego_plugin = *text;
    }
    if (const toml::node* version = ego->get("version")) {
      if (auto text = non_empty_string(*version, "ego.version")) config.ego_version = *text;
    } else if (ego->contains("plugin")) {
      error(ego->source(),
            "[ego] names a plugin but no version: expected `version = \"...\"` (a git hash, a "
            "release), which tells one night's ego from the next");
    }
    if (config.ego_version.empty() && !ego->contains("plugin"))
      config.ego_version = kReferenceEgoVersion;
  }

  void read_budget(const toml::table& root) {
    const toml::table* budget = table(root, "budget");
    if (budget == nullptr) {
      if (!root.contains("budget"))
        error_at_start(
            "no [budget]: expected a [budget] table with simulations and/or "
            "wall_seconds");
      return;
    }
    check_keys(*budget, "[budget]", {"simulations", "wall_seconds"});
    const toml::node* simulations = budget->get("simulations");
    const toml::node* wall_seconds = budget->get("wall_seconds");
    if (simulations != nullptr) {
      if (auto value =
              integer(*simulations, "budget.simulations", 1, static_cast<std::int64_t>(kMaxBudget)))
        config.budget_simulations = static_cast<std::uint64_t>(*value);
    }
    if (wall_seconds != nullptr) {
      config.budget_wall_seconds = positive_number(*wall_seconds, "budget.wall_seconds");
    }
    if (simulations == nullptr && wall_seconds == nullptr)
      error(budget->source(),
            "[budget] is empty: expected simulations (a total) and/or "
            "wall_seconds");
  }

  void read_search(const toml::table& root) {
    const toml::table* search = table(root, "search");
    if (search == nullptr) return;
    check_keys(*search, "[search]", {"algo", "seed", "jobs", "mutate", "tmin"});
    if (const toml::node* algo = search->get("algo")) {
      if (auto name = algorithm(*algo, "search.algo")) config.search.algorithm = *name;
    }
    if (const toml::node* seed = search->get("seed")) {
      // TOML's integers are 64-bit signed: --seed's upper half cannot be written here.
      const std::int64_t highest = std::numeric_limits<std::int64_t>::max();
      if (auto value = integer(*seed, "search.seed", 0, highest))
        config.search.seed = static_cast<std::uint64_t>(*value);
    }
    if (const toml::node* jobs = search->get("jobs")) {
      if (auto value = integer(*jobs, "search.jobs", 0, static_cast<std::int64_t>(kMaxJobs)))
        config.search.jobs = static_cast<std::size_t>(*value);
    }
    if (const toml::node* mutate = search->get("mutate")) read_mutate(*mutate);
    if (const toml::node* tmin = search->get("tmin")) {
      if (tmin->is_boolean())
        config.search.tmin = tmin->as_boolean()->get();
      else
        error(tmin->source(), "'search.tmin': expected true or false, found " + type_text(*tmin));
    }
  }

  // `mutate = ["speed=2", ...]`, each item as a --mutate option.
  void read_mutate(const toml::node& node) {
    auto items = strings(node, "search.mutate");
    if (!items) return;
    MutationSizes sizes;
    for (const auto& [item, where] : *items) {
      if (std::optional<std::string> problem = apply_mutation_option(item, sizes))
        error(where->source(), "'search.mutate': " + *problem);
      config.search.mutate.push_back(item);
    }
  }

  void read_seed_override(const toml::table& table, std::map<std::string, std::uint32_t>& lines) {
    check_keys(table, "[[seed]]", {"path", "budget_share", "algo", "scenario"});
    CampaignSeedOverride seed;
    const toml::node* path = table.get("path");
    if (path == nullptr) {
      error(table.source(),
            "[[seed]] without a path: expected `path = \"...\"`, one of the "
            "files `seeds` lists");
      return;
    }
    auto text = non_empty_string(*path, "seed.path");
    if (!text) return;
    seed.path = seed_key(*text);
    seed.location = location_of(source, path->source());
    if (std::find(config.seed_files.begin(), config.seed_files.end(), seed.path) ==
        config.seed_files.end())
      error(path->source(), "'seed.path': '" + *text + "' is not one of the " +
                                std::to_string(config.seed_files.size()) +
                                " scenario files `seeds` stands for");
    const auto [earlier, first] = lines.emplace(seed.path, seed.location.line);
    if (!first)
      error(path->source(), "a second [[seed]] for '" + *text + "' (the first is on line " +
                                std::to_string(earlier->second) + ")");
    if (const toml::node* share = table.get("budget_share")) {
      if (auto value = positive_number(*share, "seed.budget_share")) seed.budget_share = *value;
    }
    if (const toml::node* algo = table.get("algo")) seed.algorithm = algorithm(*algo, "seed.algo");
    if (const toml::node* scenario = table.get("scenario"))
      if (auto name = non_empty_string(*scenario, "seed.scenario")) seed.scenario = *name;
    config.seed_overrides.push_back(std::move(seed));
  }

  void read_seed_overrides(const toml::table& root) {
    const toml::node* node = root.get("seed");
    if (node == nullptr) return;
    const toml::array* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
      error(node->source(),
            "'seed': expected [[seed]] tables (path = ..., budget_share = ..., "
            "algo = ...), found " +
                type_text(*node));
      return;
    }
    std::map<std::string, std::uint32_t> lines;
    for (const toml::node& item : *array) read_seed_override(*item.as_table(), lines);
  }

  void read_map_paths(const toml::table& root) {
    const toml::node* node = root.get("map_paths");
    if (node == nullptr) return;
    if (auto entries = strings(*node, "map_paths"))
      for (const auto& entry : *entries) config.map_paths.push_back(entry.first);
  }

  void read(const toml::table& root) {
    check_keys(root, "campaign.toml",
               {"seeds", "map_paths", "campaign", "ego", "budget", "search", "seed"});
    read_campaign(root);
    read_seeds(root);
    read_ego(root);
    read_budget(root);
    read_search(root);
    read_seed_overrides(root);
    read_map_paths(root);
  }
};

fs::path campaign_folder(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  return folder.empty() ? fs::path(".") : folder;
}

// The default campaign name: the folder's own name ("nightly" for "ci/nightly/campaign.toml").
std::string folder_name(const fs::path& folder) {
  std::error_code error;
  fs::path absolute = fs::absolute(folder, error).lexically_normal();
  if (!absolute.has_filename()) absolute = absolute.parent_path();
  return absolute.filename().string();
}

}  // namespace

CampaignConfigResult parse_campaign_config(const std::string& text, const std::string& path) {
  CampaignConfigResult result;
  const SourceFile file(path, text);
  CampaignConfig config;
  config.folder = campaign_folder(path);
  config.name = folder_name(config.folder);
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& error) {
    result.diagnostics.error(location_of(file, error.source()),
                             "not valid TOML: " + std::string(error.description()));
    return result;
  }
  Reader reader{file, result.diagnostics, config};
  reader.read(root);
  if (!result.diagnostics.has_errors()) result.config = std::move(config);
  return result;
}

}  // namespace scenfuzz
