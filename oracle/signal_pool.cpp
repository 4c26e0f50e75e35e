// The per-thread store of the robustness engine's working signals (signal_pool.hpp).
#include "oracle/signal_pool.hpp"

#include <algorithm>
#include <cstddef>
#include <new>
#include <utility>

namespace scenfuzz {

namespace {

thread_local SpareSignals kept;

}  // namespace

SpareSignals take_spare_signals() { return std::exchange(kept, SpareSignals{}); }

void keep_spare_signals(SpareSignals&& spare) noexcept {
  // What a nested evaluation kept meanwhile joins this one's; the largest buffers are kept first,
  // since a small buffer handed a long signal has to be allocated again. Called from a destructor,
  // also while an OracleError unwinds: when there is no memory to merge the lists, the nested
  // evaluation's buffers are freed instead.
  try {
    for (std::vector<double>& buffer : kept) spare.push_back(std::move(buffer));
  } catch (const std::bad_alloc&) {
  }
  std::sort(spare.begin(), spare.end(),
            [](const auto& a, const auto& b) { return a.capacity() > b.capacity(); });
  std::size_t keep = 0, doubles = 0;
  while (keep < spare.size() && doubles + spare[keep].capacity() <= kKeptDoubles)
    doubles += spare[keep++].capacity();
  spare.erase(spare.begin() + static_cast<std::ptrdiff_t>(keep), spare.end());
  kept = std::move(spare);  // frees what a failed merge left in `kept`
}

}  // namespace scenfuzz
