// Output folder locks (flock) and the clean-up of temporary files left by a killed writer.
#include "core/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/error.h"
#include "core/escape.h"

namespace raygrade {
namespace {

constexpr const char* kLockName = ".raygrade.lock";

[[noreturn]] void fail(const std::filesystem::path& path, std::string message, std::string code) {
  throw Error(
      Diagnostic{path.string(), "", 0, 0, Severity::kError, std::move(message), std::move(code)});
}

std::string read_all(int fd) {
  std::string out;
  char buffer[512];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0 && out.size() < 4096;) {
    out.append(buffer, static_cast<std::size_t>(n));
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

// ".NAME.tmp-XXXXXX", as write_file_atomically names its temporary files (mkstemp's six
// letters and digits).
bool is_temporary_name(const std::string& name) {
  constexpr std::string_view kMark = ".tmp-";
  if (name.size() < 1 + 1 + kMark.size() + 6 || name[0] != '.') return false;
  std::size_t mark = name.size() - 6 - kMark.size();
  if (name.compare(mark, kMark.size(), kMark) != 0) return false;
  for (std::size_t i = name.size() - 6; i < name.size(); ++i) {
    char c = name[i];
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!ok) return false;
  }
  return true;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& folder, const std::string& what)
    : path_(folder / kLockName) {
  const std::filesystem::path& path = path_;
  // A holder removes the file when it is done, while it still holds the lock: a lock taken on a
  // file that is no longer at the path (removed between our open and our flock) guards nothing,
  // so it is let go and taken again on the file now there.
  bool locked = false;
  for (int attempt = 0; !locked; ++attempt) {
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0)
      fail(path, fmt::format("cannot make the lock file: {}", std::strerror(errno)), "unwritable");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) break;  // held by another: reported below
    struct stat held {
    }, there{};
    locked = ::fstat(fd_, &held) == 0 && ::stat(path.c_str(), &there) == 0 &&
             held.st_dev == there.st_dev && held.st_ino == there.st_ino;
    if (locked) break;
    ::close(fd_);
    fd_ = -1;
    if (attempt == 100) fail(path, "the lock file keeps being replaced", "locked");
  }
  if (!locked) {
    int error = errno;
    std::string holder = error == EWOULDBLOCK ? read_all(fd_) : "";
    ::close(fd_);
    fd_ = -1;
    if (error != EWOULDBLOCK) {
      fail(path, fmt::format("cannot lock the folder: {}", std::strerror(error)), "unwritable");
    }
    fail(folder,
         fmt::format("the folder is in use by another raygrade ({}); wait for it to finish, or "
                     "write to another folder",
                     holder.empty() ? "it has not said who it is yet" : printable(holder, 200)),
         "locked");
  }
  char host[256] = "";
  ::gethostname(host, sizeof host - 1);
  auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char when[32] = "";
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  std::string who = fmt::format("{}, process {} on {}, since {}\n", what, ::getpid(), host, when);
  if (::ftruncate(fd_, 0) == 0) {
    ssize_t ignored = ::pwrite(fd_, who.data(), who.size(), 0);
    (void)ignored;  // the lock holds without its note
  }
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  // Removed while held, so that a finished run leaves nothing behind; a writer waiting on the
  // old file sees it gone and takes a new one (see the constructor).
  ::unlink(path_.c_str());
  ::close(fd_);  // closing releases the flock
}

std::vector<std::string> remove_stale_temporaries(const std::filesystem::path& folder) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end;
       it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (!is_temporary_name(name) || !it->is_regular_file(ec)) continue;
    if (std::filesystem::remove(it->path(), ec)) removed.push_back(name);
  }
  return removed;
}

}  // namespace raygrade
