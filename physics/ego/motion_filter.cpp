// Exponential smoothing of each perceived object's velocity vector (not of its speed: the noise
// of the heading then averages out too), and of a vehicle's heading as a unit vector.
#include "physics/ego/motion_filter.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace scenfuzz {

void MotionFilter::update(std::span<const WorldObject> objects, double dt) {
  double weight = std::clamp(dt / time_constant_, 0.0, 1.0);
  std::vector<Track>& next = spare_;  // last step's tracks' memory: no allocation per step
  next.clear();
  next.reserve(objects.size());
  auto old = tracks_.begin();
  for (const WorldObject& object : objects) {
    if (object.kind == TraceActorKind::obstacle) continue;
    double velocity = object.reversing ? -object.speed : object.speed;
    // Standing (perception clamps noisy speeds at 0): no sine and cosine for a zero vector. Only
    // the sign of a zero could differ, which no reader of speed() or velocity() tells apart.
    const bool still = velocity == 0 && std::isfinite(object.heading);
    double vx = still ? 0.0 : velocity * std::cos(object.heading);
    double vy = still ? 0.0 : velocity * std::sin(object.heading);
    // A vehicle's heading as a unit vector (averaging angles would break at +-pi); a pedestrian,
    // round, has none worth a sine and cosine.
    const bool oriented = object.kind == TraceActorKind::vehicle && std::isfinite(object.heading);
    double hx = oriented ? std::cos(object.heading) : 0.0;
    double hy = oriented ? std::sin(object.heading) : 0.0;
    while (old != tracks_.end() && old->id < object.id) ++old;
    if (old != tracks_.end() && old->id == object.id) {
      vx = old->vx + weight * (vx - old->vx);
      vy = old->vy + weight * (vy - old->vy);
      hx = oriented ? old->hx + weight * (hx - old->hx) : old->hx;
      hy = oriented ? old->hy + weight * (hy - old->hy) : old->hy;
    }
    next.push_back({object.id, vx, vy, hx, hy});
  }
  std::swap(tracks_, next);
}

const MotionFilter::Track* MotionFilter::find(ActorId id) const {
  auto found = std::lower_bound(tracks_.begin(), tracks_.end(), id,
                                [](const Track& t, ActorId wanted) { return t.id < wanted; });
  return found == tracks_.end() || found->id != id ? nullptr : &*found;
}

double MotionFilter::speed(ActorId id) const {
  const Track* found = find(id);
  return found ? std::hypot(found->vx, found->vy) : 0;
}

std::optional<MotionFilter::Velocity> MotionFilter::velocity(ActorId id) const {
  const Track* found = find(id);
  if (!found) return std::nullopt;
  return Velocity{found->vx, found->vy};
}

std::optional<double> MotionFilter::heading(ActorId id) const {
  const Track* found = find(id);
  if (!found || (found->hx == 0 && found->hy == 0)) return std::nullopt;
  return std::atan2(found->hy, found->hx);
}

// Exponential smoothing with weight w leaves w / (2 - w) of white noise's variance.
double MotionFilter::noise_reduction(double dt) const {
  const double weight = std::clamp(dt / time_constant_, 0.0, 1.0);
  return weight > 0 ? std::sqrt(weight / (2 - weight)) : 1.0;
}

}  // namespace scenfuzz
