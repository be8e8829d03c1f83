#include "files/results_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <stdexcept>

#include "files/durable_file.h"

namespace walkers {
namespace fs = std::filesystem;
namespace {

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

// DIR, created unless resuming, and its lock
FolderLock LockFolder(const std::string& dir, const std::string& what, bool resume) {
  if (resume) {
    if (!fs::is_directory(dir)) throw std::runtime_error(dir + ": no " + what + " to resume (no such directory)");
  } else {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
      throw std::runtime_error(dir + ": cannot create the " + what + " directory (" + ec.message() + ")");
    }
  }
  return FolderLock(dir, what);
}

}  // namespace

FolderLock::FolderLock(const std::string& dir, const std::string& what) {
  const std::string path = (fs::path(dir) / kLockFileName).string();
  // close-on-exec: a child (the figure script) must not inherit the lock
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) FailWithErrno("creating the lock file", path);
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
    FailWithErrno("locking", path);
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

ResultsFolder::ResultsFolder(const std::string& dir, const std::string& what, StartMode mode,
                             const std::string& first_checkpoint, const std::function<FolderContents()>& contents,
                             const std::function<std::vector<FolderLock>(const FolderContents&)>& lock_before_set_aside)
    : lock_(LockFolder(dir, what, mode == StartMode::kResume)) {
  // with the lock held: what stopped writers left is cleaned up first
  SetAside::Recover(dir);
  RemoveStaleTemporaries(dir);
  const std::string aside = SetAside::FolderIn(dir);
  bool stopped_force = fs::exists(aside);
  if (stopped_force && fs::exists(first_checkpoint)) {
    // the --force that set it aside reached its first checkpoint: it can go
    std::error_code ec;
    fs::remove_all(aside, ec);
    stopped_force = false;
  }
  const FolderContents held = contents();
  switch (mode) {
    case StartMode::kResume:
      if (stopped_force) {
        throw std::runtime_error(dir + ": a --force was stopped before the new " + what +
                                 " completed a generation; the " + what + " it replaces is in " + aside +
                                 ". Pass --force to start the new " + what + " again, or move what " + aside +
                                 " holds back to keep the old " + what);
      }
      break;
    case StartMode::kNew:
      if (stopped_force || held.any) {
        const std::string found = stopped_force ? " (" + aside + ")" : held.found;
        throw std::runtime_error(dir + ": holds a " + what + " already" + found +
                                 "; pass --resume to continue it or --force to replace it");
      }
      break;
    case StartMode::kForce: {
      // nothing may be moved while another process writes it
      const std::vector<FolderLock> locks =
          lock_before_set_aside ? lock_before_set_aside(held) : std::vector<FolderLock>{};
      replaced_ = std::make_unique<SetAside>(dir, held.names);
      break;
    }
  }
}

// replaced_ goes first, while the lock is still held
ResultsFolder::~ResultsFolder() = default;

void ResultsFolder::DiscardReplaced() {
  if (!replaced_) return;
  replaced_->Discard();
  replaced_.reset();
}

}  // namespace walkers
