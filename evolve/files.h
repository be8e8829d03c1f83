// Durable files for runs that can be killed at any moment: atomic
// replacement, appends that reach the disk before a checkpoint names them,
// and exact number formatting.
#pragma once

#include <cstdint>
#include <string>

#include "control/input_file.h"   // ReadFile
#include "control/number_text.h"  // FormatExact

namespace walkers {

// Replaces `path` by `content` atomically: a reader (or a resumed run) sees
// the old file or the new one, never a mix, even after SIGKILL or power loss.
// Throws std::runtime_error naming the file on failure.
void WriteFileAtomically(const std::string& path, const std::string& content);

// Appends `content` to `path` (created if missing) and waits until it is on
// disk. Returns the file's size afterwards.
std::uint64_t AppendDurably(const std::string& path, const std::string& content);

// Cuts `path` back to `size` bytes (what a checkpoint recorded).
void TruncateFile(const std::string& path, std::uint64_t size);

std::uint64_t FileSize(const std::string& path);

}  // namespace walkers
