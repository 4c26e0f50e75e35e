// FolderLock: open, flock(LOCK_EX | LOCK_NB), then write who holds it.
#include "fuzz/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <system_error>

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

std::string holder_text() {
  char host[256] = "";
  if (::gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "this host");
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char since[32];
  std::strftime(since, sizeof since, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return "process " + std::to_string(::getpid()) + " on " + host + ", since " + since;
}

std::string read_holder(const fs::path& lock_path) {
  std::ifstream in(lock_path);
  std::string holder;
  std::getline(in, holder);
  return holder.empty() ? "another process" : holder;
}

}  // namespace

FolderLock::~FolderLock() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

FolderLock::FolderLock(FolderLock&& other) noexcept : descriptor_(other.descriptor_) {
  other.descriptor_ = -1;
}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
  if (this != &other) {
    if (descriptor_ >= 0) ::close(descriptor_);
    descriptor_ = other.descriptor_;
    other.descriptor_ = -1;
  }
  return *this;
}

bool FolderLock::acquire(const fs::path& dir, const std::string& file_name,
                         FolderLockRefusal& refusal) {
  refusal = {};
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) {
    refusal.error = "cannot create '" + dir.string() + "': " + error.message();
    return false;
  }
  const fs::path lock_path = dir / file_name;
  const int descriptor = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (descriptor < 0) {
    refusal.error = "cannot write '" + lock_path.string() + "': " + std::strerror(errno);
    return false;
  }
  if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
    const int reason = errno;
    ::close(descriptor);
    refusal.busy = reason == EWOULDBLOCK;
    if (refusal.busy)
      refusal.holder = read_holder(lock_path);
    else
      refusal.error = "cannot lock '" + lock_path.string() + "': " + std::strerror(reason);
    return false;
  }
  // Who holds it is for the refusal above only; the lock itself is the flock.
  const std::string holder = holder_text() + "\n";
  if (::ftruncate(descriptor, 0) != 0 || ::write(descriptor, holder.data(), holder.size()) < 0) {
    // Not fatal: the lock holds; the next claimant's message just cannot name this one.
  }
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = descriptor;
  return true;
}

}  // namespace scenfuzz
