// The git commit this program was built from, as results record it: 12 hex
// digits, with "-dirty" when the tree had uncommitted changes, or "unknown"
// when it was not built from a git checkout (cmake/source_commit.cmake).
#pragma once

namespace walkers {

const char* SourceCommit();

}  // namespace walkers
