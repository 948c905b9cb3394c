#include "sph/engine/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>

namespace sph {

namespace {

[[noreturn]] void fail(int error, const std::string& what, const std::filesystem::path& path) {
  throw std::system_error(error, std::generic_category(), what + " \"" + path.string() + "\"");
}

// Removes the temporary file and throws with the errno of the step that failed.
[[noreturn]] void discard(const std::filesystem::path& temporary, int error, const std::string& what,
                          const std::filesystem::path& named) {
  ::unlink(temporary.c_str());
  fail(error, what, named);
}

void write_all(int fd, std::string_view content, const std::filesystem::path& temporary) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      discard(temporary, error, "cannot write", temporary);
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

// fsync of the folder makes the rename durable (POSIX: the directory entry lives in the folder).
void sync_folder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail(errno, "cannot open folder", folder);
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: the file system cannot sync folders
  const int error = errno;
  ::close(fd);
  if (!synced) fail(error, "cannot flush folder", folder);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  static std::atomic<unsigned long> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);

  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(errno, "cannot create", temporary);
  write_all(fd, content, temporary);
  const bool synced = ::fsync(fd) == 0;
  int error = errno;
  const bool closed = ::close(fd) == 0;
  if (synced && !closed) error = errno;
  if (!synced || !closed) discard(temporary, error, "cannot flush", temporary);
  if (::rename(temporary.c_str(), path.c_str()) != 0) discard(temporary, errno, "cannot rename temporary file onto", path);
  sync_folder(path.parent_path());
}

}  // namespace sph
