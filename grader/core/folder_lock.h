// An output folder held by one writer at a time, and the temporary files a killed writer left.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raygrade {

// An exclusive lock on an output folder: flock() on "<folder>/.raygrade.lock", which also holds
// who took it (process id, host, time, what). The kernel releases the lock when the process
// ends, however it ends, so a killed writer never leaves the folder locked. The lock file is
// removed when the lock is let go (a finished run leaves no file behind); a writer that locked
// a file removed meanwhile finds it no longer at the path and locks the new one, so two writers
// never hold two different files.
class FolderLock {
 public:
  // Takes the lock without waiting. Throws Error (code "locked", naming the folder and the
  // holder) when another process holds it, or "unwritable" when the file cannot be made.
  FolderLock(const std::filesystem::path& folder, const std::string& what);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// Removes the temporary files write_file_atomically leaves in `folder` when its process is
// killed mid-write (".NAME.tmp-XXXXXX"); returns their names. Only safe while holding the
// folder's FolderLock: another writer's temporary file looks the same.
std::vector<std::string> remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace raygrade
