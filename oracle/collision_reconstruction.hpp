// Accident reconstruction: how far a simulated trace is from reproducing the collisions a written
// accident description lists (CarSim's formalism: `ACTOR = truck1, front; VICTIM = car1,
// leftside; COORD = (1.75, -1.75)`, in order). The search minimises the robustness returned here,
// so it is negative exactly when every described collision happened as described, and where it
// is positive it measures how far off the run was (metres), so that the search can descend it.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lang/scenario.hpp"
#include "physics/collision/body_side.hpp"
#include "physics/map/map_point.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// How far (m) the contact point may lie from a described place. The coordinates of a description
// come from a written police or insurance report (a sketch measured by hand, often relative to a
// kerb or lane marking), so they locate the crash to within about a car's length, not better.
inline constexpr double kPlaceTolerance = 5.0;

// Every unmet condition scores at least this much (m) and every met collision at most minus it,
// so that |robustness| >= kReconstructionMargin: a collision that misses by a hair is still
// clearly positive, and one met exactly at a boundary (a contact in a corner, two collisions at
// the same instant) still clearly negative.
inline constexpr double kReconstructionMargin = 0.1;

// Converts a time difference (s) into metres, the unit of every other term: a typical closing
// speed in a crash, so 0.1 s out of order weighs as much as a contact 1 m off.
inline constexpr double kOrderSpeed = 10.0;

// The body side a description's part names; nullopt for `unknown` (any side matches).
std::optional<BodySide> body_side_of(VehiclePart part);

// "front", "rear", "left side", "right side": a side in a description's words.
std::string body_side_words(BodySide side);

// A described part in words: its side's, "any part" for `unknown`.
std::string vehicle_part_words(VehiclePart part);

// One described collision checked against the trace.
struct CollisionCheck {
  bool happened = false;   // the named pair touched at all
  bool satisfied = false;  // it happened with the named parts, in order and at the place
  double robustness = 0;   // negative exactly when satisfied
  // Where the pair touched (valid when happened): the trace's time, contact point, and the side
  // of the striker and of the victim it touched.
  double time = 0;
  MapPoint contact;
  BodySide striker_side = BodySide::front;
  BodySide victim_side = BodySide::front;
  // When not happened: the smallest distance (m) over the run between the named parts (the whole
  // body for `unknown`; between two named faces, how far their middles are apart, since the gap
  // alone stalled searches on corners grazing each other); +inf when the two were never on the
  // map together.
  double closest_approach = 0;
  // What is wrong, in one sentence for a report ("truck1 hit car1 with its front on car1's rear,
  // not its left side"); empty when satisfied.
  std::string problem;
};

// A collision the description does not list, before its last one: a run with it is not the
// accident described (an overtaking car that first rear-ends the truck it overtakes).
struct UndescribedCollision {
  std::string first, second;  // the actors' names
  double time = 0;
  double robustness = 0;  // > 0: how far it weighs against the run
};

struct ReconstructionScore {
  // The max over the described collisions (all must hold) and the undescribed ones; -inf when
  // none is described and nothing collided.
  double robustness = 0;
  std::vector<CollisionCheck> collisions;  // one per described collision, in order
  std::vector<UndescribedCollision> undescribed;
};

// Scores `trace` against `expected`, in the order described. A collision between a pair the
// description does not list, no later than the last described collision that happened (or at any
// time while one has not), scores kReconstructionMargin + kOrderSpeed x how long before that it
// came, so that a search pushes it out of the accident. Places are evaluated with
// `parameter_values`; they must be coordinates in the ENU frame, or IMU (relative to the ego's
// initial pose). Throws std::invalid_argument for a name that is no actor of the trace, a
// collision of an actor with itself, or a place of another kind: the translation of a
// description checks these, so any of them is a bug upstream.
ReconstructionScore score_reconstruction(const Trace& trace,
                                         const std::vector<ExpectedCollision>& expected,
                                         std::span<const double> parameter_values);

}  // namespace scenfuzz
