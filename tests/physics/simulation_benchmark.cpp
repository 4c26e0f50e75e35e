// Real-time factor of the simulation (simulated seconds per wall second, one core) on the three
// bundled benchmark scenarios in corpora/benchmarks: 2 actors on a straight road, 10 at a
// crossroads, 30 on san_francisco, 101 on san_francisco (100 cars spread over its lanes), and the
// ego among about 100 background-traffic cars from 8 flows on san_francisco. Each run simulates
// the full 30 s (collisions do not end it). docs/performance.md says how to run it
// and what it measured.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "lang/avunit/avunit.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

struct Prepared {
  std::optional<RoadMap> map;
  std::optional<SimulationSetup> setup;
};

Prepared prepare(const std::string& name) {
  Prepared prepared;
  fs::path file = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "benchmarks" / name;
  auto source = read_source_file(file.string());
  if (!source) return prepared;
  avunit::ParseResult parsed = avunit::parse(*source);
  if (!parsed.ok()) return prepared;
  ParameterSpace space = parameter_space(parsed.scenario);
  std::vector<double> values = decode(space, std::vector<double>(space.dimensions.size(), 0.5));
  MapSearchPath search_path = map_search_path({fs::path(SCENFUZZ_SHARED_DIR) / "maps" / "apollo"});
  try {
    prepared.map.emplace(load_scenario_map(parsed.scenario.map, search_path, values));
  } catch (const MapError&) {
    return prepared;
  }
  Diagnostics diagnostics;
  prepared.setup = prepare_simulation(parsed.scenario, values, *prepared.map, 1, diagnostics);
  return prepared;
}

void simulate_scenario(benchmark::State& state, const std::string& name) {
  Prepared prepared = prepare(name);
  if (!prepared.setup) {
    state.SkipWithError(("cannot prepare corpora/benchmarks/" + name).c_str());
    return;
  }
  SimulationOptions options;
  options.duration = 30;
  options.stop_at_collision = false;
  options.seed = 1;
  double simulated = 0;
  double steps = 0;
  std::size_t actors = 0, background = 0;
  for (auto _ : state) {
    Trace trace = simulate(*prepared.map, *prepared.setup, options);
    simulated += trace.time.back();
    steps += static_cast<double>(trace.sample_count());
    actors = trace.actors.size();
    // Flow vehicles come after the ego, the scenario's actors and its obstacles; these were on
    // the map at some time.
    background = 0;
    const std::size_t first_flow =
        1 + prepared.setup->actors.size() + prepared.setup->obstacles.size();
    for (std::size_t k = first_flow; k < trace.actors.size(); ++k)
      if (trace.actors[k].present_from <
          std::min(trace.actors[k].present_until, trace.sample_count()))
        ++background;
    benchmark::DoNotOptimize(trace);
  }
  state.counters["actors"] = static_cast<double>(actors);
  if (!prepared.setup->flows.empty())
    state.counters["background"] = static_cast<double>(background);
  state.counters["realtime_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
}

void BM_Straight2Actors(benchmark::State& state) {
  simulate_scenario(state, "straight_2_actors.avu");
}
void BM_Crossroads10Actors(benchmark::State& state) {
  simulate_scenario(state, "crossroads_10_actors.avu");
}
void BM_SanFrancisco30Actors(benchmark::State& state) {
  simulate_scenario(state, "san_francisco_30_actors.avu");
}

void BM_SanFrancisco100Actors(benchmark::State& state) {
  simulate_scenario(state, "san_francisco_100_actors.avu");
}

void BM_SanFrancisco100Background(benchmark::State& state) {
  simulate_scenario(state, "san_francisco_100_background.avu");
}

BENCHMARK(BM_Straight2Actors)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Crossroads10Actors)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SanFrancisco30Actors)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SanFrancisco100Actors)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SanFrancisco100Background)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace scenfuzz

BENCHMARK_MAIN();
