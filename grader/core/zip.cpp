// A zip archive of files stored as they are (PKWARE APPNOTE 6.3.10, sections 4.3 and 4.4).
#include "core/zip.h"

#include <array>
#include <cstdint>
#include <limits>

#include "core/error.h"

namespace raygrade {
namespace {

std::uint32_t crc32(const std::string& bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) c = table[(c ^ b) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put16(std::string& out, std::uint32_t v) {
  out += static_cast<char>(v & 0xFF);
  out += static_cast<char>((v >> 8) & 0xFF);
}

void put32(std::string& out, std::uint32_t v) {
  put16(out, v & 0xFFFF);
  put16(out, v >> 16);
}

[[noreturn]] void too_large(const std::string& what) {
  Diagnostic d;
  d.message = "cannot write the zip archive: " + what;
  d.code = "zip";
  throw Error(d);
}

}  // namespace

std::string zip_archive(const std::vector<ZipEntry>& entries) {
  constexpr std::uint32_t kMax = std::numeric_limits<std::uint32_t>::max();
  if (entries.size() >= 0xFFFF) too_large("more than 65,534 files");
  std::string out, central;
  for (const auto& e : entries) {
    if (e.bytes.size() >= kMax || e.name.size() >= 0xFFFF) too_large(e.name + " is too large");
    if (out.size() >= kMax) too_large("the archive would exceed 4 GB");
    auto offset = static_cast<std::uint32_t>(out.size());
    auto size = static_cast<std::uint32_t>(e.bytes.size());
    std::uint32_t crc = crc32(e.bytes);
    // Local file header: version 1.0, no flags, stored, time 00:00 of 1980-01-01.
    put32(out, 0x04034b50);
    put16(out, 10);
    put16(out, 0);
    put16(out, 0);
    put16(out, 0);
    put16(out, 0x21);
    put32(out, crc);
    put32(out, size);
    put32(out, size);
    put16(out, static_cast<std::uint32_t>(e.name.size()));
    put16(out, 0);
    out += e.name;
    out += e.bytes;
    // Central directory header: made by Unix (3), the mode in the high half of the external
    // attributes.
    std::uint32_t mode = 0100000u | (e.executable ? 0755u : 0644u);
    put32(central, 0x02014b50);
    put16(central, (3u << 8) | 20u);
    put16(central, 10);
    put16(central, 0);
    put16(central, 0);
    put16(central, 0);
    put16(central, 0x21);
    put32(central, crc);
    put32(central, size);
    put32(central, size);
    put16(central, static_cast<std::uint32_t>(e.name.size()));
    put16(central, 0);
    put16(central, 0);
    put16(central, 0);
    put16(central, 0);
    put32(central, mode << 16);
    put32(central, offset);
    central += e.name;
  }
  if (out.size() + central.size() >= kMax) too_large("the archive would exceed 4 GB");
  auto directory_offset = static_cast<std::uint32_t>(out.size());
  auto directory_size = static_cast<std::uint32_t>(central.size());
  out += central;
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<std::uint32_t>(entries.size()));
  put16(out, static_cast<std::uint32_t>(entries.size()));
  put32(out, directory_size);
  put32(out, directory_offset);
  put16(out, 0);
  return out;
}

}  // namespace raygrade
