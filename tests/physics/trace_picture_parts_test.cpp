// The parts of a trace's picture below the drawing: label placement (estimates never narrower
// than the text, no place taken twice, nothing outside the area, wrapping within a width), the
// moment the inset zooms on, and what simulate records for the picture (the ego's target, the
// perception range in fog).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "physics/trace/label_placement.hpp"
#include "physics/trace/trace_moment.hpp"
#include "physics/trace/trace_svg_parts.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

TEST(LabelPlacement, EstimatesAreAtLeastDejaVuSansAdvances) {
  // DejaVu Sans advances in ems: 'm' 0.974, 'W' 0.989, digits 0.636, bold digits 0.696.
  EXPECT_GE(estimated_text_width("mmmm", {10, false}), 4 * 9.74);
  EXPECT_GE(estimated_text_width("WWWW", {10, false}), 4 * 9.89);
  EXPECT_GE(estimated_text_width("0123456789", {10, true}), 10 * 6.96);
  EXPECT_GE(estimated_text_width("ego_vehicle", {13, true}), 13 * 6.9);  // measured 6.86 em
  // A multi-byte character counts once, as wide as an em dash.
  EXPECT_DOUBLE_EQ(estimated_text_width("\xe2\x80\x94", {10, false}), 10.5);
}

TEST(LabelPlacement, PlacesAroundTheAnchorWithoutOverlapOrLeavingTheArea) {
  LabelPlacer placer({0, 0, 200, 100});
  const TextFont font{12, false};
  std::vector<PixelBox> placed;
  for (int k = 0; k < 6; ++k) {
    const std::optional<PlacedLabel> label = placer.place(100, 50, 5, "label", font);
    ASSERT_TRUE(label) << k;
    EXPECT_TRUE(contains({0, 0, 200, 100}, label->box));
    for (const PixelBox& other : placed) EXPECT_FALSE(overlaps(other, label->box));
    placed.push_back(label->box);
    // The box is the one a reader computes from the text's start and baseline.
    const PixelBox again = text_box(label->x, label->baseline, "label", font);
    EXPECT_DOUBLE_EQ(again.left, label->box.left);
    EXPECT_DOUBLE_EQ(again.bottom, label->box.bottom);
  }
  // An anchor in the corner still gets its label inside.
  const std::optional<PlacedLabel> corner = placer.place(199, 1, 3, "corner", font);
  ASSERT_TRUE(corner);
  EXPECT_TRUE(contains({0, 0, 200, 100}, corner->box));
  // Text wider than the area has no place.
  EXPECT_FALSE(placer.place(100, 50, 5, std::string(40, 'x'), font));
}

TEST(LabelPlacement, KeepsOffBlockedBoxes) {
  LabelPlacer placer({0, 0, 300, 300});
  placer.block({0, 0, 300, 140});
  const std::optional<PlacedLabel> label = placer.place(150, 150, 4, "name", {13, true});
  ASSERT_TRUE(label);
  EXPECT_GE(label->box.top, 140);
}

TEST(LabelPlacement, WrapsWithinTheWidthAndCutsAWordTooLong) {
  const TextFont font{13, false};
  const std::string text =
      "the other entered the ego's lane 1.1 s before impact, less than the "
      "ego's stopping time at 8 m/s2 " +
      std::string(80, 'x');
  const std::vector<std::string> lines = wrapped(text, font, 250);
  ASSERT_GE(lines.size(), 3u);
  for (const std::string& line : lines) EXPECT_LE(estimated_text_width(line, font), 250) << line;
  EXPECT_TRUE(lines.back().ends_with("..."));
}

Trace two_cars(double gap_at_two_seconds) {
  Trace trace;
  trace.dt = 1;
  TraceActor ego, other;
  ego.kind = TraceActorKind::ego;
  ego.length = other.length = 4;
  ego.width = other.width = 2;
  for (int i = 0; i <= 4; ++i) {
    trace.time.push_back(i);
    const double gap = i == 2 ? gap_at_two_seconds : 20;
    for (auto [actor, x] : {std::pair{&ego, 0.0}, std::pair{&other, 4 + gap}}) {
      actor->x.push_back(x + i);
      actor->y.push_back(0);
      actor->heading.push_back(0);
      actor->speed.push_back(1);
    }
  }
  trace.actors = {ego, other};
  return trace;
}

TEST(TraceMoment, TheEgosFirstCollisionOverAnythingElse) {
  Trace trace = two_cars(3);
  trace.actors.push_back(trace.actors[1]);
  trace.collisions = {{1, 1, 2, {10, 0}, BodySide::front, BodySide::rear},  // not the ego's
                      {3, 0, 2, {5, 0}, BodySide::front, BodySide::rear},
                      {4, 0, 1, {6, 0}, BodySide::front, BodySide::rear}};
  const std::optional<TraceMoment> moment = key_moment(trace, 2.0);
  ASSERT_TRUE(moment);
  EXPECT_EQ(moment->kind, MomentKind::collision);
  EXPECT_EQ(moment->sample, 3u);
  EXPECT_EQ(moment->other, 2u);
  EXPECT_EQ(moment->collision, 1u);
  EXPECT_EQ(moment->point, (MapPoint{5, 0}));
}

TEST(TraceMoment, TheVerdictsTimeElseTheNearestApproach) {
  const Trace trace = two_cars(3);
  const std::optional<TraceMoment> verdict = key_moment(trace, 3.2);
  ASSERT_TRUE(verdict);
  EXPECT_EQ(verdict->kind, MomentKind::verdict);
  EXPECT_EQ(verdict->sample, 4u);  // at or just after
  EXPECT_EQ(verdict->other, 1u);
  const std::optional<TraceMoment> nearest = key_moment(trace, std::nullopt);
  ASSERT_TRUE(nearest);
  EXPECT_EQ(nearest->kind, MomentKind::nearest_approach);
  EXPECT_EQ(nearest->sample, 2u);
  EXPECT_NEAR(gap_to_ego(trace, 1, 2), 3, 1e-9);
  EXPECT_EQ(nearest->point, (MapPoint{2, 0}));  // the ego's position then
  EXPECT_FALSE(key_moment(Trace{}, 1.0));
}

TEST(TracePictureInputs, SimulateRecordsTheTargetAndTheRangeInFog) {
  const std::filesystem::path file =
      std::filesystem::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit" / "fog_night_following.avu";
  const std::optional<SourceFile> source = read_source_file(file.string());
  ASSERT_TRUE(source);
  const test::SimulatedRun run = test::simulate_file(*source);
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_TRUE(run.trace->ego_target);
  EXPECT_NEAR(run.trace->ego_target->x, 495, 5);  // "east_0"->495 on the straight road
  EXPECT_TRUE(run.trace->sensing.limited);
  EXPECT_LT(run.trace->sensing.vehicle_range, PerceptionSettings{}.vehicle_range / 2);
  EXPECT_LT(run.trace->sensing.pedestrian_range, run.trace->sensing.vehicle_range);

  // A seed without weather or a time of day is clear daylight: nothing limited.
  const std::optional<SourceFile> clear_source =
      read_source_file((file.parent_path() / "cut_in_straight.avu").string());
  ASSERT_TRUE(clear_source);
  const test::SimulatedRun clear = test::simulate_file(*clear_source);
  ASSERT_TRUE(clear.trace) << clear.errors;
  EXPECT_FALSE(clear.trace->sensing.limited);
  EXPECT_DOUBLE_EQ(clear.trace->sensing.vehicle_range, PerceptionSettings{}.vehicle_range);
}

}  // namespace
}  // namespace scenfuzz
