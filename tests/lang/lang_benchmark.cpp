// Front-end figures: what `scenfuzz check` spends (time and peak memory) on a small real scenario
// and on a big generated AVUnit file, a real scenario after 400,000 trivial top-level assignments
// (about 8 MB). Peak memory is the process's high-water mark (VmHWM), reset before each
// iteration where the kernel allows it, so it is the peak of one check.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <string>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {
namespace {

// A complete scenario with a range, an actor, an environment and a specification.
constexpr const char* kScenario = R"(ego_start = ("lane_1"->range(5, 15), , 10);
ego = AV(ego_start, ("lane_1"->200));
npc = Vehicle(("lane_1"->40, , range(2, 8)));
env = Environment(12:00, {rain: 0.2});
s = CreateScenario{load("straight"); ego; {npc}; {}; {}; env;};
Trace trace = EXE(s);
gap = dis(trace[ego], trace[truth][npc]);
trace |= G (gap > 2.0);
)";

// The kinds of trivial assignment the grammar allows at the top level, taken in turn: a number,
// a string, a tuple and a lane position. 400,000 of them make about 8 MB.
std::string trivial_assignment(std::size_t i) {
  const std::string n = std::to_string(i);
  switch (i % 4) {
    case 0: return "a" + n + " = " + n + ".5;\n";
    case 1: return "b" + n + " = \"lane_" + std::to_string(i % 97) + "\";\n";
    case 2: return "c" + n + " = (1.5, " + std::to_string(i % 89) + ");\n";
    default: return "d" + n + " = \"lane_3\"->" + std::to_string(i % 83) + ".5;\n";
  }
}

std::string big_avunit(std::size_t assignments) {
  std::string text;
  text.reserve(assignments * 22 + 1024);
  for (std::size_t i = 0; i < assignments; ++i) text += trivial_assignment(i);
  return text + kScenario;
}

// The process's peak resident set in MB, from /proc/self/status; 0 where there is none.
double peak_resident_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

// Writing 5 to clear_refs resets VmHWM to the current resident set (Linux 4.0 and later).
void reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
}

// What `scenfuzz check` does with a file it has read: parse, elaborate, format the diagnostics.
// `broken`: the file is meant to have errors.
void check(benchmark::State& state, const std::string& text, bool broken = false) {
  double peak = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    reset_peak_resident();
    state.ResumeTiming();
    SourceFile file("big.avu", text);
    avunit::ParseResult parsed = avunit::parse(file);
    std::string messages = format_diagnostics(file, parsed.diagnostics);
    benchmark::DoNotOptimize(messages);
    if (broken ? parsed.ok() : !parsed.ok() || !parsed.scenario.has_scenario) {
      state.SkipWithError(("the generated file is not as meant:\n" + messages).c_str());
      return;
    }
    state.PauseTiming();
    peak = std::max(peak, peak_resident_mb());
    state.ResumeTiming();
  }
  state.counters["peak_MB"] = peak;
  state.counters["file_MB"] = static_cast<double>(text.size()) / (1024.0 * 1024.0);
}

void BM_CheckSmallScenario(benchmark::State& state) { check(state, kScenario); }
BENCHMARK(BM_CheckSmallScenario)->Unit(benchmark::kMicrosecond);

void BM_CheckBigAvunit(benchmark::State& state) {
  static const std::string text = big_avunit(static_cast<std::size_t>(state.range(0)));
  check(state, text);
}
BENCHMARK(BM_CheckBigAvunit)->Arg(400000)->Unit(benchmark::kMillisecond);

// The same with as many misspelt names as are reported (Diagnostics::kErrorLimit): each is
// weighed against every defined name for a "did you mean" suggestion.
void BM_CheckBigAvunitWithErrors(benchmark::State& state) {
  static const std::string text = [&] {
    std::string broken = big_avunit(static_cast<std::size_t>(state.range(0)));
    for (std::size_t i = 0; i < Diagnostics::kErrorLimit; ++i)
      broken += "e" + std::to_string(i) + " = a12" + std::to_string(i) + "x;\n";
    return broken;
  }();
  check(state, text, true);
}
BENCHMARK(BM_CheckBigAvunitWithErrors)->Arg(400000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace scenfuzz

BENCHMARK_MAIN();
