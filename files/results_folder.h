// Folders of results (a run, a reproduction) that one process writes at a
// time: the folder's lock, earlier results set aside rather than deleted
// while --force replaces them, and ResultsFolder, the one place that decides
// what each start mode (new, resume, force) does with what a folder holds.
//
// DIR/walkers.lock   locked by the one process writing DIR
// DIR/replaced/      while --force replaces DIR's results: the old ones,
//                    until the new results' first checkpoint is on disk
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace walkers {

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

enum class StartMode {
  kNew,     // refuse a directory that holds results
  kResume,  // continue them (their configuration must match)
  kForce,   // replace them (nothing else in the directory): the old ones are
            // set aside until the new results' first checkpoint
};

// What a folder holds, for ResultsFolder.
struct FolderContents {
  // the names in DIR that make up the results (files or folders, present or not)
  std::vector<std::string> names;
  // what kNew's refusal says after "holds a <what> already": "" or " (PATH)"
  std::string found;
  bool any = false;  // whether one of them exists
};

// A folder of results opened for writing, held from construction to
// destruction: its lock, and under kForce the old results set aside until
// DiscardReplaced().
class ResultsFolder {
 public:
  // Opens DIR for writing `what` ("run", "reproduction") under `mode`:
  // resuming needs DIR, otherwise it is created; then DIR's lock is taken,
  // and only then is anything in it looked at. What a process stopped while
  // setting results aside began is undone (SetAside::Recover), killed
  // writers' temporary files are removed, and DIR/replaced/ is deleted if
  // `first_checkpoint` exists (the --force that made it got that far). Then
  // kNew refuses a folder that holds results (`contents`, called with the
  // lock held), or the old ones a stopped --force set aside; kResume refuses
  // a folder whose --force was stopped; kForce sets the results aside,
  // holding the locks `lock_before_set_aside` returns (of folders that will
  // be moved) while it moves them. Throws std::runtime_error naming DIR.
  ResultsFolder(const std::string& dir, const std::string& what, StartMode mode,
                const std::string& first_checkpoint, const std::function<FolderContents()>& contents,
                const std::function<std::vector<FolderLock>(const FolderContents&)>& lock_before_set_aside = nullptr);
  // Under kForce, destroyed before DiscardReplaced(), it puts the old results
  // back (while the lock is still held).
  ~ResultsFolder();
  ResultsFolder(const ResultsFolder&) = delete;
  ResultsFolder& operator=(const ResultsFolder&) = delete;

  // The new results have their first checkpoint on disk: what --force set
  // aside is deleted (nothing is done otherwise, or a second time).
  void DiscardReplaced();

 private:
  FolderLock lock_;
  std::unique_ptr<SetAside> replaced_;  // under kForce, until DiscardReplaced()
};

}  // namespace walkers
