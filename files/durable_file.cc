#include "files/durable_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace walkers {
namespace fs = std::filesystem;
namespace {

void WriteAll(int fd, const std::string& content, const std::string& path) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      FailWithErrno("writing", path);
    }
    written += static_cast<std::size_t>(n);
  }
}

void SyncDirectoryOf(const std::string& path) { SyncDirectory(fs::path(path).parent_path().string()); }

// Syncs the finished temporary file and renames it into place; removes it on failure.
void CommitTemporary(int fd, const std::string& temporary, const std::string& path) {
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    errno = error;
    FailWithErrno("syncing", temporary);
  }
  ::close(fd);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    errno = error;
    FailWithErrno("renaming to " + path, temporary);
  }
  SyncDirectoryOf(path);
}

// "NAME.tmp.PID": the pid, or 0 if the name is not a temporary file's
long TemporaryOwner(const std::string& name) {
  const std::size_t at = name.rfind(".tmp.");
  if (at == std::string::npos || at + 5 == name.size()) return 0;
  long pid = 0;
  const char* first = name.data() + at + 5;
  const char* last = name.data() + name.size();
  const auto [end, error] = std::from_chars(first, last, pid);
  return error == std::errc() && end == last ? pid : 0;
}

}  // namespace

void FailWithErrno(const std::string& what, const std::string& path) {
  throw std::runtime_error(path + ": " + what + " failed (" + std::strerror(errno) + ")");
}

void SyncDirectory(const std::string& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // best effort: the renames themselves are atomic
  ::fsync(fd);
  ::close(fd);
}

std::string TemporaryPathFor(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::string tmp = TemporaryPathFor(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) FailWithErrno("creating", tmp);
  try {
    WriteAll(fd, content, tmp);
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  CommitTemporary(fd, tmp, path);
}

AtomicFileWriter::AtomicFileWriter(const std::string& path, const std::string& what)
    : path_(path),
      what_(what),
      temporary_(TemporaryPathFor(path)),
      out_(temporary_, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error(path_ + ": cannot write " + what_ + " (" + std::strerror(errno) + ")");
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  ::unlink(temporary_.c_str());
}

void AtomicFileWriter::Commit() {
  out_.close();
  if (!out_) {
    ::unlink(temporary_.c_str());
    committed_ = true;  // nothing left to remove
    throw std::runtime_error(path_ + ": writing " + what_ + " failed (" + std::strerror(errno) + ")");
  }
  committed_ = true;
  const int fd = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    ::unlink(temporary_.c_str());
    FailWithErrno("reopening", temporary_);
  }
  CommitTemporary(fd, temporary_, path_);
}

std::uint64_t AppendDurably(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) FailWithErrno("opening", path);
  WriteAll(fd, content, path);
  if (::fsync(fd) != 0) FailWithErrno("syncing", path);
  struct stat st {};
  if (::fstat(fd, &st) != 0) FailWithErrno("reading the size of", path);
  ::close(fd);
  return static_cast<std::uint64_t>(st.st_size);
}

void TruncateFile(const std::string& path, std::uint64_t size) {
  if (::truncate(path.c_str(), static_cast<off_t>(size)) != 0) FailWithErrno("truncating", path);
}

std::uint64_t FileSize(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) FailWithErrno("reading the size of", path);
  return static_cast<std::uint64_t>(st.st_size);
}

void RemoveStaleTemporaries(const std::string& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const long owner = TemporaryOwner(entry.path().filename().string());
    if (owner != 0 && owner != ::getpid() && entry.is_regular_file()) {
      std::error_code ec;
      fs::remove(entry.path(), ec);
    }
  }
}

}  // namespace walkers
