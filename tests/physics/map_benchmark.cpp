// Map figures: loading san_francisco (text and binary protobuf, each with and without building
// the indexed RoadMap) and point-to-lane projection on it, against a brute-force scan over every
// lane as the baseline. docs/performance.md records the figures and how to reproduce them.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "physics/map/apollo_map_reader.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {
namespace {

std::filesystem::path san_francisco(const char* file) {
  return std::filesystem::path(SCENFUZZ_SHARED_DIR) / "maps/apollo/san_francisco" / file;
}

bool have_map(benchmark::State& state) {
  if (SCENFUZZ_HAVE_SHARED_DIR && std::filesystem::exists(san_francisco("base_map.bin")))
    return true;
  state.SkipWithError("shared/maps/apollo/san_francisco not found (SCENFUZZ_SHARED_DIR)");
  return false;
}

const RoadMap& loaded_map() {
  static const RoadMap map = build_road_map(read_apollo_map_binary(san_francisco("base_map.bin")));
  return map;
}

// Query points on and around the roads: lane positions with a lateral offset of up to 5 m, so
// the figures are for the points a simulation asks about.
std::vector<MapPose> query_poses(const RoadMap& map, std::size_t count) {
  std::mt19937_64 random(2026);
  std::uniform_int_distribution<std::size_t> lane(0, map.lanes().size() - 1);
  std::uniform_real_distribution<double> fraction(0, 1), lateral(-5, 5);
  std::vector<MapPose> poses;
  while (poses.size() < count) {
    LaneIndex index = static_cast<LaneIndex>(lane(random));
    auto pose =
        lane_pose_at(map, index, fraction(random) * map.lane(index).length(), lateral(random));
    if (pose) poses.push_back(*pose);
  }
  return poses;
}

void LoadText(benchmark::State& state) {
  if (!have_map(state)) return;
  for (auto _ : state)
    benchmark::DoNotOptimize(read_apollo_map_text(san_francisco("base_map.txt")));
}

void LoadBinary(benchmark::State& state) {
  if (!have_map(state)) return;
  for (auto _ : state)
    benchmark::DoNotOptimize(read_apollo_map_binary(san_francisco("base_map.bin")));
}

void LoadAndBuildText(benchmark::State& state) {
  if (!have_map(state)) return;
  for (auto _ : state)
    benchmark::DoNotOptimize(build_road_map(read_apollo_map_text(san_francisco("base_map.txt"))));
}

void LoadAndBuildBinary(benchmark::State& state) {
  if (!have_map(state)) return;
  for (auto _ : state)
    benchmark::DoNotOptimize(build_road_map(read_apollo_map_binary(san_francisco("base_map.bin"))));
}

void ProjectToLane(benchmark::State& state) {
  if (!have_map(state)) return;
  const RoadMap& map = loaded_map();
  std::vector<MapPose> poses = query_poses(map, 4096);
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(project_to_lane(map, poses[next].position));
    next = (next + 1) % poses.size();
  }
}

void ProjectToLaneWithHeading(benchmark::State& state) {
  if (!have_map(state)) return;
  const RoadMap& map = loaded_map();
  std::vector<MapPose> poses = query_poses(map, 4096);
  std::size_t next = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(project_to_lane(map, poses[next].position, poses[next].heading));
    next = (next + 1) % poses.size();
  }
}

// The baseline: every segment of every lane, no index.
void ProjectToLaneBruteForce(benchmark::State& state) {
  if (!have_map(state)) return;
  const RoadMap& map = loaded_map();
  std::vector<MapPose> poses = query_poses(map, 4096);
  std::size_t next = 0;
  for (auto _ : state) {
    double best = std::numeric_limits<double>::infinity();
    for (const Lane& lane : map.lanes())
      best = std::min(best, lane.centre_line.project(poses[next].position).distance);
    benchmark::DoNotOptimize(best);
    next = (next + 1) % poses.size();
  }
}

void FindRoute(benchmark::State& state) {
  if (!have_map(state)) return;
  const RoadMap& map = loaded_map();
  std::mt19937_64 random(11);
  std::uniform_int_distribution<std::size_t> lane(0, map.lanes().size() - 1);
  std::int64_t found = 0;
  for (auto _ : state) {
    LanePosition from{static_cast<LaneIndex>(lane(random)), 0, 0};
    LanePosition to{static_cast<LaneIndex>(lane(random)), 0, 0};
    found += find_route(map, from, to).has_value() ? 1 : 0;
  }
  state.counters["found"] =
      benchmark::Counter(static_cast<double>(found), benchmark::Counter::kAvgIterations);
}

// Five repetitions each; the median is the figure to quote.
BENCHMARK(LoadText)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(LoadBinary)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(LoadAndBuildText)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(LoadAndBuildBinary)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(ProjectToLane)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(ProjectToLaneWithHeading)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(ProjectToLaneBruteForce)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(FindRoute)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace scenfuzz

BENCHMARK_MAIN();
