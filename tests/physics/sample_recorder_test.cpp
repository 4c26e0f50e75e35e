// The sample recorder: what a step records reaches the trace's columns, in order, whether or
// not the run ends on a whole block, and an actor perception missed has NaN in its perceived
// columns.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/simulation/sample_columns.hpp"

namespace scenfuzz {
namespace {

Trace two_actors() {
  Trace trace;
  trace.actors.resize(2);
  trace.actors[0].kind = TraceActorKind::ego;
  trace.perceived.push_back({1, {}, {}, {}, {}, {}, {}});
  return trace;
}

KinematicState state_at(std::size_t step, std::size_t actor) {
  KinematicState state;
  state.x = static_cast<double>(step) + 0.5 * static_cast<double>(actor);
  state.y = -state.x;
  state.heading = 0.01 * state.x;
  state.speed = 2 * state.x;
  state.acceleration = 3 * state.x;
  state.yaw_rate = 4 * state.x;
  state.reversing = step % 3 == 0;
  return state;
}

// Records `steps` steps (actor 1 seen on even steps only), then finishes.
Trace recorded(std::size_t steps) {
  Trace trace = two_actors();
  SampleRecorder recorder(trace, steps);
  for (std::size_t step = 0; step < steps; ++step) {
    trace.time.push_back(0.05 * static_cast<double>(step));
    for (std::size_t k = 0; k < 2; ++k)
      recorder.sample(
          k, state_at(step, k),
          LaneFix{static_cast<std::int32_t>(step % 4) - 1, 10.0 + static_cast<double>(step)});
    WorldObject seen;
    seen.x = 100.0 + static_cast<double>(step);
    seen.y = 200.0 + static_cast<double>(step);
    seen.heading = 0.5;
    seen.speed = 7;
    seen.reversing = true;
    recorder.perceived(1, step % 2 == 0 ? &seen : nullptr);
    recorder.end_step();
  }
  recorder.finish();
  return trace;
}

TEST(SampleRecorderTest, EveryStepReachesItsColumnsWhereverTheRunEnds) {
  // Less than a block, a block and a bit, several blocks and a bit.
  for (std::size_t steps : {1u, 5u, 33u, 70u, 601u}) {
    SCOPED_TRACE(steps);
    const Trace trace = recorded(steps);
    for (std::size_t k = 0; k < 2; ++k) {
      const TraceActor& actor = trace.actors[k];
      ASSERT_EQ(actor.x.size(), steps);
      ASSERT_EQ(actor.reversing.size(), steps);
      ASSERT_EQ(actor.lane.size(), steps);
      for (std::size_t i = 0; i < steps; ++i) {
        const KinematicState want = state_at(i, k);
        EXPECT_EQ(actor.x[i], want.x);
        EXPECT_EQ(actor.y[i], want.y);
        EXPECT_EQ(actor.heading[i], want.heading);
        EXPECT_EQ(actor.speed[i], want.speed);
        EXPECT_EQ(actor.acceleration[i], want.acceleration);
        EXPECT_EQ(actor.yaw_rate[i], want.yaw_rate);
        EXPECT_EQ(actor.reversing[i], want.reversing ? 1 : 0);
        EXPECT_EQ(actor.lane[i], static_cast<std::int32_t>(i % 4) - 1);
        EXPECT_EQ(actor.s[i], 10.0 + static_cast<double>(i));
      }
    }
    const PerceivedActor& perceived = trace.perceived[0];
    ASSERT_EQ(perceived.detected.size(), steps);
    for (std::size_t i = 0; i < steps; ++i) {
      const bool seen = i % 2 == 0;
      EXPECT_EQ(perceived.detected[i], seen ? 1 : 0);
      EXPECT_EQ(perceived.reversing[i], seen ? 1 : 0);
      if (seen) {
        EXPECT_EQ(perceived.x[i], 100.0 + static_cast<double>(i));
        EXPECT_EQ(perceived.y[i], 200.0 + static_cast<double>(i));
        EXPECT_EQ(perceived.heading[i], 0.5);
        EXPECT_EQ(perceived.speed[i], 7);
      } else {
        EXPECT_TRUE(std::isnan(perceived.x[i]) && std::isnan(perceived.y[i]) &&
                    std::isnan(perceived.heading[i]) && std::isnan(perceived.speed[i]));
      }
    }
  }
}

}  // namespace
}  // namespace scenfuzz
