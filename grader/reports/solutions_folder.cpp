// Generating, writing and checking the solutions folder.
#include "reports/solutions_folder.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/atomic_file.h"
#include "core/escape.h"
#include "reports/json_report.h"
#include "reports/scene_view_assets.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;

std::string index_file(const std::vector<std::pair<const Problem*, std::string>>& problems,
                       const std::vector<Format>& formats, const std::string& note) {
  std::string out = "<!-- " + html_escape(note) + " -->\n# Worked solutions\n\n";
  out +=
      "One worked solution per problem of the bank, in each format: Markdown with LaTeX math, "
      "an HTML page (MathML, a sketch and a 3D view, whose script scene_view.js `raygrade "
      "solutions` writes beside the pages), plain text and JSON. Step names are "
      "listed in docs/steps.md.\n\n| problem | kind | title | files |\n| --- | --- | --- | --- |\n";
  for (const auto& [p, base] : problems) {
    std::string links;
    for (Format f : formats) {
      std::string ext(format_extension(f));
      if (!links.empty()) links += " · ";
      links += fmt::format("[{}]({}.{})", ext, base, ext);
    }
    std::string title = p->title;
    for (char& c : title) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    out += "| " + markdown_escape(p->id) + " | " + markdown_escape(p->kind) + " | " +
           markdown_escape(title) + " | " + links + " |\n";
  }
  return out;
}

bool is_generated(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first;
  if (!in || !std::getline(in, first)) return false;
  return first.find(kGeneratedMarker) != std::string::npos;
}

FolderSync compare(const std::string& folder, const std::vector<GeneratedFile>& files, bool write) {
  FolderSync sync;
  std::set<std::string> produced;
  if (write) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) {
      throw Error(Diagnostic{folder, "", 0, 0, Severity::kError,
                             "cannot create the folder: " + ec.message(), "unwritable"});
    }
  }
  for (const auto& f : files) {
    produced.insert(f.name);
    fs::path path = fs::path(folder) / f.name;
    // Each file is renamed into place whole; the folder is flushed once at the end rather
    // than file by file (thousands of fsyncs took 20 s for a 1,000-problem bank).
    if (update_generated_file(path, f.bytes, !write, false) == FileUpdate::kUpToDate) {
      ++sync.unchanged;
      continue;
    }
    sync.written.push_back(f.name);
  }
  if (write && !sync.written.empty()) flush_folder(folder);
  std::error_code ec;
  std::vector<fs::path> leftovers;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    std::string name = it->path().filename().string();
    // The 3D view's script is written beside the pages but not checked (the folder in git
    // leaves it out: it is the same bundle in every build).
    if (name == kSceneViewFile) continue;
    if (produced.count(name) == 0 && is_generated(it->path())) leftovers.push_back(it->path());
  }
  std::sort(leftovers.begin(), leftovers.end());
  for (const auto& p : leftovers) {
    if (write) fs::remove(p, ec);
    sync.removed.push_back(p.filename().string());
  }
  return sync;
}

}  // namespace

std::string solutions_command(const std::vector<std::string>& paths, const std::string& folder) {
  // Absolute paths are written relative to the working folder, so that no generated file
  // names where on this machine it was written (and the command still runs from there).
  auto shown = [](const std::string& p) {
    std::error_code ec;
    fs::path cwd = fs::current_path(ec);
    if (ec || !fs::path(p).is_absolute()) return p;
    return fs::path(p).lexically_proximate(cwd).string();
  };
  std::vector<std::string> relative;
  relative.reserve(paths.size());
  for (const auto& p : paths) relative.push_back(shown(p));
  return fmt::format("raygrade solutions {} --out {}", fmt::join(relative, " "), shown(folder));
}

std::vector<GeneratedFile> solution_files(const std::vector<Problem>& problems,
                                          const std::vector<Format>& formats,
                                          const std::string& command,
                                          std::vector<Diagnostic>& errors) {
  std::string note = fmt::format("{} with `{}`; do not edit.", kGeneratedMarker, command);
  std::vector<GeneratedFile> files;
  std::vector<std::pair<const Problem*, std::string>> done;
  std::set<std::string> bases;
  for (const auto& p : problems) {
    try {
      Solution s = make_solution(p, "", number_format_for(p));
      // Ids that map to the same safe name ("a/b", "a_b") get a number, in bank order.
      std::string base = safe_file_name(p.id);
      for (int n = 2; bases.count(base); ++n) base = safe_file_name(p.id) + "-" + std::to_string(n);
      bases.insert(base);
      std::vector<GeneratedFile> mine;
      for (Format f : formats) {
        DocumentOptions o;
        o.generated = note;
        if (f == Format::kHtml) o.scene_view_src = kSceneViewFile;
        if (f == Format::kMarkdown &&
            std::find(formats.begin(), formats.end(), Format::kHtml) != formats.end()) {
          o.html_link = base + ".html";
        }
        mine.push_back(
            {base + "." + std::string(format_extension(f)), render_document(f, {&s}, o)});
      }
      files.insert(files.end(), mine.begin(), mine.end());
      done.emplace_back(&p, base);
    } catch (const Error& e) {
      Diagnostic d = e.diagnostic();
      if (d.file.empty()) d.file = p.file;
      if (d.path.empty()) d.path = p.path;
      errors.push_back(d);
    }
  }
  files.push_back({"README.md", index_file(done, formats, note)});
  return files;
}

FolderSync write_solution_folder(const std::string& folder,
                                 const std::vector<GeneratedFile>& files) {
  FolderSync sync = compare(folder, files, true);
  bool pages = std::any_of(files.begin(), files.end(), [](const GeneratedFile& f) {
    return f.name.size() > 5 && f.name.compare(f.name.size() - 5, 5, ".html") == 0;
  });
  if (pages) update_generated_file(fs::path(folder) / kSceneViewFile, kSceneViewScript, false);
  return sync;
}

FolderSync check_solution_folder(const std::string& folder,
                                 const std::vector<GeneratedFile>& files) {
  return compare(folder, files, false);
}

}  // namespace raygrade
