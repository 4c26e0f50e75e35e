// The genetic algorithm behind --algo ga: Latin hypercube start, tournament selection, BLX-alpha
// blending (on the circle for angles, by choice for discrete genes) or a whole-actor swap,
// Gaussian or re-draw mutation, held runs of signal segments, refinement of the best point,
// (mu + lambda) survival, duplicate rejection and restarts on stagnation.
#include "fuzz/genetic_algorithm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace scenfuzz {
namespace {

// How many times breeding may produce only duplicates for one slot of a generation before the
// slot gets a uniform random point instead (the population has then converged so far that new
// blood helps more than another try).
constexpr std::size_t max_breeding_attempts = 20;

std::size_t cell_of(double coordinate, std::size_t choices) {
  const double scaled = std::floor(coordinate * static_cast<double>(choices));
  if (!(scaled > 0.0)) return 0;
  return std::min(static_cast<std::size_t>(scaled), choices - 1);
}

double middle_of_cell(std::size_t cell, std::size_t choices) {
  return (static_cast<double>(cell) + 0.5) / static_cast<double>(choices);
}

// Into [0, 1): 0 and 1 are the same angle.
double wrap(double coordinate) {
  const double wrapped = coordinate - std::floor(coordinate);
  return wrapped < 1.0 ? wrapped : 0.0;
}

// Into [0, 1] by folding at the bounds: unlike clamping, this piles no points up on a bound
// (each would be a duplicate of the last) and keeps the mutation's spread near the edges.
double reflect(double coordinate) {
  const double folded = coordinate - 2.0 * std::floor(coordinate / 2.0);  // [0, 2)
  return folded <= 1.0 ? folded : 2.0 - folded;
}

// The signed shortest way round the circle from `from` to `to`, in [-0.5, 0.5).
double circular_difference(double from, double to) { return wrap(to - from + 0.5) - 0.5; }

// Gene indices per non-empty label, labels in order of first appearance, genes in order.
template <typename Label>
std::vector<std::vector<std::size_t>> genes_by_label(std::span<const SearchDimension> dimensions,
                                                     Label label_of) {
  std::vector<std::string> labels;
  std::vector<std::vector<std::size_t>> genes;
  for (std::size_t gene = 0; gene < dimensions.size(); ++gene) {
    const std::string label = label_of(dimensions[gene]);
    if (label.empty()) continue;
    const auto known = std::find(labels.begin(), labels.end(), label);
    if (known == labels.end()) {
      labels.push_back(label);
      genes.push_back({gene});
    } else {
      genes[static_cast<std::size_t>(known - labels.begin())].push_back(gene);
    }
  }
  return genes;
}

double usable_objective(const Observation& result) {
  return result.judged && !std::isnan(result.objective) ? result.objective
                                                        : std::numeric_limits<double>::infinity();
}

std::size_t default_population(std::size_t dimensions, std::size_t budget) {
  std::size_t population = std::clamp<std::size_t>(4 + 2 * dimensions, 10, 50);
  if (budget > 0) population = std::min(population, std::max<std::size_t>(budget / 4, 4));
  return population;
}

}  // namespace

GeneticAlgorithm::GeneticAlgorithm(std::span<const SearchDimension> dimensions, std::uint64_t seed,
                                   std::size_t budget, const GeneticAlgorithmOptions& options)
    : dimensions_(dimensions.begin(), dimensions.end()), options_(options), random_(seed) {
  for (const SearchDimension& dimension : dimensions_) {
    if (dimension.kind == GeneKind::discrete && dimension.choices == 0) {
      throw std::invalid_argument("discrete dimension '" + dimension.name + "' has no choices");
    }
  }
  options_.tournament_size = std::max<std::size_t>(options_.tournament_size, 1);
  options_.duplicate_grid = std::max<std::size_t>(options_.duplicate_grid, 1);
  if (dimensions_.empty()) {
    // The cube is a single point: evaluating it once is the whole search.
    status_.population = 1;
  } else {
    status_.population = options_.population > 0 ? std::max<std::size_t>(options_.population, 2)
                                                 : default_population(dimensions_.size(), budget);
  }
  elites_ = std::min(options_.elites, status_.population / 2);
  descending_ = options_.local_search && !dimensions_.empty() &&
                dimensions_.size() <= options_.local_search_max_dimensions;
  first_generation_ = status_.population;
  if (descending_) {
    first_generation_ =
        options_.first_generation > 0
            ? options_.first_generation
            : std::min(std::max<std::size_t>(dimensions_.size(), 4), first_generation_);
  }

  actor_genes_ =
      genes_by_label(dimensions_, [](const SearchDimension& dimension) { return dimension.group; });
  // Swapping a group that holds every gene would only exchange the parents.
  std::erase_if(actor_genes_,
                [&](const auto& genes) { return genes.size() == dimensions_.size(); });
  series_genes_ = genes_by_label(dimensions_, [](const SearchDimension& dimension) {
    return dimension.kind == GeneKind::continuous ? dimension.series : std::string();
  });
  std::erase_if(series_genes_, [](const auto& genes) { return genes.size() < 2; });
}

std::vector<UnitPoint> GeneticAlgorithm::propose(std::size_t limit) {
  if (limit == 0) throw std::invalid_argument("propose needs a limit of at least 1");
  if (awaiting_ > 0) throw std::logic_error("propose called before the last batch was observed");
  if (std::vector<UnitPoint> batch = descent_points(limit); !batch.empty()) {
    awaiting_ = batch.size();
    return batch;
  }
  if (observed_ == generation_.size()) {
    if (dimensions_.empty() && status_.generations > 0) return {};
    start_generation();
  }
  const std::size_t count = std::min(limit, generation_.size() - handed_out_);
  std::vector<UnitPoint> batch;
  batch.reserve(count);
  for (std::size_t i = 0; i < count; ++i) batch.push_back(generation_[handed_out_ + i].point);
  handed_out_ += count;
  awaiting_ = count;
  return batch;
}

void GeneticAlgorithm::observe(std::span<const Observation> results) {
  if (results.size() != awaiting_) {
    throw std::invalid_argument("observe got " + std::to_string(results.size()) +
                                " results for a batch of " + std::to_string(awaiting_));
  }
  awaiting_ = 0;
  observed_points_ += results.size();
  if (round_in_batch_ > 0) {
    for (const Observation& result : results) observe_round_point(result);
    round_in_batch_ = 0;
    return;
  }
  for (const Observation& result : results)
    generation_[observed_++].objective = usable_objective(result);
  if (observed_ == generation_.size()) finish_generation();
}

void GeneticAlgorithm::start_generation() {
  std::vector<UnitPoint> points;
  if (population_.empty()) {
    points = fresh_points(first_generation_);
  } else if (restart_pending_) {
    restart_pending_ = false;
    population_.resize(std::min(population_.size(), elites_));
    points = fresh_points(status_.population - elites_);
  } else {
    points =
        bred_points(options_.offspring > 0 ? options_.offspring : status_.population - elites_);
  }
  generation_.clear();
  for (UnitPoint& point : points) generation_.push_back({std::move(point), {}});
  handed_out_ = 0;
  observed_ = 0;
}

// (mu + lambda) survival of one more individual.
void GeneticAlgorithm::survive(const Individual& individual) {
  if (individual.objective < status_.best_objective) {
    status_.best_objective = individual.objective;
    status_.best_point = individual.point;
  }
  // After the last individual that is not worse, so that ties keep their order of evaluation
  // and the course stays deterministic.
  const auto place = std::upper_bound(
      population_.begin(), population_.end(), individual,
      [](const Individual& a, const Individual& b) { return a.objective < b.objective; });
  population_.insert(place, individual);
  population_.resize(std::min(population_.size(), status_.population));
}

void GeneticAlgorithm::finish_generation() {
  for (const Individual& individual : generation_) survive(individual);
  ++status_.generations;

  const double level = std::max(status_.best_objective, options_.progress_floor);
  const bool progress =
      std::isinf(progress_reference_)
          ? level < progress_reference_
          : level < progress_reference_ - options_.improvement_tolerance *
                                              std::max(1.0, std::abs(progress_reference_));
  if (progress) {
    progress_reference_ = level;
    observed_at_progress_ = observed_points_;
  } else if (options_.stagnation_simulations > 0 &&
             observed_points_ - observed_at_progress_ >= options_.stagnation_simulations) {
    restart_pending_ = true;
    observed_at_progress_ = observed_points_;
    ++status_.restarts;
  }
  if (!descending_ || restart_pending_) return;
  const auto best = std::min_element(
      generation_.begin(), generation_.end(),
      [](const Individual& a, const Individual& b) { return a.objective < b.objective; });
  if (best != generation_.end() && std::isfinite(best->objective) &&
      best->objective >= options_.progress_floor) {
    descents_.push_back({LocalRun(best->point, best->objective, options_.local_run), {}, {}});
    ++status_.local_runs;
  }
  if (options_.random_descent) {
    descents_.push_back({LocalRun(uniform_fresh_point(), options_.local_run), {}, {}});
    ++status_.local_runs;
  }
}

// Descents advance in rounds: every descent asks for one point, children bred from the
// population top the round up to descent_round_points, and the next round starts once the
// whole round is observed, so the points never depend on how propose() splits a round into
// batches. A descent that has ended gives its best point to the population.
void GeneticAlgorithm::start_descent_round() {
  round_.clear();
  round_children_.clear();
  // Each pass either fills the round or removes an ended descent.
  while (round_.empty() && !descents_.empty()) {
    for (Descent& descent : descents_) {
      // Snapped like every other point (a discrete gene in the middle of its cell): the same
      // scenario as the point the descent asked for, so its value answers the descent.
      descent.asked = descent.run.next_point();
      if (descent.asked) normalise(*descent.asked);
    }
    std::erase_if(descents_, [&](const Descent& descent) {
      if (!descent.run.ended()) return false;
      if (std::isfinite(descent.best.objective)) survive(descent.best);
      return true;
    });
    for (std::size_t i = 0; i < descents_.size(); ++i) {
      if (descents_[i].asked) round_.push_back(i);
    }
  }
  // Once the descents have all ended the generations go on instead (with no children here).
  if (!round_.empty() && round_.size() < options_.descent_round_points)
    round_children_ = bred_points(options_.descent_round_points - round_.size());
  round_handed_ = 0;
  round_observed_ = 0;
}

// The descents' points first, then the children.
const UnitPoint& GeneticAlgorithm::round_point(std::size_t position) const {
  if (position < round_.size()) return *descents_[round_[position]].asked;
  return round_children_[position - round_.size()];
}

void GeneticAlgorithm::observe_round_point(const Observation& result) {
  const std::size_t position = round_observed_++;
  const double objective = usable_objective(result);
  if (position >= round_.size()) {
    // A child joins the population at once (its best point is then the search's).
    survive({round_children_[position - round_.size()], objective});
    return;
  }
  Descent& descent = descents_[round_[position]];
  descent.run.tell(objective);
  if (objective < status_.best_objective) {
    status_.best_objective = objective;
    status_.best_point = *descent.asked;
  }
  if (objective < descent.best.objective) descent.best = {std::move(*descent.asked), objective};
  descent.asked.reset();
}

std::vector<UnitPoint> GeneticAlgorithm::descent_points(std::size_t limit) {
  const std::size_t round_size = round_.size() + round_children_.size();
  if (round_observed_ == round_size) start_descent_round();
  round_in_batch_ = std::min(limit, round_.size() + round_children_.size() - round_handed_);
  std::vector<UnitPoint> batch;
  for (std::size_t i = round_handed_; i < round_handed_ + round_in_batch_; ++i) {
    const UnitPoint& point = round_point(i);
    // Children were remembered as they were bred.
    if (i < round_.size()) remember(point);
    batch.push_back(point);
  }
  round_handed_ += round_in_batch_;
  return batch;
}

std::vector<UnitPoint> GeneticAlgorithm::fresh_points(std::size_t count) {
  std::vector<UnitPoint> points = latin_hypercube(count, dimensions_.size(), random_);
  for (UnitPoint& point : points) {
    normalise(point);
    // Snapping discrete genes to their cells can make two points of the design equal, and a
    // restart's design can meet an earlier point.
    for (std::size_t attempt = 0; !remember(point) && attempt < max_breeding_attempts; ++attempt) {
      point = uniform_fresh_point();
    }
  }
  return points;
}

std::vector<UnitPoint> GeneticAlgorithm::bred_points(std::size_t count) {
  std::vector<UnitPoint> children;
  children.reserve(count);
  const auto refinements = static_cast<std::size_t>(
      std::round(options_.refinement_fraction * static_cast<double>(count)));
  // A converged best point can make every refinement a duplicate: the slots then go to breeding.
  for (std::size_t attempt = 0;
       children.size() < std::min(refinements, count) && attempt < max_breeding_attempts * count;
       ++attempt) {
    UnitPoint point = refined_point();
    maybe_hold(point);
    if (remember(point)) children.push_back(std::move(point));
  }
  std::size_t failures = 0;
  while (children.size() < count) {
    UnitPoint first = tournament().point;
    UnitPoint second = tournament().point;
    if (random_.chance(options_.crossover_probability)) {
      if (!actor_genes_.empty() && random_.chance(options_.actor_swap_probability)) {
        swap_actor(first, second);
      } else {
        blend(first, second);
      }
    }
    mutate(first);
    mutate(second);
    maybe_hold(first);
    maybe_hold(second);
    bool accepted = false;
    for (UnitPoint* child : {&first, &second}) {
      if (children.size() < count && remember(*child)) {
        children.push_back(std::move(*child));
        accepted = true;
      }
    }
    if (accepted) {
      failures = 0;
    } else if (++failures >= max_breeding_attempts) {
      UnitPoint point = uniform_fresh_point();
      remember(point);
      children.push_back(std::move(point));
      failures = 0;
    }
  }
  return children;
}

const GeneticAlgorithm::Individual& GeneticAlgorithm::tournament() {
  const Individual* winner = &population_[random_.index(population_.size())];
  for (std::size_t round = 1; round < options_.tournament_size; ++round) {
    const Individual& challenger = population_[random_.index(population_.size())];
    if (challenger.objective < winner->objective) winner = &challenger;
  }
  return *winner;
}

void GeneticAlgorithm::blend(UnitPoint& first, UnitPoint& second) {
  const double alpha = options_.blend_alpha;
  for (std::size_t gene = 0; gene < dimensions_.size(); ++gene) {
    const double a = first[gene];
    const double b = second[gene];
    switch (dimensions_[gene].kind) {
      case GeneKind::continuous: {
        const double width = std::abs(a - b);
        const double lower = std::min(a, b) - alpha * width;
        const double upper = std::max(a, b) + alpha * width;
        first[gene] = random_.uniform(lower, upper);
        second[gene] = random_.uniform(lower, upper);
        break;
      }
      case GeneKind::angle: {
        // Blend along the shorter arc, so parents at 0.95 and 0.05 give children near 0, not
        // near 0.5.
        const double arc = circular_difference(a, b);
        first[gene] = a + arc * random_.uniform(-alpha, 1.0 + alpha);
        second[gene] = a + arc * random_.uniform(-alpha, 1.0 + alpha);
        break;
      }
      case GeneKind::discrete:
        // A choice has no in-between: each child takes one parent's.
        if (random_.chance(0.5)) std::swap(first[gene], second[gene]);
        break;
    }
  }
  normalise(first);
  normalise(second);
}

void GeneticAlgorithm::swap_actor(UnitPoint& first, UnitPoint& second) {
  for (const std::size_t gene : actor_genes_[random_.index(actor_genes_.size())]) {
    std::swap(first[gene], second[gene]);
  }
}

void GeneticAlgorithm::mutate(UnitPoint& point) {
  const double probability = options_.mutation_rate / static_cast<double>(dimensions_.size());
  for (std::size_t gene = 0; gene < dimensions_.size(); ++gene) {
    if (!random_.chance(probability)) continue;
    const SearchDimension& dimension = dimensions_[gene];
    if (dimension.kind == GeneKind::discrete) {
      // Re-draw among the other choices: choices are unordered, so no choice is "near" another.
      if (dimension.choices < 2) continue;
      const std::size_t current = cell_of(point[gene], dimension.choices);
      std::size_t drawn = random_.index(dimension.choices - 1);
      if (drawn >= current) ++drawn;
      point[gene] = middle_of_cell(drawn, dimension.choices);
    } else {
      point[gene] += options_.mutation_scale * random_.normal();
    }
  }
  normalise(point);
}

UnitPoint GeneticAlgorithm::refined_point() {
  UnitPoint point = population_.front().point;
  const double scale =
      options_.refinement_min_scale *
      std::pow(options_.refinement_max_scale / options_.refinement_min_scale, random_.uniform());
  for (std::size_t gene = 0; gene < dimensions_.size(); ++gene) {
    if (dimensions_[gene].kind != GeneKind::discrete) point[gene] += scale * random_.normal();
  }
  normalise(point);
  return point;
}

void GeneticAlgorithm::maybe_hold(UnitPoint& point) {
  if (!series_genes_.empty() && random_.chance(options_.hold_probability)) hold(point);
}

void GeneticAlgorithm::hold(UnitPoint& point) {
  const std::vector<std::size_t>& genes = series_genes_[random_.index(series_genes_.size())];
  const std::size_t length = 2 + random_.index(genes.size() - 1);
  const std::size_t start = random_.index(genes.size() - length + 1);
  const double draw = random_.uniform();
  const double extreme = options_.hold_extreme_probability;
  double value = random_.uniform();
  if (draw < extreme) {
    value = random_.chance(0.5) ? 0.0 : 1.0;
  } else if (draw < extreme + 0.5 * (1.0 - extreme)) {
    value = point[genes[start]];
  }
  for (std::size_t k = start; k < start + length; ++k) point[genes[k]] = value;
}

void GeneticAlgorithm::normalise(UnitPoint& point) const {
  for (std::size_t gene = 0; gene < dimensions_.size(); ++gene) {
    const SearchDimension& dimension = dimensions_[gene];
    switch (dimension.kind) {
      case GeneKind::continuous: point[gene] = reflect(point[gene]); break;
      case GeneKind::angle: point[gene] = wrap(point[gene]); break;
      case GeneKind::discrete:
        point[gene] = middle_of_cell(cell_of(point[gene], dimension.choices), dimension.choices);
        break;
    }
  }
}

UnitPoint GeneticAlgorithm::uniform_fresh_point() {
  UnitPoint point = uniform_point(dimensions_.size(), random_);
  normalise(point);
  return point;
}

// Diversity: a point is rejected when it falls in the same cell of a fine grid (a thousandth of
// every parameter's range by default) as any point proposed before. That is the simplest measure
// that removes what actually wastes simulations in a falsification run: elites re-bred unchanged,
// children of two equal parents, and discrete-only combinations tried before. Crowding or fitness
// sharing would also keep the population spread, but restarts on stagnation already move the
// search to new regions, and neither would need less tuning than a grid.
bool GeneticAlgorithm::remember(const UnitPoint& point) {
  const auto grid = static_cast<double>(options_.duplicate_grid);
  std::vector<std::int64_t> key(point.size());
  for (std::size_t gene = 0; gene < point.size(); ++gene) {
    const SearchDimension& dimension = dimensions_[gene];
    if (dimension.kind == GeneKind::discrete) {
      key[gene] = static_cast<std::int64_t>(cell_of(point[gene], dimension.choices));
    } else {
      auto cell = static_cast<std::int64_t>(std::floor(point[gene] * grid));
      if (dimension.kind == GeneKind::angle)
        cell %= static_cast<std::int64_t>(options_.duplicate_grid);
      key[gene] = cell;
    }
  }
  return seen_.insert(std::move(key)).second;
}

std::unique_ptr<SearchStrategy> make_genetic_algorithm(std::span<const SearchDimension> dimensions,
                                                       std::uint64_t seed, std::size_t budget,
                                                       const GeneticAlgorithmOptions& options) {
  return std::make_unique<GeneticAlgorithm>(dimensions, seed, budget, options);
}

}  // namespace scenfuzz
