// The ego's perception model: latency buffer, range and field-of-view test, distance-dependent
// misses, Gaussian noise and coasting of missed tracks; and how weather and darkness degrade
// the settings. docs/simulation.md ("Perception") documents every figure used here.
#include "physics/ego/perception.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "lang/demand.hpp"
#include "physics/ego/ziggurat_normal.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
// Degraded ranges never fall below this (or below the clear range, if that is shorter): even in
// thick fog at night a car sees what is right in front of it.
constexpr double kMinimumRange = 10;

void check_unit_interval(double value, const char* name) {
  if (!(value >= 0 && value <= 1)) {
    throw std::invalid_argument(std::string("perception condition '") + name +
                                "' must lie in [0, 1], not " + std::to_string(value));
  }
}

void check_non_negative(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("perception setting '") + name +
                                "' must be a finite number >= 0, not " + std::to_string(value));
  }
}

void check_settings(const PerceptionSettings& settings) {
  check_non_negative(settings.vehicle_range, "vehicle_range");
  check_non_negative(settings.pedestrian_range, "pedestrian_range");
  check_non_negative(settings.field_of_view, "field_of_view");
  check_non_negative(settings.position_noise, "position_noise");
  check_non_negative(settings.heading_noise, "heading_noise");
  check_non_negative(settings.speed_noise, "speed_noise");
  check_non_negative(settings.latency, "latency");
  check_non_negative(settings.coast_time, "coast_time");
  check_unit_interval(settings.miss_probability, "miss_probability");
}

double degraded_range(double clear, double factor) {
  return std::min(clear, std::max(kMinimumRange, clear * factor));
}

// Probability of one more miss, combined with `probability` as independent causes.
double add_miss(double probability, double extra) {
  return probability + (1 - probability) * extra;
}

}  // namespace

double darkness_at(double time_of_day) {
  if (!std::isfinite(time_of_day)) {
    throw std::invalid_argument("time of day must be a finite number of seconds");
  }
  constexpr double kHour = 3600;
  const double t = std::fmod(std::fmod(time_of_day, 24 * kHour) + 24 * kHour, 24 * kHour);
  if (t <= 5 * kHour || t >= 20 * kHour) return 1;
  if (t < 7 * kHour) return (7 * kHour - t) / (2 * kHour);
  if (t <= 18 * kHour) return 0;
  return (t - 18 * kHour) / (2 * kHour);
}

PerceptionSettings degraded(const PerceptionSettings& clear, const Conditions& conditions) {
  check_unit_interval(conditions.fog, "fog");
  check_unit_interval(conditions.rain, "rain");
  check_unit_interval(conditions.snow, "snow");
  check_unit_interval(conditions.darkness, "darkness");
  const double fog = conditions.fog, rain = conditions.rain, snow = conditions.snow;
  const double darkness = conditions.darkness;

  // Fog cuts visibility roughly geometrically with its density (0.15 of the range at 1, about
  // 0.39 at 0.5); rain and snow scatter lidar and camera returns linearly with intensity.
  const double weather_range = std::pow(0.15, fog) * (1 - 0.3 * rain) * (1 - 0.5 * snow);
  // Headlights and lidar keep vehicles (lit, retro-reflective) visible at night; pedestrians
  // are found mostly by cameras, which lose them in the dark.
  const double vehicle_light = 1 - 0.2 * darkness;
  const double pedestrian_light = 1 - 0.6 * darkness;

  PerceptionSettings result = clear;
  result.vehicle_range = degraded_range(clear.vehicle_range, weather_range * vehicle_light);
  result.pedestrian_range =
      degraded_range(clear.pedestrian_range, weather_range * pedestrian_light);

  const double noise = (1 + fog) * (1 + 0.5 * rain) * (1 + snow) * (1 + 0.5 * darkness);
  result.position_noise = clear.position_noise * noise;
  result.heading_noise = clear.heading_noise * noise;
  result.speed_noise = clear.speed_noise * noise;

  double miss = clear.miss_probability;
  miss = add_miss(miss, 0.10 * fog);
  miss = add_miss(miss, 0.05 * rain);
  miss = add_miss(miss, 0.10 * snow);
  miss = add_miss(miss, 0.05 * darkness);
  result.miss_probability = miss;
  return result;
}

Perception::Perception(const PerceptionSettings& settings, std::uint64_t seed, double dt)
    : settings_(settings), random_(seed), dt_(dt) {
  SCENFUZZ_DEMAND(dt > 0);
  check_settings(settings_);
  history_.resize(static_cast<std::size_t>(std::lround(settings_.latency / dt_)) + 1);
}

const std::vector<WorldObject>& Perception::observe(const KinematicState& ego,
                                                    std::span<const WorldObject> truth) {
  // The snapshot written now is read back latency steps later. Before the run the world is
  // taken to have stood as it is at the first call, so the first samples are not blind.
  Snapshot& current = history_[history_head_];
  current.ego = ego;
  current.objects.assign(truth.begin(), truth.end());
  auto by_id = [](const WorldObject& a, const WorldObject& b) { return a.id < b.id; };
  if (!std::is_sorted(current.objects.begin(), current.objects.end(), by_id))
    std::sort(current.objects.begin(), current.objects.end(), by_id);
  if (!started_) {
    std::fill(history_.begin(), history_.end(), current);
    started_ = true;
  }
  history_head_ = (history_head_ + 1) % history_.size();
  // The oldest slot is the one the next call overwrites.
  const Snapshot& sample = history_[history_head_];

  const bool all_round = settings_.field_of_view >= kTwoPi - 1e-3;
  // The objects come in id order, as the tracks are kept: each one's track lies at or after the
  // previous one's, and is found by walking on from there.
  std::size_t next_track = 0;
  for (const WorldObject& object : sample.objects) {
    if (object.kind == TraceActorKind::ego) continue;
    const double range = object.kind == TraceActorKind::pedestrian ? settings_.pedestrian_range
                                                                   : settings_.vehicle_range;
    const double dx = object.x - sample.ego.x;
    const double dy = object.y - sample.ego.y;
    const double distance = std::sqrt(dx * dx + dy * dy);
    if (distance > range) continue;
    if (!all_round && distance > 0 &&
        std::abs(angle_difference(std::atan2(dy, dx), sample.ego.heading)) >
            settings_.field_of_view / 2) {
      continue;
    }
    // Detection falls off steeply near the edge of the range: a miss is certain there.
    const double fraction = distance / range, fraction2 = fraction * fraction;
    const double edge = range > 0 ? fraction2 * fraction2 : 1;
    const double miss = add_miss(settings_.miss_probability, edge);
    if (uniform01(random_) < miss) continue;

    while (next_track < tracks_.size() && tracks_[next_track].object.id < object.id) ++next_track;
    if (next_track == tracks_.size() || tracks_[next_track].object.id != object.id)
      tracks_.insert(tracks_.begin() + static_cast<std::ptrdiff_t>(next_track), Track{});
    Track& track = tracks_[next_track];
    WorldObject& seen = track.object;
    seen = object;
    track.last_seen = time_;
    // xoshiro256** and the ziggurat: both written out, so a seed gives the same noise with
    // every standard library, and several times cheaper than mt19937_64 and the polar method.
    const double noise_x = standard_normal(random_);
    const double noise_y = standard_normal(random_);
    const double noise_heading = standard_normal(random_);
    const double noise_speed = standard_normal(random_);
    seen.x += settings_.position_noise * noise_x;
    seen.y += settings_.position_noise * noise_y;
    seen.heading = angle_difference(object.heading + settings_.heading_noise * noise_heading, 0);
    seen.speed = std::max(0.0, object.speed + settings_.speed_noise * noise_speed);
  }

  // A track not refreshed this step coasts on its last detection, then is dropped.
  const double tolerance = 1e-9 * std::max(1.0, time_);
  std::erase_if(tracks_, [&](const Track& track) {
    return time_ - track.last_seen > settings_.coast_time + tolerance;
  });
  output_.clear();
  for (const Track& track : tracks_) {
    WorldObject object = track.object;
    const double coasted =
        (object.reversing ? -object.speed : object.speed) * (time_ - track.last_seen);
    if (coasted != 0) {  // most tracks were detected this step
      object.x += coasted * std::cos(object.heading);
      object.y += coasted * std::sin(object.heading);
    }
    output_.push_back(object);
  }
  time_ += dt_;
  return output_;
}

}  // namespace scenfuzz
