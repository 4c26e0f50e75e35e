// Pins the benchmark scenarios' traces bit for bit: a hash over every sample, perception column,
// light colour, collision and event. Speed-ups of the simulation step (broadphase, lane tracking,
// trajectory lookups) must not change a single bit of what a run records. The pinned values were
// taken before those speed-ups, on Debian 12 (x86-64, glibc 2.36); a different libm may round
// differently, so a changed hash on another platform is first a question, not a bug. They were
// taken again when scripted actors began to record their heading's change over each step as their
// yaw rate (step_yaw_rate): only the yaw rate column changed, every other column kept its bits.
// Both san_francisco runs were pinned again when lane followers began to follow their leader along
// the lanes between scans (the gap by lane position, not by searching the path): their gaps, and
// so their motion, changed by millimetres (docs/performance.md, "Following along the lanes").
// All three were pinned again when perception noise came from xoshiro256** and the ziggurat
// instead of mt19937_64 and the polar method: other noise values of the same distributions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "../support/shared_dir.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// FNV-1a over raw bytes: doubles are hashed as their bit patterns, so -0.0, NaN payloads and the
// last ulp all count.
struct TraceHash {
  std::uint64_t value = 0xcbf29ce484222325ull;

  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      value ^= p[i];
      value *= 0x100000001b3ull;
    }
  }
  template <typename T>
  void scalar(T x) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&x, sizeof x);
  }
  template <typename T>
  void column(const std::vector<T>& values) {
    scalar(values.size());
    if (!values.empty()) bytes(values.data(), values.size() * sizeof(T));
  }
  void text(const std::string& s) {
    scalar(s.size());
    bytes(s.data(), s.size());
  }
};

std::uint64_t hash_of(const Trace& trace) {
  TraceHash h;
  h.column(trace.time);
  for (const TraceActor& actor : trace.actors) {
    h.text(actor.name);
    for (const auto* column : {&actor.x, &actor.y, &actor.heading, &actor.speed,
                               &actor.acceleration, &actor.yaw_rate, &actor.s})
      h.column(*column);
    h.column(actor.lane);
    h.column(actor.reversing);
  }
  for (const PerceivedActor& perceived : trace.perceived) {
    h.scalar(perceived.actor);
    h.column(perceived.detected);
    for (const auto* column : {&perceived.x, &perceived.y, &perceived.heading, &perceived.speed})
      h.column(*column);
    h.column(perceived.reversing);
  }
  for (const TraceLight& light : trace.lights) {
    h.text(light.id);
    h.column(light.colour);
  }
  for (const Collision& collision : trace.collisions) {
    h.scalar(collision.time);
    h.scalar(collision.first);
    h.scalar(collision.second);
    h.scalar(collision.point.x);
    h.scalar(collision.point.y);
    h.scalar(collision.first_side);
    h.scalar(collision.second_side);
  }
  for (const TraceEvent& event : trace.events) {
    h.scalar(event.kind);
    h.scalar(event.time);
    h.scalar(event.collision);
    h.text(event.message);
  }
  h.scalar(trace.end);
  return h.value;
}

struct Pinned {
  Trace trace;
  std::uint64_t hash = 0;
};

// Runs corpora/benchmarks/<name> as simulation_benchmark does: the middle of its space, seed 1,
// the full 30 s whatever collides. The scenario is still set up for its default duration
// (physics/simulation/default_duration.hpp), which plans scripted paths and random walks: these
// benchmarks' egos have routes that take longer than 30 s at the limits, so their NPCs are
// planned for longer runs than the 30 s simulated.
Pinned run_benchmark(const std::string& name) {
  fs::path file = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "benchmarks" / name;
  auto source = read_source_file(file.string());
  EXPECT_TRUE(source) << file;
  if (!source) return {};
  SimulationOptions options;
  options.duration = 30;
  options.stop_at_collision = false;
  options.seed = 1;
  test::SimulatedRun run = test::simulate_file(
      *source, options, map_search_path({test::shared_dir() / "maps" / "apollo"}));
  EXPECT_TRUE(run.trace) << run.errors;
  if (!run.trace) return {};
  return {*run.trace, hash_of(*run.trace)};
}

TEST(SimulationTraceHashTest, TenActorCrossroadsTraceIsUnchanged) {
  Pinned run = run_benchmark("crossroads_10_actors.avu");
  EXPECT_EQ(run.trace.sample_count(), 601u);
  EXPECT_EQ(run.hash, 0xb3fe9ece67e857f0ull) << std::hex << run.hash;
}

TEST(SimulationTraceHashTest, ThirtyActorSanFranciscoTraceIsUnchanged) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  Pinned run = run_benchmark("san_francisco_30_actors.avu");
  EXPECT_EQ(run.trace.sample_count(), 601u);
  EXPECT_EQ(run.trace.collisions.size(), 1u);  // a random walker into a standing car
  EXPECT_EQ(run.hash, 0xc17e71c02abade9full) << std::hex << run.hash;
}

TEST(SimulationTraceHashTest, HundredActorSanFranciscoTraceIsUnchanged) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  Pinned run = run_benchmark("san_francisco_100_actors.avu");
  EXPECT_EQ(run.trace.sample_count(), 601u);
  EXPECT_EQ(run.trace.collisions.size(), 0u);
  EXPECT_EQ(run.hash, 0x677e73c03e75c468ull) << std::hex << run.hash;
}

// The hash sees a single bit: a trace that differs in one sample's last ulp hashes differently.
TEST(SimulationTraceHashTest, OneUlpChangesTheHash) {
  Trace trace;
  trace.time = {0, 0.05};
  trace.actors.push_back({});
  trace.actors[0].x = {1.0, 2.0};
  const std::uint64_t before = hash_of(trace);
  trace.actors[0].x[1] = std::nextafter(2.0, 3.0);
  EXPECT_NE(hash_of(trace), before);
}

}  // namespace
}  // namespace scenfuzz
