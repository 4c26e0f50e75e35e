// A repeat evaluation of a formula over a long trace takes no new working memory: the engine
// keeps its buffers per thread (oracle/signal_pool.hpp). Before, every evaluation allocated a
// dozen signals afresh, which glibc served with fresh zeroed pages once a trace passed 10^4
// samples; the page faults cost more than the passes (issue 23). Counted here by replacing the
// global operator new (for all of oracle_tests; it counts only while a test of this file sets
// `counting` on its thread), so the check does not depend on malloc's trimming or on timing.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <map>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/source_file.hpp"
#include "oracle/robustness.hpp"

namespace {

// Bytes allocated by this thread while `counting` is set.
thread_local bool counting = false;
thread_local std::size_t counted_bytes = 0;

}  // namespace

// GCC sees free() meet memory from operator new; here both are this file's malloc and free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t bytes) {
  if (counting) counted_bytes += bytes;
  if (void* memory = std::malloc(bytes == 0 ? 1 : bytes)) return memory;
  throw std::bad_alloc();
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
#pragma GCC diagnostic pop

namespace scenfuzz {
namespace {

constexpr std::size_t kSamples = 100'000;

struct Trace {
  std::vector<double> time;
  std::map<std::string, std::vector<double>> signals;
};

// Every 0.05 s, or jittered by up to 0.018 s so that windows are not constant offsets and take the
// two-stack sliding windows (and bounded until its decomposition over window cursors).
Trace trace_of(std::size_t samples, bool uneven) {
  Trace trace;
  for (std::size_t i = 0; i < samples; ++i) {
    const double jitter = uneven ? 0.002 * static_cast<double>(i * 37 % 10) : 0.0;
    trace.time.push_back(0.05 * static_cast<double>(i) + jitter);
    const auto k = static_cast<double>(i % 97);
    trace.signals["x"].push_back(k / 10 - 4);
    trace.signals["y"].push_back(5 - k / 7);
    trace.signals["z"].push_back(k / 30);
  }
  return trace;
}

// Leaves are handed over by value, as the CSV and trace sources do; every call allocates a copy.
struct CountedSource {
  const Trace& trace;
  std::size_t leaf_calls = 0;

  SignalSource source() {
    return SignalSource{trace.time,
                        [this](const SpecTerm& term) {
                          ++leaf_calls;
                          return SignalValues{trace.signals.at(term.name), false};
                        },
                        {}};
  }
};

std::size_t bytes_allocated_by(const Formula& formula, CountedSource& counted) {
  const SignalSource source = counted.source();
  counted_bytes = 0;
  counting = true;
  const std::vector<double> robustness = robustness_signal(formula, source);
  counting = false;
  EXPECT_EQ(robustness.size(), counted.trace.time.size());
  return counted_bytes;
}

// On the repeat evaluation only the leaves' copies and the returned signal are new memory.
void expect_repeat_reuses(const std::string& text, bool uneven) {
  const std::optional<Formula> formula = avunit::parse_formula(SourceFile("--spec", text)).formula;
  ASSERT_TRUE(formula) << text;
  const Trace trace = trace_of(kSamples, uneven);
  CountedSource counted{trace};
  bytes_allocated_by(*formula, counted);
  counted.leaf_calls = 0;
  const std::size_t repeat = bytes_allocated_by(*formula, counted);
  const std::size_t signal_bytes = kSamples * sizeof(double);
  EXPECT_LE(repeat, (counted.leaf_calls + 1) * signal_bytes + 4096)
      << text << ": " << repeat / signal_bytes << " signals' worth allocated on the repeat, "
      << counted.leaf_calls << " leaves";
}

const std::string kTenNodes = "G[0:5](x > 0.5 & F[0:2](y < 0.1)) | ~(z >= 1 U[0:3] x < 2)";

TEST(RobustnessMemoryReuse, RepeatEvaluationOnUniformTraceTakesNoNewWorkingMemory) {
  expect_repeat_reuses(kTenNodes, false);
}

TEST(RobustnessMemoryReuse, RepeatEvaluationOnUnevenTraceTakesNoNewWorkingMemory) {
  expect_repeat_reuses(kTenNodes, true);
}

}  // namespace
}  // namespace scenfuzz
