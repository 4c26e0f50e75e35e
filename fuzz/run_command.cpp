// `scenfuzz run FILE`: simulate one concrete scenario (or one point of a logical one) and report
// what happened; write the trace (CSV, JSON), a bird's-eye SVG and the concrete scenario.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "fuzz/atomic_file.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/collision_report.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/ego_failure_report.hpp"
#include "fuzz/options.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_language.hpp"
#include "lang/number_format.hpp"
#include "lang/parameter_provenance.hpp"
#include "oracle/actor_interaction.hpp"
#include "oracle/judge.hpp"
#include "oracle/responsibility.hpp"
#include "oracle/robustness.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "physics/trace/trace_export.hpp"
#include "physics/trace/trace_svg.hpp"
#include "sampler/mutation_space.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

// A point of the unit cube: its middle, or uniform random from the seed.
std::vector<double> unit_point(std::size_t dimensions, const std::string& at, std::uint64_t seed) {
  std::vector<double> point(dimensions, 0.5);
  if (at != "random") return point;
  std::mt19937_64 random(seed);
  // 53 random bits to [0, 1), the same on every standard library.
  for (double& u : point) u = static_cast<double>(random() >> 11) * 0x1.0p-53;
  return point;
}

std::string place_of(const SourceFile& file, const SourceLocation& location) {
  return file.path() + ":" + std::to_string(location.line) + ":" + std::to_string(location.column);
}

// "by 'dis(...) <= 2' (file:3:9)": the responsible atom.
std::string atom_of(const SourceFile& file, const SpecVerdict& verdict) {
  if (verdict.atom.known())
    return " by '" + verdict.atom_text + "' (" + place_of(file, verdict.atom) + ")";
  return verdict.atom_text.empty() ? "" : ": " + verdict.atom_text;
}

// Nine decimals read better than the 17 digits a double may need; --json has them all.
std::string robustness_text(double robustness) {
  return format_number(std::round(robustness * 1e9) / 1e9);
}

// " at 2 s": a verdict's time to the millisecond.
std::string at_time(double time) {
  return " at " + format_number(std::round(time * 1000) / 1000) + " s";
}

std::string describe_verdict(const SourceFile& file, const SpecVerdict& verdict, double grace) {
  if (!verdict.judged())
    return "spec " + verdict.name + ": not judged: " +
           (verdict.not_judged_at.known() ? place_of(file, verdict.not_judged_at) + ": " : "") +
           verdict.not_judged;
  const std::string at = at_time(verdict.time);
  if (verdict.ending == VerdictEnding::time_out)
    return "spec " + verdict.name +
           ": time-out: the run ended while the ego still made progress (" + verdict.progress +
           "); robustness " + robustness_text(verdict.robustness_as_observed) + at +
           atom_of(file, verdict) + " as it ended, " + robustness_text(verdict.robustness) +
           " had it gone on";
  if (verdict.ending == VerdictEnding::start)
    return "spec " + verdict.name + ": start-state: violated" + at + atom_of(file, verdict) +
           " (robustness " + robustness_text(verdict.robustness_as_observed) +
           ") by the scenario's start state; holds from " + format_number(grace) +
           " s on (robustness " + robustness_text(verdict.robustness) + ")";
  if (verdict.ending == VerdictEnding::other_fault)
    return "spec " + verdict.name + ": other-fault: violated" + at + atom_of(file, verdict) +
           " (robustness " + robustness_text(verdict.robustness_as_observed) + ") only once " +
           verdict.other +
           ", whose collision with the ego was not the ego's fault, brought the danger" +
           at_time(verdict.danger_from) + "; holds before (robustness " +
           robustness_text(verdict.robustness) + ")";
  std::string text = "spec " + verdict.name + ": robustness " + robustness_text(verdict.robustness);
  if (!verdict.violated()) return text + " (satisfied)";
  text += at + ", violated" + atom_of(file, verdict);
  // The driver's share is what the line leads with; the start state's worse value follows.
  if (verdict.start_excused)
    text += " (from the start state " + robustness_text(verdict.robustness_as_observed) +
            at_time(verdict.time_as_observed) + ")";
  if (verdict.ending == VerdictEnding::stuck)
    text += "; stuck: the run ended before it could hold, and the ego " + verdict.progress;
  return text;
}

// "satisfied", "violated", "time-out", "start-state", "other-fault": a spec's verdict in words.
std::string verdict_word(const SpecVerdict& verdict) {
  if (!verdict.judged()) return "not judged";
  if (verdict.ending == VerdictEnding::time_out || verdict.ending == VerdictEnding::start ||
      verdict.ending == VerdictEnding::other_fault)
    return std::string(verdict_ending_name(verdict.ending));
  return verdict.violated() ? "violated" : "satisfied";
}

nlohmann::json verdicts_json(const SourceFile& file, const std::vector<SpecVerdict>& verdicts,
                             double grace) {
  nlohmann::json specs = nlohmann::json::array();
  for (const SpecVerdict& verdict : verdicts) {
    nlohmann::json spec = {
        {"name", verdict.name},           {"robustness", robustness_json(verdict.robustness)},
        {"violated", verdict.violated()}, {"verdict", verdict_word(verdict)},
        {"time", verdict.time},           {"atom", verdict.atom_text}};
    if (verdict.atom.known()) spec["atom_location"] = place_of(file, verdict.atom);
    if (!verdict.judged()) {
      spec["robustness"] = nullptr;
      spec["not_judged"] = verdict.not_judged;
      if (verdict.not_judged_at.known())
        spec["not_judged_location"] = place_of(file, verdict.not_judged_at);
    }
    if (verdict.ending != VerdictEnding::decided || verdict.start_excused)
      spec["robustness_as_observed"] = robustness_json(verdict.robustness_as_observed);
    if (verdict.ending == VerdictEnding::other_fault) {
      spec["other"] = verdict.other;
      spec["danger_from"] = verdict.danger_from;
    }
    if (verdict.ending == VerdictEnding::time_out)  // its name before start-state shared it
      spec["robustness_at_end"] = robustness_json(verdict.robustness_as_observed);
    if (verdict.start_excused) spec["time_as_observed"] = verdict.time_as_observed;
    if (verdict.ending == VerdictEnding::start || verdict.start_excused)
      spec["start_grace"] = grace;
    if (verdict.ending != VerdictEnding::decided) {
      spec["ending"] = verdict_ending_name(verdict.ending);
      if (!verdict.progress.empty() || verdict.ending == VerdictEnding::time_out ||
          verdict.ending == VerdictEnding::stuck)
        spec["progress"] = verdict.progress;
    }
    specs.push_back(spec);
  }
  return specs;
}

// Seconds to the millisecond, as the collisions print them.
std::string seconds(double time) { return format_number(std::round(time * 1000) / 1000) + " s"; }

// Four significant digits: enough to compare a value with its limit (--json has them all).
std::string approx(double value) {
  if (value == 0 || !std::isfinite(value)) return format_number(value);
  const double scale = std::pow(10.0, 3 - std::floor(std::log10(std::abs(value))));
  return format_number(std::round(value * scale) / scale);
}

// "first at 0.05 s, 23 samples": where a check first failed and how often.
std::string extent(const AuditIssue& issue) {
  return "first at " + seconds(issue.time) + ", " + std::to_string(issue.samples) + " samples";
}

// One line of the audit: what the actor did, its worst value against the limit, and when.
std::string describe_audit_issue(const AuditIssue& issue) {
  const std::string who = "audit: " + issue.actor_name + " ";
  const std::string at = " at " + seconds(issue.worst_time);
  switch (issue.kind) {
    case AuditKind::off_road: {
      std::string text = who + "off the road from " + seconds(issue.worst_time) + " for " +
                         seconds(issue.worst) + " (grace " + seconds(issue.limit) + ")";
      if (issue.time < issue.worst_time) text += ", first off from " + seconds(issue.time);
      return text;
    }
    case AuditKind::speed_limit:
      return who + "at " + approx(issue.worst) + " m/s" + at + ", above its class's " +
             approx(issue.limit) + " m/s (" + extent(issue) + ")";
    case AuditKind::lateral_acceleration:
      return who + "cornering at " + approx(issue.worst) + " m/s^2" + at +
             ", above its class's grip of " + approx(issue.limit) + " m/s^2 (" + extent(issue) +
             ")";
    case AuditKind::acceleration:
      return who + "accelerating at " + approx(issue.worst) + " m/s^2" + at +
             ", beyond its class's " + approx(issue.limit) + " m/s^2 (" + extent(issue) + ")";
    case AuditKind::turning_radius:
      return who + "turning at " + approx(issue.worst) + " rad/s" + at +
             ", tighter than full lock allows at its speed (" + approx(issue.limit) + " rad/s; " +
             extent(issue) + ")";
    case AuditKind::yaw_rate_inconsistent:
      return who + "yaw rate " + approx(issue.worst) + " rad/s off the heading's derivative" + at +
             " (tolerance " + approx(issue.limit) + " rad/s; " + extent(issue) + ")";
    case AuditKind::npc_overlap:
      return who + "overlaps " + issue.other_name + " from " + seconds(issue.time);
  }
  return who + std::string(audit_kind_name(issue.kind));
}

// Whether the actors came near the ego's path, and the nearest each came (actor_interaction.hpp).
nlohmann::json interaction_json(const Trace& trace, const std::vector<ActorApproach>& approaches) {
  nlohmann::json nearest = nlohmann::json::array();
  for (const ActorApproach& a : approaches)
    nearest.push_back({{"actor", trace.actors[a.actor].name}, {"gap", a.gap}, {"time", a.time}});
  return {{"actors_interact", actors_interact(approaches)}, {"nearest_to_ego_path", nearest}};
}

nlohmann::json audit_json(const TraceAudit& audit) {
  nlohmann::json issues = nlohmann::json::array();
  for (const AuditIssue& issue : audit.issues) {
    nlohmann::json entry = {
        {"actor", issue.actor_name}, {"kind", std::string(audit_kind_name(issue.kind))},
        {"time", issue.time},        {"worst_time", issue.worst_time},
        {"worst", issue.worst},      {"limit", issue.limit},
        {"samples", issue.samples}};
    if (issue.kind == AuditKind::npc_overlap) entry["other"] = issue.other_name;
    issues.push_back(entry);
  }
  return issues;
}

nlohmann::json summary_json(const Trace& trace, const ParameterSpace& space,
                            const std::vector<double>& values,
                            const std::vector<CollisionResponsibility>& responsibilities,
                            const std::vector<std::string>& files) {
  nlohmann::json summary;
  summary["map"] = trace.map_name;
  summary["seed"] = trace.seed;
  summary["dt"] = trace.dt;
  summary["duration"] = trace.time.empty() ? 0.0 : trace.time.back();
  summary["end"] = std::string(end_reason_name(trace.end));
  summary["target_reached"] = trace.end == EndReason::target_reached;
  nlohmann::json parameters = nlohmann::json::object();
  for (std::size_t i = 0; i < space.dimensions.size(); ++i)
    parameters[space.dimensions[i].name] = values[i];
  summary["parameters"] = parameters;
  nlohmann::json collisions = nlohmann::json::array();
  for (const Collision& c : trace.collisions)
    collisions.push_back({{"time", c.time},
                          {"first", trace.actors[c.first].name},
                          {"second", trace.actors[c.second].name},
                          {"first_side", std::string(body_side_name(c.first_side))},
                          {"second_side", std::string(body_side_name(c.second_side))},
                          {"point", {c.point.x, c.point.y}}});
  for (const CollisionResponsibility& r : responsibilities) {
    nlohmann::json& entry = collisions[r.collision];
    entry["responsibility"] = std::string(responsibility_name(r.responsibility));
    entry["reason"] = r.reason;
    entry["triage"] = responsibility_json(r);
  }
  summary["collisions"] = collisions;
  if (const std::optional<EgoFailureReport> failure = ego_failure_report(trace))
    summary["ego_failure"] = ego_failure_json(*failure);
  summary["files"] = files;
  return summary;
}

}  // namespace

int run_run(const RunCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<ScenarioFile> input = read_scenario(options.path, "simulate", err, options.choice);
  if (!input) return kExitBadInput;
  apply_scenario_overrides(options.simulation, input->scenario);
  const SourceFile& file = input->file;
  const ScenarioTemplate& scenario = input->scenario;

  const ParameterSpace space = parameter_space(scenario);
  const bool only_events = searched_by_mutation(scenario) && !scenario.parameters.empty();
  if (!space.dimensions.empty() && options.at.empty() && !only_events) {
    err << "scenfuzz: error: '" << options.path << "' is a logical scenario with "
        << space.dimensions.size()
        << " parameters; choose the point to simulate with --at mid or --at random\n";
    return kExitUsage;
  }
  std::vector<double> values;
  if (only_events && options.at.empty()) {
    // A concrete file with probabilistic events (CH-Scenario) runs as written: every event fires.
    err << "scenfuzz: note: every probabilistic event fires (--at mid or --at random chooses "
           "otherwise)\n";
    values.assign(scenario.parameters.size(), 1);
  } else {
    values = decode(space, unit_point(space.dimensions.size(), options.at, options.seed));
  }

  std::vector<std::filesystem::path> map_paths(options.simulation.map_paths.begin(),
                                               options.simulation.map_paths.end());
  std::optional<RoadMap> map;
  try {
    map = load_scenario_map(scenario.map, map_search_path(map_paths), values);
  } catch (const MapError& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return kExitBadInput;
  }

  Diagnostics diagnostics;
  auto setup = prepare_simulation(scenario, values, *map, options.seed, diagnostics);
  err << format_diagnostics(file, diagnostics);
  if (!setup) return kExitBadInput;
  for (const std::string& warning : duration_warnings(options.simulation, scenario.specs))
    err << "scenfuzz: warning: " << warning << "\n";

  // The scenario's own duration is known only now; too many steps would exhaust memory.
  if (!options.simulation.duration) {
    if (const std::optional<std::string> problem = check_step_count(
            setup->duration, options.simulation.dt,
            "the scenario's duration of " + format_number(setup->duration) + " s")) {
      err << "scenfuzz: error: " << *problem << "\n";
      return kExitUsage;
    }
  }

  SimulationOptions simulation = simulation_options(options.simulation);
  simulation.seed = options.seed;
  const Trace trace = simulate(*map, *setup, simulation);
  const std::optional<EgoFailureReport> ego_failure = ego_failure_report(trace);
  if (ego_failure && ego_failed_to_start(trace, *ego_failure)) {
    // The plugin could not be loaded or created: a bad --ego-plugin, not something the scenario
    // found.
    err << "scenfuzz: error: " << ego_failure->message << "\n";
    return kExitBadInput;
  }

  const JudgeOptions judge = judge_options(options.simulation);
  // Whose fault each collision of the ego is (oracle/responsibility.hpp).
  const std::vector<CollisionResponsibility> responsibilities =
      trace.sample_count() > 0 ? ego_collision_responsibilities(trace, *map, judge.rss)
                               : std::vector<CollisionResponsibility>{};
  std::vector<SpecVerdict> verdicts;
  // A plugin that crashed or hung before the first sample leaves no trace to judge.
  if (trace.sample_count() > 0) {
    try {
      verdicts = judge_trace(scenario, values, trace, *map, file, judge);
    } catch (const OracleError& error) {
      Diagnostics oracle_diagnostics;
      oracle_diagnostics.error(error.location(), error.what());
      err << format_diagnostics(file, oracle_diagnostics);
      return kExitBadInput;
    }
  }
  // A failure of the ego under test (a crash, a hang, an error) is a finding like a violated spec.
  bool violated = ego_failure.has_value();
  for (const SpecVerdict& verdict : verdicts) violated = violated || verdict.violated();
  // Specs the oracle could not judge are reported with the others; with none judged there is no
  // verdict to give (DESIGN.md, "Exit statuses").
  const bool none_judged =
      !verdicts.empty() && std::none_of(verdicts.begin(), verdicts.end(),
                                        [](const SpecVerdict& v) { return v.judged(); });
  const int exit_code = violated ? kExitViolated : none_judged ? kExitBadInput : kExitSuccess;
  if (none_judged && !violated)
    err << "scenfuzz: error: no spec of '" << options.path
        << "' could be judged on the simulated trace: each is reported as not judged\n";
  // What the simulated world did that no real road user does: not a finding, but a reason to
  // doubt one (docs/oracle.md, "Trace audit").
  const TraceAudit audit = audit_trace(trace, *map);
  const std::vector<ActorApproach> approaches = actor_approaches(trace);
  if (const std::string warning = no_interaction_warning(trace, approaches); !warning.empty())
    err << "scenfuzz: warning: " << warning << "\n";

  std::vector<std::string> written;
  if (!options.out_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.out_dir, error);
    if (error) {
      err << "scenfuzz: error: cannot create '" << options.out_dir << "': " << error.message()
          << "\n";
      return kExitBadInput;
    }
    std::vector<std::string> lane_ids;
    for (const Lane& lane : map->lanes()) lane_ids.push_back(lane.id);
    const std::filesystem::path dir = options.out_dir;
    std::vector<std::pair<std::string, std::string>> outputs = {
        {"scenario" + concrete_extension(file.path()),
         print_concrete_scenario(file, scenario, values)}};
    // The picture's title names the worst spec (responsibility is not decided here yet).
    TraceSvgOptions picture;
    const auto worst = std::min_element(
        verdicts.begin(), verdicts.end(), [](const SpecVerdict& a, const SpecVerdict& b) {
          return a.judged() && (!b.judged() || a.robustness < b.robustness);
        });
    if (worst != verdicts.end() && worst->judged())
      picture.caption = {worst->name, worst->robustness, worst->time, worst->atom_text, "", "", ""};
    // An ego that failed before the first sample leaves no trace to write.
    if (trace.sample_count() > 0)
      outputs.insert(outputs.begin(), {{"trace.csv", trace_csv(trace, lane_ids)},
                                       {"trace.json", trace_json(trace)},
                                       {"trace.svg", render_trace_svg(*map, trace, picture)}});
    for (const auto& [name, content] : outputs) {
      std::string failure = write_file_atomically(dir / name, content);
      if (!failure.empty()) {
        err << "scenfuzz: error: " << failure << "\n";
        return kExitBadInput;
      }
      written.push_back((dir / name).string());
    }
  }

  if (options.json) {
    nlohmann::json summary = summary_json(trace, space, values, responsibilities, written);
    summary["specs"] = verdicts_json(file, verdicts, judge.start_grace);
    summary["audit"] = audit_json(audit);
    summary["interaction"] = interaction_json(trace, approaches);
    out << summary.dump(2) << "\n";
    return exit_code;
  }
  out << "map " << trace.map_name << ", seed " << trace.seed << ", dt " << format_number(trace.dt)
      << " s\n";
  for (std::size_t i = 0; i < space.dimensions.size(); ++i)
    out << "  " << parameter_value_text(file, scenario, values, i) << "\n";
  double simulated = trace.time.empty() ? 0.0 : trace.time.back();
  out << "simulated " << format_number(std::round(simulated * 1000) / 1000)
      << " s, ended: " << end_reason_name(trace.end) << "\n";
  for (std::size_t i = 0; i < trace.collisions.size(); ++i) {
    out << describe_collision(trace, trace.collisions[i]) << "\n";
    for (const CollisionResponsibility& r : responsibilities)
      if (r.collision == i) out << describe_responsibility(trace, r) << "\n";
  }
  if (trace.collisions.empty()) out << "no collision\n";
  for (const AuditIssue& issue : audit.issues) out << describe_audit_issue(issue) << "\n";
  if (audit.clean()) out << "audit: every actor drove plausibly\n";
  out << "ego reached its target: " << (trace.end == EndReason::target_reached ? "yes" : "no")
      << "\n";
  if (ego_failure) out << describe_ego_failure(*ego_failure) << "\n";
  for (const SpecVerdict& verdict : verdicts)
    out << describe_verdict(file, verdict, judge.start_grace) << "\n";
  for (const std::string& path : written) out << "wrote " << path << "\n";
  return exit_code;
}

}  // namespace scenfuzz
