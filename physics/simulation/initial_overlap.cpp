#include "physics/simulation/initial_overlap.hpp"

#include <cmath>
#include <vector>

#include "lang/number_format.hpp"
#include "physics/collision/footprint.hpp"

namespace scenfuzz {

namespace {

struct InitialBody {
  const std::string* name;
  Footprint footprint;
  bool obstacle = false;
};

}  // namespace

std::optional<std::string> initial_overlap(const SimulationSetup& setup) {
  std::vector<InitialBody> bodies;
  const KinematicState& ego = setup.ego_initial;
  bodies.push_back(
      {&setup.ego_name,
       {{ego.x, ego.y}, ego.heading, setup.ego_body.length / 2, setup.ego_body.width / 2, false},
       false});
  for (const ScriptedActor& actor : setup.actors) {
    const KinematicState start = actor.trajectory.state_at(0);
    const bool round = actor.kind == TraceActorKind::pedestrian;
    bodies.push_back(
        {&actor.name,
         {{start.x, start.y}, start.heading, actor.body.length / 2, actor.body.width / 2, round},
         false});
  }
  for (const StaticObstacle& obstacle : setup.obstacles)
    bodies.push_back({&obstacle.name,
                      {obstacle.pose.position, obstacle.pose.heading, obstacle.geometry.length / 2,
                       obstacle.geometry.width / 2, obstacle.geometry.shape != BodyShape::box},
                      true});
  for (std::size_t j = 1; j < bodies.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      if (bodies[i].obstacle && bodies[j].obstacle) continue;
      const double distance = signed_distance(bodies[i].footprint, bodies[j].footprint);
      if (distance < 0)
        return *bodies[j].name + " overlaps " + *bodies[i].name + " at t = 0 (by " +
               format_number(std::round(-distance * 100) / 100) + " m)";
    }
  return std::nullopt;
}

}  // namespace scenfuzz
