// The ego plugin host: fork, a socket pair, and a child loop that only touches the plugin.
//
// The child is forked from a process whose other threads (TBB workers, other evaluations) may
// hold locks at that moment; it therefore uses only system calls, dlopen/dlsym (glibc makes
// malloc and the loader usable after fork) and the plugin itself, and ends with _exit so that
// none of the parent's destructors or atexit handlers run twice. stdout and stderr are locked
// and flushed around fork(), so that a plugin that prints neither deadlocks on a lock another
// thread held nor repeats the parent's buffered output.
#include "physics/ego/plugin_driver.hpp"

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <utility>

#include "lang/demand.hpp"

namespace scenfuzz {
namespace {

using Clock = std::chrono::steady_clock;

enum class StartStatus : int32_t {
  ready = 0,
  cannot_load = 1,
  lacks_symbol = 2,
  create_failed = 3
};

struct StartReply {
  StartStatus status;
  char detail[1000];  // dlerror's text or the missing symbol's name
};

struct StepReply {
  int32_t status;
  scenfuzz_control control;
};

using CreateFunction = void* (*)(const scenfuzz_ego_config*);
using StepFunction = int (*)(void*, const scenfuzz_observation*, scenfuzz_control*);
using DestroyFunction = void (*)(void*);
using VersionFunction = uint32_t (*)(void);

// The control's signal bits are VehicleSignals' as they are: a plugin's word is stored as is.
static_assert(SCENFUZZ_SIGNAL_LEFT_INDICATOR == vehicle_signal::left_indicator);
static_assert(SCENFUZZ_SIGNAL_RIGHT_INDICATOR == vehicle_signal::right_indicator);
static_assert(SCENFUZZ_SIGNAL_HAZARD_LIGHTS == vehicle_signal::hazard_lights);
static_assert(SCENFUZZ_SIGNAL_HORN == vehicle_signal::horn);
static_assert(SCENFUZZ_SIGNAL_LOW_BEAM == vehicle_signal::low_beam);
static_assert(SCENFUZZ_SIGNAL_HIGH_BEAM == vehicle_signal::high_beam);
static_assert(SCENFUZZ_SIGNAL_FOG_LIGHTS == vehicle_signal::fog_lights);
static_assert(SCENFUZZ_SIGNAL_WIPERS == vehicle_signal::wipers);
static_assert(SCENFUZZ_SIGNAL_BRAKE_LIGHTS == vehicle_signal::brake_lights);
// Version 2 only appended fields: version 1 plugins find theirs where they were.
static_assert(offsetof(scenfuzz_control, version) == 2 * sizeof(double));
static_assert(offsetof(scenfuzz_observation, object_signals) >=
              offsetof(scenfuzz_observation, stop_sign_distance) + sizeof(double));

// The version the plugin and scenfuzz both speak: the plugin's own (its optional
// scenfuzz_ego_abi_version; 1 without it), or scenfuzz's if that is lower.
uint32_t agreed_version(void* handle) {
  const auto version = reinterpret_cast<VersionFunction>(dlsym(handle, "scenfuzz_ego_abi_version"));
  const uint32_t plugin = version != nullptr ? version() : 1;
  return std::min<uint32_t>(std::max<uint32_t>(plugin, 1), SCENFUZZ_EGO_ABI_VERSION);
}

Clock::time_point deadline_after(double seconds) {
  return Clock::now() +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// Milliseconds until `deadline` for poll(), rounded up so that a wait never ends early.
int milliseconds_until(Clock::time_point deadline) {
  const auto left = deadline - Clock::now();
  if (left <= Clock::duration::zero()) return 0;
  const auto milliseconds = std::chrono::ceil<std::chrono::milliseconds>(left).count();
  return static_cast<int>(std::min<decltype(milliseconds)>(milliseconds, 1 << 30));
}

enum class Transfer { complete, closed, timed_out };
enum class Wait { ready, child_ended, timed_out };

// Waits until `fd` is ready for `events`, the child has ended (`child_fd`, a pidfd, is readable;
// -1 is not watched) or the deadline passes. POLLHUP/POLLERR count as ready: the following read
// or write then reports the closed peer. The child's end is watched besides the socket because
// a process the plugin forked keeps the socket open after the plugin itself has died. Data the
// child sent before it ended is already in the socket, so the socket is looked at first.
Wait wait_ready(int fd, short events, int child_fd, Clock::time_point deadline) {
  for (;;) {
    pollfd entries[2] = {{fd, events, 0}, {child_fd, POLLIN, 0}};
    const int ready = poll(entries, 2, milliseconds_until(deadline));
    if (ready > 0) return entries[0].revents != 0 ? Wait::ready : Wait::child_ended;
    if (ready == 0) {
      if (Clock::now() >= deadline) return Wait::timed_out;
      continue;
    }
    if (errno != EINTR) return Wait::ready;  // let the read or write report the error
  }
}

Transfer send_all(int fd, int child_fd, const void* data, size_t size, Clock::time_point deadline) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const Wait wait = wait_ready(fd, POLLOUT, child_fd, deadline);
    if (wait == Wait::timed_out) return Transfer::timed_out;
    if (wait == Wait::child_ended) return Transfer::closed;
    const ssize_t sent = send(fd, bytes, size, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (sent < 0) {
      if (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK) continue;
      return Transfer::closed;  // EPIPE, ECONNRESET: the child has gone
    }
    bytes += sent;
    size -= static_cast<size_t>(sent);
  }
  return Transfer::complete;
}

Transfer receive_all(int fd, int child_fd, void* data, size_t size, Clock::time_point deadline) {
  auto* bytes = static_cast<char*>(data);
  while (size > 0) {
    const Wait wait = wait_ready(fd, POLLIN, child_fd, deadline);
    if (wait == Wait::timed_out) return Transfer::timed_out;
    if (wait == Wait::child_ended) return Transfer::closed;
    const ssize_t received = recv(fd, bytes, size, MSG_DONTWAIT);
    if (received < 0) {
      if (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK) continue;
      return Transfer::closed;
    }
    if (received == 0) return Transfer::closed;
    bytes += received;
    size -= static_cast<size_t>(received);
  }
  return Transfer::complete;
}

// "SIGSEGV"; "signal 40" for one glibc has no abbreviation for (real-time signals).
std::string signal_name(int number) {
  const char* abbreviation = sigabbrev_np(number);
  if (abbreviation == nullptr) return "signal " + std::to_string(number);
  return std::string("SIG") + abbreviation;
}

// "2", "0.3": seconds as people write them.
std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

// --- The child. Everything below runs after fork() in the child only. ---

[[noreturn]] void leave_child(int code) {
  // Only these two streams: they were flushed and unlocked at fork, unlike any other FILE.
  std::fflush(stdout);
  std::fflush(stderr);
  _exit(code);
}

void send_or_leave(int fd, const void* data, size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t sent = send(fd, bytes, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) leave_child(0);  // the parent has gone
    bytes += sent;
    size -= static_cast<size_t>(sent);
  }
}

// False on end of file (the parent closed its end or died).
bool receive_in_child(int fd, void* data, size_t size) {
  auto* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t received = recv(fd, bytes, size, 0);
    if (received < 0 && errno == EINTR) continue;
    if (received <= 0) return false;
    bytes += received;
    size -= static_cast<size_t>(received);
  }
  return true;
}

void copy_text(char* target, size_t capacity, const char* text) {
  size_t length = 0;
  if (text != nullptr) {
    while (length + 1 < capacity && text[length] != '\0') {
      target[length] = text[length];
      ++length;
    }
  }
  target[length] = '\0';
}

// The parent's signal handlers and mask are not the plugin's business: a handler written for
// scenfuzz must not run in the child. Closing inherited descriptors matters for the other
// evaluations: a child that kept another child's socket end would hide that child's death.
void isolate_child(int socket_fd, pid_t parent) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(0);  // the parent died before the line above took effect
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  for (int number = 1; number < NSIG; ++number) sigaction(number, &default_action, nullptr);
  sigset_t nothing;
  sigemptyset(&nothing);
  sigprocmask(SIG_SETMASK, &nothing, nullptr);
  // A fuzzing run would otherwise leave a core file per crashing evaluation.
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  if (socket_fd > 3) close_range(3, static_cast<unsigned>(socket_fd) - 1, 0);
  close_range(static_cast<unsigned>(socket_fd) + 1, ~0U, 0);
}

[[noreturn]] void run_child(int socket_fd, pid_t parent, const char* library,
                            const scenfuzz_ego_config& config) {
  // Before any plugin code runs, so that every process it forks joins the group the parent
  // kills at the end (the parent sets it too, whichever of the two runs first).
  setpgid(0, 0);
  isolate_child(socket_fd, parent);

  StartReply start{};
  void* handle = dlopen(library, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    start.status = StartStatus::cannot_load;
    copy_text(start.detail, sizeof start.detail, dlerror());
    send_or_leave(socket_fd, &start, sizeof start);
    leave_child(1);
  }
  void* symbols[3] = {};
  const char* const names[3] = {"scenfuzz_ego_create", "scenfuzz_ego_step", "scenfuzz_ego_destroy"};
  for (int index = 0; index < 3; ++index) {
    symbols[index] = dlsym(handle, names[index]);
    if (symbols[index] == nullptr) {
      start.status = StartStatus::lacks_symbol;
      copy_text(start.detail, sizeof start.detail, names[index]);
      send_or_leave(socket_fd, &start, sizeof start);
      leave_child(1);
    }
  }
  const auto create = reinterpret_cast<CreateFunction>(symbols[0]);
  const auto step = reinterpret_cast<StepFunction>(symbols[1]);
  const auto destroy = reinterpret_cast<DestroyFunction>(symbols[2]);

  scenfuzz_ego_config agreed = config;
  agreed.abi_version = agreed_version(handle);
  void* driver = create(&agreed);
  if (driver == nullptr) {
    start.status = StartStatus::create_failed;
    send_or_leave(socket_fd, &start, sizeof start);
    leave_child(1);
  }
  start.status = StartStatus::ready;
  send_or_leave(socket_fd, &start, sizeof start);

  // Static: 6 kB is more than a plugin should find missing from its stack. End of file is
  // the parent's request to stop.
  static scenfuzz_observation observation;
  while (receive_in_child(socket_fd, &observation, sizeof observation)) {
    StepReply reply{};
    reply.status = step(driver, &observation, &reply.control);
    std::fflush(stdout);  // the plugin's prints show now, not at its end or never on a crash
    std::fflush(stderr);
    send_or_leave(socket_fd, &reply, sizeof reply);
  }
  destroy(driver);
  leave_child(0);
}

// --- The parent. ---

// A bare name is looked up by dlopen on the library path, not in the current folder; users who
// write `--ego-plugin libmine.so` mean the file beside them.
std::string library_to_open(const std::string& library) {
  if (library.find('/') == std::string::npos && access(library.c_str(), F_OK) == 0) {
    return "./" + library;
  }
  return library;
}

}  // namespace

PluginDriver::PluginDriver(const PluginOptions& options, const scenfuzz_ego_config& config)
    : library_(options.library), step_timeout_(options.step_timeout) {
  if (options.library.empty()) throw std::invalid_argument("ego plugin: no library given");
  if (!(options.step_timeout > 0) || !(options.start_timeout > 0)) {
    throw std::invalid_argument("ego plugin: the step and start timeouts must be positive");
  }
  // The start limit counts from the call: starting the process is part of starting the plugin.
  const auto deadline = deadline_after(options.start_timeout);
  scenfuzz_ego_config child_config = config;
  child_config.abi_version = SCENFUZZ_EGO_ABI_VERSION;
  const std::string path = library_to_open(options.library);

  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    throw EgoPluginError(
        EgoFailureKind::error,
        "ego plugin '" + library_ + "': cannot create a socket: " + std::strerror(errno), 0);
  }
  const pid_t parent = getpid();
  flockfile(stdout);
  flockfile(stderr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  const int fork_error = errno;
  funlockfile(stderr);
  funlockfile(stdout);
  if (child == 0) {
    close(ends[0]);
    run_child(ends[1], parent, path.c_str(), child_config);
  }
  close(ends[1]);
  if (child < 0) {
    close(ends[0]);
    throw EgoPluginError(
        EgoFailureKind::error,
        "ego plugin '" + library_ + "': cannot start a process: " + std::strerror(fork_error), 0);
  }
  setpgid(child, child);  // as the child does: whichever runs first, the group exists at once
  child_ = child;
  socket_ = ends[0];
  // The system call, not glibc's wrapper, whose header lacks extern "C" in glibc 2.36. -1 before
  // Linux 5.3: a death is then seen by the socket alone.
  child_fd_ = static_cast<int>(syscall(SYS_pidfd_open, child, 0));

  StartReply start{};
  const Transfer received = receive_all(socket_, child_fd_, &start, sizeof start, deadline);
  if (received == Transfer::timed_out) {
    end_group();
    close_descriptors();
    throw EgoPluginError(EgoFailureKind::hang,
                         "ego plugin '" + library_ + "' did not start within " +
                             seconds_text(options.start_timeout) + " s (killed)",
                         0);
  }
  if (received == Transfer::closed) {
    const EgoPluginError error = describe_death("while starting");
    close_descriptors();
    throw error;
  }
  start.detail[sizeof start.detail - 1] = '\0';
  std::string problem;
  switch (start.status) {
    case StartStatus::ready: return;
    case StartStatus::cannot_load:
      problem = "cannot load ego plugin '" + library_ + "': " + start.detail;
      break;
    case StartStatus::lacks_symbol:
      problem = "ego plugin '" + library_ + "' lacks symbol " + start.detail;
      break;
    case StartStatus::create_failed:
      problem = "ego plugin '" + library_ + "': scenfuzz_ego_create returned NULL";
      break;
  }
  if (problem.empty()) problem = "ego plugin '" + library_ + "' sent a malformed start reply";
  shut_down();
  throw EgoPluginError(EgoFailureKind::error, problem, 0);
}

PluginDriver::~PluginDriver() { shut_down(); }

PluginDriver::PluginDriver(PluginDriver&& other) noexcept
    : library_(std::move(other.library_)),
      step_timeout_(other.step_timeout_),
      child_(std::exchange(other.child_, -1)),
      socket_(std::exchange(other.socket_, -1)),
      child_fd_(std::exchange(other.child_fd_, -1)),
      steps_(other.steps_),
      failure_(std::move(other.failure_)) {}

PluginDriver& PluginDriver::operator=(PluginDriver&& other) noexcept {
  if (this != &other) {
    shut_down();
    library_ = std::move(other.library_);
    step_timeout_ = other.step_timeout_;
    child_ = std::exchange(other.child_, -1);
    socket_ = std::exchange(other.socket_, -1);
    child_fd_ = std::exchange(other.child_fd_, -1);
    steps_ = other.steps_;
    failure_ = std::move(other.failure_);
  }
  return *this;
}

scenfuzz_control PluginDriver::step(const scenfuzz_observation& observation) {
  if (failure_) throw *failure_;
  // Not an assert: a stray waitpid(-1) would reap some other part of scenfuzz's children.
  if (child_ <= 0) throw std::logic_error("PluginDriver::step on a moved-from driver");
  SCENFUZZ_DEMAND(observation.object_count <= SCENFUZZ_MAX_OBJECTS);
  SCENFUZZ_DEMAND(observation.route_point_count <= SCENFUZZ_ROUTE_POINTS);
  const auto deadline = deadline_after(step_timeout_);
  ++steps_;
  const std::string when =
      "at step " + std::to_string(steps_) + " (t = " + seconds_text(observation.ego.time) + " s)";

  Transfer transfer = send_all(socket_, child_fd_, &observation, sizeof observation, deadline);
  StepReply reply{};
  if (transfer == Transfer::complete) {
    transfer = receive_all(socket_, child_fd_, &reply, sizeof reply, deadline);
  }
  if (transfer == Transfer::timed_out) {
    end_group();
    close_descriptors();
    fail({EgoFailureKind::hang,
          "ego plugin '" + library_ + "' did not answer within " + seconds_text(step_timeout_) +
              " s " + when + " (killed)",
          steps_});
  }
  if (transfer == Transfer::closed) {
    const EgoPluginError error = describe_death(when);
    close_descriptors();
    fail(error);
  }
  if (reply.status != 0) {
    fail({EgoFailureKind::error,
          "ego plugin '" + library_ + "' returned error " + std::to_string(reply.status) + " " +
              when,
          steps_});
  }
  if (!std::isfinite(reply.control.acceleration) || !std::isfinite(reply.control.steering_angle)) {
    fail({EgoFailureKind::error,
          "ego plugin '" + library_ + "' returned a non-finite control (acceleration " +
              seconds_text(reply.control.acceleration) + ", steering angle " +
              seconds_text(reply.control.steering_angle) + ") " + when,
          steps_});
  }
  return reply.control;
}

void PluginDriver::fail(const EgoPluginError& error) {
  failure_ = error;
  throw error;
}

EgoPluginError PluginDriver::describe_death(const std::string& when) {
  // The socket closes a moment before the process is gone; a child that closed it and lives
  // on is killed after step_timeout (and reported as killed).
  await_exit(step_timeout_);
  const int status = end_group();
  std::string how;
  std::string signal;
  if (WIFSIGNALED(status)) {
    signal = signal_name(WTERMSIG(status));
    how = "crashed (" + signal + ")";
  } else if (WIFEXITED(status)) {
    how = "exited with status " + std::to_string(WEXITSTATUS(status));
  } else {
    how = "stopped answering";
  }
  return {EgoFailureKind::crash, "ego plugin '" + library_ + "' " + how + " " + when, steps_,
          signal};
}

bool PluginDriver::await_exit(double seconds) const {
  if (child_ <= 0) return true;
  const auto deadline = deadline_after(seconds);
  if (child_fd_ >= 0) {
    for (;;) {
      pollfd entry{child_fd_, POLLIN, 0};
      const int ready = poll(&entry, 1, milliseconds_until(deadline));
      if (ready > 0) return true;
      if (ready == 0 && Clock::now() >= deadline) return false;
      if (ready < 0 && errno != EINTR) break;  // fall back to asking waitid
    }
  }
  for (;;) {
    siginfo_t info{};
    // WNOWAIT: the child stays unreaped, so its process group id cannot be reused before
    // end_group has killed the group.
    if (waitid(P_PID, static_cast<id_t>(child_), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
      if (errno == EINTR) continue;
      return true;  // not our child: nothing to wait for
    }
    if (info.si_pid == child_) return true;
    if (Clock::now() >= deadline) return false;
    const timespec pause{0, 1'000'000};
    nanosleep(&pause, nullptr);
  }
}

int PluginDriver::end_group() noexcept {
  if (child_ <= 0) return 0;
  // The child is not reaped yet, so the group's id is still its own. Killing the child by its
  // id too covers a group that setpgid could not make.
  kill(-child_, SIGKILL);
  kill(child_, SIGKILL);
  int status = 0;
  while (waitpid(child_, &status, 0) < 0 && errno == EINTR) {
  }
  child_ = -1;
  return status;
}

void PluginDriver::shut_down() noexcept {
  if (child_ > 0) {
    // End of file tells the child to call destroy and exit. Its exit is what is waited for,
    // not the socket's end of file: a process the plugin forked may hold the socket open.
    shutdown(socket_, SHUT_WR);
    await_exit(step_timeout_);
    end_group();
  }
  close_descriptors();
}

void PluginDriver::close_descriptors() noexcept {
  if (socket_ >= 0) {
    close(socket_);
    socket_ = -1;
  }
  if (child_fd_ >= 0) {
    close(child_fd_);
    child_fd_ = -1;
  }
}

}  // namespace scenfuzz
