// Files read and written whole: output written so that a crash or a full disk never leaves a
// half-written file, and input read in one piece.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
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

// The bytes of the file at `path`, or nothing when it cannot be opened or read.
std::optional<std::string> read_whole_file(const std::filesystem::path& path);

// What bringing a generated file up to date found or did.
enum class FileUpdate {
  kUpToDate,  // the file already held the bytes
  kStale,     // it did not (or could not be read), and it was only checked
  kWritten,   // it did not, and now does
};

// Brings the file at `path` up to date with `bytes`, the text a command generates: nothing
// happens when it holds them already; otherwise, with `check_only`, it is reported stale and
// left as it is, else written with write_file_atomically(path, bytes, flush) (which throws
// Error when it cannot write). A file that cannot be read counts as stale.
FileUpdate update_generated_file(const std::filesystem::path& path, std::string_view bytes,
                                 bool check_only, bool flush = true);

}  // namespace raygrade
