#include "evolve/results_folder.h"

#include <stdexcept>

namespace walkers {

StartedFolder StartResultsFolder(const std::string& dir, const std::string& what, StartMode mode,
                                 const std::string& first_checkpoint, const std::function<FolderContents()>& contents,
                                 const std::function<std::vector<FolderLock>(const FolderContents&)>& lock_before_set_aside) {
  OpenedFolder opened = OpenResultsFolder(dir, what, mode == StartMode::kResume, first_checkpoint);
  StartedFolder started{std::move(opened.lock), nullptr};
  const FolderContents held = contents();
  switch (mode) {
    case StartMode::kResume:
      if (opened.stopped_force) throw StoppedForceError(dir, what);
      break;
    case StartMode::kNew:
      if (opened.stopped_force || held.any) {
        const std::string found = opened.stopped_force ? " (" + SetAside::FolderIn(dir) + ")" : held.found;
        throw std::runtime_error(dir + ": holds a " + what + " already" + found +
                                 "; pass --resume to continue it or --force to replace it");
      }
      break;
    case StartMode::kForce: {
      // nothing may be moved while another process writes it
      const std::vector<FolderLock> locks = lock_before_set_aside ? lock_before_set_aside(held) : std::vector<FolderLock>{};
      started.replaced = std::make_unique<SetAside>(dir, held.names);
      break;
    }
  }
  return started;
}

}  // namespace walkers
