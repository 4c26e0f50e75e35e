// The nearest approach of each actor to the ego's path: each of its samples against the ego's
// path thinned to points a metre apart (bodies are metres wide, so the thinning's error of a few
// centimetres cannot turn an interaction into none).
#include "oracle/actor_interaction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lang/number_format.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {
namespace {

constexpr double kPathSpacing = 1.0;  // m between the thinned path's points
constexpr std::size_t kListed = 8;    // actors a warning names, the nearest first
constexpr double kHeadingOnFor = 3;   // s of the ego's last speed and heading added to its path

// Half the diagonal of the body: the radius of the circle around it, so that a car crossing the
// path nose first counts its length.
double outer_radius(const TraceActor& actor) { return 0.5 * std::hypot(actor.length, actor.width); }

// The ego's trajectory, and where it was heading when the run ended: a run that an end condition
// stops just before the ego reaches a pedestrian crossing ahead of it did bring them together.
std::vector<MapPoint> ego_path(const TraceActor& ego) {
  std::vector<MapPoint> path;
  for (std::size_t i = 0; i < ego.x.size(); ++i) {
    const MapPoint p{ego.x[i], ego.y[i]};
    if (path.empty() || distance(path.back(), p) >= kPathSpacing || i + 1 == ego.x.size())
      path.push_back(p);
  }
  const std::size_t last = ego.x.size() - 1;
  const double ahead = kHeadingOnFor * ego.speed[last];
  if (ahead > 0)
    path.push_back({ego.x[last] + ahead * std::cos(ego.heading[last]),
                    ego.y[last] + ahead * std::sin(ego.heading[last])});
  return path;
}

double distance_to_segment(MapPoint p, MapPoint a, MapPoint b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, MapPoint{a.x + t * dx, a.y + t * dy});
}

double distance_to_path(MapPoint p, const std::vector<MapPoint>& path) {
  if (path.size() == 1) return distance(p, path.front());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    best = std::min(best, distance_to_segment(p, path[k], path[k + 1]));
  return best;
}

}  // namespace

std::vector<ActorApproach> actor_approaches(const Trace& trace) {
  std::vector<ActorApproach> out;
  if (trace.actors.empty() || trace.sample_count() == 0) return out;
  const TraceActor& ego = trace.actors[kEgo];
  const std::vector<MapPoint> path = ego_path(ego);
  for (ActorId id = 1; id < trace.actors.size(); ++id) {
    const TraceActor& actor = trace.actors[id];
    const std::size_t until = std::min(actor.present_until, trace.sample_count());
    if (actor.present_from >= until) continue;
    ActorApproach approach{id, std::numeric_limits<double>::infinity(), 0};
    for (std::size_t i = actor.present_from; i < until; ++i) {
      const double gap =
          distance_to_path({actor.x[i], actor.y[i]}, path) - outer_radius(actor) - 0.5 * ego.width;
      if (gap < approach.gap) approach = {id, std::max(gap, 0.0), trace.time[i]};
    }
    out.push_back(approach);
  }
  return out;
}

bool actors_interact(const std::vector<ActorApproach>& approaches) {
  return approaches.empty() ||
         std::any_of(approaches.begin(), approaches.end(),
                     [](const ActorApproach& a) { return a.gap <= kInteractionReach; });
}

std::string no_interaction_warning(const Trace& trace,
                                   const std::vector<ActorApproach>& approaches) {
  if (actors_interact(approaches)) return "";
  std::vector<ActorApproach> nearest = approaches;
  std::stable_sort(nearest.begin(), nearest.end(),
                   [](const ActorApproach& a, const ActorApproach& b) { return a.gap < b.gap; });
  std::string text = "the scenario's actors never come within " + format_number(kInteractionReach) +
                     " m of the ego's path (nearest: ";
  for (std::size_t k = 0; k < std::min(nearest.size(), kListed); ++k) {
    const ActorApproach& a = nearest[k];
    if (k > 0) text += ", ";
    text += trace.actors[a.actor].name + " " + format_number(std::round(a.gap * 10) / 10) +
            " m at " + format_number(std::round(a.time * 100) / 100) + " s";
  }
  if (nearest.size() > kListed)
    text += ", and " + std::to_string(nearest.size() - kListed) + " more";
  return text + "), so nothing the specs say about them can fail: check where the file puts them";
}

}  // namespace scenfuzz
