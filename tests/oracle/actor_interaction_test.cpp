// The sanity check that a scenario's actors come near the ego at all
// (oracle/actor_interaction.hpp), on hand-built traces.
#include "oracle/actor_interaction.hpp"

#include <gtest/gtest.h>

#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::drive_east;
using test::empty_trace;
using test::still_actor;

// An ego driving east along y = 0 from x = 0 at 10 m/s for 10 s (100 samples of 0.1 s).
Trace ego_driving_east() {
  Trace trace = empty_trace(100);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 2.0, 0, 0));
  drive_east(trace, trace.actors[kEgo], 0, 10, -1, 0);
  return trace;
}

TEST(ActorInteractionTest, APedestrianCrossingWhereTheEgoHasPassedInteracts) {
  Trace trace = ego_driving_east();
  // Crosses the ego's path at x = 20 from 8 s on, long after the ego went by: the path is the
  // ground the ego covers, whenever it covers it.
  trace.actors.push_back(still_actor(trace, "ped", TraceActorKind::pedestrian, BodyShape::cylinder,
                                     0.6, 0.6, 20, -10));
  for (std::size_t i = 80; i < 100; ++i) trace.actors[1].y[i] = -10 + 0.5 * (double(i) - 79);
  const auto approaches = actor_approaches(trace);
  ASSERT_EQ(approaches.size(), 1u);
  EXPECT_EQ(approaches[0].gap, 0);
  EXPECT_TRUE(actors_interact(approaches));
  EXPECT_EQ(no_interaction_warning(trace, approaches), "");
}

TEST(ActorInteractionTest, ActorsThatStayAwayAreNamedWithTheNearestTheyCame) {
  Trace trace = ego_driving_east();
  // A car driving parallel 12 m to the side, and a pedestrian walking away from the road.
  trace.actors.push_back(
      still_actor(trace, "npc", TraceActorKind::vehicle, BodyShape::box, 4.0, 3.0, 0, 12));
  drive_east(trace, trace.actors[1], 0, 10, -1, 12);
  trace.actors.push_back(
      still_actor(trace, "ped", TraceActorKind::pedestrian, BodyShape::cylinder, 0.6, 0.6, 50, -8));
  for (std::size_t i = 0; i < 100; ++i) trace.actors[2].y[i] = -8 - 0.1 * double(i);
  const auto approaches = actor_approaches(trace);
  ASSERT_EQ(approaches.size(), 2u);
  // 12 m between centre and path, less the car's outer radius (2.5 m) and the ego's half width.
  EXPECT_NEAR(approaches[0].gap, 12 - 2.5 - 1.0, 1e-9);
  EXPECT_NEAR(approaches[1].gap, 8 - 0.3 * std::sqrt(2.0) - 1.0, 1e-9);
  EXPECT_EQ(approaches[1].time, 0);  // nearest at the start, then walking away
  EXPECT_FALSE(actors_interact(approaches));
  EXPECT_EQ(no_interaction_warning(trace, approaches),
            "the scenario's actors never come within 3 m of the ego's path (nearest: ped 6.6 m "
            "at 0 s, npc 8.5 m at 0 s), so nothing the specs say about them can fail: check "
            "where the file puts them");
  // One actor that comes near is enough.
  trace.actors[1].y[50] = 4.0;
  EXPECT_TRUE(actors_interact(actor_approaches(trace)));
}

TEST(ActorInteractionTest, AnEgoAloneOrActorsNeverOnTheMapAreNoWarning) {
  Trace trace = ego_driving_east();
  EXPECT_TRUE(actor_approaches(trace).empty());
  EXPECT_TRUE(actors_interact(actor_approaches(trace)));
  // A background vehicle that never got onto the map is not an actor that stayed away.
  trace.actors.push_back(
      still_actor(trace, "flow.1", TraceActorKind::vehicle, BodyShape::box, 4.0, 2.0, 0, 50));
  trace.actors[1].present_from = trace.actors[1].present_until = 0;
  EXPECT_TRUE(actor_approaches(trace).empty());
}

}  // namespace
}  // namespace scenfuzz
