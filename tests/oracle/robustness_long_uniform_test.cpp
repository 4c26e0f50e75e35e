// Long uniformly sampled traces, with times built as dt * i (the simulator) and as accumulated sums
// t += dt (some loggers), over 10^5 samples and more (issue 23): constant window offsets, and so
// van Herk / Gil-Werman, are used exactly where the definition's windows are constant offsets, and
// the engine agrees with the definition at every sample. The reference here finds each window by
// bisection and scans it, since the quadratic naive_robustness would take hours at this length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/source_file.hpp"
#include "oracle/robustness.hpp"
#include "oracle/window_offsets.hpp"
#include "tests/oracle/naive_robustness.hpp"

namespace scenfuzz {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Times { product, sum };  // t_i = dt * i, or t_i = t_{i-1} + dt

std::vector<double> times(Times construction, double dt, std::size_t samples) {
  std::vector<double> time(samples);
  double t = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    if (construction == Times::product) {
      time[i] = dt * static_cast<double>(i);
    } else {
      time[i] = t;
      t += dt;
    }
  }
  return time;
}

const char* name(Times construction) {
  return construction == Times::product ? "dt * i" : "t += dt";
}

// Sample i's window [begin, end) by the definition (in_window in naive_robustness.cpp): the
// samples j with lower - tolerance <= t_j - t_i <= upper + tolerance. Times increase, so the
// rounded t_j - t_i never decreases in j and those samples are one run, found by bisection.
struct Window {
  std::size_t begin = 0, end = 0;
};

Window window_of(const std::vector<double>& time, std::size_t i, const TimeInterval& interval) {
  const double t = time[i];
  const auto begin = std::partition_point(time.begin(), time.end(), [&](double tj) {
    return tj - t < interval.lower - kWindowTolerance;
  });
  const auto end = std::partition_point(
      begin, time.end(), [&](double tj) { return tj - t <= interval.upper + kWindowTolerance; });
  return {static_cast<std::size_t>(begin - time.begin()),
          static_cast<std::size_t>(end - time.begin())};
}

// The offsets every window has, or nullopt when they differ somewhere (clipped at the ends).
std::optional<Offsets> offsets_by_definition(const std::vector<double>& time,
                                             const TimeInterval& interval) {
  const auto n = static_cast<std::ptrdiff_t>(time.size());
  const std::ptrdiff_t middle = n / 2;
  const Window probe = window_of(time, static_cast<std::size_t>(middle), interval);
  const Offsets offsets{static_cast<std::ptrdiff_t>(probe.begin) - middle,
                        static_cast<std::ptrdiff_t>(probe.end) - middle - 1};
  auto clipped = [n](std::ptrdiff_t k) {
    return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(k, 0, n));
  };
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Window window = window_of(time, static_cast<std::size_t>(i), interval);
    const std::size_t begin = clipped(i + offsets.first);
    const std::size_t end = std::max(begin, clipped(i + offsets.last + 1));
    if (window.begin != begin || std::max(window.begin, window.end) != end) return std::nullopt;
  }
  return offsets;
}

const std::vector<TimeInterval> kIntervals = {{0, 5}, {0, 2},       {0, 3},     {-1, 1}, {1, 4},
                                              {0, 0}, {0.02, 0.04}, {0.3, 0.3}, {0, 50}, {0, 500}};

TEST(RobustnessLongUniform, OffsetsFoundExactlyWhereTheDefinitionsWindowsAreConstant) {
  std::size_t found = 0, checked = 0;
  for (const Times construction : {Times::product, Times::sum}) {
    for (const double dt : {0.05, 0.1, 0.01}) {
      const std::vector<double> time = times(construction, dt, 100'000);
      for (const TimeInterval& interval : kIntervals) {
        const std::optional<Offsets> expected = offsets_by_definition(time, interval);
        const std::optional<Offsets> got = constant_window_offsets(time, interval);
        const std::string what = std::string(name(construction)) + ", dt " + std::to_string(dt) +
                                 ", [" + std::to_string(interval.lower) + ", " +
                                 std::to_string(interval.upper) + "]";
        ++checked;
        // The simulator's times, dt * i, are a rounding error from the grid at most: every
        // window of the definition is the grid's. (Not so for windows reaching past half the
        // trace, clipped at the middle sample that proposes the offsets: those take the deque.)
        const double half = time.back() / 2;
        if (construction == Times::product && interval.upper < half && interval.lower > -half) {
          EXPECT_TRUE(expected) << what;
        }
        ASSERT_EQ(got.has_value(), expected.has_value()) << what;
        if (!got) continue;
        ++found;
        EXPECT_EQ(got->first, expected->first) << what;
        EXPECT_EQ(got->last, expected->last) << what;
      }
    }
  }
  // Most of the accumulated sums keep constant windows too; what they do not is the deque's.
  EXPECT_GT(found, checked / 2);
}

TEST(RobustnessLongUniform, SimulatorTimesTakeTheFastPathAtEveryLength) {
  for (const std::size_t samples : {1'000u, 10'000u, 100'000u, 1'000'000u}) {
    const std::vector<double> time = times(Times::product, 0.05, samples);
    for (const TimeInterval& interval :
         {TimeInterval{0, 5}, TimeInterval{0, 2}, TimeInterval{0, 3}}) {
      const std::optional<Offsets> offsets = constant_window_offsets(time, interval);
      ASSERT_TRUE(offsets) << samples << " samples, [0, " << interval.upper << "]";
      EXPECT_EQ(offsets->first, 0);
      EXPECT_EQ(offsets->last, std::lround(interval.upper / 0.05));
    }
  }
}

// The robustness by the definition, every window operator scanning its window: O(n * w).
std::vector<double> reference(const Formula& f, const SignalSource& source) {
  const std::vector<double> time(source.time.begin(), source.time.end());
  const std::size_t n = time.size();
  switch (f.kind) {
    case FormulaKind::comparison:
    case FormulaKind::predicate: return test::naive_robustness(f, source);
    case FormulaKind::negation: {
      std::vector<double> r = reference(f.operands[0], source);
      for (double& v : r) v = -v;
      return r;
    }
    case FormulaKind::conjunction:
    case FormulaKind::disjunction:
    case FormulaKind::implication: {
      std::vector<double> a = reference(f.operands[0], source);
      const std::vector<double> b = reference(f.operands[1], source);
      for (std::size_t i = 0; i < n; ++i)
        a[i] = f.kind == FormulaKind::conjunction   ? std::min(a[i], b[i])
               : f.kind == FormulaKind::disjunction ? std::max(a[i], b[i])
                                                    : std::max(-a[i], b[i]);
      return a;
    }
    case FormulaKind::always:
    case FormulaKind::eventually: {
      const std::vector<double> x = reference(f.operands[0], source);
      const bool always = f.kind == FormulaKind::always;
      std::vector<double> r(n, always ? kInf : -kInf);
      for (std::size_t i = 0; i < n; ++i) {
        const Window w = window_of(time, i, *f.interval);
        for (std::size_t j = w.begin; j < w.end; ++j)
          r[i] = always ? std::min(r[i], x[j]) : std::max(r[i], x[j]);
      }
      return r;
    }
    case FormulaKind::next: {
      std::vector<double> r = reference(f.operands[0], source);
      r.erase(r.begin());
      r.push_back(kInf);
      return r;
    }
    case FormulaKind::until: {
      const std::vector<double> p = reference(f.operands[0], source);
      const std::vector<double> q = reference(f.operands[1], source);
      std::vector<double> r(n, -kInf);
      for (std::size_t i = 0; i < n; ++i) {
        const Window w = window_of(time, i, *f.interval);
        double holding = kInf;  // min p[i, j), +inf while j <= i
        for (std::size_t k = i; k < w.begin; ++k) holding = std::min(holding, p[k]);
        for (std::size_t j = w.begin; j < w.end; ++j) {
          r[i] = std::max(r[i], std::min(q[j], holding));
          if (j >= i) holding = std::min(holding, p[j]);
        }
      }
      return r;
    }
  }
  return {};
}

// Random walks, x and z real, y whole numbers so that windows meet ties.
std::map<std::string, std::vector<double>> walks(std::size_t samples) {
  std::mt19937_64 random(23);
  std::normal_distribution<double> step(0.0, 0.1);
  std::map<std::string, std::vector<double>> signals;
  for (const char* signal : {"x", "y", "z"}) {
    double value = 0;
    for (std::size_t i = 0; i < samples; ++i) {
      value += step(random);
      signals[signal].push_back(signal[0] == 'y' ? std::round(value) : value);
    }
  }
  return signals;
}

TEST(RobustnessLongUniform, EngineMatchesDefinitionOverLongTraces) {
  const std::vector<std::string> formulas = {
      "G[0 : 5](x > 0.5 & F[0 : 2](y < 0.1)) | ~(z >= 1 U[0 : 3] x < 2)",
      "F[-1 : 1](z == 0) & G[1 : 4](y <= 2)",
      "(x > 0 U[0.5 : 2.5] y > 0) | (y < 1 U[-1 : 1] z > 0)",
      "G[0 : 0.05](x > 0) & F[0.02 : 0.04](y > 0) | X(z < 0)",
      "G[0 : 50](x > -3) | F[0.3 : 0.3](z < 0)"};
  const std::size_t samples = 100'000;
  const std::map<std::string, std::vector<double>> signals = walks(samples);
  for (const Times construction : {Times::product, Times::sum}) {
    const std::vector<double> time = times(construction, 0.05, samples);
    const SignalSource source{time,
                              [&](const SpecTerm& term) {
                                return SignalValues{signals.at(term.name), false};
                              },
                              {}};
    for (const std::string& text : formulas) {
      const std::optional<Formula> formula =
          avunit::parse_formula(SourceFile("--spec", text)).formula;
      ASSERT_TRUE(formula) << text;
      const std::vector<double> expected = reference(*formula, source);
      const std::vector<double> got = robustness_signal(*formula, source);
      ASSERT_EQ(got.size(), expected.size());
      std::size_t wrong = 0, first_wrong = 0;
      for (std::size_t i = 0; i < samples; ++i) {
        const bool same = std::isinf(expected[i]) ? got[i] == expected[i]
                                                  : std::abs(got[i] - expected[i]) <= 1e-9;
        if (!same && wrong++ == 0) first_wrong = i;
      }
      EXPECT_EQ(wrong, 0u) << name(construction) << ": " << text << "\nfirst at sample "
                           << first_wrong << " (t = " << time[first_wrong] << "): expected "
                           << expected[first_wrong] << ", got " << got[first_wrong];
    }
  }
}

}  // namespace
}  // namespace scenfuzz
