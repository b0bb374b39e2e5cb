// The docs' reference tables, from the shape, kind and format tables.
#include "reports/reference_tables.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"
#include "grading/outputs.h"
#include "json/cursor.h"
#include "json/source.h"
#include "kinds/fields/field_type.h"
#include "problems/problem.h"
#include "reports/render.h"
#include "shapes/shape.h"

namespace raygrade {
namespace {

constexpr std::string_view kBegin = "<!-- raygrade tables: ";
constexpr std::string_view kEnd = "<!-- raygrade tables: end -->";

// A table cell: a | would end the cell.
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string code_list(const std::vector<std::string>& names) {
  std::vector<std::string> quoted;
  quoted.reserve(names.size());
  for (const auto& n : names) quoted.push_back(fmt::format("`{}`", n));
  return fmt::format("{}", fmt::join(quoted, ", "));
}

// A default value as the docs write JSON: [0, 0, 1].
std::string json_value(const nlohmann::ordered_json& value) {
  if (!value.is_array()) return value.dump();
  std::vector<std::string> items;
  for (const auto& v : value) items.push_back(json_value(v));
  return fmt::format("[{}]", fmt::join(items, ", "));
}

std::string primitives_table() {
  std::string out =
      "| type | keys | what it is | methods (the first is the default) |\n"
      "| --- | --- | --- | --- |\n";
  for (const ShapeEntry& entry : shape_table()) {
    nlohmann::ordered_json fragment = entry.schema();
    std::vector<std::string> keys;
    for (const auto& [key, value] : fragment["properties"].items()) {
      keys.push_back(value.contains("default")
                         ? fmt::format("`{}` (default {})", key, json_value(value["default"]))
                         : fmt::format("`{}`", key));
    }
    // The methods of the primitive, asked of its first schema example.
    std::string example = fragment["examples"][0].dump();
    std::unique_ptr<Shape> shape = entry.read(Cursor(
        parse_json_text(fmt::format("the {} schema example", entry.type), std::move(example))));
    out += fmt::format("| `{}` | {} | {} | {} |\n", entry.type,
                       cell(fmt::format("{}", fmt::join(keys, ", "))),
                       cell(fragment.value("description", std::string(entry.summary))),
                       code_list(shape->methods()));
  }
  return out;
}

std::string kinds_table() {
  std::string out =
      "| kind | asks for | its keys (beside the common ones) |\n| --- | --- | --- |\n";
  for (const KindEntry& k : kind_table())
    out += fmt::format("| `{}` | {} | {} |\n", k.name, cell(k.summary), code_list(k.keys));
  return out;
}

// Every kind's parts, in the order of the table of kinds and of each kind's parts().
std::string parts_table() {
  std::string out =
      "| kind | part | asks for | default points | compared as |\n| --- | --- | --- | --- | --- "
      "|\n";
  for (const KindEntry& k : kind_table()) {
    bool first = true;
    for (const PartSpec& part : k.parts) {
      out += fmt::format("| {} | `{}` | {} | {} | {} |\n", first ? fmt::format("`{}`", k.name) : "",
                         part.name, cell(part.asks), part.points, to_string(part.compare));
      first = false;
    }
  }
  return out;
}

std::string solution_formats_table() {
  std::string out = "| format | what it is |\n| --- | --- |\n";
  for (const SolutionFormat& f : solution_formats())
    out += fmt::format("| `{}` | {} |\n", f.name, cell(f.summary));
  return out;
}

std::string grade_formats_table(const std::vector<GradeFormat>& grade_formats) {
  std::string out = "| format | what it is | with several submissions |\n| --- | --- | --- |\n";
  for (const GradeFormat& f : grade_formats) {
    std::string several;
    switch (f.layout) {
      case GradeLayout::kDocument:
        several = f.needs_out ? fmt::format("`--out DIR` needed: one `{}` file each", f.extension)
                              : fmt::format(
                                    "one after the other; with `--out DIR`, one `{}` "
                                    "file each",
                                    f.extension);
        break;
      case GradeLayout::kJsonArray:
        several = fmt::format(
            "one `{{\"submissions\": [...]}}`; with `--out DIR`, one `{}` file "
            "each",
            f.extension);
        break;
      case GradeLayout::kGradebook:
        several =
            fmt::format("one row each; with `--out DIR`, the file `gradebook{}`", f.extension);
        break;
      case GradeLayout::kClassGradebook:
        several = fmt::format(
            "one row per roster student; with `--out DIR`, the file `gradebook{}`", f.extension);
        break;
    }
    out += fmt::format("| `{}` | {} | {} |\n", f.name, cell(f.summary), several);
  }
  return out;
}

// The field types of the answer forms, from their list (kinds/fields/field_types.h).
std::string field_types_table() {
  std::string out =
      "| type | what the student gives | shape | a value | in one text box |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const FieldTypeEntry& e : field_type_table()) {
    out += fmt::format("| `{}` | {} | `{}` | `{}` | {} |\n", e.name, cell(e.asks),
                       field_shape_word(e.shape), field_value_word(e.value), cell(e.placeholder));
  }
  return out;
}

}  // namespace

std::vector<ReferenceTable> reference_tables(const std::vector<GradeFormat>& grade_formats) {
  return {
      {"primitives", primitives_table()},
      {"kinds", kinds_table()},
      {"parts", parts_table()},
      {"field-types", field_types_table()},
      {"solution-formats", solution_formats_table()},
      {"grade-formats", grade_formats_table(grade_formats)},
  };
}

std::string with_reference_tables(std::string_view text, const std::string& file_name,
                                  const std::vector<GradeFormat>& grade_formats) {
  const std::vector<ReferenceTable> tables = reference_tables(grade_formats);
  auto fault = [&](std::size_t at, std::string message) {
    int line = 1;
    for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
    throw Error(Diagnostic{file_name, "", line, 0, Severity::kError, std::move(message),
                           "reference-table"});
  };
  std::string out;
  std::size_t pos = 0;
  while (true) {
    // A marker starts a line; the same words inside a line are text about the markers.
    std::size_t begin = text.find(kBegin, pos);
    while (begin != std::string_view::npos && begin > 0 && text[begin - 1] != '\n')
      begin = text.find(kBegin, begin + 1);
    if (begin == std::string_view::npos) break;
    std::size_t close = text.find("-->", begin);
    std::size_t line_end = text.find('\n', begin);
    if (close == std::string_view::npos || line_end == std::string_view::npos || close > line_end)
      fault(begin, "a reference-table marker must be one line ending with -->");
    std::string name(text.substr(begin + kBegin.size(), close - begin - kBegin.size()));
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (name == "end") fault(begin, "an end marker with no table before it");
    const ReferenceTable* table = nullptr;
    std::vector<std::string> names;
    for (const auto& t : tables) {
      names.push_back(t.name);
      if (t.name == name) table = &t;
    }
    if (!table)
      fault(begin,
            fmt::format("no reference table '{}' (known: {})", name, fmt::join(names, ", ")));
    std::size_t end = text.find(kEnd, line_end);
    while (end != std::string_view::npos && text[end - 1] != '\n') end = text.find(kEnd, end + 1);
    if (end == std::string_view::npos)
      fault(begin, fmt::format("the table '{}' has no end marker ({})", name, kEnd));
    out += text.substr(pos, line_end + 1 - pos);
    out += table->markdown;
    out += kEnd;
    pos = end + kEnd.size();
  }
  out += text.substr(pos);
  return out;
}

}  // namespace raygrade
