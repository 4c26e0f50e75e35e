// Robustness figures: samples per second for formulas of 1, 10 and 30 nodes over 10^3 to 10^6
// samples, with times built as dt * i (the simulator), as accumulated sums t += dt (loggers) and
// jittered (logs from other tools), which should grow linearly with the trace: after the runs, the
// time ratio between consecutive lengths is printed per formula size (x10 is linear). Also G[0:w]
// and U[0:w] at a fixed trace length over window widths from 0.5 s to 500 s, which should not
// depend on w.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/source_file.hpp"
#include "lang/spec.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {
namespace {

constexpr double kStep = 0.05;  // seconds, the simulator's default

// Random walks for x, y and z, so that comparisons change sign and windows see varied extrema.
struct Trace {
  std::vector<double> time;
  std::map<std::string, std::vector<double>> signals;
};

// How sample times are built. Uneven traces jitter each time by up to 40 % of a step, which sends
// windows down the monotone-deque path instead of the uniform grid's van Herk / Gil-Werman path.
enum class Times { product, sum, uneven };

// Built once per length and kept: the timed loop measures the oracle alone. The signals are the
// same whatever the times.
const Trace& trace_of(std::size_t samples, Times times) {
  static std::map<std::pair<std::size_t, Times>, Trace> traces;
  auto [found, added] = traces.try_emplace({samples, times});
  Trace& trace = found->second;
  if (!added) return trace;
  std::mt19937_64 random(7);
  std::normal_distribution<double> step(0.0, 0.1);
  std::uniform_real_distribution<double> jitter(0.0, 0.4 * kStep);
  double sum = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double grid = kStep * static_cast<double>(i);
    trace.time.push_back(times == Times::product ? grid
                         : times == Times::sum   ? sum
                                                 : grid + jitter(random));
    sum += kStep;
  }
  random.seed(7);
  for (const char* name : {"x", "y", "z"}) {
    std::vector<double>& values = trace.signals[name];
    double value = 0;
    for (std::size_t i = 0; i < samples; ++i) values.push_back(value += step(random));
  }
  return trace;
}

SignalSource source_of(const Trace& trace) {
  return SignalSource{trace.time,
                      [&trace](const SpecTerm& term) {
                        auto found = trace.signals.find(term.name);
                        if (found == trace.signals.end())
                          throw OracleError(term.location, "no signal " + term.name);
                        return SignalValues{found->second, false};
                      },
                      {}};
}

// Size is counted in Formula nodes (comparisons, predicates and operators); the terms inside a
// comparison are not counted, since the engine's passes run per formula node.
std::size_t formula_nodes(const Formula& formula) {
  std::size_t nodes = 1;
  for (const Formula& operand : formula.operands) nodes += formula_nodes(operand);
  return nodes;
}

const std::string kTenNodes = "G[0:5](x > 0.5 & F[0:2](y < 0.1)) | ~(z >= 1 U[0:3] x < 2)";
const std::string kThirtyNodes = "((" + kTenNodes +
                                 ") & (F[0:10](x < 3 & X(y > -1)) -> G(z != 0 | x >= -2))) | "
                                 "((G[1:4](y <= 2) U F[-1:1](z == 0)) & X(x > 1))";

std::optional<Formula> parse(const std::string& text) {
  return avunit::parse_formula(SourceFile("--spec", text)).formula;
}

void run(benchmark::State& state, const std::string& text, std::size_t nodes, std::size_t samples,
         Times times = Times::product) {
  const std::optional<Formula> formula = parse(text);
  if (!formula || formula_nodes(*formula) != nodes) {
    state.SkipWithError(("not a formula of " + std::to_string(nodes) + " nodes: " + text).c_str());
    return;
  }
  const SignalSource source = source_of(trace_of(samples, times));
  for (auto _ : state) benchmark::DoNotOptimize(robustness_signal(*formula, source));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(samples));
}

// range(0): formula nodes (1, 10 or 30); range(1): samples.
void run_sized(benchmark::State& state, Times times, const char* label) {
  const auto nodes = static_cast<std::size_t>(state.range(0));
  const std::string& text = nodes == 1    ? std::string("x > 0")
                            : nodes == 10 ? kTenNodes
                                          : kThirtyNodes;
  state.SetLabel(std::to_string(nodes) + " nodes" + label);
  run(state, text, nodes, static_cast<std::size_t>(state.range(1)), times);
}

const std::vector<std::vector<std::int64_t>> kSizes = {{1, 10, 30},
                                                       {1'000, 10'000, 100'000, 1'000'000}};

// t_i = 0.05 * i, as the simulator writes its traces.
void BM_Robustness(benchmark::State& state) { run_sized(state, Times::product, ""); }
BENCHMARK(BM_Robustness)->ArgsProduct(kSizes)->Unit(benchmark::kMicrosecond);

// t_i = t_{i-1} + 0.05: rounding drifts, so a window edge may move past a sample somewhere.
void BM_RobustnessSummed(benchmark::State& state) { run_sized(state, Times::sum, ", t += dt"); }
BENCHMARK(BM_RobustnessSummed)->ArgsProduct(kSizes)->Unit(benchmark::kMicrosecond);

// Unevenly sampled traces: the monotone-deque path.
void BM_RobustnessUneven(benchmark::State& state) { run_sized(state, Times::uneven, ", uneven"); }
BENCHMARK(BM_RobustnessUneven)->ArgsProduct(kSizes)->Unit(benchmark::kMicrosecond);

// The window width in tenths of a second as text: 5 -> "0.5".
std::string width_text(std::int64_t tenths) {
  return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10);
}

// range(0): the window width in tenths of a second, over 10^5 samples (5000 s of trace).
void BM_AlwaysWindowWidth(benchmark::State& state) {
  const std::string text = "G[0:" + width_text(state.range(0)) + "](x > 0)";
  state.SetLabel(text);
  run(state, text, 2, 100'000);
}
BENCHMARK(BM_AlwaysWindowWidth)
    ->Arg(5)
    ->Arg(50)
    ->Arg(500)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);

// Bounded until is decomposed into windows too, so it should not depend on the width either.
void BM_UntilWindowWidth(benchmark::State& state) {
  const std::string text = "x > 0 U[0:" + width_text(state.range(0)) + "] y > 0";
  state.SetLabel(text);
  run(state, text, 3, 100'000);
}
BENCHMARK(BM_UntilWindowWidth)->Arg(5)->Arg(50)->Arg(500)->Arg(5000)->Unit(benchmark::kMicrosecond);

// The monotone deque's cost does not depend on the width either.
void BM_AlwaysWindowWidthUneven(benchmark::State& state) {
  const std::string text = "G[0:" + width_text(state.range(0)) + "](x > 0)";
  state.SetLabel(text + ", uneven");
  run(state, text, 2, 100'000, Times::uneven);
}
BENCHMARK(BM_AlwaysWindowWidthUneven)
    ->Arg(5)
    ->Arg(50)
    ->Arg(500)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);

// The console output, and after it, per family and formula size, how much longer each length
// took than the one ten times shorter (CPU time, the median when repeated): x10 is linear.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
      const std::string& args = run.run_name.args;
      const std::size_t slash = args.find('/');
      if (slash == std::string::npos) continue;  // the window-width rows
      Series& series = series_[{run.run_name.function_name, std::stol(args.substr(0, slash))}];
      Time& time = series[std::stol(args.substr(slash + 1))];
      // A median replaces the repetitions it summarises.
      if (run.run_type == Run::RT_Aggregate) time = {0, 0, true};
      if (time.median && run.run_type != Run::RT_Aggregate) continue;
      time.sum += run.GetAdjustedCPUTime();
      ++time.count;
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    if (series_.empty()) return;
    std::printf("\nTime ratio between consecutive lengths (CPU time; x10 is linear):\n");
    for (const auto& [key, series] : series_) {
      if (series.size() < 2) continue;
      std::printf("  %-20s %2ld nodes:", key.first.c_str(), key.second);
      const Time* previous = nullptr;
      long previous_samples = 0;
      for (const auto& [samples, time] : series) {
        if (previous)
          std::printf("  %ld->%ld x%.1f", previous_samples, samples,
                      (time.sum / time.count) / (previous->sum / previous->count));
        previous = &time;
        previous_samples = samples;
      }
      std::printf("\n");
    }
  }

 private:
  struct Time {
    double sum = 0;
    int count = 0;
    bool median = false;
  };
  using Series = std::map<long, Time>;  // by samples
  std::map<std::pair<std::string, long>, Series> series_;
};

}  // namespace
}  // namespace scenfuzz

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  scenfuzz::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
