// minimise_findings: minimize_finding over a list of findings on a TBB arena; each job writes only
// its own output file, so the jobs need nothing from each other.
#include "fuzz/findings_tmin.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <filesystem>

#include "fuzz/tmin_finding.hpp"

namespace scenfuzz {

namespace {

TminJobResult minimise_one(const TminJob& job, const std::function<bool()>& interrupted) {
  TminJobResult result;
  const std::string out_path =
      job.out_path.empty() ? default_minimised_path(job.finding_file) : job.out_path;
  std::error_code error;
  if (std::filesystem::exists(out_path, error)) {
    result.minimised_file = out_path;
    result.reused = true;
    return result;
  }
  const TminResult tmin = minimize_finding(job.finding_file, TminOptions{out_path, interrupted});
  if (tmin.ok())
    result.minimised_file = tmin.out_path;
  else
    result.reason = tmin.error;
  result.interrupted = tmin.interrupted;
  return result;
}

}  // namespace

std::vector<TminJobResult> minimise_findings(const std::vector<TminJob>& jobs, std::size_t threads,
                                             const std::function<bool()>& interrupted) {
  std::vector<TminJobResult> results(jobs.size());
  if (jobs.empty()) return results;
  const int workers = threads == 0 ? tbb::info::default_concurrency() : static_cast<int>(threads);
  tbb::task_arena arena(workers);
  // One finding per task: a reduction is hundreds of simulations, so there is nothing to batch.
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, jobs.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t k = range.begin(); k != range.end(); ++k)
            results[k] = minimise_one(jobs[k], interrupted);
        },
        tbb::simple_partitioner());
  });
  return results;
}

}  // namespace scenfuzz
