// Files that survive a process killed at any moment: atomic replacement
// (a reader sees the old file or the new one, never a mix, even after SIGKILL
// or power loss), and appends that reach the disk before a checkpoint names
// them. Every result file the project writes goes through here.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

namespace walkers {

// The temporary file beside `path` that this process writes before renaming
// it into place: PATH.tmp.PID (two processes never share one).
std::string TemporaryPathFor(const std::string& path);

// Replaces `path` by `content` atomically. Throws std::runtime_error naming
// the file on failure.
void WriteFileAtomically(const std::string& path, const std::string& content);

// A file written in full before it replaces `path`: the text goes to
// TemporaryPathFor(path), which Commit() syncs and renames into place.
// Destroyed uncommitted, the writer removes its temporary file and leaves
// `path` as it was.
class AtomicFileWriter {
 public:
  // Throws std::runtime_error naming `path` if the temporary file cannot be
  // created; `what` names the file's kind in messages ("the trajectory file").
  explicit AtomicFileWriter(const std::string& path, const std::string& what = "the file");
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  std::ostream& stream() { return out_; }
  // Throws std::runtime_error naming `path` if writing failed.
  void Commit();

 private:
  std::string path_, what_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// Appends `content` to `path` (created if missing) and waits until it is on
// disk. Returns the file's size afterwards.
std::uint64_t AppendDurably(const std::string& path, const std::string& content);

// Cuts `path` back to `size` bytes (what a checkpoint recorded).
void TruncateFile(const std::string& path, std::uint64_t size);

std::uint64_t FileSize(const std::string& path);

// Removes the temporary files (TemporaryPathFor) that killed writers left in
// DIR. Only for a folder whose lock this process holds (files/results_folder.h).
void RemoveStaleTemporaries(const std::string& dir);

// Waits until DIR's entries (files renamed or moved into it) are on disk; best
// effort, since the renames themselves are atomic.
void SyncDirectory(const std::string& dir);

// Throws std::runtime_error "PATH: WHAT failed (errno's text)".
[[noreturn]] void FailWithErrno(const std::string& what, const std::string& path);

}  // namespace walkers
