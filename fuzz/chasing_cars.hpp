// The ARCH-COMP falsification benchmark "chasing cars" (CC; ../shared/reference/arch-cc.md) as a
// built-in system: its hybrid model simulated with exact event location, its requirements CC1-CC5
// and CCx as STL text judged by our oracle, and an Evaluator so the search engine that drives
// scenarios can be measured against published falsification results on the same problem.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "lang/spec.hpp"

namespace scenfuzz {

// The benchmark simulates from t = 0 to this time (s).
inline constexpr double kChasingCarsHorizon = 100.0;

// One sample every integration step, as a fixed-step reference simulation samples: on a coarser
// grid the oracle would miss gap extremes between samples (gaps change at up to ~50 m/s).
struct ChasingCarsTrace {
  std::vector<double> time;              // s: 0, step, 2 step, ..., 100
  std::array<std::vector<double>, 5> y;  // y[i]: position of car i + 1 (m); the outputs y1..y5
  std::array<std::vector<double>, 5> v;  // v[i]: the velocity state of car i + 1, signed as in
                                         // the model (cars 2..5 move by -v except in Keeping)
};

// Simulates the five cars over [0, 100] s. Car 1's throttle u1 and brake u2 are piecewise constant:
// throttle[k] and brake[k] hold on [k, k + 1) * segment_seconds, the last value holds to the end
// when the segments stop short of 100 s. Within a step every mode's dynamics are integrated in
// closed form and mode switches are located inside the step to 1e-12 s (regula falsi on the gap),
// so `step` only sets the sampling (and the grid on which guard crossings are looked for): results
// do not drift with it. Throws std::invalid_argument for inputs outside [0, 1], throttle and brake
// of different or zero length, a non-positive segment length, or a step that does not divide 100 s.
ChasingCarsTrace simulate_chasing_cars(std::span<const double> throttle,
                                       std::span<const double> brake, double segment_seconds,
                                       double step = 0.01);

// "CC1", ..., "CC5", "CCx": the benchmark's requirements.
std::vector<std::string> chasing_cars_requirement_names();

// The requirement's STL formula in AVUnit syntax over the signals y1..y5, e.g.
// "G[0:100] (y5 - y4 <= 40)" for CC1. Throws std::invalid_argument for an unknown name.
std::string chasing_cars_requirement(const std::string& requirement);

// The requirement's formula, parsed. Throws std::invalid_argument for an unknown name.
Formula parse_chasing_cars_requirement(const std::string& requirement);

// The robustness at t = 0 of `formula` on the trace, whose signals y1..y5 are the cars'
// positions. Throws OracleError when the formula names another signal.
double chasing_cars_robustness(const Formula& formula, const ChasingCarsTrace& trace);

// The robustness at t = 0 of the named requirement (CC1..CC5, CCx) on the trace.
double chasing_cars_robustness(const std::string& requirement, const ChasingCarsTrace& trace);

// The benchmark's instance 2 for one requirement: `segments` piecewise-constant segments of
// 100 / segments s (at least 5 s each, the instance's rule, so 1 to 20), and the dimensions
// throttle_0.., then brake_0.., whose unit-cube coordinate is the input value itself. One
// objective, named after the requirement. Deterministic: the seed is not used.
class ChasingCarsEvaluator : public Evaluator {
 public:
  // Throws std::invalid_argument for an unknown requirement or a segment count outside 1..20.
  explicit ChasingCarsEvaluator(std::string requirement, std::size_t segments = 20);

  std::vector<SearchDimension> dimensions() const override;
  std::vector<std::string> objectives() const override;
  // Throws std::invalid_argument when `unit_point` does not have 2 * segments coordinates.
  Evaluation evaluate(std::span<const double> unit_point, std::uint64_t seed) const override;

 private:
  std::string requirement_;
  std::size_t segments_;
  Formula formula_;
};

}  // namespace scenfuzz
