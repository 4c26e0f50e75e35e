// The sampling baselines: each is a point generator behind the SearchStrategy interface.
#include "fuzz/sampling_strategy.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sampler/point_samplers.hpp"

namespace scenfuzz {
namespace {

// Proposes the next `limit` points of an endless sequence and ignores what it hears back; the
// sequence is the only state, which is why batch sizes cannot change it.
class PointSequenceStrategy : public SearchStrategy {
 public:
  std::vector<UnitPoint> propose(std::size_t limit) final {
    std::vector<UnitPoint> batch;
    batch.reserve(limit);
    for (std::size_t i = 0; i < limit; ++i) batch.push_back(next_point());
    return batch;
  }
  void observe(std::span<const Observation>) final {}

 protected:
  virtual UnitPoint next_point() = 0;
};

class RandomStrategy final : public PointSequenceStrategy {
 public:
  RandomStrategy(std::size_t dimensions, std::uint64_t seed)
      : dimensions_(dimensions), random_(seed) {}

 private:
  UnitPoint next_point() override { return uniform_point(dimensions_, random_); }

  std::size_t dimensions_;
  Random random_;
};

class HaltonStrategy final : public PointSequenceStrategy {
 public:
  HaltonStrategy(std::size_t dimensions, std::uint64_t seed) : sequence_(dimensions, seed) {}

 private:
  UnitPoint next_point() override { return sequence_.point(next_index_++); }

  HaltonSequence sequence_;
  std::uint64_t next_index_ = 0;
};

class LatinHypercubeStrategy final : public PointSequenceStrategy {
 public:
  LatinHypercubeStrategy(std::size_t dimensions, std::uint64_t seed, std::size_t design_size)
      : dimensions_(dimensions),
        design_size_(std::max<std::size_t>(design_size, 1)),
        random_(seed) {}

 private:
  UnitPoint next_point() override {
    // Designs are drawn only when the previous one is used up, so the draws from random_ happen
    // in the same order however the points are batched.
    if (next_in_design_ == design_.size()) {
      design_ = latin_hypercube(design_size_, dimensions_, random_);
      next_in_design_ = 0;
    }
    return std::move(design_[next_in_design_++]);
  }

  std::size_t dimensions_;
  std::size_t design_size_;
  Random random_;
  std::vector<UnitPoint> design_;
  std::size_t next_in_design_ = 0;
};

}  // namespace

std::unique_ptr<SearchStrategy> make_sampling_strategy(const std::string& name,
                                                       std::span<const SearchDimension> dimensions,
                                                       std::uint64_t seed, std::size_t budget) {
  if (name == "random") return std::make_unique<RandomStrategy>(dimensions.size(), seed);
  if (name == "halton") return std::make_unique<HaltonStrategy>(dimensions.size(), seed);
  if (name == "lhs") {
    return std::make_unique<LatinHypercubeStrategy>(dimensions.size(), seed, budget);
  }
  throw std::invalid_argument("unknown sampling strategy '" + name +
                              "' (expected random, halton or lhs)");
}

}  // namespace scenfuzz
