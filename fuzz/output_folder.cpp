#include "fuzz/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string_view>

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kSearchFiles[] = {"evaluations.csv", "summary.json", "search.json"};

std::string lock_holder(const fs::path& lock_path) {
  std::ifstream in(lock_path);
  std::string pid;
  std::getline(in, pid);
  return pid.empty() ? "another process" : "process " + pid;
}

bool is_temporary(const fs::path& path) {
  return path.filename().string().find(".tmp.") != std::string::npos;
}

}  // namespace

OutputFolderLock::~OutputFolderLock() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

OutputFolderLock::OutputFolderLock(OutputFolderLock&& other) noexcept
    : descriptor_(other.descriptor_) {
  other.descriptor_ = -1;
}

OutputFolderLock& OutputFolderLock::operator=(OutputFolderLock&& other) noexcept {
  if (this != &other) {
    if (descriptor_ >= 0) ::close(descriptor_);
    descriptor_ = other.descriptor_;
    other.descriptor_ = -1;
  }
  return *this;
}

std::string OutputFolderLock::acquire(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) return "cannot create '" + dir.string() + "': " + error.message();
  const fs::path lock_path = dir / ".lock";
  const int descriptor = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (descriptor < 0) return "cannot write '" + lock_path.string() + "': " + std::strerror(errno);
  if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
    const int reason = errno;
    ::close(descriptor);
    if (reason != EWOULDBLOCK)
      return "cannot lock '" + lock_path.string() + "': " + std::strerror(reason);
    return "'" + dir.string() + "' is in use by another search (" + lock_holder(lock_path) +
           "); wait for it to end, or write into another folder with --out DIR";
  }
  // The pid is for the message above only; the lock itself is the flock.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(descriptor, 0) != 0 || ::write(descriptor, pid.data(), pid.size()) < 0) {
    // Not fatal: the lock holds; another search's message just cannot name us.
  }
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = descriptor;
  return {};
}

bool holds_search(const fs::path& dir) {
  std::error_code error;
  for (std::string_view name : kSearchFiles)
    if (fs::exists(dir / name, error)) return true;
  return fs::is_directory(dir / "findings", error) &&
         fs::directory_iterator(dir / "findings", error) != fs::directory_iterator();
}

std::string remove_search(const fs::path& dir) {
  std::error_code error;
  fs::remove_all(dir / "findings", error);
  if (error) return "cannot remove '" + (dir / "findings").string() + "': " + error.message();
  for (std::string_view name : kSearchFiles) {
    fs::remove(dir / name, error);
    if (error) return "cannot remove '" + (dir / name).string() + "': " + error.message();
  }
  return {};
}

void remove_temporary_files(const fs::path& dir) {
  for (const fs::path& folder : {dir, dir / "findings"}) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) continue;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
      if (entry.is_regular_file(error) && is_temporary(entry.path()))
        fs::remove(entry.path(), error);
  }
}

}  // namespace scenfuzz
