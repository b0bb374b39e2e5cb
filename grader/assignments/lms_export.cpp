// What every platform's export shares: the assignment and its bank as shipped, a static
// raygrade, the files written.
#include "assignments/lms_export.h"

#include <elf.h>
#include <fmt/format.h>

#include <fstream>
#include <set>

#include "core/atomic_file.h"
#include "json/source.h"

namespace raygrade {

std::string read_file_bytes(const std::filesystem::path& path) {
  std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) {
    Diagnostic d;
    d.file = path.string();
    d.message = "cannot read the file";
    d.code = "unreadable";
    throw Error(d);
  }
  return std::move(*bytes);
}

bool is_static_executable(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  Elf64_Ehdr header{};
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return false;
  if (std::string_view(reinterpret_cast<const char*>(header.e_ident), 4) != ELFMAG ||
      header.e_ident[EI_CLASS] != ELFCLASS64 || header.e_phentsize != sizeof(Elf64_Phdr)) {
    return false;
  }
  for (int i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr ph{};
    in.seekg(static_cast<std::streamoff>(header.e_phoff + i * sizeof ph));
    if (!in.read(reinterpret_cast<char*>(&ph), sizeof ph)) return false;
    if (ph.p_type == PT_INTERP) return false;
  }
  return header.e_type == ET_EXEC || header.e_type == ET_DYN;
}

std::optional<std::filesystem::path> find_static_raygrade(const std::filesystem::path& running) {
  if (is_static_executable(running)) return running;
  // running is <build>/<preset>/grader/raygrade.
  auto candidate =
      running.parent_path().parent_path().parent_path() / "static" / "grader" / "raygrade";
  if (is_static_executable(candidate)) return candidate;
  return std::nullopt;
}

std::vector<ZipEntry> assignment_files(const AssignmentSpec& spec, const Bank& bank) {
  std::vector<ZipEntry> entries;
  std::set<std::string> names;
  for (const auto& f : bank.files) {
    std::filesystem::path p(f);
    std::string name = p.filename().string();
    for (int k = 2; !names.insert(name).second; ++k)
      name = fmt::format("{}-{}{}", p.stem().string(), k, p.extension().string());
    entries.push_back({"bank/" + name, read_file_bytes(p), false});
  }
  // The assignment as written, with its bank in bank/ (its $schema path would point nowhere).
  nlohmann::json a = load_json_file(spec.file)->root;
  a.erase("$schema");
  a["bank"] = "bank";
  entries.push_back({"assignment.json", a.dump(2) + "\n", false});
  return entries;
}

void write_entries(const std::filesystem::path& folder, const std::vector<ZipEntry>& entries) {
  for (const auto& e : entries) {
    std::filesystem::path p = folder / e.name;
    std::filesystem::create_directories(p.parent_path());
    write_file_atomically(p, e.bytes);
    using std::filesystem::perms;
    std::filesystem::permissions(
        p, e.executable
               ? perms::owner_all | perms::group_read | perms::group_exec | perms::others_read |
                     perms::others_exec
               : perms::owner_read | perms::owner_write | perms::group_read | perms::others_read);
  }
}

}  // namespace raygrade
