// The trace's per-sample columns as the simulation records them: reserved for the whole run
// before its first step, then appended to a block of steps at a time. A step's samples are kept
// row by row (one actor's values side by side) and go to the columns every kBlock steps: written
// straight into 15 columns per actor, every store of a step touched a cache line of its own and
// stalled on it (about 7 % of a 30-actor run's time; docs/performance.md).
#pragma once

#include <cstddef>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/ego/perception.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

class SampleRecorder {
 public:
  // Reserves every actor's and perceived actor's sample columns, time, signals and the lights'
  // colours for `samples` samples.
  SampleRecorder(Trace& trace, std::size_t samples);

  // This step's sample of actor k, and what perception reports of it (null: not detected; actor
  // 0, the ego, has no perceived columns).
  void sample(std::size_t k, const KinematicState& state, LaneFix lane);
  void perceived(std::size_t k, const WorldObject* seen);
  // Ends the step: its rows go to the columns with the block's.
  void end_step();
  // Writes what is left: the columns then hold as many samples as trace.time.
  void finish();

 private:
  // Steps: four cache lines of doubles per column (a block of 8, one line, was about 2 % slower).
  static constexpr std::size_t kBlock = 32;
  struct Row {
    KinematicState state;
    LaneFix lane;
    WorldObject seen;
    bool detected = false;
  };
  void flush();

  Trace& trace_;
  std::size_t actors_ = 0;
  std::size_t first_ = 0;   // samples already in the columns
  std::size_t rows_ = 0;    // steps in the block
  std::vector<Row> block_;  // [step in block][actor]
};

}  // namespace scenfuzz
