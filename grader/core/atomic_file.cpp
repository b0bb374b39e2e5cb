// Atomic file writes (a temporary file in the same folder, fsync, rename), and whole reads.
#include "core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"

namespace raygrade {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view what, int error) {
  // A full disk, a quota, no memory or no file descriptors left: the machine's limits, which
  // another run may not meet, not a fault of the path.
  bool resource = error == ENOSPC || error == EDQUOT || error == ENOMEM || error == EMFILE ||
                  error == ENFILE || error == EFBIG;
  throw Error(Diagnostic{path.string(), "", 0, 0, Severity::kError,
                         fmt::format("cannot write the file: {}: {}", what, std::strerror(error)),
                         resource ? "resource" : "unwritable"});
}

// Removes the temporary file when the write does not complete.
class TempFile {
 public:
  explicit TempFile(std::string name) : name_(std::move(name)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(name_.c_str());
  }
  int fd_ = -1;
  bool committed_ = false;
  std::string name_;
};

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes, bool flush) {
  if (path.filename().empty()) fail(path, "the path names a folder", EISDIR);
  // mkstemp needs a writable template: "<folder>/.<name>.tmp-XXXXXX", hidden and in the same
  // folder so that the rename stays on one file system.
  std::filesystem::path folder = path.parent_path();
  std::string pattern = (folder / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  int fd = ::mkstemp(name.data());
  if (fd < 0) fail(path, "creating a temporary file", errno);
  TempFile temp(name.data());
  temp.fd_ = fd;
  // mkstemp creates the file readable by its owner only; results are meant to be shared.
  if (::fchmod(fd, 0644) != 0) fail(path, "setting permissions", errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(path, "writing", errno);
    }
    done += static_cast<std::size_t>(n);
  }
  if (flush && ::fsync(fd) != 0) fail(path, "flushing to disk", errno);
  temp.fd_ = -1;
  if (::close(fd) != 0) fail(path, "closing", errno);
  if (::rename(temp.name_.c_str(), path.c_str()) != 0) fail(path, "renaming into place", errno);
  temp.committed_ = true;
}

void flush_folder(const std::filesystem::path& folder) {
  int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) fail(folder, "opening the folder to flush it", errno);
  int rc = ::syncfs(fd);
  int error = errno;
  ::close(fd);
  if (rc != 0) fail(folder, "flushing to disk", error);
}

std::optional<std::string> read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return std::nullopt;
  return bytes;
}

FileUpdate update_generated_file(const std::filesystem::path& path, std::string_view bytes,
                                 bool check_only, bool flush) {
  if (read_whole_file(path) == bytes) return FileUpdate::kUpToDate;
  if (check_only) return FileUpdate::kStale;
  write_file_atomically(path, bytes, flush);
  return FileUpdate::kWritten;
}

}  // namespace raygrade
