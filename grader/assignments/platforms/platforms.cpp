// The table of platforms, made from the list `Platforms` (platforms.h). Everything that works
// with a platform takes it from here.
#include "assignments/platforms/platforms.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"
#include "core/escape.h"

namespace raygrade {

const std::vector<PlatformEntry>& platform_table() {
  static const std::vector<PlatformEntry> table = Platforms::entries();
  return table;
}

const PlatformEntry* find_platform(std::string_view name) {
  for (const PlatformEntry& p : platform_table()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const std::vector<LmsExport>& lms_exports() {
  static const std::vector<LmsExport> table = [] {
    std::vector<LmsExport> t;
    for (const PlatformEntry& p : platform_table()) {
      if (p.lms_export) t.push_back(*p.lms_export);
    }
    return t;
  }();
  return table;
}

const LmsExport* find_lms_export(std::string_view name) {
  for (const LmsExport& e : lms_exports()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

const std::vector<GradeFormat>& grade_formats() {
  static const std::vector<GradeFormat> table = [] {
    std::vector<GradeFormat> t = own_grade_formats();
    for (const PlatformEntry& p : platform_table()) {
      if (p.results) t.push_back(*p.results);
      if (p.gradebook) {
        t.push_back({p.gradebook->format, p.gradebook->summary, ".csv",
                     GradeLayout::kClassGradebook, false, false, nullptr});
      }
    }
    return t;
  }();
  return table;
}

const GradeFormat* find_grade_format(std::string_view name) {
  for (const auto& f : grade_formats()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::string grade_format_names() {
  std::vector<std::string_view> names;
  for (const auto& f : grade_formats()) names.push_back(f.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

const std::vector<GradebookLayout>& gradebook_layouts() {
  static const std::vector<GradebookLayout> table = [] {
    std::vector<GradebookLayout> t;
    for (const PlatformEntry& p : platform_table()) {
      if (p.gradebook) t.push_back(*p.gradebook);
    }
    return t;
  }();
  return table;
}

const GradebookLayout* find_gradebook_layout(std::string_view format) {
  for (const GradebookLayout& g : gradebook_layouts()) {
    if (g.format == format) return &g;
  }
  return nullptr;
}

std::string platform_gradebook(std::string_view format, const ClassRows& book,
                               const std::string& title, const std::string& column_id) {
  const GradebookLayout* layout = find_gradebook_layout(format);
  if (!layout) {
    std::string known;
    for (const GradebookLayout& g : gradebook_layouts())
      known += fmt::format("{}{}", known.empty() ? "" : ", ", g.format);
    throw Error(Diagnostic{
        "", "", 0, 0, Severity::kError,
        fmt::format("'{}' is no platform's gradebook layout ({})", printable(format), known),
        "unknown-format"});
  }
  return layout->write(book, title, column_id);
}

const std::vector<BulkFormat>& bulk_formats() {
  static const std::vector<BulkFormat> table = [] {
    std::vector<BulkFormat> t;
    for (const PlatformEntry& p : platform_table()) {
      if (p.bulk) t.push_back(*p.bulk);
    }
    return t;
  }();
  return table;
}

}  // namespace raygrade
