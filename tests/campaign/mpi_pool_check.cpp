// The MPI pool in a real MPI job, for mpi_pool_test.cpp, which starts it under mpirun: rank 0
// hands out `tasks` tasks (payload n, result n*n after a short sleep) and prints every result it
// gets, one line each ("result ID VALUE"), then the tasks not done ("not_done ID") and the live
// workers ("live N"). Options: `die RANK` makes that rank kill itself (SIGKILL) on its second
// task; `interrupt N` makes rank 0 stop handing out tasks after N results.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "fuzz/campaign/mpi_pool.hpp"

namespace {

struct CheckOptions {
  int tasks = 12;
  int die_rank = -1;
  int interrupt_after = -1;
};

CheckOptions parse(int argc, char** argv) {
  CheckOptions options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (key == "tasks") options.tasks = value;
    if (key == "die") options.die_rank = value;
    if (key == "interrupt") options.interrupt_after = value;
  }
  return options;
}

void run_rank0(scenfuzz::MpiSession& session, const CheckOptions& options) {
  std::vector<scenfuzz::MpiTask> tasks;
  for (int n = 0; n < options.tasks; ++n) tasks.push_back({n, std::to_string(n)});
  int results = 0;
  const std::vector<std::int64_t> not_done = session.distribute(
      tasks,
      [&](std::int64_t id, const std::string& result) {
        std::printf("result %lld %s\n", static_cast<long long>(id), result.c_str());
        ++results;
      },
      [&] { return options.interrupt_after >= 0 && results >= options.interrupt_after; },
      {0.1, 2.0});
  for (std::int64_t id : not_done) std::printf("not_done %lld\n", static_cast<long long>(id));
  std::printf("live %d\n", session.live_workers());
  std::fflush(stdout);
  session.release_workers();
}

void run_worker(scenfuzz::MpiSession& session, const CheckOptions& options) {
  int jobs = 0;
  session.serve(
      [&](const std::string& payload, const std::function<bool()>&) {
        if (++jobs == 2 && session.rank() == options.die_rank) std::raise(SIGKILL);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        const long long n = std::atoll(payload.c_str());
        return std::to_string(n * n);
      },
      [] { return false; }, {0.1, 2.0});
}

}  // namespace

int main(int argc, char** argv) {
  const CheckOptions options = parse(argc, argv);
  scenfuzz::MpiSession session;
  if (session.rank() == 0)
    run_rank0(session, options);
  else
    run_worker(session, options);
  return 0;
}
