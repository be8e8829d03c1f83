// Durable files for runs that can be killed at any moment: atomic
// replacement, appends that reach the disk before a checkpoint names them,
// one writer per folder, earlier results set aside rather than deleted, and
// a CSV reader whose messages name the file, the row and the column.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "control/input_file.h"   // ReadFile
#include "control/number_text.h"  // FormatExact

namespace walkers {

// The temporary file beside `path` that this process writes before renaming
// it into place: PATH.tmp.PID (two processes never share one).
std::string TemporaryPathFor(const std::string& path);

// Replaces `path` by `content` atomically: a reader (or a resumed run) sees
// the old file or the new one, never a mix, even after SIGKILL or power loss.
// Throws std::runtime_error naming the file on failure.
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

// The file a FolderLock holds in its folder.
constexpr const char* kLockFileName = "walkers.lock";

// One writer per folder: an advisory lock (flock) on DIR/walkers.lock, held
// from construction to destruction. The kernel releases it when the process
// ends, however it ends, so a killed writer never leaves it stale.
class FolderLock {
 public:
  // Throws std::runtime_error naming the folder, and the holder's pid, when
  // another process holds the lock; `what` names the folder's contents ("run").
  FolderLock(const std::string& dir, const std::string& what);
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  FolderLock& operator=(FolderLock&&) = delete;

 private:
  int fd_ = -1;
};

// Removes the temporary files (TemporaryPathFor) that killed writers left in
// DIR. Only for a folder whose lock this process holds.
void RemoveStaleTemporaries(const std::string& dir);

// Earlier results set aside while `--force` replaces them: moved into
// DIR/replaced/ (renames within one file system: nothing copied, nothing
// half-moved), deleted once the new results' first checkpoint is on disk,
// moved back if the new results are abandoned before that.
class SetAside {
 public:
  static constexpr const char* kFolder = "replaced";

  // Moves those of `names` (files or folders in DIR) that exist into
  // DIR/replaced/ (if none exists, there is nothing to keep and nothing is
  // done). If DIR/replaced/ exists already, it holds the results a
  // stopped --force was replacing: they stay set aside, and `names` in DIR,
  // that --force's unfinished start, are deleted. Throws std::runtime_error
  // naming the file that could not be moved (after moving the others back).
  SetAside(const std::string& dir, std::vector<std::string> names);
  // Restore() unless Discard() was called; never throws.
  ~SetAside();
  SetAside(const SetAside&) = delete;
  SetAside& operator=(const SetAside&) = delete;

  // The new results have their first checkpoint: deletes DIR/replaced/.
  void Discard();
  // Deletes `names` in DIR and moves the set-aside ones back.
  void Restore();

  static std::string FolderIn(const std::string& dir);
  // Finishes what a process stopped while moving files in or out of
  // DIR/replaced/ had begun: moves them back into DIR. Call it, holding
  // DIR's lock, before looking at DIR.
  static void Recover(const std::string& dir);

 private:
  std::string dir_;
  std::vector<std::string> names_;
  bool pending_ = true;
};

// A folder of results (a run, a reproduction) opened for writing.
struct OpenedFolder {
  FolderLock lock;
  // DIR/replaced/ holds what a --force, stopped before the new results'
  // first checkpoint, was replacing
  bool stopped_force = false;
};

// Opens DIR for writing `what` ("run", "reproduction"): resuming needs DIR,
// otherwise it is created; then its lock is taken, and only then is anything
// in it looked at: what a process stopped while setting files aside began is
// undone (SetAside::Recover), killed writers' temporary files are removed,
// and DIR/replaced/ is deleted if `first_checkpoint` exists (the --force that
// made it got that far). Throws std::runtime_error naming DIR.
OpenedFolder OpenResultsFolder(const std::string& dir, const std::string& what, bool resume,
                               const std::string& first_checkpoint);

// The error for resuming DIR whose --force was stopped (stopped_force).
std::runtime_error StoppedForceError(const std::string& dir, const std::string& what);

// Reads CSV text (as the run files hold it) row by row. A field in double
// quotes may hold commas; "" inside it is one quote. Empty lines are skipped.
class CsvReader {
 public:
  // Reads the header line; `path` names the file in messages. Throws
  // std::runtime_error for text without a header.
  CsvReader(std::string text, std::string path);

  const std::vector<std::string>& header() const { return header_; }
  // The index of a column; throws naming the file if there is none.
  int Column(const std::string& name) const;
  // Moves to the next row; false at the end. Throws if the row's number of
  // fields differs from the header's.
  bool Next();
  int row() const { return row_; }  // the line number (the header is row 1)
  const std::vector<std::string>& fields() const { return fields_; }
  // A field as a finite number, or an integer in [lo, hi]; throws
  // "PATH: row N, column 'name': 'text' is not a number".
  double Number(int column) const;
  std::int64_t Integer(int column, std::int64_t lo, std::int64_t hi) const;

 private:
  [[noreturn]] void Fail(int column, const std::string& problem) const;

  std::string text_, path_;
  std::size_t at_ = 0;
  int row_ = 1;
  std::vector<std::string> header_, fields_;
};

// The fields of one CSV line.
std::vector<std::string> SplitCsvLine(const std::string& line);

}  // namespace walkers
