// Background traffic in the loop: presence bookkeeping, the spawn queue per flow with its entry
// check, and the lane followers of the vehicles on the map.
#include "physics/simulation/background_traffic.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "lang/demand.hpp"
#include "physics/actors/path_pose.hpp"

namespace scenfuzz {
namespace {

constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();

// `state`'s pose, standing still: an absent vehicle's columns.
KinematicState at_rest(const KinematicState& state) {
  KinematicState rest;
  rest.x = state.x;
  rest.y = state.y;
  rest.heading = state.heading;
  return rest;
}

}  // namespace

BackgroundTraffic::BackgroundTraffic(const RoadMap& map, const SimulationSetup& setup,
                                     FlowSchedule schedule, std::size_t first)
    : map_(&map),
      setup_(&setup),
      vehicles_(std::move(schedule.vehicles)),
      first_(first),
      followers_(vehicles_.size()),
      from_(vehicles_.size(), kNever),
      until_(vehicles_.size(), kNever),
      queues_(setup.flows.size()),
      next_(setup.flows.size(), 0) {
  for (std::size_t j = 0; j < vehicles_.size(); ++j) {
    const FlowVehicle& vehicle = vehicles_[j];
    SCENFUZZ_DEMAND(vehicle.flow < setup.flows.size());
    if (vehicle.prefilled) {
      followers_[j].emplace(make_follower(j, setup.flows[vehicle.flow].speed));
      followers_[j]->start_at(vehicle.progress);
      from_[j] = 0;
    } else {
      queues_[vehicle.flow].push_back(j);
    }
  }
}

LaneFollower BackgroundTraffic::make_follower(std::size_t j, double speed) const {
  const FlowPlan& flow = setup_->flows[vehicles_[j].flow];
  return LaneFollower(*map_, flow.route, flow.path, flow.places, flow.body, flow.speed, speed,
                      true);
}

KinematicState BackgroundTraffic::initial_state(std::size_t j) const {
  if (followers_[j]) return followers_[j]->state();
  const Polyline& path = setup_->flows[vehicles_[j].flow].path;
  KinematicState entry;
  const MapPoint start = path.point_at(0);
  entry.x = start.x;
  entry.y = start.y;
  entry.heading = direction_at(path, 0).heading;
  return entry;
}

void BackgroundTraffic::update(std::size_t step, double t, std::span<KinematicState> states,
                               std::span<const double> lengths, std::span<const double> widths,
                               std::span<std::uint8_t> present, CollisionWorld& world) {
  for (std::size_t j = 0; j < vehicles_.size(); ++j) {
    const std::size_t id = first_ + j;
    if (!followers_[j]) {
      states[id].yaw_rate = 0;  // gone: its heading no longer changes
      continue;
    }
    if (followers_[j]->finished()) {  // it drove off its route's end during the last step
      // At rest where it left; the yaw rate still records the heading's change over that step,
      // as every sample's does.
      states[id] = at_rest(followers_[j]->state());
      states[id].yaw_rate = followers_[j]->state().yaw_rate;
      followers_[j].reset();
      until_[j] = step;
      present[id] = 0;
      world.set_enabled(static_cast<BodyId>(id), false);
      continue;
    }
    states[id] = followers_[j]->state();
    world.set_pose(static_cast<BodyId>(id), {{states[id].x, states[id].y}, states[id].heading});
  }
  for (std::size_t flow = 0; flow < queues_.size(); ++flow) {
    const std::vector<std::size_t>& queue = queues_[flow];
    while (next_[flow] < queue.size()) {
      const std::size_t j = queue[next_[flow]];
      if (vehicles_[j].due > t + 1e-9) break;
      const std::optional<double> speed =
          flow_entry_speed(setup_->flows[flow], states, lengths, widths, present);
      if (!speed) break;
      const std::size_t id = first_ + j;
      followers_[j].emplace(make_follower(j, *speed));
      states[id] = followers_[j]->state();
      from_[j] = step;
      present[id] = 1;
      world.set_pose(static_cast<BodyId>(id), {{states[id].x, states[id].y}, states[id].heading});
      world.set_enabled(static_cast<BodyId>(id), true);
      ++next_[flow];
    }
  }
}

void BackgroundTraffic::step(const WorldSnapshot& world, double dt) {
  // Every vehicle decides on the same world before any moves (LaneFollower::decide).
  for (std::size_t j = 0; j < vehicles_.size(); ++j)
    if (followers_[j]) followers_[j]->decide(world, static_cast<std::uint32_t>(first_ + j), dt);
  for (auto& follower : followers_)
    if (follower) follower->move(dt);
}

void BackgroundTraffic::finish(std::span<TraceActor> actors, std::size_t samples) const {
  for (std::size_t j = 0; j < vehicles_.size(); ++j) {
    TraceActor& actor = actors[first_ + j];
    actor.present_from = std::min(from_[j], samples);
    actor.present_until = std::min(until_[j], samples);
  }
}

}  // namespace scenfuzz
