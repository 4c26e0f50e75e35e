// Rank 0 and its workers talk by four kinds of message, each a byte string: a task (rank 0 to a
// worker: the task id in 8 bytes, then the payload), a result (back, framed the same way), a
// heartbeat (a worker, empty) and a release (rank 0, empty). Nobody blocks inside MPI: blocking
// calls in Open MPI spin, and a spinning idle rank would take a core from a working one on an
// oversubscribed machine, so every wait is a probe and a short sleep.
#include "fuzz/campaign/mpi_pool.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <future>
#include <map>
#include <stdexcept>
#include <thread>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

enum Tag : int { kTask = 1, kResult = 2, kHeartbeat = 3, kRelease = 4 };

using Clock = std::chrono::steady_clock;

constexpr auto kPollPause = std::chrono::milliseconds(2);

std::string frame(std::int64_t id, const std::string& payload) {
  std::string bytes(sizeof id, '\0');
  std::memcpy(bytes.data(), &id, sizeof id);
  return bytes + payload;
}

std::int64_t frame_id(const std::string& bytes) {
  SCENFUZZ_DEMAND(bytes.size() >= sizeof(std::int64_t));
  std::int64_t id = 0;
  std::memcpy(&id, bytes.data(), sizeof id);
  return id;
}

void send(int rank, Tag tag, const std::string& bytes) {
  const int rc =
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, rank, tag, MPI_COMM_WORLD);
  if (rc != MPI_SUCCESS)
    throw std::runtime_error("MPI: cannot send to rank " + std::to_string(rank));
}

// A message that has arrived, if any (from `source`, or anyone).
struct Message {
  int source = 0;
  int tag = 0;
  std::string bytes;
};

std::optional<Message> poll(int source) {
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  Message message{status.MPI_SOURCE, status.MPI_TAG,
                  std::string(static_cast<std::size_t>(count), '\0')};
  MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return message;
}

double seconds_since(Clock::time_point then) {
  return std::chrono::duration<double>(Clock::now() - then).count();
}

// Rank 0's view of one distribute() call.
struct Dispatch {
  std::deque<MpiTask> pending;  // in the order handed in
  struct InFlight {
    MpiTask task;
    Clock::time_point heard;
  };
  std::map<int, InFlight> in_flight;  // by worker rank
};

}  // namespace

bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

MpiSession::MpiSession() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI could not start");
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("this MPI library cannot run a search beside its main thread");
  }
  // Errors come back as return codes, so that a dead peer is not the end of this rank.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  dead_.assign(static_cast<std::size_t>(size_), false);
  dead_[0] = true;  // rank 0 is not a worker
}

MpiSession::~MpiSession() {
  if (rank_ == 0 && !released_) {
    try {
      release_workers();
    } catch (const std::runtime_error&) {
      // A worker that cannot be told ends with the job.
    }
  }
  MPI_Finalize();
}

int MpiSession::live_workers() const {
  return static_cast<int>(std::count(dead_.begin(), dead_.end(), false));
}

std::vector<std::int64_t> MpiSession::distribute(
    const std::vector<MpiTask>& tasks,
    const std::function<void(std::int64_t, const std::string&)>& on_result,
    const std::function<bool()>& interrupted, const MpiPoolTimes& times) {
  SCENFUZZ_DEMAND(rank_ == 0);
  Dispatch dispatch;
  dispatch.pending.assign(tasks.begin(), tasks.end());
  for (;;) {
    const bool stopping = interrupted();
    for (int worker = 1; worker < size_ && !stopping && !dispatch.pending.empty(); ++worker) {
      if (dead_[static_cast<std::size_t>(worker)] || dispatch.in_flight.count(worker)) continue;
      MpiTask task = std::move(dispatch.pending.front());
      dispatch.pending.pop_front();
      send(worker, kTask, frame(task.id, task.payload));
      dispatch.in_flight[worker] = {std::move(task), Clock::now()};
    }
    if (dispatch.in_flight.empty() && (stopping || dispatch.pending.empty() || live_workers() == 0))
      break;
    // Everything that has arrived first, then the deaths: heartbeats queued while on_result was
    // busy must not make a working rank look dead.
    bool heard = false;
    while (std::optional<Message> message = poll(MPI_ANY_SOURCE)) {
      heard = true;
      auto flight = dispatch.in_flight.find(message->source);
      if (dead_[static_cast<std::size_t>(message->source)] || flight == dispatch.in_flight.end())
        continue;  // a rank given up for dead: its task is someone else's now
      flight->second.heard = Clock::now();
      if (message->tag != kResult) continue;
      const std::int64_t id = frame_id(message->bytes);
      SCENFUZZ_DEMAND(id == flight->second.task.id);
      dispatch.in_flight.erase(flight);
      on_result(id, message->bytes.substr(sizeof id));
    }
    for (auto flight = dispatch.in_flight.begin(); flight != dispatch.in_flight.end();) {
      if (seconds_since(flight->second.heard) <= times.dead_after_seconds) {
        ++flight;
        continue;
      }
      dead_[static_cast<std::size_t>(flight->first)] = true;
      // Next out: it was handed out before every task still pending.
      dispatch.pending.push_front(std::move(flight->second.task));
      flight = dispatch.in_flight.erase(flight);
    }
    if (!heard) std::this_thread::sleep_for(kPollPause);
  }
  std::vector<std::int64_t> not_done;
  for (const MpiTask& task : dispatch.pending) not_done.push_back(task.id);
  return not_done;
}

void MpiSession::release_workers() {
  SCENFUZZ_DEMAND(rank_ == 0);
  released_ = true;
  // Not the dead: a message to a rank that is gone never completes, and MPI_Finalize waits for
  // it. (A rank only given up for dead, stopped for longer than dead_after_seconds, is left
  // waiting; mpirun ends it with the job.)
  for (int worker = 1; worker < size_; ++worker)
    if (!dead_[static_cast<std::size_t>(worker)]) send(worker, kRelease, "");
}

void MpiSession::serve(const MpiJob& job, const std::function<bool()>& interrupted,
                       const MpiPoolTimes& times) {
  SCENFUZZ_DEMAND(rank_ != 0);
  for (;;) {
    std::optional<Message> message = poll(0);
    if (!message) {
      std::this_thread::sleep_for(kPollPause);
      continue;
    }
    if (message->tag == kRelease) return;
    SCENFUZZ_DEMAND(message->tag == kTask);
    const std::int64_t id = frame_id(message->bytes);
    // The job runs beside this thread, which alone calls MPI (MPI_THREAD_FUNNELED).
    std::future<std::string> result = std::async(
        std::launch::async, [&job, &interrupted, payload = message->bytes.substr(sizeof id)] {
          return job(payload, interrupted);
        });
    Clock::time_point last_beat = Clock::now();
    while (result.wait_for(kPollPause) != std::future_status::ready) {
      if (seconds_since(last_beat) < times.heartbeat_seconds) continue;
      send(0, kHeartbeat, "");
      last_beat = Clock::now();
    }
    send(0, kResult, frame(id, result.get()));
  }
}

}  // namespace scenfuzz
