// The actors filed by the lanes they occupy at one step, as traffic simulators find what is ahead
// of a vehicle (SUMO: the vehicles on the lanes of its route and their foes), so that a lane
// follower's scan looks only at the actors on the lanes its path runs over and at the lanes
// that cross them, instead of at every actor near its path. Built once per step by the
// simulation for all followers.
//
// A vehicle is filed by lane only while it keeps to its lane: its body lies within the lane's
// narrowest width, both where it is and where it is predicted to be (predicted_points.hpp, its
// heading held for the prediction time against the lane's direction where it is). It is filed
// under its lane, under the successors its predicted body can reach, and under the predecessors
// its body can reach back into. Every other actor (the ego, pedestrians, obstacles, a vehicle
// off the lanes, changing lane or turned across its lane) is "loose": followers look at it by
// geometry, as at every actor before.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/map/map_point.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/simulation/predicted_points.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// What LaneOccupancy::build reads of one step, by actor id.
struct OccupancyInputs {
  std::span<const KinematicState> states;
  const PointPredictor* facings = nullptr;  // cos and sin of each actor's heading (facing)
  std::span<const LaneFix> lanes;
  std::span<const double> lengths;
  std::span<const double> widths;
  std::span<const TraceActorKind> kinds;
  std::span<const std::uint8_t> present;  // empty: every actor is present
  double prediction_time = 0;             // s
};

class LaneOccupancy {
 public:
  explicit LaneOccupancy(const RoadMap& map);

  // The step's actors; they are filed when first asked for (followers scan every few steps
  // only, so most steps nobody asks). The spans must stay valid until the next call.
  void set_step(const OccupancyInputs& inputs);

  // Appends the actors filed under `lane` (ascending).
  void append_on(LaneIndex lane, std::vector<std::uint32_t>& actors) const;
  // Every present actor filed under no lane (ascending).
  const std::vector<std::uint32_t>& loose() const;
  // Into `actors` (cleared first), ascending: every loose actor and every actor filed under one
  // of `lanes` (repeats allowed). The same as appending each lane's actors and the loose ones,
  // sorted and without repeats, from bit masks of the actors instead of a sort.
  void gather(std::span<const LaneIndex> lanes, std::vector<std::uint32_t>& actors) const;

  // Whether a present pedestrian at least `walking_speed` fast is within `clearance` of the
  // outline of crosswalk `crosswalk` (RoadMap::crosswalks()): the lane followers' crosswalk
  // test, answered once per step for all of them (each asked of every pedestrian before).
  bool walkers_at(std::uint32_t crosswalk, double walking_speed, double clearance) const;

 private:
  // The filing, kept out of the const queries' sight: it is a cache of the step's inputs.
  struct Filing {
    std::vector<std::pair<LaneIndex, std::uint32_t>> filed;  // (lane, actor), sorted
    // Of each lane: 1 + the index into `filed` of its first entry, or 0 (only filed lanes are
    // set, and reset at the next build).
    std::vector<std::uint32_t> first;
    std::vector<std::uint32_t> loose;
    // The same as bit masks of `words` 64-bit words (bit k % 64 of word k / 64 for actor k):
    // lane l's actors at masks[(mask_slot[l] - 1) * words] on (mask_slot[l] == 0: none, only
    // filed lanes are set, and reset at the next build), the loose actors at loose_mask.
    std::size_t words = 0;
    std::vector<std::uint64_t> masks;
    std::vector<std::uint32_t> mask_slot;
    std::vector<std::uint64_t> loose_mask;
    std::vector<std::uint64_t> gathered;  // gather's sum of masks, kept to reuse its memory
    std::vector<std::size_t> segments;    // of each actor: its lane's segment at the last build
    bool built = false;
  };

  // walkers_at's answers this step, by crosswalk, for one walking speed and clearance (the
  // followers' settings; another pair is answered without keeping it).
  struct Walkers {
    std::vector<std::uint8_t> answers;  // 0: not asked this step, 1: none, 2: some
    std::vector<std::uint32_t> asked;   // the crosswalks answered, to reset at the next step
    double walking_speed = -1, clearance = -1;
  };

  void build() const;
  bool any_walker_at(std::uint32_t crosswalk, double walking_speed, double clearance) const;
  // The filing as bit masks of actors (Filing::masks), after build's sort.
  void make_masks() const;
  // Whether actor k keeps to lane fix.lane now and where predicted; files it if so.
  bool file_on_lanes(std::uint32_t k) const;
  void file_ahead(LaneIndex lane, double reach, std::uint32_t k, int depth) const;
  void file_behind(LaneIndex lane, double reach, std::uint32_t k, int depth) const;

  const RoadMap* map_;
  OccupancyInputs inputs_;
  mutable Filing filing_;
  mutable Walkers walkers_;
};

}  // namespace scenfuzz
