// The chasing-cars model and requirements. The model is a cascade: car i's mode depends only on
// the gap to car i - 1, and within one mode and constant inputs every car's motion has a closed
// form. So the simulation is exact up to rounding and event location: each step is integrated in
// closed form, and when a guard becomes true by the step's end the switch time is located inside
// the step (regula falsi on the gap) and the step resumes from there in the new mode.
#include "fuzz/chasing_cars.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {

namespace {

constexpr std::size_t kCarCount = 5;

// Switch times are located to this width (s): far below anything the 0.01 s sampling resolves.
constexpr double kEventTolerance = 1e-12;

// Time comparisons (segment boundaries against step ends) up to this slack (s), so that 500 *
// 0.01 counts as the boundary at 5 s.
constexpr double kTimeTolerance = 1e-9;

// Instance 2 asks for input jumps at least 5 s apart.
constexpr double kShortestSegment = 5.0;

enum class FollowerMode { keeping, chasing, braking };

struct CarState {
  double position = 0;
  double velocity = 0;
};

struct CarsState {
  std::array<CarState, kCarCount> cars;
  std::array<FollowerMode, kCarCount> modes{};  // modes[0] unused: car 1 is driven by the inputs
};

struct Inputs {
  double throttle = 0;
  double brake = 0;
};

// The coefficients 1 / (k + offset)! of the series below, k = 0..kSeriesTerms - 1.
constexpr int kSeriesTerms = 18;
template <int offset>
constexpr std::array<double, kSeriesTerms> inverse_factorials() {
  std::array<double, kSeriesTerms> coefficients{};
  double factorial = 1;
  for (int k = 2; k <= offset; ++k) factorial *= k;
  for (int k = 0; k < kSeriesTerms; ++k) {
    coefficients[static_cast<std::size_t>(k)] = 1.0 / factorial;
    factorial *= k + offset + 1;
  }
  return coefficients;
}

// sum over k of (-x)^k / (k + offset)!, for 0 <= x <= 0.5 where 18 terms reach rounding.
template <int offset>
double alternating_series(double x) {
  static constexpr std::array<double, kSeriesTerms> coefficients = inverse_factorials<offset>();
  double sum = 0;
  for (std::size_t k = kSeriesTerms; k-- > 0;) sum = coefficients[k] - x * sum;
  return sum;
}

// (1 - e^-x) / x and (e^-x - 1 + x) / x^2: the weights of v0 and of u1 in car 1's exact solution.
// Their direct formulas cancel for small x (and divide by zero at 0), where the series is used.
double phi1(double x) { return x > 0.5 ? -std::expm1(-x) / x : alternating_series<1>(x); }
double phi2(double x) {
  return x > 0.5 ? (std::expm1(-x) + x) / (x * x) : alternating_series<2>(x);
}

// Car 1 after `dt` s of constant inputs: v' = -u1 - u2 v, y' = v, solved exactly. With x = u2 dt,
// v = v0 e^-x - u1 dt phi1(x) and y = y0 + v0 dt phi1(x) - u1 dt^2 phi2(x); u2 = 0 is the limit
// (phi1 = 1, phi2 = 1/2), so both cases share one formula.
CarState advance_lead(const CarState& car, const Inputs& inputs, double dt) {
  const double x = inputs.brake * dt;
  const double weight1 = phi1(x), weight2 = phi2(x);
  return {car.position + car.velocity * dt * weight1 - inputs.throttle * dt * dt * weight2,
          car.velocity * std::exp(-x) - inputs.throttle * dt * weight1};
}

// A follower after `dt` s in one mode, exactly: Keeping y' = v, v' = 0; Chasing y' = -v, v' = 1;
// Braking y' = -v, v' = -v (signs as in the official model).
CarState advance_follower(const CarState& car, FollowerMode mode, double dt) {
  switch (mode) {
    case FollowerMode::keeping: return {car.position + car.velocity * dt, car.velocity};
    case FollowerMode::chasing:
      return {car.position - car.velocity * dt - 0.5 * dt * dt, car.velocity + dt};
    case FollowerMode::braking:
      return {car.position + car.velocity * std::expm1(-dt), car.velocity * std::exp(-dt)};
  }
  return car;
}

// Car `i` (0 is car 1) after `dt` s in its current mode.
CarState advance_car(const CarsState& state, std::size_t i, const Inputs& inputs, double dt) {
  return i == 0 ? advance_lead(state.cars[0], inputs, dt)
                : advance_follower(state.cars[i], state.modes[i], dt);
}

CarsState advance(const CarsState& state, const Inputs& inputs, double dt) {
  CarsState next = state;
  for (std::size_t i = 0; i < kCarCount; ++i) next.cars[i] = advance_car(state, i, inputs, dt);
  return next;
}

// How far past its nearest exit guard a follower in `mode` is at `gap` (m): negative while no
// guard holds, >= 0 exactly when one does. Keeping -> Chasing is checked before Keeping ->
// Braking, as in the official chart (both cannot hold at once).
double guard_margin(FollowerMode mode, double gap) {
  switch (mode) {
    case FollowerMode::keeping: return std::max(gap - 15, 5 - gap);
    case FollowerMode::chasing: return 10 - gap;
    case FollowerMode::braking: return gap - 20;
  }
  return -1;
}

FollowerMode next_mode(FollowerMode mode, double gap) {
  if (guard_margin(mode, gap) < 0) return mode;
  switch (mode) {
    case FollowerMode::keeping: return gap >= 15 ? FollowerMode::chasing : FollowerMode::braking;
    case FollowerMode::chasing: return FollowerMode::keeping;
    case FollowerMode::braking: return FollowerMode::chasing;
  }
  return mode;
}

double gap(const CarsState& state, std::size_t i) {
  return state.cars[i].position - state.cars[i - 1].position;
}

// Every follower whose guard holds switches at once: a switch changes no position, so the other
// cars' guards read the same gaps whatever the order.
void take_transitions(CarsState& state) {
  for (std::size_t i = 1; i < kCarCount; ++i) {
    state.modes[i] = next_mode(state.modes[i], gap(state, i));
  }
}

// The time in (0, limit] at which follower `i`'s guard starts to hold, given that it does not
// hold at 0 and does at `limit`: Illinois regula falsi, which keeps a bracket [before, after]
// (guard false, true) and shrinks it superlinearly, to kEventTolerance. Returns the bracket's
// `after` end, so the guard holds there when the state is advanced to it.
double crossing_time(const CarsState& state, std::size_t i, const Inputs& inputs, double limit) {
  const auto margin = [&](double dt) {
    return guard_margin(state.modes[i], advance_car(state, i, inputs, dt).position -
                                            advance_car(state, i - 1, inputs, dt).position);
  };
  double before = 0, after = limit;
  double margin_before = margin(before), margin_after = margin(after);
  int kept = 0;  // which end the last iteration kept: -1 before, +1 after
  for (int iteration = 0; iteration < 100 && after - before > kEventTolerance; ++iteration) {
    double middle =
        (before * margin_after - after * margin_before) / (margin_after - margin_before);
    if (!(middle > before && middle < after)) middle = 0.5 * (before + after);
    const double margin_middle = margin(middle);
    if (margin_middle >= 0) {
      after = middle;
      margin_after = margin_middle;
      if (margin_middle == 0) break;
      if (kept == -1) margin_before *= 0.5;
      kept = -1;
    } else {
      before = middle;
      margin_before = margin_middle;
      if (kept == 1) margin_after *= 0.5;
      kept = 1;
    }
  }
  return after;
}

// Advances `duration` s under constant inputs, switching modes where guards become true: the
// earliest crossing among the followers whose guard holds at the end is located, every car is
// advanced to it, and the rest of the time is integrated in the new modes. The guards have
// hysteresis (a mode's exit guard is 5 m or more from its entry guard), so after a switch no
// guard holds and each pass moves time forward. A guard that becomes true and false again within
// the remaining time (at most a step) is not seen; with gap accelerations of at most about
// 1 + |v| m/s^2 such a grazing touch overshoots the guard by under a millimetre in 0.01 s.
void integrate(CarsState& state, const Inputs& inputs, double duration) {
  take_transitions(state);
  double remaining = duration;
  while (remaining > 0) {
    const CarsState end = advance(state, inputs, remaining);
    double earliest = remaining;
    bool switches = false;
    for (std::size_t i = 1; i < kCarCount; ++i) {
      if (guard_margin(state.modes[i], gap(end, i)) < 0) continue;
      switches = true;
      // Car i's guard may hold at the end without holding by `earliest`: then it crosses later.
      if (earliest < remaining &&
          guard_margin(state.modes[i], gap(advance(state, inputs, earliest), i)) < 0) {
        continue;
      }
      earliest = crossing_time(state, i, inputs, earliest);
    }
    if (!switches) {
      state = end;
      return;
    }
    state = advance(state, inputs, earliest);
    take_transitions(state);
    remaining -= earliest;
  }
}

void check_inputs(std::span<const double> values, const char* name) {
  for (const double value : values) {
    if (!(value >= 0 && value <= 1)) {
      throw std::invalid_argument(std::string("chasing cars: ") + name + " " +
                                  std::to_string(value) + " is outside [0, 1]");
    }
  }
}

struct Requirement {
  const char* name;
  const char* formula;
};

// As published (arch-cc.md), in AVUnit's syntax: intervals `[a:b]`, `>` kept where CCx has it.
constexpr std::array<Requirement, 6> kRequirements{{
    {"CC1", "G[0:100] (y5 - y4 <= 40)"},
    {"CC2", "G[0:70] F[0:30] (y5 - y4 >= 15)"},
    {"CC3", "G[0:80] ((G[0:20] (y2 - y1 <= 20)) | (F[0:20] (y5 - y4 >= 40)))"},
    {"CC4", "G[0:65] F[0:30] G[0:5] (y5 - y4 >= 8)"},
    {"CC5", "G[0:72] F[0:8] ((G[0:5] (y2 - y1 >= 9)) -> (G[5:20] (y5 - y4 >= 9)))"},
    {"CCx",
     "G[0:50] (y2 - y1 > 7.5) & G[0:50] (y3 - y2 > 7.5) & G[0:50] (y4 - y3 > 7.5) & "
     "G[0:50] (y5 - y4 > 7.5)"},
}};

}  // namespace

ChasingCarsTrace simulate_chasing_cars(std::span<const double> throttle,
                                       std::span<const double> brake, double segment_seconds,
                                       double step) {
  if (throttle.empty() || throttle.size() != brake.size()) {
    throw std::invalid_argument("chasing cars: throttle and brake need the same, non-zero length");
  }
  if (!(segment_seconds > 0)) {
    throw std::invalid_argument("chasing cars: the segment length must be positive");
  }
  const double step_count = std::round(kChasingCarsHorizon / step);
  if (!(step > 0) || step_count < 1 ||
      std::abs(step_count * step - kChasingCarsHorizon) > kTimeTolerance) {
    throw std::invalid_argument("chasing cars: the step must divide 100 s");
  }
  check_inputs(throttle, "throttle");
  check_inputs(brake, "brake");

  const auto steps = static_cast<std::size_t>(step_count);
  const std::size_t last_segment = throttle.size() - 1;
  // The segment in force just after time t (the last one past the end of the inputs).
  const auto segment_at = [&](double t) {
    const double index = std::floor((t + kTimeTolerance) / segment_seconds);
    return index >= static_cast<double>(last_segment) ? last_segment
                                                      : static_cast<std::size_t>(index);
  };

  CarsState state;
  for (std::size_t i = 0; i < kCarCount; ++i) {
    state.cars[i] = {10.0 * static_cast<double>(i), 0.0};
    state.modes[i] = FollowerMode::keeping;
  }

  ChasingCarsTrace trace;
  trace.time.reserve(steps + 1);
  for (std::size_t i = 0; i < kCarCount; ++i) {
    trace.y[i].reserve(steps + 1);
    trace.v[i].reserve(steps + 1);
  }
  const auto record = [&](double t) {
    trace.time.push_back(t);
    for (std::size_t i = 0; i < kCarCount; ++i) {
      trace.y[i].push_back(state.cars[i].position);
      trace.v[i].push_back(state.cars[i].velocity);
    }
  };

  record(0.0);
  for (std::size_t k = 0; k < steps; ++k) {
    // Times are k * step rather than sums of steps, so they do not drift.
    const double step_end = static_cast<double>(k + 1) * step;
    double t = static_cast<double>(k) * step;
    while (t < step_end) {
      const std::size_t segment = segment_at(t);
      double piece_end = step_end;
      if (segment < last_segment) {
        const double boundary = static_cast<double>(segment + 1) * segment_seconds;
        if (boundary < step_end - kTimeTolerance) piece_end = boundary;
      }
      integrate(state, {throttle[segment], brake[segment]}, piece_end - t);
      t = piece_end;
    }
    record(step_end);
  }
  return trace;
}

std::vector<std::string> chasing_cars_requirement_names() {
  std::vector<std::string> names;
  for (const Requirement& requirement : kRequirements) names.emplace_back(requirement.name);
  return names;
}

std::string chasing_cars_requirement(const std::string& requirement) {
  for (const Requirement& known : kRequirements) {
    if (requirement == known.name) return known.formula;
  }
  throw std::invalid_argument("chasing cars: unknown requirement '" + requirement +
                              "' (CC1, CC2, CC3, CC4, CC5 or CCx)");
}

Formula parse_chasing_cars_requirement(const std::string& requirement) {
  const SourceFile file(requirement, chasing_cars_requirement(requirement));
  avunit::FormulaParseResult parsed = avunit::parse_formula(file);
  if (!parsed.formula) {
    throw std::logic_error("chasing cars: requirement " + requirement + " does not parse:\n" +
                           format_diagnostics(file, parsed.diagnostics));
  }
  return std::move(*parsed.formula);
}

double chasing_cars_robustness(const Formula& formula, const ChasingCarsTrace& trace) {
  const LeafSignal leaf = [&trace](const SpecTerm& term) {
    if (term.kind == TermKind::signal && term.operands.empty() && term.name.size() == 2 &&
        term.name[0] == 'y' && term.name[1] >= '1' && term.name[1] <= '5') {
      return SignalValues{trace.y[static_cast<std::size_t>(term.name[1] - '1')], false};
    }
    throw OracleError(term.location,
                      "the chasing-cars trace has only the signals y1, y2, y3, y4 and y5");
  };
  const SignalSource source{trace.time, leaf, {}};
  return robustness_signal(formula, source).front();
}

double chasing_cars_robustness(const std::string& requirement, const ChasingCarsTrace& trace) {
  return chasing_cars_robustness(parse_chasing_cars_requirement(requirement), trace);
}

ChasingCarsEvaluator::ChasingCarsEvaluator(std::string requirement, std::size_t segments)
    : requirement_(std::move(requirement)),
      segments_(segments),
      formula_(parse_chasing_cars_requirement(requirement_)) {
  if (segments_ < 1 ||
      kChasingCarsHorizon / static_cast<double>(segments_) < kShortestSegment - kTimeTolerance) {
    throw std::invalid_argument(
        "chasing cars: instance 2 allows 1 to 20 segments (jumps at "
        "least 5 s apart), not " +
        std::to_string(segments_));
  }
}

std::vector<SearchDimension> ChasingCarsEvaluator::dimensions() const {
  std::vector<SearchDimension> dimensions;
  for (const std::string input : {"throttle", "brake"}) {
    for (std::size_t k = 0; k < segments_; ++k) {
      dimensions.push_back({input + "_" + std::to_string(k), GeneKind::continuous, 0, "", input});
    }
  }
  return dimensions;
}

std::vector<std::string> ChasingCarsEvaluator::objectives() const { return {requirement_}; }

Evaluation ChasingCarsEvaluator::evaluate(std::span<const double> unit_point,
                                          std::uint64_t /*seed*/) const {
  if (unit_point.size() != 2 * segments_) {
    throw std::invalid_argument("chasing cars: expected " + std::to_string(2 * segments_) +
                                " coordinates, got " + std::to_string(unit_point.size()));
  }
  const auto started = std::chrono::steady_clock::now();
  const ChasingCarsTrace trace =
      simulate_chasing_cars(unit_point.first(segments_), unit_point.subspan(segments_),
                            kChasingCarsHorizon / static_cast<double>(segments_));
  Evaluation evaluation;
  evaluation.robustness = {chasing_cars_robustness(formula_, trace)};
  evaluation.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return evaluation;
}

}  // namespace scenfuzz
