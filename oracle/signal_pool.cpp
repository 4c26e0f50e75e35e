// The per-thread store of the robustness engine's working signals (signal_pool.hpp).
#include "oracle/signal_pool.hpp"

#include <algorithm>
#include <utility>

namespace scenfuzz {

namespace {

thread_local SpareSignals kept;

}  // namespace

SpareSignals take_spare_signals() { return std::exchange(kept, SpareSignals{}); }

void keep_spare_signals(SpareSignals&& spare) {
  // What a nested evaluation kept meanwhile joins this one's; the largest buffers are kept first,
  // since a small buffer handed a long signal has to be allocated again.
  for (std::vector<double>& buffer : kept) spare.push_back(std::move(buffer));
  std::sort(spare.begin(), spare.end(),
            [](const auto& a, const auto& b) { return a.capacity() > b.capacity(); });
  std::size_t doubles = 0;
  kept.clear();
  for (std::vector<double>& buffer : spare) {
    if (doubles + buffer.capacity() > kKeptDoubles) break;
    doubles += buffer.capacity();
    kept.push_back(std::move(buffer));
  }
}

}  // namespace scenfuzz
