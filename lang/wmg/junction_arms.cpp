// Road-to-arm assignment by the stated angles. Every arm of the generators points
// c0 + c1 * angle degrees counter-clockwise from east, where `angle` is the generator's free
// parameter (45 to 135; c1 is 0 for the through road's arms and a roundabout's), so the angle
// between two arms, taken as the smaller one round (0 to 180: "the angle between roads" says
// nothing of which way round), is again c0 + c1 * angle with c1 in {-1, 0, 1} over that range.
// Each stated range then bounds `angle` to an interval, or holds or fails outright; an
// assignment can be built when the intervals meet.
#include "lang/wmg/junction_arms.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "lang/number_format.hpp"

namespace scenfuzz::wmg {
namespace {

constexpr double kAngleLow = 45;  // the generators' `angle` range, builtin_maps.cpp
constexpr double kAngleHigh = 135;
// Degrees a stated angle may be off the layout's: "180" for a through road, or a right angle
// written "90" beside a generator angle drawn from another pair, describe it as a person would.
constexpr double kTolerance = 10;

struct ArmDirection {
  const char* name;
  double c0;  // degrees counter-clockwise from east, plus c1 * angle
  double c1;
};

std::vector<ArmDirection> generator_arms(const std::string& map_name) {
  if (map_name == "t_junction") return {{"west", 180, 0}, {"south", 180, 1}, {"east", 0, 0}};
  if (map_name == "roundabout")
    return {{"west", 180, 0}, {"south", 270, 0}, {"east", 0, 0}, {"north", 90, 0}};
  return {{"west", 180, 0}, {"south", 180, 1}, {"east", 0, 0}, {"north", 0, 1}};
}

// The angle between two arms as c0 + c1 * angle, folded into 0..180. Over 45..135 the difference
// of two directions never crosses a multiple of 180 except where c1 is 0, so the fold is linear.
struct Between {
  double c0 = 0;
  double c1 = 0;
};

Between between(const ArmDirection& a, const ArmDirection& b) {
  const double c1 = a.c1 - b.c1;
  const double middle = a.c0 - b.c0 + c1 * 90;  // the difference at the middle of the range
  const double r = std::fmod(std::fmod(middle, 360) + 360, 360);
  const double slope = (r <= 180 ? 1 : -1) * c1;  // the fold mirrors differences beyond 180
  return {(r <= 180 ? r : 360 - r) - slope * 90, slope};
}

struct Interval {
  double low = kAngleLow;
  double high = kAngleHigh;
  bool empty() const { return low > high; }
};

// Narrows `angle` to where c0 + c1 * angle lies in [low, high].
void constrain(Interval& angle, const Between& b, const NumberRange& range) {
  const double low = (range.is_range ? std::min(range.low, range.high) : range.low) - kTolerance;
  const double high = (range.is_range ? std::max(range.low, range.high) : range.low) + kTolerance;
  if (b.c1 == 0) {
    if (b.c0 < low || b.c0 > high) angle.low = angle.high + 1;
    return;
  }
  const double from = (low - b.c0) / b.c1;
  const double to = (high - b.c0) / b.c1;
  angle.low = std::max(angle.low, std::min(from, to));
  angle.high = std::min(angle.high, std::max(from, to));
}

std::size_t road_index(const Junction& junction, const Identifier& road) {
  const auto found = std::find_if(junction.connected_roads.begin(), junction.connected_roads.end(),
                                  [&road](const Identifier& id) { return id.name == road.name; });
  return static_cast<std::size_t>(found - junction.connected_roads.begin());
}

// False after an error at each pair or connection naming a road the junction does not connect.
bool names_known_roads(const Junction& junction, Diagnostics& diagnostics) {
  bool known = true;
  auto check = [&](const Identifier& road, const std::string& what) {
    if (road_index(junction, road) < junction.connected_roads.size()) return;
    diagnostics.error(road.location, what + " names road '" + road.name + "', which junction '" +
                                         junction.id.name + "' does not connect");
    known = false;
  };
  for (const RoadPair& pair : junction.angle_pairs) {
    check(pair.from, "the angle pair");
    check(pair.to, "the angle pair");
  }
  for (const LaneConnection& connection : junction.lane_connections) {
    check(connection.from.road, "the lane connection");
    for (const LaneName& to : connection.to) check(to.road, "the lane connection");
  }
  return known;
}

// Whether the stated angles can hold with road i on arm arms[chosen[i]]; `angle` is narrowed.
bool fits(const Junction& junction, const std::vector<ArmDirection>& arms,
          const std::vector<std::size_t>& chosen, Interval& angle) {
  const std::size_t pairs = std::min(junction.angle_pairs.size(), junction.angles.size());
  for (std::size_t k = 0; k < pairs && !angle.empty(); ++k) {
    const std::size_t a = road_index(junction, junction.angle_pairs[k].from);
    const std::size_t b = road_index(junction, junction.angle_pairs[k].to);
    constrain(angle, between(arms[chosen[a]], arms[chosen[b]]), junction.angles[k]);
  }
  return !angle.empty();
}

std::string range_text(const NumberRange& range) {
  return range.is_range ? format_number(range.low) + " to " + format_number(range.high)
                        : format_number(range.low);
}

std::string conflict_message(const Junction& junction, const std::string& map_name) {
  std::string stated;
  const std::size_t pairs = std::min(junction.angle_pairs.size(), junction.angles.size());
  for (std::size_t k = 0; k < pairs; ++k)
    stated += (k > 0 ? ", " : "") + junction.angle_pairs[k].from.name + " -> " +
              junction.angle_pairs[k].to.name + " " + range_text(junction.angles[k]);
  const std::string shape =
      map_name == "t_junction"
          ? "two roads in line (180 degrees apart) and a third meeting them at 45 to 135 degrees"
      : map_name == "roundabout"
          ? "its roads a quarter turn apart round the ring (90 degrees, 180 across it)"
          : "two straight roads crossing at 45 to 135 degrees (opposite roads 180 apart)";
  return "no layout of the " + map_name + " map (" + shape +
         ") gives these angles between roads (" + stated + ")";
}

// The first stated pair whose angle moves with the generator's `angle`.
void choose_angle_pair(const Junction& junction, const std::vector<ArmDirection>& arms,
                       const std::vector<std::size_t>& chosen, ArmLayout& layout) {
  const std::size_t pairs = std::min(junction.angle_pairs.size(), junction.angles.size());
  for (std::size_t k = 0; k < pairs; ++k) {
    const std::size_t a = road_index(junction, junction.angle_pairs[k].from);
    const std::size_t b = road_index(junction, junction.angle_pairs[k].to);
    const Between angle = between(arms[chosen[a]], arms[chosen[b]]);
    if (angle.c1 == 0) continue;
    // angle = c0 + c1 * generator's: with c0 = 0, c1 = 1 it is the generator's; with c0 = 180,
    // c1 = -1 its supplement.
    layout.angle_pair = k;
    layout.supplement = angle.c1 < 0;
    return;
  }
}

// A roundabout's roads take its arms in the order written, counter-clockwise round the ring. Its
// generator sets them a quarter turn apart whatever the file says (three roads evenly round a
// ring are 120 degrees apart, which no arrangement of it gives), so stated angles that cannot
// hold are a warning, not an error.
ArmLayout round_the_ring(const Junction& junction, const std::vector<ArmDirection>& arms,
                         Diagnostics& diagnostics) {
  std::vector<std::size_t> chosen(junction.connected_roads.size());
  std::iota(chosen.begin(), chosen.end(), 0);
  Interval angle;
  if (!fits(junction, arms, chosen, angle) && !junction.angles.empty())
    diagnostics.warning(junction.angles.front().location,
                        conflict_message(junction, "roundabout") +
                            ": the roads are set round the ring in the order written, and the "
                            "angles stay search dimensions that move nothing");
  ArmLayout layout;
  for (std::size_t i : chosen) layout.arms.push_back(arms[i].name);
  return layout;
}

// An actor on road `actor` placed in a sector of the reference on road `reference`: where the
// actor's arm must lie as the reference drives in on its own.
struct SideHint {
  std::size_t reference = 0, actor = 0;  // connected-road indices
  RelativeLocation sector = RelativeLocation::front;
};

std::vector<SideHint> side_hints(const Junction& junction, const Initialisation& initialisation) {
  std::map<std::string, std::string> road_of;  // actor -> the road of its initial lane
  road_of[initialisation.first.actor.name] = initialisation.first.lane.road.name;
  std::vector<SideHint> hints;
  for (const RelativeActorInit& init : initialisation.relative) {
    road_of[init.actor.name] = init.lane.road.name;
    const auto reference = road_of.find(init.reference.name);
    if (reference == road_of.end()) continue;
    const std::size_t a = road_index(junction, Identifier{reference->second, {}});
    const std::size_t b = road_index(junction, Identifier{init.lane.road.name, {}});
    const std::size_t roads = junction.connected_roads.size();
    if (a < roads && b < roads && a != b) hints.push_back({a, b, init.relative_position.value});
  }
  return hints;
}

// Whether the actor's arm lies in its sector of the reference driving in on its own arm, with the
// generator's angle at `angle`: straight across for F, to the left for SL and RSL, to the left or
// across for FSL (and the same on the right), never for R (behind, on the reference's own road).
bool on_named_side(const ArmDirection& reference, const ArmDirection& actor, double angle,
                   RelativeLocation sector) {
  const double heading = reference.c0 + reference.c1 * angle + 180;  // driving in
  double turn = std::fmod(actor.c0 + actor.c1 * angle - heading, 360);
  if (turn > 180) turn -= 360;
  if (turn <= -180) turn += 360;
  constexpr double kAcross = 45;  // degrees either side of straight on that are "across"
  switch (sector) {
    case RelativeLocation::front: return std::abs(turn) < kAcross;
    // Ahead and to one side: that side's arm, or the one across (ahead, a little to that side).
    case RelativeLocation::front_side_left: return turn > -kAcross && turn < 180;
    case RelativeLocation::front_side_right: return turn < kAcross && turn > -180;
    case RelativeLocation::side_left:
    case RelativeLocation::rear_side_left: return turn > 0 && turn < 180;
    case RelativeLocation::side_right:
    case RelativeLocation::rear_side_right: return turn < 0 && turn > -180;
    case RelativeLocation::rear: return false;
  }
  return false;
}

std::size_t hints_kept(const std::vector<SideHint>& hints, const std::vector<ArmDirection>& arms,
                       const std::vector<std::size_t>& chosen, const Interval& angle) {
  const double middle = (angle.low + angle.high) / 2;
  return static_cast<std::size_t>(std::count_if(hints.begin(), hints.end(), [&](const SideHint& h) {
    return on_named_side(arms[chosen[h.reference]], arms[chosen[h.actor]], middle, h.sector);
  }));
}

}  // namespace

std::optional<ArmLayout> lay_out_arms(const Junction& junction, const std::string& map_name,
                                      const Initialisation& initialisation,
                                      Diagnostics& diagnostics) {
  if (!names_known_roads(junction, diagnostics)) return std::nullopt;
  const std::vector<ArmDirection> arms = generator_arms(map_name);
  const std::size_t roads = junction.connected_roads.size();
  if (roads > arms.size()) return std::nullopt;  // translate_junction reports it
  // Arrangements of `roads` of the arms, in lexicographic order of the arm indices: the first is
  // the old reading (the first road west, the second south, ...), kept where the angles allow it.
  if (map_name == "roundabout") return round_the_ring(junction, arms, diagnostics);
  const std::vector<SideHint> hints = side_hints(junction, initialisation);
  std::optional<std::vector<std::size_t>> best;
  std::size_t best_kept = 0;
  std::vector<std::size_t> order(arms.size());
  std::iota(order.begin(), order.end(), 0);
  do {
    std::vector<std::size_t> chosen(order.begin(),
                                    order.begin() + static_cast<std::ptrdiff_t>(roads));
    Interval angle;
    if (!fits(junction, arms, chosen, angle)) continue;
    const std::size_t kept = hints_kept(hints, arms, chosen, angle);
    if (!best || kept > best_kept) {
      best = std::move(chosen);
      best_kept = kept;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  if (best) {
    ArmLayout layout;
    for (std::size_t i : *best) layout.arms.push_back(arms[i].name);
    choose_angle_pair(junction, arms, *best, layout);
    return layout;
  }
  const SourceLocation where =
      junction.angles.empty() ? junction.location : junction.angles.front().location;
  diagnostics.error(where, conflict_message(junction, map_name));
  return std::nullopt;
}

}  // namespace scenfuzz::wmg
