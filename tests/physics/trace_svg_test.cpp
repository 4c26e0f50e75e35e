// render_trace_svg on hand-made traces over the built-in crossroads: a well-formed document with
// escaped names, the collision marked and labelled, bodies at the asked instants, and a viewBox
// that covers the actors but not the whole map, whose roads alone are drawn.
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

// The map region the document's viewBox shows, from its size and the origin its <desc> gives.
MapBounds shown_region(std::string_view svg) {
  std::size_t position = 0;
  const double width = number_after(svg, "viewBox=\"0 0 ", position);
  const double height = number_after(svg, " ", position);
  const double origin_x = number_after(svg, "map x = ", position);
  const double origin_y = number_after(svg, "map y = ", position);
  MapBounds region;
  region.include({origin_x, origin_y - height});
  region.include({origin_x + width, origin_y});
  return region;
}

TEST(TraceSvg, IsAWellFormedDocumentWithEscapedNames) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  EXPECT_TRUE(svg.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg "));
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_NE(svg.find(">npc&lt;1&gt; &amp; co</text>"), std::string::npos);
  EXPECT_EQ(svg.find("npc<1>"), std::string::npos);
  EXPECT_EQ(count(svg, "<svg "), 1u);  // the roads are drawn in the picture's own frame
  EXPECT_NE(svg.find("class=\"lane\""), std::string::npos);
  EXPECT_EQ(svg.find("class=\"legend\""), std::string::npos);  // the map's own legend is left out
}

TEST(TraceSvg, MarksAndLabelsTheCollision) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  EXPECT_EQ(count(svg, "<polygon class=\"trace-collision\""), 2u);  // on the map and in the legend
  EXPECT_NE(svg.find(">t=7.00 s ego front / npc&lt;1&gt; &amp; co rear</text>"), std::string::npos);
  // Both bodies are drawn as colliding at the collision's sample, the pedestrian's is not.
  EXPECT_EQ(count(svg, "class=\"trace-box trace-box-collision\""), 2u);
}

TEST(TraceSvg, DrawsBodiesAtTheStartEveryIntervalAndTheEnd) {
  // Snapshots at 0, 5 and 7 s (the end and the collision): three per actor.
  const std::string every_five = render_trace_svg(crossroads(), crossing_trace());
  EXPECT_EQ(count(every_five, "<polygon class=\"trace-box"), 6u);  // ego and npc
  EXPECT_EQ(count(every_five, "<circle class=\"trace-box"), 3u);   // the pedestrian

  TraceSvgOptions options;
  options.snapshot_interval = 2;  // 0, 2, 4, 6, 7 s
  const std::string every_two = render_trace_svg(crossroads(), crossing_trace(), options);
  EXPECT_EQ(count(every_two, "<polygon class=\"trace-box"), 10u);
  EXPECT_EQ(count(every_two, "<circle class=\"trace-box"), 5u);
}

TEST(TraceSvg, PathsBreakAtMissingSamplesAndDarkenWithTime) {
  const std::string svg = render_trace_svg(crossroads(), crossing_trace());
  const std::size_t paths = count(svg, "<polyline class=\"trace-path\"");
  EXPECT_GE(paths, 3u * 10);  // each moving actor's path in several time slices
  EXPECT_NE(svg.find("stroke-opacity=\"1\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-opacity=\"0.36\""), std::string::npos);
}

TEST(TraceSvg, ViewBoxCoversTheActorsButNotTheWholeMap) {
  const Trace trace = crossing_trace();
  const std::string svg = render_trace_svg(crossroads(), trace);
  const MapBounds shown = shown_region(svg);
  for (const TraceActor& each : trace.actors)
    for (std::size_t i = 0; i < each.x.size(); ++i) {
      if (std::isnan(each.x[i])) continue;
      EXPECT_GE(each.x[i] - each.length / 2, shown.min.x) << each.name;
      EXPECT_LE(each.x[i] + each.length / 2, shown.max.x) << each.name;
      EXPECT_GE(each.y[i] - each.length / 2, shown.min.y) << each.name;
      EXPECT_LE(each.y[i] + each.length / 2, shown.max.y) << each.name;
    }
  const MapBounds& whole = crossroads().bounds();
  EXPECT_LT(shown.max.x - shown.min.x, 0.4 * (whole.max.x - whole.min.x));
  EXPECT_LT(shown.max.y - shown.min.y, 0.4 * (whole.max.y - whole.min.y));
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

TEST(TraceSvg, ScaleAndTitle) {
  TraceSvgOptions options;
  options.pixels_per_metre = 4;
  const std::string svg = render_trace_svg(crossroads(), crossing_trace(), options);
  std::size_t position = 0;
  const double width_pixels = number_after(svg, "width=\"", position);
  const double width_metres = number_after(svg, "viewBox=\"0 0 ", position);
  EXPECT_NEAR(width_pixels, 4 * width_metres, 1);
  EXPECT_NE(svg.find("<title>Trace on crossroads (seed 7): ended by collision after 7.00 s"),
            std::string::npos);
}

TEST(TraceSvg, ActorsOffTheMapAndEmptyTracesStillDraw) {
  Trace far_away = crossing_trace();
  for (TraceActor& each : far_away.actors)
    for (double& x : each.x) x += 5000;
  far_away.collisions.clear();
  const std::string svg = render_trace_svg(crossroads(), far_away);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(count(svg, "<polygon class=\"lane\""), 0u);     // no road there
  EXPECT_EQ(count(svg, "<polygon class=\"trace-box"), 6u);  // 0, 5 and 7 s

  const std::string empty = render_trace_svg(crossroads(), Trace{});
  EXPECT_EQ(xml_problem(empty), "");
  EXPECT_EQ(count(empty, "<polygon class=\"lane\""), crossroads().lanes().size());  // all of it
}

}  // namespace
}  // namespace scenfuzz
