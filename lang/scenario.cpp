#include "lang/scenario.hpp"

namespace scenfuzz {

const Actor* find_actor(const ScenarioTemplate& scenario, const std::string& name) {
  if (scenario.ego.name == name) return &scenario.ego;
  for (const Actor& actor : scenario.vehicles)
    if (actor.name == name) return &actor;
  for (const Actor& actor : scenario.pedestrians)
    if (actor.name == name) return &actor;
  return nullptr;
}

}  // namespace scenfuzz
