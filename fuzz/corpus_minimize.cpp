// minimize_corpus: the seeds, their coverage (reused from the control file or computed by a pool
// of threads, each result appended to it), the set cover, then the outputs, each written whole.
#include "fuzz/corpus_minimize.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>
#include <thread>

#include "fuzz/atomic_file.hpp"
#include "fuzz/cmin_control_file.hpp"
#include "fuzz/cmin_output_folder.hpp"
#include "fuzz/cmin_table.hpp"
#include "fuzz/content_hash.hpp"
#include "fuzz/seed_paths.hpp"
#include "fuzz/set_cover.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

bool read_bytes(const std::string& path, std::string& bytes, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    error = "cannot read '" + path + "': " + std::strerror(errno);
    return false;
  }
  bytes = text.str();
  return true;
}

// A seed that stands for an input entry naming no seed.
CminSeed entry_error(const std::string& entry, const std::string& error) {
  CminSeed seed;
  seed.path = entry;
  seed.coverage.path = entry;
  seed.coverage.error = error;
  return seed;
}

// The seeds of the inputs, in input order, each once; `output` is its place under its input.
std::vector<CminSeed> collect_seeds(const std::vector<std::string>& inputs) {
  std::vector<CminSeed> seeds;
  std::set<std::string> seen;
  for (const std::string& entry : inputs) {
    std::error_code error;
    if (!fs::exists(entry, error)) {
      seeds.push_back(entry_error(entry, "'" + entry + "' does not exist"));
      continue;
    }
    const SeedExpansion expansion = expand_seed_entry(fs::path(), entry);
    if (!expansion.error.empty()) seeds.push_back(entry_error(entry, expansion.error));
    fs::path base = fs::path(entry).lexically_normal();
    if (!base.has_filename()) base = base.parent_path();
    const bool folder = fs::is_directory(entry, error);
    for (const std::string& file : expansion.files) {
      if (!seen.insert(file).second) continue;
      CminSeed seed;
      seed.path = file;
      seed.coverage.path = file;
      seed.output = folder ? fs::path(file).lexically_relative(base).generic_string()
                           : fs::path(file).filename().generic_string();
      seeds.push_back(std::move(seed));
    }
  }
  return seeds;
}

// What a run shares between its covering threads.
struct CoverPool {
  std::vector<CminSeed>& seeds;
  const std::map<std::string, CminRecord>& records;
  const CoverFunction& cover;
  const std::function<bool()>& stop_requested;
  CminControlAppender& control;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::atomic<std::size_t> covered_now{0};
  std::atomic<bool> stopped{false};
  std::mutex failure_mutex{};
  std::string write_failure{};
};

SeedCoverage cover_safely(const CoverFunction& cover, const std::string& path) {
  try {
    return cover(path);
  } catch (const std::exception& exception) {
    SeedCoverage coverage;
    coverage.error = "cannot cover '" + path + "': " + exception.what();
    return coverage;
  }
}

// Covers one seed, or takes its coverage from the control file when its bytes are unchanged.
void cover_one(CoverPool& pool, CminSeed& seed) {
  std::string bytes, error;
  if (!read_bytes(seed.path, bytes, error)) {
    seed.coverage.error = error;  // not recorded: reading is cheap to try again
    return;
  }
  seed.hash = content_hash(bytes);
  const auto known = pool.records.find(seed.path);
  if (known != pool.records.end() && known->second.hash == seed.hash) {
    seed.coverage = known->second.coverage;
    seed.reused = true;
    return;
  }
  seed.coverage = cover_safely(pool.cover, seed.path);
  seed.coverage.path = seed.path;
  seed.coverage.file_size = bytes.size();
  ++pool.covered_now;
  if (std::string failure = pool.control.append(cmin_control_line({seed.hash, seed.coverage}));
      !failure.empty()) {
    std::lock_guard<std::mutex> lock(pool.failure_mutex);
    pool.write_failure = failure;
    pool.stopped = true;
  }
}

void cover_worker(CoverPool& pool, const std::vector<std::size_t>& order) {
  for (;;) {
    if (pool.stopped || (pool.stop_requested && pool.stop_requested())) {
      pool.stopped = true;
      return;
    }
    const std::size_t at = pool.next++;
    if (at >= order.size()) return;
    cover_one(pool, pool.seeds[order[at]]);
    ++pool.done;
  }
}

std::size_t job_count(std::size_t jobs, std::size_t work) {
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min(jobs, work));
}

// Covers every seed that has none yet, `jobs` at a time; false when stopped before the end.
bool cover_all(CoverPool& pool, std::size_t jobs) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < pool.seeds.size(); ++i)
    if (pool.seeds[i].coverage.error.empty()) order.push_back(i);
  std::vector<std::thread> threads;
  const std::size_t count = job_count(jobs, order.size());
  for (std::size_t t = 1; t < count; ++t)
    threads.emplace_back([&pool, &order] { cover_worker(pool, order); });
  cover_worker(pool, order);
  for (std::thread& thread : threads) thread.join();
  return pool.done.load() == order.size();
}

// The control file as this run starts it: its usable records, rewritten whole (a line a kill cut
// short would otherwise run into the next one appended).
std::string start_control(const fs::path& path, const CminOptions& options,
                          const std::vector<CminSeed>& seeds, CminControlContents& contents,
                          CminResult& result) {
  contents = read_cmin_control(path, options.identity);
  if (contents.other_identity)
    result.notes.push_back("'" + path.string() +
                           "' was made with other coverage options or another scenfuzz: every "
                           "seed is covered again");
  std::string text = cmin_control_header(options.identity);
  std::set<std::string> current;
  for (const CminSeed& seed : seeds) current.insert(seed.path);
  for (const auto& [seed_path, record] : contents.records)
    if (current.count(seed_path) != 0) text += cmin_control_line(record);
  return write_file_atomically(path, text);
}

// The control file as it ends: one line per covered seed, in input order, whatever the order
// (and the number of runs) the coverage came in.
std::string end_control(const fs::path& path, const CminOptions& options,
                        const std::vector<CminSeed>& seeds) {
  std::string text = cmin_control_header(options.identity);
  for (const CminSeed& seed : seeds)
    if (!seed.hash.empty()) text += cmin_control_line({seed.hash, seed.coverage});
  return write_file_atomically(path, text);
}

// Names that differ: a second "a.avu" (from another input) becomes "a-2.avu", in input order.
void resolve_output_names(CminResult& result) {
  std::set<std::string> taken;
  for (CminSeed& seed : result.seeds) {
    if (seed.verdict != CminVerdict::kept) {
      seed.output.clear();
      continue;
    }
    const fs::path name(seed.output);
    for (int n = 2; taken.count(seed.output) != 0; ++n)
      seed.output = (name.parent_path() /
                     (name.stem().string() + "-" + std::to_string(n) + name.extension().string()))
                        .generic_string();
    taken.insert(seed.output);
  }
}

void choose(CminResult& result) {
  std::vector<SeedCoverage> coverage;
  for (const CminSeed& seed : result.seeds) coverage.push_back(seed.coverage);
  const SetCover cover = greedy_set_cover(coverage);
  result.kept = cover.kept;
  result.features = cover.features;
  for (std::size_t i = 0; i < result.seeds.size(); ++i) {
    CminSeed& seed = result.seeds[i];
    if (!seed.coverage.error.empty()) continue;
    seed.verdict = CminVerdict::dropped;
    seed.new_features = cover.new_features[i];
    for (std::size_t k : cover.covered_by[i]) seed.covered_by.push_back(result.seeds[k].path);
  }
  for (std::size_t k : cover.kept) {
    result.seeds[k].verdict = CminVerdict::kept;
    result.seeds[k].covered_by.clear();
  }
  resolve_output_names(result);
}

// The kept seeds copied, stale files removed, then the table: written last, so a table in
// OUT_DIR always goes with its copies.
std::string write_outputs(const fs::path& out_dir, const CminResult& result) {
  std::set<std::string> kept;
  for (std::size_t k : result.kept) {
    const CminSeed& seed = result.seeds[k];
    std::string bytes, error;
    if (!read_bytes(seed.path, bytes, error)) return error;
    const fs::path target = out_dir / seed.output;
    std::error_code made;
    fs::create_directories(target.parent_path(), made);
    if (std::string failure = write_file_atomically(target, bytes); !failure.empty())
      return failure;
    kept.insert(seed.output);
  }
  if (std::string failure = remove_stale_cmin_files(out_dir, kept); !failure.empty())
    return failure;
  return write_file_atomically(out_dir / kCminTableFileName, cmin_table_json(result));
}

CminResult fail(CminResult result, CminProblem problem, const std::string& message) {
  result.problem = problem;
  result.message = message;
  return result;
}

}  // namespace

CminResult minimize_corpus(const CminOptions& options, const CoverFunction& cover,
                           const std::function<bool()>& stop_requested) {
  CminResult result;
  result.seeds = collect_seeds(options.inputs);
  const fs::path out_dir(options.out_dir);
  FolderLock lock;
  if (std::string why = claim_cmin_output_folder(out_dir, options.inputs, lock); !why.empty())
    return fail(std::move(result), CminProblem::output_folder, why);
  const fs::path control_path = out_dir / kCminControlFileName;
  CminControlContents contents;
  CminControlAppender control;
  if (std::string failure = start_control(control_path, options, result.seeds, contents, result);
      !failure.empty() || !(failure = control.open(control_path)).empty())
    return fail(std::move(result), CminProblem::output_folder, failure);

  CoverPool pool{result.seeds, contents.records, cover, stop_requested, control};
  const bool complete = cover_all(pool, options.jobs);
  result.covered_now = pool.covered_now;
  if (!pool.write_failure.empty())
    return fail(std::move(result), CminProblem::output_folder, pool.write_failure);
  if (!complete) return fail(std::move(result), CminProblem::interrupted, "interrupted");

  choose(result);
  if (std::string failure = end_control(control_path, options, result.seeds); !failure.empty())
    return fail(std::move(result), CminProblem::output_folder, failure);
  if (std::string failure = write_outputs(out_dir, result); !failure.empty())
    return fail(std::move(result), CminProblem::output_folder, failure);
  const bool any = std::any_of(result.seeds.begin(), result.seeds.end(),
                               [](const CminSeed& seed) { return seed.coverage.error.empty(); });
  if (!any)
    return fail(std::move(result), CminProblem::nothing_covered, "no seed could be covered");
  return result;
}

}  // namespace scenfuzz
