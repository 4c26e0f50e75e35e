// libFuzzer harness for the CH-Scenario front end. For any input bytes: parsing and formatting
// the diagnostics must not crash, leak or hang; a parse gives a file exactly when it reports no
// error; every diagnostic and every located value lies within the input; a file that parses
// prints to text that parses, without a diagnostic, to an equal tree; its translation into the
// IR reports only diagnostics within the input, and its concrete scenario with the ego's speed
// as a parameter reads back with that speed, and with the ego's lane place (a written point in a
// lane of a file's only road) moved across its lane reads back as that place.
// Built by scripts/fuzz.sh (SCENFUZZ_FUZZ=ON, clang, ASan + UBSan).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "lang/chs/chs.hpp"
#include "lang/chs/parser.hpp"
#include "lang/chs/printer.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "tests/fuzz/fuzz_checks.hpp"

namespace {

using namespace scenfuzz;

using fuzz_checks::expect_within;

void expect_values_within(const SourceFile& source, const chs::File& file) {
  for (const chs::Road& road : file.roads) {
    expect_within(source, road.name.location, "a road's name");
    for (const auto* points : {&road.left_boundary, &road.centre_lines, &road.right_boundary})
      for (const chs::Point& point : *points) {
        expect_within(source, point.location, "a point");
        expect_within(source, point.x_at, "a point's x");
        expect_within(source, point.y_at, "a point's y");
      }
  }
  for (const chs::DynamicEntity& entity : file.dynamic_entities) {
    expect_within(source, entity.name.location, "an entity's name");
    expect_within(source, entity.speed.location, "a speed");
  }
  for (const chs::Constraint& constraint : file.constraints)
    for (const chs::Event& event : constraint.events) {
      expect_within(source, event.guard.location, "a guard");
      for (const chs::Statement& statement : event.action)
        expect_within(source, statement.location, "a statement");
    }
}

void expect_prints_back(const chs::File& file) {
  const SourceFile printed("printed.chs", chs::print(file));
  const chs::ParseResult reparsed = chs::parse(printed);
  if (!reparsed.file || !reparsed.diagnostics.all().empty()) {
    std::fprintf(stderr, "print(file) does not parse cleanly:\n%s\n--- printed ---\n%s\n",
                 format_diagnostics(printed, reparsed.diagnostics).c_str(), printed.text().c_str());
    __builtin_trap();
  }
  if (!(*reparsed.file == file)) {
    std::fprintf(stderr, "parse(print(file)) != file\n--- printed ---\n%s\n",
                 printed.text().c_str());
    __builtin_trap();
  }
}

// The ego's lane place (lane_places.hpp) moved across its lane, as the search would.
struct LanePlaceMove {
  std::string lane;
  double s = 0, lateral = 0;
};

std::optional<LanePlaceMove> move_lane_place(const chs::File& file, ScenarioTemplate& scenario,
                                             std::vector<double>& values) {
  if (file.roads.size() != 1) return std::nullopt;
  Position& position = scenario.ego.initial.position;
  if (position.kind != PositionKind::lane || !position.lateral || !position.s.location.known())
    return std::nullopt;
  // Halfway to the lane's centre at the same station stays in the lane; elsewhere on a road whose
  // width varies, or where roads overlap, the point may lie in another lane.
  const LanePlaceMove moved{position.lane, position.s.constant, position.lateral->constant / 2};
  for (auto [value, name, wanted] :
       {std::tuple{&position.s, "ego.init.position.s", moved.s},
        {&*position.lateral, "ego.init.position.lateral", moved.lateral}}) {
    Parameter parameter;
    parameter.name = name;
    parameter.unit = "m";
    parameter.location = value->location;
    *value = parameter_value(static_cast<int>(scenario.parameters.size()), value->location);
    scenario.parameters.push_back(parameter);
    values.push_back(wanted);
  }
  return moved;
}

// A lane place written back as a point reads as the same place.
void expect_lane_place_back(const std::string& concrete, const LanePlaceMove& moved) {
  const chs::ScenarioParse back = chs::parse_scenario(SourceFile("concrete.chs", concrete));
  const Position& position = back.scenario.ego.initial.position;
  const bool same = back.ok() && position.kind == PositionKind::lane &&
                    position.lane == moved.lane && position.lateral &&
                    std::abs(position.s.constant - moved.s) < 1e-6 &&
                    std::abs(position.lateral->constant - moved.lateral) < 1e-6;
  if (!same) {
    std::fprintf(stderr, "the ego's place %s s=%.17g lateral=%.17g does not read back:\n%s\n",
                 moved.lane.c_str(), moved.s, moved.lateral, concrete.c_str());
    __builtin_trap();
  }
}

// The translation locates its diagnostics in the input, and the ego's speed written back as a
// concrete scenario's parameter (m/s in the IR, km/h in the file) reads back as written.
void expect_translates(const SourceFile& source) {
  const chs::ScenarioParse parsed = chs::parse_scenario(source);
  for (const Diagnostic& diagnostic : parsed.diagnostics.all())
    expect_within(source, diagnostic.location, "a translation diagnostic");
  if (!parsed.ok()) return;
  ScenarioTemplate scenario = parsed.scenario;
  std::vector<double> values;
  if (scenario.ego.initial.speed && scenario.ego.initial.speed->location.known()) {
    Parameter speed;
    speed.name = "ego.init.speed";
    speed.unit = "m/s";
    speed.location = scenario.ego.initial.speed->location;
    scenario.parameters.push_back(speed);
    values.push_back(scenario.ego.initial.speed->constant);
  }
  const chs::ParseResult first = chs::parse(source);
  const std::optional<LanePlaceMove> moved = move_lane_place(*first.file, scenario, values);
  const std::string concrete = chs::print_concrete(source, scenario, values);
  if (moved) expect_lane_place_back(concrete, *moved);
  const chs::ParseResult reparsed = chs::parse(SourceFile("concrete.chs", concrete));
  if (!reparsed.file) {
    std::fprintf(stderr, "the concrete scenario does not parse:\n%s\n", concrete.c_str());
    __builtin_trap();
  }
  const chs::File& original = *first.file;
  for (std::size_t i = 0; i < original.dynamic_entities.size(); ++i) {
    const double written = original.dynamic_entities[i].speed.value;
    const double back = reparsed.file->dynamic_entities[i].speed.value;
    if (std::abs(back - written) > 1e-9 * std::max(1.0, written)) {
      std::fprintf(stderr, "a speed of %.17g km/h reads back as %.17g:\n%s\n", written, back,
                   concrete.c_str());
      __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const SourceFile source("fuzz.chs", std::string(reinterpret_cast<const char*>(data), size));
  const chs::ParseResult result = chs::parse(source);
  fuzz_checks::expect_consistent_parse(source, result.diagnostics, result.file.has_value());
  if (result.file) {
    expect_values_within(source, *result.file);
    expect_prints_back(*result.file);
    expect_translates(source);
  }
  return 0;
}
