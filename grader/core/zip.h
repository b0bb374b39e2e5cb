// Zip archives through libzip: written deflated (the Gradescope export, Moodle's feedback zip)
// and read (a learning platform's "download all submissions").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace raygrade {

struct ZipEntry {
  std::string name;   // the path inside the archive, with '/' between folders
  std::string bytes;  // the file's contents
  bool executable = false;
};

// The archive's bytes: each entry deflated with Unix permissions (0755 for executables, else
// 0644) and the fixed time 1980-01-01 00:00, so that the same entries give the same bytes.
// Throws Error when libzip refuses an entry or the archive.
std::string zip_archive(const std::vector<ZipEntry>& entries);

// One file read from an archive.
struct ZipFileRead {
  std::string name;           // its path inside the archive
  std::string bytes;          // empty when `fault` says why it was not read
  std::int64_t modified = 0;  // its modification time, seconds since 1970 (as the zip gives it)
  std::string fault;          // why this file alone was not read (too large, damaged)
};

// How much of an archive is read: a damaged or hostile zip (a "zip bomb") costs at most this.
struct ZipReadLimits {
  std::size_t max_files = 10000;            // a class of a few thousand, several files each
  std::uint64_t max_file_bytes = 1u << 20;  // a submission's own limit (JsonLimits::submission)
  std::uint64_t max_total_bytes = 256u << 20;
};

// The files of the archive at `path` (folders left out), in the archive's order. A file over
// the limits, or one that cannot be decompressed, comes back with its `fault` and no bytes.
// Throws Error naming `path` when it is no zip archive, cannot be opened, or holds more files
// or bytes than the limits allow.
std::vector<ZipFileRead> read_zip(const std::string& path, const ZipReadLimits& limits = {});

// False in builds made without libzip (the static and WebAssembly builds: Debian ships libzip
// as a shared library only); zip_archive and read_zip then throw Error saying so.
bool zip_available();

}  // namespace raygrade
