#include "evolve/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace walkers {
namespace {

[[noreturn]] void Fail(const std::string& what, const std::string& path) {
  throw std::runtime_error(path + ": " + what + " failed (" + std::strerror(errno) + ")");
}

void WriteAll(int fd, const std::string& content, const std::string& path) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail("writing", path);
    }
    written += static_cast<std::size_t>(n);
  }
}

void SyncDirectoryOf(const std::string& path) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // best effort: the rename itself is atomic
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) Fail("creating", tmp);
  WriteAll(fd, content, tmp);
  if (::fsync(fd) != 0) Fail("syncing", tmp);
  ::close(fd);
  if (::rename(tmp.c_str(), path.c_str()) != 0) Fail("renaming to " + path, tmp);
  SyncDirectoryOf(path);
}

std::uint64_t AppendDurably(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) Fail("opening", path);
  WriteAll(fd, content, path);
  if (::fsync(fd) != 0) Fail("syncing", path);
  struct stat st {};
  if (::fstat(fd, &st) != 0) Fail("reading the size of", path);
  ::close(fd);
  return static_cast<std::uint64_t>(st.st_size);
}

void TruncateFile(const std::string& path, std::uint64_t size) {
  if (::truncate(path.c_str(), static_cast<off_t>(size)) != 0) Fail("truncating", path);
}

std::uint64_t FileSize(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) Fail("reading the size of", path);
  return static_cast<std::uint64_t>(st.st_size);
}

}  // namespace walkers
