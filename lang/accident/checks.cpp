// Checking IDs and the references to them.
#include "lang/accident/checks.hpp"

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "lang/accident/blocks.hpp"
#include "lang/accident/vocabulary.hpp"

namespace scenfuzz::accident {

namespace {

struct Declaration {
  std::string_view kind;  // "VEHICLE", "TREE", "LIGHT"
  SourceLocation at;
};

using Declarations = std::map<std::string, Declaration, std::less<>>;

Declarations declarations(const File& file, Diagnostics* duplicates) {
  Declarations declared;
  auto declare = [&](const Name& id, std::string_view kind) {
    if (id.text.empty()) return;
    auto [it, fresh] = declared.emplace(id.text, Declaration{kind, id.location});
    if (!fresh && duplicates != nullptr)
      duplicates->error(id.location, "ID '" + id.text + "' is already the " +
                                         std::string(it->second.kind) + "'s at " +
                                         place(it->second.at));
  };
  for (const Tree& tree : file.trees) declare(tree.id, "TREE");
  for (const Light& light : file.lights) declare(light.id, "LIGHT");
  for (const Vehicle& vehicle : file.vehicles) declare(vehicle.id, "VEHICLE");
  return declared;
}

// "; did you mean 'car1'?" among the declarations of the kinds allowed.
std::string suggestion(const Declarations& declared, const std::string& written,
                       const std::vector<std::string_view>& kinds) {
  std::vector<std::string> names;
  for (const auto& [name, declaration] : declared)
    for (std::string_view kind : kinds)
      if (declaration.kind == kind) names.push_back(name);
  std::vector<std::string_view> views(names.begin(), names.end());
  // Names are compared without case by nearest(); the exact spelling is what is suggested.
  auto best = nearest(written, views);
  return best ? "; did you mean '" + *best + "'?" : "";
}

// `role` ("the ACTOR") must name one of `kinds`, listed in `kinds_text` ("a VEHICLE").
void check_reference(const Declarations& declared, const Name& name, const std::string& role,
                     const std::vector<std::string_view>& kinds, const std::string& kinds_text,
                     Diagnostics& diagnostics) {
  if (diagnostics.too_many_errors()) return;  // a suggestion weighs every ID: not for nothing
  const std::string must = role + " must name " + kinds_text + ", and ";
  auto it = declared.find(name.text);
  if (it == declared.end()) {
    diagnostics.error(name.location, must + "no ID is '" + name.text + "'" +
                                         suggestion(declared, name.text, kinds));
    return;
  }
  for (std::string_view kind : kinds)
    if (it->second.kind == kind) return;
  diagnostics.error(name.location, must + "'" + name.text + "' is a " +
                                       std::string(it->second.kind) + "'s ID (at " +
                                       place(it->second.at) + ")");
}

void check_sign(const Declarations& declared, const std::optional<SignReference>& sign,
                const std::string& role, Diagnostics& diagnostics) {
  if (!sign || sign->kind != SignReference::Kind::name) return;
  check_reference(declared, sign->name, role, {"LIGHT", "TREE"}, "a LIGHT or a TREE", diagnostics);
}

}  // namespace

void check_ids(const File& file, Diagnostics& diagnostics) {
  (void)declarations(file, &diagnostics);
}

void check_references(const File& file, Diagnostics& diagnostics) {
  const Declarations declared = declarations(file, nullptr);
  for (const Vehicle& vehicle : file.vehicles) {
    check_sign(declared, vehicle.start_sign, "the STARTSIGN", diagnostics);
    check_sign(declared, vehicle.end_sign, "the ENDSIGN", diagnostics);
  }
  for (const Collision& collision : file.collisions) {
    const Name& actor = collision.actor.id;
    const Name& victim = collision.victim.id;
    if (!actor.text.empty())
      check_reference(declared, actor, "the ACTOR", {"VEHICLE"}, "a VEHICLE", diagnostics);
    if (!victim.text.empty())
      check_reference(declared, victim, "the VICTIM", {"VEHICLE", "TREE", "LIGHT"},
                      "a VEHICLE, a TREE or a LIGHT", diagnostics);
    if (!actor.text.empty() && actor.text == victim.text)
      diagnostics.error(victim.location, "the VICTIM is the ACTOR, '" + actor.text +
                                             "': a vehicle does not collide with itself");
  }
}

}  // namespace scenfuzz::accident
