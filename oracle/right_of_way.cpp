// Stop lines crossed, from the lane and arc length each sample records: on one lane, a line
// between two arc lengths; from a lane into its successor, the rest of the first lane and the
// start of the second.
#include "oracle/right_of_way.hpp"

#include <algorithm>

namespace scenfuzz {

namespace {

// How long before a stop sign's line a stop counts (s): a driver stops at the line, then creeps.
constexpr double kStopSignMemory = 5;

bool is_control(FeatureKind kind) {
  return kind == FeatureKind::traffic_light || kind == FeatureKind::stop_sign ||
         kind == FeatureKind::yield_sign;
}

bool stood_still_before(const TraceActor& actor, const Trace& trace, std::size_t sample) {
  const double since = trace.time[sample] - kStopSignMemory;
  for (std::size_t i = sample + 1; i-- > 0 && trace.time[i] >= since;) {
    if (!present_at(actor, i)) break;
    if (actor.speed[i] <= kStandstillSpeed) return true;
  }
  return false;
}

CrossedControl crossed(const Trace& trace, const RoadMap& map, const TraceActor& actor,
                       const LaneFeature& feature, std::size_t sample) {
  CrossedControl control;
  control.kind = feature.kind;
  control.index = feature.index;
  control.sample = sample;
  if (feature.kind == FeatureKind::traffic_light)
    control.colour = light_colour(trace, map, feature.index, sample);
  else
    control.stopped = stood_still_before(actor, trace, sample);
  return control;
}

// The controls on `lane` whose line lies in (s_from, s_to].
void add_lines(const Trace& trace, const RoadMap& map, const TraceActor& actor, LaneIndex lane,
               double s_from, double s_to, std::size_t sample, std::vector<CrossedControl>& out) {
  for (const LaneFeature& feature : map.lane(lane).features)
    if (is_control(feature.kind) && s_from < feature.s_begin && feature.s_begin <= s_to)
      out.push_back(crossed(trace, map, actor, feature, sample));
}

bool is_successor(const RoadMap& map, LaneIndex from, LaneIndex to) {
  const std::vector<LaneIndex>& next = map.lane(from).successors;
  return std::find(next.begin(), next.end(), to) != next.end();
}

}  // namespace

SignalColour light_colour(const Trace& trace, const RoadMap& map, std::uint32_t index,
                          std::size_t sample) {
  const std::string& id = map.traffic_lights()[index].id;
  for (const TraceLight& light : trace.lights)
    if (light.id == id && sample < light.colour.size()) return light.colour[sample];
  return SignalColour::green;
}

std::vector<CrossedControl> controls_crossed(const Trace& trace, const RoadMap& map, ActorId id,
                                             std::size_t first, std::size_t last) {
  const TraceActor& actor = trace.actors[id];
  std::vector<CrossedControl> out;
  std::int32_t lane = -1;
  double s = 0;
  for (std::size_t i = first; i <= last && i < trace.sample_count(); ++i) {
    if (!present_at(actor, i) || actor.lane[i] < 0) continue;
    const auto here = static_cast<LaneIndex>(actor.lane[i]);
    if (lane == actor.lane[i]) {
      add_lines(trace, map, actor, here, s, actor.s[i], i, out);
    } else if (lane >= 0 && is_successor(map, static_cast<LaneIndex>(lane), here)) {
      add_lines(trace, map, actor, static_cast<LaneIndex>(lane), s,
                map.lane(static_cast<LaneIndex>(lane)).length(), i, out);
      add_lines(trace, map, actor, here, -1, actor.s[i], i, out);
    }
    lane = actor.lane[i];
    s = actor.s[i];
  }
  return out;
}

const std::string& control_id(const RoadMap& map, const CrossedControl& control) {
  return control.kind == FeatureKind::traffic_light ? map.traffic_lights()[control.index].id
                                                    : map.signs()[control.index].id;
}

bool control_violated(const CrossedControl& control) {
  if (control.kind == FeatureKind::traffic_light) return control.colour == SignalColour::red;
  return control.kind == FeatureKind::stop_sign && !control.stopped;
}

ControlAhead control_ahead(const Trace& trace, const RoadMap& map, ActorId id, std::size_t sample,
                           double ahead) {
  ControlAhead found;
  const TraceActor& actor = trace.actors[id];
  if (actor.lane[sample] < 0) return found;
  const double s = actor.s[sample];
  for (const LaneFeature& feature : map.lane(static_cast<LaneIndex>(actor.lane[sample])).features) {
    if (feature.s_begin < s || feature.s_begin > s + ahead) continue;
    if (feature.kind == FeatureKind::traffic_light &&
        light_colour(trace, map, feature.index, sample) == SignalColour::red)
      found.red_light = true;
    if (feature.kind == FeatureKind::stop_sign) found.stop_sign = true;
  }
  return found;
}

}  // namespace scenfuzz
