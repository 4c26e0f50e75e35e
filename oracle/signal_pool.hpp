// The robustness engine's working buffers, kept per thread from one evaluation to the next.
// glibc gives the memory of a finished evaluation back to the system (it trims the heap top past
// 128 KiB and unmaps large blocks), so each evaluation of a trace of 10^4 samples or more faulted
// in fresh zeroed pages, which cost more than the passes themselves (issue 23,
// docs/performance.md "STL robustness"). The fuzzer judges trace after trace of similar length on
// each worker thread, so the buffers of the last evaluation fit the next.
#pragma once

#include <cstddef>
#include <vector>

namespace scenfuzz {

struct SpareBuffers {
  std::vector<std::vector<double>> signals;  // capacity matters, not contents
  std::vector<std::size_t> indices;          // the sliding windows' deque
};

// At most this many doubles (512 MiB) are kept per thread: a few signals of an hours-long log;
// past it, buffers go back to malloc as before.
inline constexpr std::size_t kKeptDoubles = std::size_t{1} << 26;

// The buffers this thread kept, moved out: a nested evaluation (a leaf that evaluates a formula)
// starts without them and allocates its own.
SpareBuffers take_spare_buffers();

// Keeps `spare` for the thread's next evaluation, as far as kKeptDoubles allows.
void keep_spare_buffers(SpareBuffers&& spare);

}  // namespace scenfuzz
