// CH-Scenario safety protocols as specs (translation.hpp; docs/ch-scenario.md, "Safety
// protocols"): each predicate must hold throughout the run, `G (predicate)`, over the ego's
// signals. A name is a condition (wiper, lighton, hazardlighton, emergencybreak) or a number
// (dist, safedistance, speed); comparing a condition with true or false is the condition or its
// negation.
#include <algorithm>
#include <array>

#include "lang/chs/predicates.hpp"
#include "lang/chs/translation.hpp"
#include "lang/chs/vocabulary.hpp"

namespace scenfuzz::chs {

namespace {

Formula flag_on(const char* signal, SourceLocation at) {
  return comparison(CompareOp::equal, signal_term(signal, at), number_term(1, at), at);
}

// The share of full braking above which the ego brakes in an emergency (law signal `brake`).
constexpr double kEmergencyBrake = 70;
// The safe distance: what the ego drives in this many seconds (the two-second rule).
constexpr double kSafeSeconds = 2;

std::optional<Meaning> named(const std::string& name, SourceLocation at) {
  const std::string key = joined_words(name);
  if (key == "wiper" || key == "wipers" || key == "wiperon") return flag_on("wiperOn", at);
  if (key == "lighton" || key == "lightson" || key == "headlighton" || key == "headlightson")
    return combined(FormulaKind::disjunction, flag_on("lowBeamOn", at), flag_on("highBeamOn", at),
                    at);
  if (key == "hazardlighton" || key == "hazardlightson" || key == "hazardlight")
    return flag_on("warningFlashOn", at);
  if (key == "foglighton" || key == "foglightson") return flag_on("fogLightOn", at);
  if (key == "hornon" || key == "horn") return flag_on("hornOn", at);
  if (key == "emergencybreak" || key == "emergencybrake" || key == "emergencybraking")
    return comparison(CompareOp::greater, signal_term("brake", at),
                      number_term(kEmergencyBrake, at), at);
  if (key == "dist" || key == "distance") return signal_term("NPCAhead", at);
  if (key == "speed") return signal_term("speed", at);  // km/h, as the file's speeds
  if (key == "safedistance") {
    SpecTerm term;
    term.kind = TermKind::multiply;
    term.operands = {signal_term("speed", at), number_term(kSafeSeconds / 3.6, at)};
    term.location = at;
    return term;
  }
  return std::nullopt;
}

constexpr const char* kNames =
    "wiper, lighton, hazardlighton, foglighton, hornon, emergencybreak, dist, safedistance, speed";

void add_protocol(Translation& translation, const Expression& predicate, const std::string& name) {
  Diagnostics& diagnostics = translation.diagnostics;
  PredicateTranslator translator(diagnostics, [&](const std::string& text, SourceLocation at) {
    auto found = named(text, at);
    if (!found)
      diagnostics.error(
          at, "scenfuzz knows no signal '" + text + "' of a safety protocol; it knows " + kNames);
    return found;
  });
  auto condition = translator.translate(predicate);
  if (!condition) return;
  Formula always;
  always.kind = FormulaKind::always;
  always.operands = {std::move(*condition)};
  always.location = predicate.location;
  translation.scenario.specs.push_back(
      {name, translation.scenario.trace_name, std::move(always), predicate.location});
}

// The names a constraint may relate with besides the file's entities: the ego, the vehicle ahead
// of it and the road's edge.
constexpr std::array<std::string_view, 7> kRelatable{
    "ego", "currentvehicle", "forwardvehicle", "edge", "road", "roadedge", "frontvehicle"};

void check_related(Translation& translation, const Constraint& constraint) {
  for (const Text& related : constraint.related) {
    const std::string key = joined_words(related.text);
    bool known = std::find(kRelatable.begin(), kRelatable.end(), key) != kRelatable.end();
    for (const auto& e : translation.file.dynamic_entities) known |= e.name.text == related.text;
    for (const auto& e : translation.file.static_entities) known |= e.name.text == related.text;
    if (!known)
      translation.diagnostics.warning(related.location,
                                      "'" + related.text +
                                          "' is no entity of the file, nor the "
                                          "ego, the forward vehicle or the road edge");
  }
}

std::string numbered(const std::string& name, std::size_t i, std::size_t count) {
  return count == 1 ? name : name + std::to_string(i + 1);
}

}  // namespace

void translate_specs(Translation& translation) {
  const File& file = translation.file;
  for (std::size_t i = 0; i < file.safety_protocols.size(); ++i)
    add_protocol(translation, file.safety_protocols[i],
                 numbered("safety_protocol", i, file.safety_protocols.size()));
  for (const Constraint& constraint : file.constraints) {
    check_related(translation, constraint);
    const std::size_t count = constraint.safety_protocols.size();
    for (std::size_t i = 0; i < count; ++i)
      add_protocol(translation, constraint.safety_protocols[i],
                   numbered(constraint.name.text + ".safety_protocol", i, count));
  }
}

}  // namespace scenfuzz::chs
