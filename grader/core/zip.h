// A zip archive of files stored as they are (no compression), for the Gradescope export.
#pragma once

#include <string>
#include <vector>

namespace raygrade {

struct ZipEntry {
  std::string name;   // the path inside the archive, with '/' between folders
  std::string bytes;  // the file's contents
  bool executable = false;
};

// The archive's bytes: each entry stored (method 0) with its CRC-32 and Unix permissions (0755
// for executables, else 0644), then the central directory. Throws Error when an entry or the
// archive exceeds what a zip without the 64-bit extension can hold (4 GB, 65,535 entries).
std::string zip_archive(const std::vector<ZipEntry>& entries);

}  // namespace raygrade
