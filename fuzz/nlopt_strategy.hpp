// The NLopt search strategies (--algo nlopt:<ALGORITHM>): any derivative-free NLopt algorithm
// minimising the objective over the unit cube. NLopt drives its objective by callbacks while the
// search loop asks and tells, so each strategy runs NLopt on a thread of its own whose callback
// hands its point to propose() and waits for observe(). NLopt is kept out of this header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "fuzz/search_strategy.hpp"

namespace scenfuzz {

// What NLopt sees instead of +inf (an infeasible or unjudged point) or NaN: several algorithms
// (the quadratic models of BOBYQA and NEWUOA, the simplex of Nelder-Mead) break on infinities.
// Finite objectives are clamped to [-nlopt_penalty, nlopt_penalty] for the same reason.
inline constexpr double nlopt_penalty = 1e9;

// Proposes one point per batch (NLopt is sequential). When an NLopt run ends (a local method
// converged, a global one reached its evaluation limit, or NLopt threw, as BOBYQA does on
// roundoff) the next run starts from a new random start point, so the strategy never ends by
// itself: the search loop's budget decides. Local methods stop a run once a step moves every
// coordinate by less than 1e-4 or changes the objective by less than 1e-8.
//
// Determinism: start points come from a generator seeded by `seed`, and NLopt's own generator
// (CRS2, ISRES, ESCH, MLSL, DIRECT_L_RAND) is reseeded with derive_seed(seed, run) before each
// run. NLopt 2.7 has no per-object seed; its generator is thread-local, and as every strategy
// runs NLopt on its own thread, strategies running at the same time do not disturb each other.
// (An NLopt built without thread-local storage would share one generator between them.)
//
// Points NLopt asks for twice are answered from a cache without evaluating them again. The
// start-independent deterministic algorithms (DIRECT without _RAND, ORIG_DIRECT, AGS) would
// repeat themselves on a restart: each restart raises their evaluation limit to twice the last
// run's, replaying the cached prefix and continuing beyond it; once a run brings nothing new
// (AGS stops by its own criterion) the strategy proposes uniform random points instead.
class NloptStrategy final : public SearchStrategy {
 public:
  // Throws std::invalid_argument for a name nlopt_algorithm_names() does not accept (naming
  // them) and for GN_AGS with more than 10 dimensions.
  NloptStrategy(const std::string& algorithm, std::span<const SearchDimension> dimensions,
                std::uint64_t seed, std::size_t budget);
  // Stops the NLopt run (also while a proposed point awaits its result) and joins its thread.
  ~NloptStrategy() override;
  NloptStrategy(const NloptStrategy&) = delete;
  NloptStrategy& operator=(const NloptStrategy&) = delete;

  // One point. Throws std::logic_error when the previous batch has not been observed.
  std::vector<UnitPoint> propose(std::size_t limit) override;
  // Exactly one result, for the point last proposed.
  void observe(std::span<const Observation> results) override;

  // The best point observed over all runs with a finite objective, and that objective (+inf
  // and an empty point before any).
  UnitPoint best_point() const;
  double best_objective() const;
  // How many NLopt runs had started when the point last proposed was asked for: 1 + the
  // restarts before it (0 before the first proposal). Unlike a live count, it does not depend
  // on how far the NLopt thread has got.
  std::size_t runs() const;

  // Defined in nlopt_strategy.cpp; named here only so NLopt's callback there can reach it.
  struct State;

 private:
  std::unique_ptr<State> state_;
};

// `algorithm` is an NLopt name without the NLOPT_ prefix (case-insensitive), e.g. "LN_BOBYQA".
// MLSL and AUGLAG need a local optimiser: LN_BOBYQA unless named after a '+', as in
// "GN_MLSL_LDS+LN_SBPLX". `budget` (0: unlimited) caps each run's evaluations.
std::unique_ptr<SearchStrategy> make_nlopt_strategy(const std::string& algorithm,
                                                    std::span<const SearchDimension> dimensions,
                                                    std::uint64_t seed, std::size_t budget);

// The algorithm names make_nlopt_strategy accepts (without the "+LOCAL" form).
std::vector<std::string> nlopt_algorithm_names();

}  // namespace scenfuzz
