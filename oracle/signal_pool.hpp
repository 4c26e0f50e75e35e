// The robustness engine's working signals, kept per thread from one evaluation to the next.
// glibc gives the memory of a finished evaluation back to the system (it trims the heap top past
// 128 KiB and unmaps large blocks), so each evaluation of a trace of 10^4 samples or more faulted
// in fresh zeroed pages, which cost more than the passes themselves (issue 23,
// docs/performance.md "STL robustness"). The fuzzer judges trace after trace of similar length on
// each worker thread, so the buffers of the last evaluation fit the next.
#pragma once

#include <cstddef>
#include <vector>

namespace scenfuzz {

// Buffers whose capacity matters, not their contents.
using SpareSignals = std::vector<std::vector<double>>;

// At most this many doubles (512 MiB) are kept per thread: a dozen signals of an hours-long log;
// past it, buffers go back to malloc as before.
inline constexpr std::size_t kKeptDoubles = std::size_t{1} << 26;

// The buffers this thread kept, moved out: a nested evaluation (a leaf that evaluates a formula)
// starts without them and allocates its own.
SpareSignals take_spare_signals();

// Keeps `spare` for the thread's next evaluation, the largest first, as far as kKeptDoubles allows.
void keep_spare_signals(SpareSignals&& spare) noexcept;

}  // namespace scenfuzz
