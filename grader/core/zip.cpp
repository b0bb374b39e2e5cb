// Zip archives through libzip (https://libzip.org/documentation/).
#include "core/zip.h"

#include <fmt/format.h>

#include "core/error.h"

#if RAYGRADE_HAS_LIBZIP
#include <zip.h>

#include <memory>
#endif

namespace raygrade {
namespace {

[[noreturn]] void zip_fault(const std::string& file, std::string message) {
  Diagnostic d;
  d.file = file;
  d.message = std::move(message);
  d.code = "zip";
  throw Error(d);
}

}  // namespace

#if RAYGRADE_HAS_LIBZIP

namespace {

// 1980-01-01 00:00 UTC, the earliest time a zip's MS-DOS date holds: what every entry written
// carries instead of the clock's time.
constexpr time_t kFixedTime = 315532800;

struct ArchiveCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct SourceFree {
  void operator()(zip_source_t* s) const { zip_source_free(s); }
};
struct FileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};

std::string error_text(int code) {
  zip_error_t e;
  zip_error_init_with_code(&e, code);
  std::string text = zip_error_strerror(&e);
  zip_error_fini(&e);
  return text;
}

}  // namespace

bool zip_available() { return true; }

std::string zip_archive(const std::vector<ZipEntry>& entries) {
  const std::string kWhat = "the zip archive being written";
  // libzip writes nothing for an archive without files; an empty zip is its end record alone.
  if (entries.empty()) return std::string("PK\x05\x06", 4) + std::string(18, '\0');
  zip_error_t error;
  zip_error_init(&error);
  // The archive is built in a buffer that outlives the archive (zip_source_keep).
  std::unique_ptr<zip_source_t, SourceFree> buffer(zip_source_buffer_create(nullptr, 0, 0, &error));
  if (!buffer) zip_fault(kWhat, zip_error_strerror(&error));
  zip_t* raw = zip_open_from_source(buffer.get(), ZIP_TRUNCATE, &error);
  if (!raw) zip_fault(kWhat, zip_error_strerror(&error));
  zip_source_keep(buffer.get());
  std::unique_ptr<zip_t, ArchiveCloser> archive(raw);
  for (const auto& e : entries) {
    // The entries' bytes outlive zip_close, which reads them.
    zip_source_t* data = zip_source_buffer(archive.get(), e.bytes.data(), e.bytes.size(), 0);
    zip_int64_t index =
        data ? zip_file_add(archive.get(), e.name.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (data) zip_source_free(data);
      zip_fault(kWhat, fmt::format("{}: {}", e.name, zip_strerror(archive.get())));
    }
    auto i = static_cast<zip_uint64_t>(index);
    zip_uint32_t mode = 0100000u | (e.executable ? 0755u : 0644u);
    if (zip_set_file_compression(archive.get(), i, ZIP_CM_DEFLATE, 9) != 0 ||
        zip_file_set_external_attributes(archive.get(), i, 0, ZIP_OPSYS_UNIX, mode << 16) != 0 ||
        zip_file_set_mtime(archive.get(), i, kFixedTime, 0) != 0)
      zip_fault(kWhat, fmt::format("{}: {}", e.name, zip_strerror(archive.get())));
  }
  if (zip_close(archive.get()) != 0) zip_fault(kWhat, zip_strerror(archive.get()));
  static_cast<void>(archive.release());  // zip_close freed it
  zip_stat_t st;
  if (zip_source_stat(buffer.get(), &st) != 0 || zip_source_open(buffer.get()) != 0)
    zip_fault(kWhat, zip_error_strerror(zip_source_error(buffer.get())));
  std::string out(static_cast<std::size_t>(st.size), '\0');
  zip_int64_t got = zip_source_read(buffer.get(), out.data(), out.size());
  zip_source_close(buffer.get());
  if (got != static_cast<zip_int64_t>(out.size())) zip_fault(kWhat, "cannot read back the archive");
  return out;
}

std::vector<ZipFileRead> read_zip(const std::string& path, const ZipReadLimits& limits) {
  int code = 0;
  std::unique_ptr<zip_t, ArchiveCloser> archive(zip_open(path.c_str(), ZIP_RDONLY, &code));
  if (!archive) zip_fault(path, "cannot read the zip archive: " + error_text(code));
  zip_int64_t count = zip_get_num_entries(archive.get(), 0);
  if (count < 0 || static_cast<std::uint64_t>(count) > limits.max_files)
    zip_fault(path, fmt::format("the archive holds {} files, more than the {} read", count,
                                limits.max_files));
  std::vector<ZipFileRead> out;
  std::uint64_t total = 0;
  for (zip_uint64_t i = 0; i < static_cast<zip_uint64_t>(count); ++i) {
    zip_stat_t st;
    if (zip_stat_index(archive.get(), i, 0, &st) != 0)
      zip_fault(path, fmt::format("file {} of the archive: {}", i, zip_strerror(archive.get())));
    std::string name = (st.valid & ZIP_STAT_NAME) ? st.name : fmt::format("file {}", i);
    if (name.ends_with('/')) continue;  // a folder
    ZipFileRead f;
    f.name = name;
    if (st.valid & ZIP_STAT_MTIME) f.modified = static_cast<std::int64_t>(st.mtime);
    if (!(st.valid & ZIP_STAT_SIZE) || st.size > limits.max_file_bytes) {
      f.fault = fmt::format("{} bytes when unpacked, more than the {} a submission may have",
                            st.size, limits.max_file_bytes);
      out.push_back(std::move(f));
      continue;
    }
    total += st.size;
    if (total > limits.max_total_bytes)
      zip_fault(path, fmt::format("the archive's files hold more than {} bytes in all",
                                  limits.max_total_bytes));
    std::unique_ptr<zip_file_t, FileCloser> file(zip_fopen_index(archive.get(), i, 0));
    f.bytes.resize(static_cast<std::size_t>(st.size));
    zip_int64_t got = file ? zip_fread(file.get(), f.bytes.data(), f.bytes.size()) : -1;
    if (got != static_cast<zip_int64_t>(f.bytes.size())) {
      f.bytes.clear();
      f.fault = fmt::format("cannot unpack it: {}",
                            file ? zip_file_strerror(file.get()) : zip_strerror(archive.get()));
    }
    out.push_back(std::move(f));
  }
  return out;
}

#else

bool zip_available() { return false; }

std::string zip_archive(const std::vector<ZipEntry>&) {
  zip_fault("the zip archive being written",
            "this raygrade was built without libzip (a static or WebAssembly build): use the "
            "release build for zip archives");
}

std::vector<ZipFileRead> read_zip(const std::string& path, const ZipReadLimits&) {
  zip_fault(path,
            "this raygrade was built without libzip (a static or WebAssembly build): unpack the "
            "archive, or use the release build");
}

#endif

}  // namespace raygrade
