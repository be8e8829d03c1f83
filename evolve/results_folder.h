// A folder of results (a run, a reproduction) started anew, resumed or
// replaced: the one place that decides what each start mode does with what
// the folder already holds.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "evolve/files.h"

namespace walkers {

enum class StartMode {
  kNew,     // refuse a directory that holds results
  kResume,  // continue them (their configuration must match)
  kForce,   // replace them (nothing else in the directory): the old ones are
            // set aside until the new results' first checkpoint
};

// What a folder holds, for StartResultsFolder.
struct FolderContents {
  // the names in DIR that make up the results (files or folders, present or not)
  std::vector<std::string> names;
  // what kNew's refusal says after "holds a <what> already": "" or " (PATH)"
  std::string found;
  bool any = false;  // whether one of them exists
};

struct StartedFolder {
  FolderLock lock;
  std::unique_ptr<SetAside> replaced;  // under kForce, until the first checkpoint
};

// Opens DIR for writing `what` ("run", "reproduction") under `mode`
// (OpenResultsFolder: DIR's lock is taken before anything in it is looked
// at), then: kNew refuses a folder that holds results, or the old ones a
// stopped --force set aside; kResume refuses a folder whose --force was
// stopped (StoppedForceError); kForce sets the results aside, holding the
// locks `lock_before_set_aside` returns (of folders that will be moved) while
// it moves them. `contents` is called with the
// lock held. Throws std::runtime_error naming DIR.
StartedFolder StartResultsFolder(const std::string& dir, const std::string& what, StartMode mode,
                                 const std::string& first_checkpoint,
                                 const std::function<FolderContents()>& contents,
                                 const std::function<std::vector<FolderLock>(const FolderContents&)>& lock_before_set_aside = nullptr);

}  // namespace walkers
