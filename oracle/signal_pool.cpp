// The per-thread store of the robustness engine's working buffers (signal_pool.hpp).
#include "oracle/signal_pool.hpp"

#include <algorithm>
#include <utility>

namespace scenfuzz {

namespace {

thread_local SpareBuffers kept;

}  // namespace

SpareBuffers take_spare_buffers() { return std::exchange(kept, SpareBuffers{}); }

void keep_spare_buffers(SpareBuffers&& spare) {
  // What a nested evaluation kept meanwhile joins this one's; the largest buffers are kept first,
  // since a small buffer handed a long signal has to be allocated again.
  for (std::vector<double>& buffer : kept.signals) spare.signals.push_back(std::move(buffer));
  std::sort(spare.signals.begin(), spare.signals.end(),
            [](const auto& a, const auto& b) { return a.capacity() > b.capacity(); });
  std::size_t doubles = 0;
  kept.signals.clear();
  for (std::vector<double>& buffer : spare.signals) {
    if (doubles + buffer.capacity() > kKeptDoubles) break;
    doubles += buffer.capacity();
    kept.signals.push_back(std::move(buffer));
  }
  if (spare.indices.capacity() > kept.indices.capacity()) kept.indices = std::move(spare.indices);
}

}  // namespace scenfuzz
