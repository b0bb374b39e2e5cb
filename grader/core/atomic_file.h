// Writing output files so that a crash or a full disk never leaves a half-written file.
#pragma once

#include <filesystem>
#include <string_view>

namespace raygrade {

// Writes `bytes` to `path` so that readers see either the old file or the whole new one: the
// bytes go to a temporary file in the same folder, are flushed to disk, and the temporary file
// is then renamed over `path`. The folder must exist. Throws Error (code "unwritable", naming
// `path`) on failure, leaving `path` as it was and no temporary file behind.
// `flush` false leaves out the fsync, for a writer of many files that flushes them all at once
// afterwards (flush_folder); the rename still makes each file appear whole or not at all.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           bool flush = true);

// Flushes the file system holding `folder` to disk once (after writes with flush = false).
void flush_folder(const std::filesystem::path& folder);

}  // namespace raygrade
