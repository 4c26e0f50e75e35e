// write_file_atomically: temporary file, flush, fsync, rename.
#include "fuzz/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace scenfuzz {

namespace {

std::string cannot_write(const std::filesystem::path& path, int error) {
  return "cannot write '" + path.string() + "': " + std::strerror(error);
}

}  // namespace

std::string write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  std::filesystem::path temporary = path;
  temporary += ".tmp." + std::to_string(::getpid());
  int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (descriptor < 0) return cannot_write(path, errno);
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    ssize_t written = ::write(descriptor, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      std::string reason = cannot_write(path, errno);
      ::close(descriptor);
      ::unlink(temporary.c_str());
      return reason;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  bool synced = ::fsync(descriptor) == 0;
  int sync_error = errno;
  bool closed = ::close(descriptor) == 0;
  if (!synced || !closed) {
    std::string reason = cannot_write(path, synced ? errno : sync_error);
    ::unlink(temporary.c_str());
    return reason;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::string reason = cannot_write(path, errno);
    ::unlink(temporary.c_str());
    return reason;
  }
  return {};
}

}  // namespace scenfuzz
