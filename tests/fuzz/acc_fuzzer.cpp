// libFuzzer harness for the accident formalism's front end (.acc, lang/accident/). For any input
// bytes: parsing and formatting the diagnostics must not crash, leak or hang; a parse gives a
// file exactly when it reports no error; every diagnostic and every located value lies within
// the input; a file that parses prints to text that parses, without a diagnostic, to an equal
// tree, and translates into a scenario (or a located error) with the ego among its vehicles, a
// search range for every unknown and an expected collision for every collision. Built by
// scripts/fuzz.sh (SCENFUZZ_FUZZ=ON, clang, ASan + UBSan).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "lang/accident/accident.hpp"
#include "lang/accident/parser.hpp"
#include "lang/accident/printer.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "tests/fuzz/fuzz_checks.hpp"

namespace {

using namespace scenfuzz;

using fuzz_checks::expect_within;

void expect_point_within(const SourceFile& source, const accident::Point& point) {
  expect_within(source, point.location, "a point");
  expect_within(source, point.x_at, "a point's x");
  expect_within(source, point.y_at, "a point's y");
}

void expect_sign_within(const SourceFile& source, const std::optional<accident::SignReference>& s) {
  if (!s) return;
  expect_within(source, s->location, "a sign");
  expect_within(source, s->name.location, "a sign's name");
  expect_point_within(source, s->point);
}

void expect_values_within(const SourceFile& source, const accident::File& file) {
  expect_within(source, file.road.kind.location, "the road's kind");
  for (const accident::Tree& tree : file.trees) {
    expect_within(source, tree.id.location, "a tree's ID");
    expect_point_within(source, tree.coords);
  }
  for (const accident::Light& light : file.lights) {
    expect_within(source, light.id.location, "a light's ID");
    expect_within(source, light.colour.location, "a light's colour");
    expect_point_within(source, light.coords);
  }
  for (const accident::LevelCrossing& crossing : file.crossings)
    expect_point_within(source, crossing.coords);
  for (const accident::StopSign& sign : file.stop_signs) expect_point_within(source, sign.coords);
  for (const accident::Vehicle& vehicle : file.vehicles) {
    expect_within(source, vehicle.location, "a vehicle");
    expect_within(source, vehicle.id.location, "a vehicle's ID");
    expect_within(source, vehicle.kind.location, "a vehicle's kind");
    if (vehicle.init_direction)
      expect_within(source, vehicle.init_direction->location, "a vehicle's direction");
    expect_sign_within(source, vehicle.start_sign);
    expect_sign_within(source, vehicle.end_sign);
    for (const accident::Event& event : vehicle.chain) {
      expect_within(source, event.location, "an event");
      expect_within(source, event.kind.location, "an event's kind");
    }
  }
  for (const accident::Collision& collision : file.collisions) {
    expect_within(source, collision.location, "a collision");
    for (const accident::Involvement* who : {&collision.actor, &collision.victim}) {
      expect_within(source, who->id.location, "an actor's or victim's ID");
      expect_within(source, who->part.location, "an actor's or victim's part");
    }
    if (collision.coords) expect_point_within(source, *collision.coords);
  }
}

void expect_prints_back(const accident::File& file) {
  const SourceFile printed("printed.acc", accident::print(file));
  const accident::ParseResult reparsed = accident::parse(printed);
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

void fail(const char* what, const SourceFile& source) {
  std::fprintf(stderr, "translation: %s\n--- input ---\n%s\n", what, source.text().c_str());
  __builtin_trap();
}

void expect_translates(const SourceFile& source, const accident::File& file) {
  const accident::ScenarioParse translated = accident::parse_scenario(source);
  for (const Diagnostic& diagnostic : translated.diagnostics.all())
    expect_within(source, diagnostic.location, "a translation diagnostic");
  if (!translated.ok()) return;
  const ScenarioTemplate& scenario = translated.scenario;
  if (scenario.ego.kind != ActorKind::ego || scenario.vehicles.size() + 1 != file.vehicles.size())
    fail("the ego and the other vehicles are not the description's vehicles", source);
  for (const Parameter& parameter : scenario.parameters)
    if (!(parameter.lower <= parameter.upper)) fail("an inverted search range", source);
  if (scenario.expected_collisions.size() != file.collisions.size())
    fail("a collision is not expected", source);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const SourceFile source("fuzz.acc", std::string(reinterpret_cast<const char*>(data), size));
  const accident::ParseResult result = accident::parse(source);
  fuzz_checks::expect_consistent_parse(source, result.diagnostics, result.file.has_value());
  if (result.file) {
    expect_values_within(source, *result.file);
    expect_prints_back(*result.file);
    expect_translates(source, *result.file);
  }
  return 0;
}
