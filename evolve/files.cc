#include "evolve/files.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace walkers {
namespace fs = std::filesystem;
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

void SyncDirectory(const std::string& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // best effort: the renames themselves are atomic
  ::fsync(fd);
  ::close(fd);
}

void SyncDirectoryOf(const std::string& path) { SyncDirectory(fs::path(path).parent_path().string()); }

// Syncs the finished temporary file and renames it into place; removes it on failure.
void CommitTemporary(int fd, const std::string& temporary, const std::string& path) {
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    ::unlink(temporary.c_str());
    errno = error;
    Fail("syncing", temporary);
  }
  ::close(fd);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    errno = error;
    Fail("renaming to " + path, temporary);
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

void RemoveNames(const std::string& dir, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    std::error_code ec;
    fs::remove_all(fs::path(dir) / name, ec);
    if (ec) throw std::runtime_error((fs::path(dir) / name).string() + ": removing it failed (" + ec.message() + ")");
  }
}

void Rename(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) throw std::runtime_error(from.string() + ": moving it to " + to.string() + " failed (" + ec.message() + ")");
}

// DIR/replaced.partial: a set-aside or a restore under way
fs::path PartialFolderIn(const std::string& dir) { return fs::path(SetAside::FolderIn(dir) + ".partial"); }

// Moves everything in `from` back into `dir` and removes `from`.
void MoveBack(const fs::path& from, const std::string& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(from)) {
    const fs::path to = fs::path(dir) / entry.path().filename();
    if (fs::exists(fs::symlink_status(to))) {
      throw std::runtime_error(entry.path().string() + ": cannot move it back, " + to.string() +
                               " exists; move one of them away by hand");
    }
    Rename(entry.path(), to);
  }
  fs::remove(from);
  SyncDirectory(dir);
}

}  // namespace

std::string TemporaryPathFor(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::string tmp = TemporaryPathFor(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) Fail("creating", tmp);
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
    Fail("reopening", temporary_);
  }
  CommitTemporary(fd, temporary_, path_);
}

std::uint64_t AppendDurably(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
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

FolderLock::FolderLock(const std::string& dir, const std::string& what) {
  const std::string path = (fs::path(dir) / kLockFileName).string();
  // close-on-exec: a child (the figure script) must not inherit the lock
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) Fail("creating the lock file", path);
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    char pid[32] = {};
    const ssize_t n = ::pread(fd_, pid, sizeof(pid) - 1, 0);
    std::string holder = n > 0 ? std::string(pid, static_cast<std::size_t>(n)) : "";
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw std::runtime_error(dir + ": another walkers process" + (holder.empty() ? "" : " (pid " + holder + ")") +
                               " is writing this " + what + "; only one may at a time: wait for it to end or stop it");
    }
    errno = error;
    Fail("locking", path);
  }
  // who holds it, for the message of a process refused
  const std::string mine = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, mine.data(), mine.size(), 0);
  }
}

FolderLock::FolderLock(FolderLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the lock
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

std::string SetAside::FolderIn(const std::string& dir) { return (fs::path(dir) / kFolder).string(); }

void SetAside::Recover(const std::string& dir) {
  const fs::path partial = PartialFolderIn(dir);
  if (fs::exists(partial)) MoveBack(partial, dir);
}

SetAside::SetAside(const std::string& dir, std::vector<std::string> names) : dir_(dir), names_(std::move(names)) {
  const fs::path aside = FolderIn(dir_);
  if (fs::exists(aside)) {
    RemoveNames(dir_, names_);
    return;
  }
  bool any = false;
  for (const std::string& name : names_) any = any || fs::exists(fs::symlink_status(fs::path(dir_) / name));
  if (!any) {
    pending_ = false;  // nothing to keep
    return;
  }
  // into replaced.partial/ first, then renamed at once: a process stopped
  // half-way leaves replaced.partial/, which Recover() moves back
  const fs::path partial = PartialFolderIn(dir_);
  std::error_code ec;
  fs::create_directory(partial, ec);
  if (ec) throw std::runtime_error(partial.string() + ": cannot create it (" + ec.message() + ")");
  try {
    for (const std::string& name : names_) {
      const fs::path from = fs::path(dir_) / name;
      if (fs::exists(fs::symlink_status(from))) Rename(from, partial / name);
    }
    SyncDirectory(partial.string());
    Rename(partial, aside);
  } catch (...) {
    pending_ = false;
    MoveBack(partial, dir_);
    throw;
  }
  SyncDirectory(dir_);
}

SetAside::~SetAside() {
  if (!pending_) return;
  try {
    Restore();
  } catch (...) {
    // left as it is: the next start finds replaced/ and says what to do
  }
}

void SetAside::Discard() {
  pending_ = false;
  std::error_code ec;
  fs::remove_all(FolderIn(dir_), ec);
  SyncDirectory(dir_);
}

void SetAside::Restore() {
  pending_ = false;
  RemoveNames(dir_, names_);
  const fs::path partial = PartialFolderIn(dir_);
  Rename(FolderIn(dir_), partial);
  MoveBack(partial, dir_);
}

OpenedFolder OpenResultsFolder(const std::string& dir, const std::string& what, bool resume,
                               const std::string& first_checkpoint) {
  if (resume) {
    if (!fs::is_directory(dir)) throw std::runtime_error(dir + ": no " + what + " to resume (no such directory)");
  } else {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
      throw std::runtime_error(dir + ": cannot create the " + what + " directory (" + ec.message() + ")");
    }
  }
  OpenedFolder opened{FolderLock(dir, what)};
  SetAside::Recover(dir);
  RemoveStaleTemporaries(dir);
  const std::string aside = SetAside::FolderIn(dir);
  opened.stopped_force = fs::exists(aside);
  if (opened.stopped_force && fs::exists(first_checkpoint)) {
    // the --force that set it aside reached its first checkpoint: it can go
    std::error_code ec;
    fs::remove_all(aside, ec);
    opened.stopped_force = false;
  }
  return opened;
}

std::runtime_error StoppedForceError(const std::string& dir, const std::string& what) {
  const std::string aside = SetAside::FolderIn(dir);
  return std::runtime_error(dir + ": a --force was stopped before the new " + what + " completed a generation; the " +
                            what + " it replaces is in " + aside + ". Pass --force to start the new " + what +
                            " again, or move what " + aside + " holds back to keep the old " + what);
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      field += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(field);
  return out;
}

CsvReader::CsvReader(std::string text, std::string path) : text_(std::move(text)), path_(std::move(path)) {
  const std::size_t end = text_.find('\n');
  if (text_.empty() || end == 0) throw std::runtime_error(path_ + ": no header line");
  header_ = SplitCsvLine(text_.substr(0, end));
  at_ = end == std::string::npos ? text_.size() : end + 1;
}

int CsvReader::Column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return static_cast<int>(i);
  }
  throw std::runtime_error(path_ + ": no column '" + name + "'");
}

bool CsvReader::Next() {
  while (at_ < text_.size()) {
    std::size_t end = text_.find('\n', at_);
    if (end == std::string::npos) end = text_.size();
    const std::string line = text_.substr(at_, end - at_);
    at_ = end + 1;
    ++row_;
    if (line.empty()) continue;
    fields_ = SplitCsvLine(line);
    if (fields_.size() != header_.size()) {
      throw std::runtime_error(path_ + ": row " + std::to_string(row_) + " has " + std::to_string(fields_.size()) +
                               " fields, the header " + std::to_string(header_.size()));
    }
    return true;
  }
  return false;
}

void CsvReader::Fail(int column, const std::string& problem) const {
  throw std::runtime_error(path_ + ": row " + std::to_string(row_) + ", column '" + header_[column] + "': '" +
                           fields_[column] + "' " + problem);
}

double CsvReader::Number(int column) const {
  const std::string& text = fields_[column];
  double x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) {
    Fail(column, "is not a finite number");
  }
  return x;
}

std::int64_t CsvReader::Integer(int column, std::int64_t lo, std::int64_t hi) const {
  const std::string& text = fields_[column];
  std::int64_t x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) Fail(column, "is not an integer");
  if (x < lo || x > hi) {
    Fail(column, "is outside its allowed range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return x;
}

}  // namespace walkers
