#pragma once
// The one durable file writer of the program: every report, figure, frame, energy history and checkpoint goes
// through it. Readers see either the old file or the complete new one, never a partial write, even when the
// process is killed or the machine loses power during the write; a killed process leaves at most a stray
// "<name>.tmp-<pid>-<n>" file next to the target.
#include <filesystem>
#include <string_view>

namespace sph {

// Writes `content` to a temporary file in the folder of `path`, flushes it to disk (fsync), renames it over
// `path` and flushes the folder (fsync), so that the rename itself survives a crash. The folder must exist.
// Throws std::system_error naming the file on failure (the temporary file is removed).
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace sph
