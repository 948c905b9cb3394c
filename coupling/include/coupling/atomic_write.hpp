#pragma once
// Atomic file writes: readers see either the old file or the complete new one, never a partial write, and a
// killed process leaves at most a stray "<name>.tmp-<pid>-<n>" file next to the target.
#include <filesystem>
#include <string_view>

namespace coupling {

// Writes `content` to a temporary file in the same directory as `path`, flushes it to disk (fsync) and renames it
// over `path`. The directory must exist. Throws std::system_error on failure (the temporary file is removed).
void atomic_write(const std::filesystem::path& path, std::string_view content);

}  // namespace coupling
