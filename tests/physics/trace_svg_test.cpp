// render_trace_svg on hand-made traces over the built-in crossroads: a well-formed document with
// escaped names; a title with the spec, robustness, responsibility and reason; the collision
// marked; bodies at the asked instants; an inset on the event with the bodies then and 1, 2, 3 s
// before and speed arrows; the ego's target; the lights in their colours at the event; the
// perception range when weather limits it; a main view cropped around the ego; labels inside
// the canvas and apart, and a bounded aspect ratio.
#include "physics/trace/trace_svg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/map_description.hpp"
#include "physics/map/road_map.hpp"
#include "svg_labels.hpp"

namespace scenfuzz {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

const RoadMap& crossroads() {
  static const RoadMap map = build_road_map(generate_builtin_map("crossroads", {}));
  return map;
}

TraceActor actor(std::string name, TraceActorKind kind, double length, double width) {
  TraceActor result;
  result.name = std::move(name);
  result.kind = kind;
  result.length = length;
  result.width = width;
  result.height = 1.5;
  return result;
}

void add_sample(TraceActor& actor, MapPoint at, double heading, double speed) {
  actor.x.push_back(at.x);
  actor.y.push_back(at.y);
  actor.heading.push_back(heading);
  actor.speed.push_back(speed);
  actor.acceleration.push_back(0);
  actor.yaw_rate.push_back(0);
  actor.lane.push_back(-1);
  actor.s.push_back(0);
}

// 7 s at dt = 0.5: the ego drives east towards the junction, an NPC comes south into it, a
// pedestrian walks north (and drops out of the trace for one sample); they collide at the end.
Trace crossing_trace() {
  Trace trace;
  trace.map_name = "crossroads";
  trace.seed = 7;
  trace.dt = 0.5;
  trace.end = EndReason::collision;
  TraceActor ego = actor("ego", TraceActorKind::ego, 4.7, 2.0);
  TraceActor npc = actor("npc<1> & co", TraceActorKind::vehicle, 4.5, 1.9);
  TraceActor pedestrian = actor("ped", TraceActorKind::pedestrian, 0.6, 0.6);
  pedestrian.shape = BodyShape::cylinder;
  for (int i = 0; i <= 14; ++i) {
    const double t = 0.5 * i;
    trace.time.push_back(t);
    add_sample(ego, {-40 + 5 * t, -5.25}, 0, 5);
    add_sample(npc, {-3.5, 30 - 4.5 * t}, -std::numbers::pi / 2, 4.5);
    add_sample(pedestrian, {-13, -8 + 1.2 * t}, std::numbers::pi / 2, 1.2);
  }
  pedestrian.x[6] = pedestrian.y[6] = nan;
  trace.actors = {ego, npc, pedestrian};
  trace.collisions = {{7.0, 0, 1, {-3.5, -4.8}, BodySide::front, BodySide::rear}};
  trace.events = {{TraceEventKind::collision, 7.0, 0, ""}};
  return trace;
}

std::size_t count(std::string_view text, std::string_view what) {
  std::size_t found = 0;
  for (std::size_t at = text.find(what); at != std::string_view::npos;
       at = text.find(what, at + what.size()))
    ++found;
  return found;
}

// The nested <svg> element with this id, up to its end (views hold no nested <svg> of their own).
std::string_view view(std::string_view svg, std::string_view id) {
  const std::size_t start = svg.find("id=\"" + std::string(id) + "\"");
  if (start == std::string_view::npos) return {};
  const std::size_t end = svg.find("</svg>", start);
  return svg.substr(start, end - start);
}

// "" when `svg` is well-formed as far as these documents need: every tag closed in order, every
// '&' an entity, no '<' in text; else what is wrong.
std::string xml_problem(std::string_view svg) {
  std::vector<std::string> open;
  for (std::size_t at = 0; at < svg.size(); ++at) {
    if (svg[at] == '&') {
      const std::string_view rest = svg.substr(at);
      if (!rest.starts_with("&amp;") && !rest.starts_with("&lt;") && !rest.starts_with("&gt;") &&
          !rest.starts_with("&quot;") && !rest.starts_with("&apos;"))
        return "bare & at " + std::to_string(at);
      continue;
    }
    if (svg[at] != '<') continue;
    const std::size_t end = svg.find('>', at);
    if (end == std::string_view::npos) return "unterminated tag at " + std::to_string(at);
    const std::string_view tag = svg.substr(at + 1, end - at - 1);
    at = end;
    if (tag.starts_with('?') || tag.starts_with('!')) continue;
    if (tag.starts_with('/')) {
      if (open.empty() || open.back() != tag.substr(1))
        return "</" + std::string(tag.substr(1)) + "> closes " +
               (open.empty() ? std::string("nothing") : "<" + open.back() + ">");
      open.pop_back();
      continue;
    }
    const std::string name(tag.substr(0, tag.find_first_of(" \n/")));
    if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0])))
      return "bad tag <" + std::string(tag) + ">";
    if (!tag.ends_with('/')) open.push_back(name);
  }
  if (!open.empty()) return "<" + open.back() + "> never closed";
  return "";
}

double number_after(std::string_view text, std::string_view marker, std::size_t& position) {
  position = text.find(marker, position);
  EXPECT_NE(position, std::string_view::npos) << marker;
  if (position == std::string_view::npos) return nan;
  position += marker.size();
  double value = nan;
  const auto [end, error] =
      std::from_chars(text.data() + position, text.data() + text.size(), value);
  EXPECT_EQ(error, std::errc()) << marker;
  position = static_cast<std::size_t>(end - text.data());
  return value;
}

// The map region a view shows, from its viewBox and the origin the document's <desc> gives.
MapBounds shown_region(std::string_view svg, std::string_view id) {
  std::size_t position = 0;
  const double origin_x = number_after(svg, "map x = ", position);
  const double origin_y = number_after(svg, "map y = ", position);
  const std::string_view element = view(svg, id);
  position = 0;
  const double u = number_after(element, "viewBox=\"", position);
  const double v = number_after(element, " ", position);
  const double width = number_after(element, " ", position);
  const double height = number_after(element, " ", position);
  MapBounds region;
  region.include({origin_x + u, origin_y - v - height});
  region.include({origin_x + u + width, origin_y - v});
  return region;
}

TEST(TraceSvg, IsAWellFormedDocumentWithEscapedNames) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  EXPECT_TRUE(svg.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg "));
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_NE(svg.find(">npc&lt;1&gt; &amp; co</text>"), std::string::npos);
  EXPECT_EQ(svg.find("npc<1>"), std::string::npos);
  // The roads are drawn once and shown in both views.
  EXPECT_EQ(count(svg, "<svg "), 3u);
  EXPECT_EQ(count(svg, "<use xlink:href=\"#trace-roads\"/>"), 2u);
  EXPECT_NE(svg.find("class=\"lane\""), std::string::npos);
  EXPECT_EQ(svg.find("class=\"legend\""), std::string::npos);  // the map's own legend is left out
}

TEST(TraceSvg, TitleSaysTheSpecRobustnessResponsibilityAndReason) {
  TraceSvgOptions options;
  options.caption = {
      "no_collision", -0.25, 7.0, "dis(ego, npc) >= 0.5", "ego", "hit the crossing car's rear", ""};
  const std::string svg = render_trace_svg(crossroads(), crossing_trace(), options);
  EXPECT_NE(svg.find(">Spec no_collision violated, robustness -0.25 at 7.00 s</text>"),
            std::string::npos);
  EXPECT_NE(svg.find(">Responsibility: ego - hit the crossing car&apos;s rear</text>"),
            std::string::npos);
  EXPECT_NE(svg.find("atom dis(ego, npc) &gt;= 0.5"), std::string::npos);
  // Who hit whom and how fast, whatever the caller knows.
  EXPECT_NE(svg.find(">Collision at 7.00 s: ego&apos;s front with npc&lt;1&gt; &amp; co&apos;s "
                     "rear; ego at 5 m/s, npc&lt;1&gt; &amp; co at 4.5 m/s (closing 6.7 m/s)"),
            std::string::npos);

  // Without a responsibility (not decided yet) the line is left out, not left blank.
  options.caption.responsibility.clear();
  options.caption.reason.clear();
  const std::string without = render_trace_svg(crossroads(), crossing_trace(), options);
  EXPECT_EQ(without.find("Responsibility"), std::string::npos);
  EXPECT_EQ(without.find("Reason"), std::string::npos);
  const std::string bare = render_trace_svg(crossroads(), crossing_trace());
  EXPECT_NE(bare.find(">Trace on crossroads (seed 7)</text>"), std::string::npos);
  EXPECT_NE(bare.find("<title>Trace on crossroads (seed 7): ended by collision after 7.00 s"),
            std::string::npos);
}

TEST(TraceSvg, MarksTheCollisionAndTheCollidingBodies) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  // On the main view, in the inset and in the legend.
  EXPECT_EQ(count(svg, "<polygon class=\"trace-collision\""), 3u);
  EXPECT_NE(svg.find(">collision 7.00 s</text>"), std::string::npos);
  // The ego's and the NPC's bodies are drawn as colliding at the collision's sample, in both
  // views; the pedestrian's are not.
  EXPECT_EQ(count(view(svg, "main-view"), "class=\"trace-box trace-box-collision\""), 2u);
  EXPECT_EQ(count(view(svg, "inset-view"), "class=\"trace-box trace-box-collision\""), 2u);
}

TEST(TraceSvg, MainViewDrawsBodiesAtTheStartEveryIntervalAndTheEnd) {
  // Snapshots at 0, 5 and 7 s (the end and the collision): three per actor.
  const std::string every_five = render_trace_svg(crossroads(), crossing_trace());
  EXPECT_EQ(count(view(every_five, "main-view"), "<polygon class=\"trace-body"), 6u);
  EXPECT_EQ(count(view(every_five, "main-view"), "<circle class=\"trace-body"), 3u);

  TraceSvgOptions options;
  options.snapshot_interval = 2;  // 0, 2, 4, 6, 7 s
  const std::string every_two = render_trace_svg(crossroads(), crossing_trace(), options);
  EXPECT_EQ(count(view(every_two, "main-view"), "<polygon class=\"trace-body"), 10u);
  EXPECT_EQ(count(view(every_two, "main-view"), "<circle class=\"trace-body"), 5u);
}

TEST(TraceSvg, InsetShowsTheEventAndThreeSecondsBeforeWithSpeeds) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  const std::string_view inset = view(svg, "inset-view");
  ASSERT_FALSE(inset.empty());
  // The ego, the NPC and the pedestrian at 7 s (bold) and at 6, 5 and 4 s (faint).
  EXPECT_EQ(count(inset, "<polygon class=\"trace-body"), 8u);
  EXPECT_EQ(count(inset, "<circle class=\"trace-body"), 4u);
  EXPECT_EQ(count(inset, "stroke-opacity=\"0.6\""), 9u);
  EXPECT_GE(count(inset, "<g class=\"trace-speed\""), 2u);
  EXPECT_NE(svg.find(">ego, 5 m/s</text>"), std::string::npos);
  EXPECT_NE(svg.find(">npc&lt;1&gt; &amp; co, 4.5 m/s</text>"), std::string::npos);
  EXPECT_NE(svg.find(">-1 s</text>"), std::string::npos);
  EXPECT_NE(svg.find(">-3 s</text>"), std::string::npos);
  // It zooms: a smaller region than the main view's, inside it.
  const MapBounds main = shown_region(svg, "main-view");
  const MapBounds zoomed = shown_region(svg, "inset-view");
  EXPECT_LT(zoomed.max.x - zoomed.min.x, main.max.x - main.min.x);
  EXPECT_GE(zoomed.min.x, main.min.x - 1e-6);
  EXPECT_LE(zoomed.max.y, main.max.y + 1e-6);
  EXPECT_LE(zoomed.min.x, -3.5 - 2);  // the collision point with room around it
  EXPECT_GE(zoomed.max.x, -3.5 + 2);
}

TEST(TraceSvg, WithoutACollisionTheInsetIsAtTheVerdictsTime) {
  Trace trace = crossing_trace();
  trace.collisions.clear();
  trace.end = EndReason::duration;
  TraceSvgOptions options;
  options.caption = {"keep_distance", -1, 2.0, "", "", "", ""};
  const std::string svg = render_trace_svg(crossroads(), trace, options);
  EXPECT_NE(svg.find("Zoomed on the verdict&apos;s time at 2.00 s"), std::string::npos);
  // At 2 s the ego is at x = -30: the inset is about it, not about the junction.
  const MapBounds zoomed = shown_region(svg, "inset-view");
  EXPECT_LE(zoomed.min.x, -30 - 2.35);
  EXPECT_GE(zoomed.max.x, -30 + 2.35);
}

TEST(TraceSvg, DrawsTheEgosTarget) {
  Trace trace = crossing_trace();
  const std::string without = render_trace_svg(crossroads(), trace);
  EXPECT_EQ(without.find("class=\"trace-target\""), std::string::npos);
  trace.ego_target = MapPoint{20, -5.25};
  const std::string svg = render_trace_svg(crossroads(), trace);
  EXPECT_NE(view(svg, "main-view").find("class=\"trace-target\""), std::string::npos);
  EXPECT_NE(svg.find(">target</text>"), std::string::npos);
  EXPECT_NE(svg.find(">the ego&apos;s target</text>"), std::string::npos);
  EXPECT_GE(shown_region(svg, "main-view").max.x, 20);  // the crop reaches it
}

TEST(TraceSvg, LightsShowTheirColourAtTheEvent) {
  Trace trace = crossing_trace();
  // Red until 5 s, green from then: green at the collision (7 s).
  for (const TrafficLight& light : crossroads().traffic_lights()) {
    TraceLight traced{light.id, {}};
    for (const double t : trace.time)
      traced.colour.push_back(t < 5 ? SignalColour::red : SignalColour::green);
    trace.lights.push_back(traced);
  }
  const std::string svg = render_trace_svg(crossroads(), trace);
  const std::string_view main = view(svg, "main-view");
  EXPECT_GT(count(main, "class=\"trace-light\""), 0u);
  EXPECT_EQ(count(main, "class=\"trace-light\" cx="), count(main, "fill=\"#00b050\"/>"));
  EXPECT_EQ(main.find("#e00000\"/>"), std::string_view::npos);
  EXPECT_NE(svg.find(">traffic lights as they were at the event</text>"), std::string::npos);
}

TEST(TraceSvg, PerceptionRangeOnlyWhenWeatherOrDarknessLimitIt) {
  Trace trace = crossing_trace();
  trace.sensing = {150, 80, false};
  const std::string clear = render_trace_svg(crossroads(), trace);
  EXPECT_EQ(clear.find("trace-perception-vehicles"), std::string::npos);
  trace.sensing = {40, 18, true};
  const std::string foggy = render_trace_svg(crossroads(), trace);
  const std::string_view main = view(foggy, "main-view");
  std::size_t position = 0;
  const double origin_x = number_after(foggy, "map x = ", position);
  position = 0;
  const double centre_u = number_after(main, "class=\"trace-perception-vehicles\" cx=\"", position);
  EXPECT_NEAR(origin_x + centre_u, -5, 1e-3) << "centred on the ego at the event";
  EXPECT_NE(main.find("r=\"40\""), std::string_view::npos);
  EXPECT_NE(main.find("class=\"trace-perception-pedestrians\""), std::string_view::npos);
  EXPECT_NE(foggy.find("vehicles 40 m</text>"), std::string::npos);
}

TEST(TraceSvg, PathsBreakAtMissingSamplesAndDarkenWithTime) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  const std::size_t paths = count(view(svg, "main-view"), "<polyline class=\"trace-path\"");
  EXPECT_GE(paths, 3u * 10);  // each moving actor's path in several time slices
  EXPECT_NE(svg.find("stroke-opacity=\"1\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-opacity=\"0.36\""), std::string::npos);
}

// The ego throughout, the others over the 5 s before the collision.
TEST(TraceSvg, MainViewCoversTheEgoAndTheActorsNearTheEventButNotTheWholeMap) {
  const Trace trace = crossing_trace();
  const std::string svg = render_trace_svg(crossroads(), trace);
  const MapBounds shown = shown_region(svg, "main-view");
  for (const TraceActor& each : trace.actors)
    for (std::size_t i = 0; i < each.x.size(); ++i) {
      if (std::isnan(each.x[i]) || (each.kind != TraceActorKind::ego && trace.time[i] < 2))
        continue;
      EXPECT_GE(each.x[i] - each.length / 2, shown.min.x) << each.name;
      EXPECT_LE(each.x[i] + each.length / 2, shown.max.x) << each.name;
      EXPECT_GE(each.y[i] - each.length / 2, shown.min.y) << each.name;
      EXPECT_LE(each.y[i] + each.length / 2, shown.max.y) << each.name;
    }
  const MapBounds& whole = crossroads().bounds();
  EXPECT_LT(shown.max.x - shown.min.x, 0.4 * (whole.max.x - whole.min.x));
  EXPECT_LT(shown.max.y - shown.min.y, 0.4 * (whole.max.y - whole.min.y));
}

// A car far from the ego all run long is left out of the crop: it does not matter to the event.
TEST(TraceSvg, MainViewLeavesOutActorsFarFromTheEgo) {
  Trace trace = crossing_trace();
  TraceActor far = actor("far_away", TraceActorKind::vehicle, 4.5, 1.9);
  for (const double t : trace.time) add_sample(far, {120 - 2 * t, 5.25}, std::numbers::pi, 2);
  trace.actors.push_back(far);
  const std::string svg = render_trace_svg(crossroads(), trace);
  EXPECT_LT(shown_region(svg, "main-view").max.x, 100);
  EXPECT_EQ(svg.find(">far_away (vehicle)</text>"), std::string::npos);
}

// A 1.2 km straight drive would be a sliver 1600 x 40 pixels; its picture stays within 1:3.
TEST(TraceSvg, LongStraightDriveKeepsABoundedAspectRatioAndItsLabelsApart) {
  Trace trace;
  trace.map_name = "crossroads";
  trace.dt = 0.5;
  TraceActor ego = actor("ego_vehicle_with_a_long_name", TraceActorKind::ego, 4.7, 2.0);
  TraceActor lead = actor("lead_vehicle_with_a_long_name", TraceActorKind::vehicle, 4.7, 2.0);
  for (int i = 0; i <= 80; ++i) {
    trace.time.push_back(0.5 * i);
    add_sample(ego, {-600 + 15 * 0.5 * i, -5.25}, 0, 15);
    add_sample(lead, {-580 + 14 * 0.5 * i, -5.25}, 0, 14);
  }
  trace.actors = {ego, lead};
  trace.ego_target = MapPoint{20, -5.25};
  TraceSvgOptions options;
  options.caption = {"a_spec_whose_name_goes_on_and_on_and_on_and_on_and_on_and_on",
                     -3.5,
                     12,
                     "",
                     "other",
                     std::string(300, 'x'),  // a word longer than any line
                     ""};
  const std::string svg = render_trace_svg(crossroads(), trace, options);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(test::layout_problems(svg), "");
}

TEST(TraceSvg, EveryCrossingPictureKeepsItsLabelsOnTheCanvasApart) {
  TraceSvgOptions options;
  options.caption = {"no_collision", -0.5, 7, "", "shared", "both entered the junction", ""};
  EXPECT_EQ(test::layout_problems(render_trace_svg(crossroads(), crossing_trace(), options)), "");
  // Names at the picture's edge (the old picture cut them: "ego_vehic").
  Trace edge = crossing_trace();
  edge.actors[0].name = "ego_vehicle";
  edge.actors[2].name = "a_pedestrian_with_a_rather_long_name";
  EXPECT_EQ(test::layout_problems(render_trace_svg(crossroads(), edge, options)), "");
  EXPECT_NE(render_trace_svg(crossroads(), edge).find(">ego_vehicle</text>"), std::string::npos);
}

TEST(TraceSvg, DrawsOnlyTheLanesNearTheActors) {
  // Ten parallel 50 m lanes, 100 m apart; the actors stay on the first.
  MapDescription description;
  description.name = "ladder";
  description.source = "test";
  for (int i = 0; i < 10; ++i) {
    LaneDescription lane;
    lane.id = "rung_" + std::to_string(i);
    lane.centre_line = {{0, 100.0 * i}, {50, 100.0 * i}};
    description.lanes.push_back(lane);
  }
  const RoadMap ladder = build_road_map(description);
  Trace trace = crossing_trace();
  for (TraceActor& each : trace.actors) {
    for (double& x : each.x) x = std::clamp(x + 45, 0.0, 50.0);
    for (double& y : each.y) y = std::clamp(y, -2.0, 2.0);
  }
  trace.collisions.front().point = {45, 0};
  const std::string svg = render_trace_svg(ladder, trace);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(count(svg, "<polygon class=\"lane\""), 1u);
}

// A city-sized map (1600 lanes of 60 m on a 40 x 40 grid) draws only the block the actors are in:
// the picture stays a few tens of kB where the whole map is a few MB.
TEST(TraceSvg, CityMapPictureStaysSmall) {
  MapDescription description;
  description.name = "grid";
  description.source = "test";
  for (int row = 0; row < 40; ++row)
    for (int column = 0; column < 40; ++column) {
      LaneDescription lane;
      lane.id = "lane_" + std::to_string(row) + "_" + std::to_string(column);
      for (int step = 0; step <= 30; ++step)
        lane.centre_line.push_back({column * 70.0 + step * 2.0, row * 20.0 - 5.25});
      description.lanes.push_back(std::move(lane));
    }
  const RoadMap grid = build_road_map(std::move(description));
  Trace trace = crossing_trace();
  for (TraceActor& each : trace.actors)
    for (double& x : each.x) x += 1400;
  trace.collisions.front().point.x += 1400;
  TraceSvgOptions options;
  options.lane_labels = true;
  const std::string svg = render_trace_svg(grid, trace, options);
  EXPECT_EQ(xml_problem(svg), "");
  const std::size_t lanes = count(svg, "<polygon class=\"lane\"");
  EXPECT_GT(lanes, 0u);
  EXPECT_LT(lanes, 30u);
  EXPECT_LT(svg.size(), 100'000u);
}

TEST(TraceSvg, ScaleOfTheMainView) {
  TraceSvgOptions options;
  options.pixels_per_metre = 4;
  const std::string svg = render_trace_svg(crossroads(), crossing_trace(), options);
  const std::string_view main = view(svg, "main-view");
  std::size_t position = 0;
  const double width_pixels = number_after(main, "width=\"", position);
  position = 0;
  number_after(main, "viewBox=\"", position);
  number_after(main, " ", position);
  const double width_metres = number_after(main, " ", position);
  EXPECT_NEAR(width_pixels, 4 * width_metres, 1);
}

TEST(TraceSvg, ActorsOffTheMapAndEmptyTracesStillDraw) {
  Trace far_away = crossing_trace();
  for (TraceActor& each : far_away.actors)
    for (double& x : each.x) x += 5000;
  far_away.collisions.clear();
  const std::string svg = render_trace_svg(crossroads(), far_away);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(count(svg, "<polygon class=\"lane\""), 0u);                         // no road there
  EXPECT_EQ(count(view(svg, "main-view"), "<polygon class=\"trace-body"), 6u);  // 0, 5 and 7 s
  EXPECT_EQ(test::layout_problems(svg), "");

  const std::string empty = render_trace_svg(crossroads(), Trace{});
  EXPECT_EQ(xml_problem(empty), "");
  EXPECT_EQ(count(empty, "<polygon class=\"lane\""), crossroads().lanes().size());  // all of it
  EXPECT_TRUE(view(empty, "inset-view").empty());
}

}  // namespace
}  // namespace scenfuzz
