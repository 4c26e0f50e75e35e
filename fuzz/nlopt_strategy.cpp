// NloptStrategy (NLopt is included only here and in local_run.cpp). The NLopt thread runs
// optimize() in a loop of restarts; its objective callback publishes the point and blocks until
// observe() (or the destructor) answers, so exactly one side runs at a time and the course of the
// search depends only on the seed and the results.
#include "fuzz/nlopt_strategy.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <nlopt.hpp>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <utility>

#include "sampler/random.hpp"

namespace scenfuzz {
namespace {

enum class Family {
  local,              // LN_*: converges from its start point, then restarts
  global,             // samples the whole box until its evaluation limit
  global_with_local,  // MLSL: needs a local optimiser or it crashes the process
  local_with_local,   // AUGLAG: needs a subsidiary optimiser or it crashes the process
};

struct AlgorithmInfo {
  std::string_view name;
  nlopt::algorithm algorithm;
  Family family;
  // Ignores the start point and draws nothing random: a restart would repeat the last run.
  bool repeats_itself = false;
};

constexpr std::array algorithm_table{
    AlgorithmInfo{"GN_DIRECT", nlopt::GN_DIRECT, Family::global, true},
    AlgorithmInfo{"GN_DIRECT_L", nlopt::GN_DIRECT_L, Family::global, true},
    AlgorithmInfo{"GN_DIRECT_L_RAND", nlopt::GN_DIRECT_L_RAND, Family::global},
    AlgorithmInfo{"GN_DIRECT_NOSCAL", nlopt::GN_DIRECT_NOSCAL, Family::global, true},
    AlgorithmInfo{"GN_DIRECT_L_NOSCAL", nlopt::GN_DIRECT_L_NOSCAL, Family::global, true},
    AlgorithmInfo{"GN_DIRECT_L_RAND_NOSCAL", nlopt::GN_DIRECT_L_RAND_NOSCAL, Family::global},
    AlgorithmInfo{"GN_ORIG_DIRECT", nlopt::GN_ORIG_DIRECT, Family::global, true},
    AlgorithmInfo{"GN_ORIG_DIRECT_L", nlopt::GN_ORIG_DIRECT_L, Family::global, true},
    AlgorithmInfo{"GN_CRS2_LM", nlopt::GN_CRS2_LM, Family::global},
    AlgorithmInfo{"GN_ISRES", nlopt::GN_ISRES, Family::global},
    AlgorithmInfo{"GN_ESCH", nlopt::GN_ESCH, Family::global},
    AlgorithmInfo{"GN_AGS", nlopt::GN_AGS, Family::global, true},
    AlgorithmInfo{"GN_MLSL", nlopt::GN_MLSL, Family::global_with_local},
    AlgorithmInfo{"GN_MLSL_LDS", nlopt::GN_MLSL_LDS, Family::global_with_local},
    AlgorithmInfo{"G_MLSL", nlopt::G_MLSL, Family::global_with_local},
    AlgorithmInfo{"G_MLSL_LDS", nlopt::G_MLSL_LDS, Family::global_with_local},
    AlgorithmInfo{"LN_BOBYQA", nlopt::LN_BOBYQA, Family::local},
    AlgorithmInfo{"LN_COBYLA", nlopt::LN_COBYLA, Family::local},
    AlgorithmInfo{"LN_SBPLX", nlopt::LN_SBPLX, Family::local},
    AlgorithmInfo{"LN_NELDERMEAD", nlopt::LN_NELDERMEAD, Family::local},
    AlgorithmInfo{"LN_PRAXIS", nlopt::LN_PRAXIS, Family::local},
    AlgorithmInfo{"LN_NEWUOA", nlopt::LN_NEWUOA, Family::local},
    AlgorithmInfo{"LN_NEWUOA_BOUND", nlopt::LN_NEWUOA_BOUND, Family::local},
    AlgorithmInfo{"LN_AUGLAG", nlopt::LN_AUGLAG, Family::local_with_local},
    AlgorithmInfo{"LN_AUGLAG_EQ", nlopt::LN_AUGLAG_EQ, Family::local_with_local},
    AlgorithmInfo{"AUGLAG", nlopt::AUGLAG, Family::local_with_local},
    AlgorithmInfo{"AUGLAG_EQ", nlopt::AUGLAG_EQ, Family::local_with_local},
};

constexpr std::string_view default_local_optimiser = "LN_BOBYQA";
// AGS (NLopt 2.7.1) rejects more dimensions than this with NLOPT_INVALID_ARGS.
constexpr std::size_t ags_max_dimensions = 10;
// Local stopping rules, in unit-cube coordinates: finer steps than 1e-4 of a parameter's range
// rarely change a simulation, and a flat objective (a plateau of robustness) should restart.
constexpr double local_xtol_abs = 1e-4;
constexpr double local_ftol_abs = 1e-8;

std::string accepted_names_text() {
  std::string text;
  for (const AlgorithmInfo& info : algorithm_table) {
    text += text.empty() ? "" : ", ";
    text += info.name;
  }
  return text + " (MLSL and AUGLAG take a local optimiser after '+', e.g. GN_MLSL+LN_SBPLX; " +
         std::string(default_local_optimiser) + " by default)";
}

[[noreturn]] void reject(const std::string& name, const std::string& why) {
  throw std::invalid_argument("NLopt algorithm '" + name + "' " + why +
                              "; accepted: " + accepted_names_text());
}

const AlgorithmInfo& find_algorithm(const std::string& full_name, std::string_view name) {
  for (const AlgorithmInfo& info : algorithm_table) {
    if (info.name == name) return info;
  }
  const bool gradient_based = name.starts_with("LD_") || name.starts_with("GD_");
  reject(full_name, gradient_based ? "needs gradients, which a simulation does not give"
                                   : "is unknown or not supported");
}

struct AlgorithmChoice {
  const AlgorithmInfo* main = nullptr;
  const AlgorithmInfo* local = nullptr;  // set for the families that need one
};

AlgorithmChoice parse_algorithm(const std::string& algorithm) {
  std::string name = algorithm;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (name.starts_with("NLOPT_")) name.erase(0, 6);
  const std::size_t plus = name.find('+');
  AlgorithmChoice choice;
  choice.main = &find_algorithm(algorithm, std::string_view(name).substr(0, plus));
  const bool needs_local = choice.main->family == Family::global_with_local ||
                           choice.main->family == Family::local_with_local;
  if (plus == std::string::npos) {
    if (needs_local) choice.local = &find_algorithm(algorithm, default_local_optimiser);
    return choice;
  }
  if (!needs_local) reject(algorithm, "takes no local optimiser");
  choice.local = &find_algorithm(algorithm, std::string_view(name).substr(plus + 1));
  if (choice.local->family != Family::local) {
    reject(algorithm, "needs a plain LN_ local optimiser after '+'");
  }
  return choice;
}

double nlopt_value(double objective) {
  if (std::isnan(objective)) return nlopt_penalty;
  return std::clamp(objective, -nlopt_penalty, nlopt_penalty);
}

int evaluation_limit(std::size_t evaluations) {
  return static_cast<int>(std::min<std::size_t>(evaluations, INT_MAX));
}

// Thrown by the NLopt thread's evaluation when the strategy is being destroyed.
struct StopRequested {};

}  // namespace

struct NloptStrategy::State {
  State(AlgorithmChoice algorithm_choice, std::size_t dimension_count_, std::uint64_t seed_,
        std::size_t budget_)
      : choice(algorithm_choice),
        dimension_count(dimension_count_),
        seed(seed_),
        budget(budget_),
        random(seed_),
        nlopt_exhausted(dimension_count_ == 0) {}

  const AlgorithmChoice choice;
  const std::size_t dimension_count;
  const std::uint64_t seed;
  const std::size_t budget;

  // Shared between the NLopt thread and the caller's thread.
  mutable std::mutex mutex;
  std::condition_variable request_published;  // NLopt thread -> propose()
  std::condition_variable result_delivered;   // observe() or destructor -> NLopt thread
  std::optional<UnitPoint> request;           // the point the NLopt thread waits on
  bool handed_out = false;                    // request proposed, not yet observed
  std::optional<double> result;
  bool stopping = false;
  bool finished = false;  // the NLopt thread has returned
  std::exception_ptr thread_error;
  std::size_t runs_started = 0;
  std::size_t request_run = 0;   // runs_started when the request was published
  std::size_t proposed_run = 0;  // request_run of the point last proposed
  UnitPoint best_point;
  double best_objective = std::numeric_limits<double>::infinity();

  // Owned by the NLopt thread.
  Random random;
  std::map<UnitPoint, double> cache;
  std::size_t proposals = 0;
  std::size_t run_calls = 0;
  std::size_t run_new_points = 0;
  // NLopt needs at least one dimension; without any, every proposal is the empty point.
  bool nlopt_exhausted;

  std::thread thread;

  // The result for `point`: published to propose() and awaited. Throws StopRequested.
  double evaluate(const UnitPoint& point) {
    std::unique_lock lock(mutex);
    if (stopping) throw StopRequested{};
    request = point;
    request_run = runs_started;
    result.reset();
    ++proposals;
    ++run_new_points;
    request_published.notify_all();
    result_delivered.wait(lock, [&] { return result.has_value() || stopping; });
    request.reset();
    if (!result) throw StopRequested{};
    const double value = *result;
    result.reset();
    return value;
  }

  double evaluate_cached(const UnitPoint& point) {
    ++run_calls;
    if (const auto found = cache.find(point); found != cache.end()) return found->second;
    const double value = evaluate(point);
    cache.emplace(point, value);
    return value;
  }

  static double objective(unsigned n, const double* x, double* /*gradient*/, void* data) {
    auto& state = *static_cast<State*>(data);
    UnitPoint point(x, x + n);
    for (double& coordinate : point) {
      coordinate = std::isnan(coordinate) ? 0.5 : std::clamp(coordinate, 0.0, 1.0);
    }
    try {
      return state.evaluate_cached(point);
    } catch (const StopRequested&) {
      // NLopt's C++ wrapper catches this, stops the run, and optimize() rethrows it.
      throw nlopt::forced_stop();
    }
  }

  nlopt::opt make_optimiser(const AlgorithmInfo& info) const {
    const auto n = static_cast<unsigned>(dimension_count);
    nlopt::opt optimiser(info.algorithm, n);
    optimiser.set_lower_bounds(0.0);
    optimiser.set_upper_bounds(1.0);
    if (info.family == Family::local || info.family == Family::local_with_local) {
      optimiser.set_xtol_abs(local_xtol_abs);
      optimiser.set_ftol_abs(local_ftol_abs);
    }
    if (choice.local != nullptr && &info == choice.main) {
      optimiser.set_local_optimizer(make_optimiser(*choice.local));
    }
    return optimiser;
  }

  std::size_t run_limit(std::size_t last_run_calls) const {
    const std::size_t remaining = budget > proposals ? budget - proposals : 0;
    if (choice.main->repeats_itself) return std::max(remaining, 2 * last_run_calls);
    // The search loop does not count infeasible points against its budget, so it may ask for
    // more than `budget` proposals: then each run gets a full budget again.
    return remaining > 0 ? remaining : budget;
  }

  void run_nlopt(std::size_t run, const UnitPoint& start, std::size_t limit) {
    nlopt::opt optimiser = make_optimiser(*choice.main);
    optimiser.set_min_objective(&State::objective, this);
    optimiser.set_maxeval(evaluation_limit(limit));
    // optimize() overwrites its argument with the best point; the start stays the fallback.
    UnitPoint x = start;
    double minimum = 0;
    nlopt::srand(derive_seed(seed, run));
    optimiser.optimize(x, minimum);
  }

  void run_restarts() {
    std::size_t last_run_calls = 0;
    for (std::size_t run = 0;; ++run) {
      {
        std::lock_guard lock(mutex);
        if (stopping) return;
        ++runs_started;
      }
      UnitPoint start(dimension_count);
      for (double& coordinate : start) coordinate = random.uniform();
      if (!nlopt_exhausted) {
        run_calls = 0;
        run_new_points = 0;
        try {
          run_nlopt(run, start, run_limit(last_run_calls));
        } catch (const std::invalid_argument& error) {
          // NLopt rejecting its very first run is a configuration it does not support: say so
          // rather than silently searching at random.
          if (run == 0 && run_new_points == 0) {
            throw std::runtime_error(std::string("NLopt ") + std::string(choice.main->name) +
                                     " refused to run: " + error.what());
          }
        } catch (const std::exception&) {
          // forced_stop (on destruction), roundoff_limited, NLopt failures: the run is over
          // either way, and the loop restarts it unless the strategy is stopping.
        }
        last_run_calls = run_calls;
        if (run_new_points > 0) continue;
        // A run that proposed nothing (every point cached) must not spin: evaluate the start
        // point instead.
        nlopt_exhausted = choice.main->repeats_itself;
      }
      evaluate(start);
    }
  }

  void thread_main() {
    try {
      run_restarts();
    } catch (const StopRequested&) {
    } catch (...) {
      std::lock_guard lock(mutex);
      thread_error = std::current_exception();
    }
    std::lock_guard lock(mutex);
    finished = true;
    request_published.notify_all();
  }
};

NloptStrategy::NloptStrategy(const std::string& algorithm,
                             std::span<const SearchDimension> dimensions, std::uint64_t seed,
                             std::size_t budget) {
  const AlgorithmChoice choice = parse_algorithm(algorithm);
  if (choice.main->algorithm == nlopt::GN_AGS && dimensions.size() > ags_max_dimensions) {
    throw std::invalid_argument("NLopt algorithm GN_AGS handles at most " +
                                std::to_string(ags_max_dimensions) + " dimensions, not " +
                                std::to_string(dimensions.size()));
  }
  state_ = std::make_unique<State>(choice, dimensions.size(), seed, budget);
  state_->thread = std::thread([state = state_.get()] { state->thread_main(); });
}

NloptStrategy::~NloptStrategy() {
  {
    std::lock_guard lock(state_->mutex);
    state_->stopping = true;
  }
  state_->result_delivered.notify_all();
  state_->thread.join();
}

std::vector<UnitPoint> NloptStrategy::propose(std::size_t limit) {
  if (limit == 0) throw std::invalid_argument("NloptStrategy::propose: limit must be >= 1");
  std::unique_lock lock(state_->mutex);
  if (state_->handed_out) {
    throw std::logic_error("NloptStrategy::propose called before the last point was observed");
  }
  state_->request_published.wait(
      lock, [&] { return (state_->request && !state_->result) || state_->finished; });
  if (state_->finished) {
    if (state_->thread_error) std::rethrow_exception(state_->thread_error);
    return {};
  }
  state_->handed_out = true;
  state_->proposed_run = state_->request_run;
  return {*state_->request};
}

void NloptStrategy::observe(std::span<const Observation> results) {
  std::unique_lock lock(state_->mutex);
  if (!state_->handed_out) {
    if (results.empty()) return;
    throw std::logic_error("NloptStrategy::observe called without a proposed point");
  }
  if (results.size() != 1) {
    throw std::invalid_argument("NloptStrategy::observe expects exactly one result");
  }
  const double objective = results.front().objective;
  if (std::isfinite(objective) && objective < state_->best_objective) {
    state_->best_objective = objective;
    state_->best_point = *state_->request;
  }
  state_->handed_out = false;
  state_->result = nlopt_value(objective);
  lock.unlock();
  state_->result_delivered.notify_all();
}

UnitPoint NloptStrategy::best_point() const {
  std::lock_guard lock(state_->mutex);
  return state_->best_point;
}

double NloptStrategy::best_objective() const {
  std::lock_guard lock(state_->mutex);
  return state_->best_objective;
}

std::size_t NloptStrategy::runs() const {
  std::lock_guard lock(state_->mutex);
  return state_->proposed_run;
}

std::unique_ptr<SearchStrategy> make_nlopt_strategy(const std::string& algorithm,
                                                    std::span<const SearchDimension> dimensions,
                                                    std::uint64_t seed, std::size_t budget) {
  return std::make_unique<NloptStrategy>(algorithm, dimensions, seed, budget);
}

std::vector<std::string> nlopt_algorithm_names() {
  std::vector<std::string> names;
  for (const AlgorithmInfo& info : algorithm_table) names.emplace_back(info.name);
  return names;
}

}  // namespace scenfuzz
