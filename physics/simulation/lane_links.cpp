// The ways through a junction a scenario says its map has: a link from a lane into a junction to a
// lane out of it holds when junction lanes alone lead from the one to the other (one connector at
// a crossroads, entry, ring and exit at a roundabout).
#include "physics/simulation/lane_links.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace scenfuzz {
namespace {

// A lane out of the junction ahead of a lane, and the turn of the first junction lane towards it.
struct Exit {
  LaneIndex lane = 0;
  LaneTurn turn = LaneTurn::none;
};

std::vector<Exit> exits_from(const RoadMap& map, LaneIndex from) {
  std::vector<Exit> exits;
  std::vector<std::pair<LaneIndex, LaneTurn>> frontier;
  for (LaneIndex next : map.lane(from).successors)
    if (map.lane(next).junction) frontier.emplace_back(next, map.lane(next).turn);
  std::set<LaneIndex> seen;
  while (!frontier.empty()) {
    const auto [lane, turn] = frontier.back();
    frontier.pop_back();
    if (!seen.insert(lane).second) continue;
    for (LaneIndex next : map.lane(lane).successors) {
      if (map.lane(next).junction) {
        frontier.emplace_back(next, turn);
      } else if (std::none_of(exits.begin(), exits.end(),
                              [&](const Exit& exit) { return exit.lane == next; })) {
        exits.push_back({next, turn});
      }
    }
  }
  return exits;
}

const char* turn_text(LaneTurn turn) {
  switch (turn) {
    case LaneTurn::left: return "turning left";
    case LaneTurn::right: return "turning right";
    case LaneTurn::u_turn: return "a U-turn";
    case LaneTurn::none: break;
  }
  return "straight on";
}

// "'east_out_0' (straight on) and 'south_out_0' (turning right)".
std::string exits_text(const RoadMap& map, const std::vector<Exit>& exits) {
  std::string text;
  for (std::size_t i = 0; i < exits.size(); ++i) {
    if (i > 0) text += i + 1 == exits.size() ? " and " : ", ";
    text += "'" + map.lane(exits[i].lane).id + "' (" + turn_text(exits[i].turn) + ")";
  }
  return text;
}

bool reaches(const std::vector<Exit>& exits, LaneIndex lane) {
  return std::any_of(exits.begin(), exits.end(),
                     [&](const Exit& exit) { return exit.lane == lane; });
}

}  // namespace

bool check_lane_links(const RoadMap& map, const std::vector<LaneLink>& links,
                      Diagnostics& diagnostics) {
  bool ok = true;
  for (const LaneLink& link : links) {
    const std::optional<LaneIndex> from = map.find_lane(link.from);
    const std::optional<LaneIndex> to = map.find_lane(link.to);
    if (!from || !to) {
      diagnostics.error(link.location, "map '" + map.name() + "' has no lane '" +
                                           (from ? link.to : link.from) + "'");
      ok = false;
      continue;
    }
    const std::vector<Exit> exits = exits_from(map, *from);
    if (reaches(exits, *to)) continue;
    diagnostics.error(link.location,
                      "map '" + map.name() + "' has no way through the junction from '" +
                          link.from + "' to '" + link.to + "': '" + link.from + "' leads " +
                          (exits.empty() ? "into no junction" : "to " + exits_text(map, exits)));
    ok = false;
  }
  return ok;
}

void warn_of_turn_against_links(const RoadMap& map, const std::vector<LaneLink>& links,
                                LaneIndex lane, LaneTurn wanted, const std::string& what,
                                const SourceLocation& where, Diagnostics& diagnostics) {
  std::vector<Exit> named;
  const std::vector<Exit> exits = exits_from(map, lane);
  for (const LaneLink& link : links) {
    const std::optional<LaneIndex> to = map.find_lane(link.to);
    if (link.from != map.lane(lane).id || !to) continue;
    for (const Exit& exit : exits)
      if (exit.lane == *to) named.push_back(exit);
  }
  if (named.empty()) return;  // the file says nothing of where this lane leads
  std::vector<Exit> turning;
  for (const Exit& exit : exits)
    if (exit.turn == wanted) turning.push_back(exit);
  if (turning.empty()) return;  // no such turn here: the phase keeps its lane
  for (const Exit& exit : turning)
    if (reaches(named, exit.lane)) return;
  const std::string verb = wanted == LaneTurn::left    ? " turns left"
                           : wanted == LaneTurn::right ? " turns right"
                                                       : " goes straight on";
  diagnostics.warning(
      where,
      what + verb + " from '" + map.lane(lane).id + "' into " + exits_text(map, turning) +
          ", where the junction's lane connections from that lane do not "
          "lead (they lead to " +
          exits_text(map, named) + "); " +
          (wanted == LaneTurn::none ? "it takes the lanes ahead" : "it turns as its phase says"));
}

}  // namespace scenfuzz
