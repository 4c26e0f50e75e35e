// Robustness figures: samples per second for formulas of 1, 10 and 30 nodes over 10^3 to 10^6
// samples, which should grow linearly with the trace, and for G[0:w] and U[0:w] at a fixed trace
// length over window widths from 0.5 s to 500 s, which should not depend on w.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
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

// Built once per length and kept: the timed loop measures the oracle alone. Uneven traces (logs
// from other tools) jitter each time by up to 40 % of a step, which sends windows down the
// monotone-deque path instead of the uniform grid's van Herk / Gil-Werman path.
const Trace& trace_of(std::size_t samples, bool uneven = false) {
  static std::map<std::pair<std::size_t, bool>, Trace> traces;
  auto [found, added] = traces.try_emplace({samples, uneven});
  Trace& trace = found->second;
  if (!added) return trace;
  std::mt19937_64 random(7);
  std::normal_distribution<double> step(0.0, 0.1);
  std::uniform_real_distribution<double> jitter(0.0, 0.4 * kStep);
  for (std::size_t i = 0; i < samples; ++i)
    trace.time.push_back(kStep * static_cast<double>(i) + (uneven ? jitter(random) : 0.0));
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
         bool uneven = false) {
  const std::optional<Formula> formula = parse(text);
  if (!formula || formula_nodes(*formula) != nodes) {
    state.SkipWithError(("not a formula of " + std::to_string(nodes) + " nodes: " + text).c_str());
    return;
  }
  const SignalSource source = source_of(trace_of(samples, uneven));
  for (auto _ : state) benchmark::DoNotOptimize(robustness_signal(*formula, source));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(samples));
}

// range(0): formula nodes (1, 10 or 30); range(1): samples.
void BM_Robustness(benchmark::State& state) {
  const auto nodes = static_cast<std::size_t>(state.range(0));
  const std::string& text = nodes == 1    ? std::string("x > 0")
                            : nodes == 10 ? kTenNodes
                                          : kThirtyNodes;
  state.SetLabel(std::to_string(nodes) + " nodes");
  run(state, text, nodes, static_cast<std::size_t>(state.range(1)));
}
BENCHMARK(BM_Robustness)
    ->ArgsProduct({{1, 10, 30}, {1'000, 10'000, 100'000, 1'000'000}})
    ->Unit(benchmark::kMicrosecond);

// The same formulas over unevenly sampled traces of 10^5 samples.
void BM_RobustnessUneven(benchmark::State& state) {
  const auto nodes = static_cast<std::size_t>(state.range(0));
  const std::string& text = nodes == 1    ? std::string("x > 0")
                            : nodes == 10 ? kTenNodes
                                          : kThirtyNodes;
  state.SetLabel(std::to_string(nodes) + " nodes, uneven");
  run(state, text, nodes, static_cast<std::size_t>(state.range(1)), true);
}
BENCHMARK(BM_RobustnessUneven)
    ->ArgsProduct({{1, 10, 30}, {100'000}})
    ->Unit(benchmark::kMicrosecond);

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
  run(state, text, 2, 100'000, true);
}
BENCHMARK(BM_AlwaysWindowWidthUneven)
    ->Arg(5)
    ->Arg(50)
    ->Arg(500)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace scenfuzz

BENCHMARK_MAIN();
