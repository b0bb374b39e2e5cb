// The docs' reference tables: what lies between the markers is rewritten, nothing else, and a
// bad marker is an error naming the file and line.
#include "reports/reference_tables.h"

#include <gtest/gtest.h>

#include "assignments/platforms/platforms.h"
#include "core/error.h"
#include "grading/outputs.h"
#include "reports/render.h"

namespace raygrade {
namespace {

std::string table(std::string_view name) {
  for (const auto& t : reference_tables(grade_formats())) {
    if (t.name == name) return t.markdown;
  }
  return "";
}

TEST(ReferenceTables, OnlyTheTextBetweenTheMarkersIsRewritten) {
  std::string doc =
      "# Title\n\nBefore.\n<!-- raygrade tables: grade-formats -->\n| old | table |\n"
      "<!-- raygrade tables: end -->\nAfter.\n";
  std::string out = with_reference_tables(doc, "doc.md", grade_formats());
  EXPECT_EQ(out, "# Title\n\nBefore.\n<!-- raygrade tables: grade-formats -->\n" +
                     table("grade-formats") + "<!-- raygrade tables: end -->\nAfter.\n");
  // Written again, it is unchanged; a doc without markers is left alone.
  EXPECT_EQ(with_reference_tables(out, "doc.md", grade_formats()), out);
  EXPECT_EQ(with_reference_tables("no tables here\n", "doc.md", grade_formats()),
            "no tables here\n");
  // A marker inside a line is text about markers, not a marker.
  std::string about = "Write `<!-- raygrade tables: NAME -->` on its own line.\n";
  EXPECT_EQ(with_reference_tables(about, "doc.md", grade_formats()), about);
}

TEST(ReferenceTables, EveryRowOfTheCodesTablesIsInTheDocsTable) {
  // One row per entry, named as the tables name it: six grade formats, four solution formats.
  const std::string& grade = table("grade-formats");
  for (const char* name : {"`text`", "`json`", "`gradescope`", "`prairielearn`", "`csv`", "`html`"})
    EXPECT_NE(grade.find(std::string("| ") + name + " |"), std::string::npos) << name;
  const std::string& solution = table("solution-formats");
  for (const char* name : {"`md`", "`html`", "`txt`", "`json`"})
    EXPECT_NE(solution.find(std::string("| ") + name + " |"), std::string::npos) << name;
  // The cone's row: its keys with their defaults, and its method.
  const std::string& primitives = table("primitives");
  EXPECT_NE(primitives.find("| `cone` | `base`, `axis` (default [0, 0, 1]), `radius`, `height`, "
                            "`capped` (default false) |"),
            std::string::npos);
  EXPECT_NE(primitives.find("| `quadratic` |"), std::string::npos);
}

TEST(ReferenceTables, AnUnknownTableOrAMissingEndIsAnErrorAtItsLine) {
  try {
    with_reference_tables("a\nb\n<!-- raygrade tables: shapes -->\n<!-- raygrade tables: end -->\n",
                          "doc.md", grade_formats());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().file, "doc.md");
    EXPECT_EQ(e.diagnostic().line, 3);
    EXPECT_NE(e.diagnostic().message.find("no reference table 'shapes'"), std::string::npos);
  }
  EXPECT_THROW(
      with_reference_tables("<!-- raygrade tables: kinds -->\nrows\n", "doc.md", grade_formats()),
      Error);
  EXPECT_THROW(with_reference_tables("<!-- raygrade tables: end -->\n", "doc.md", grade_formats()),
               Error);
}

TEST(OutputFormats, NamesAreWrittenOnceAndFoundByName) {
  EXPECT_EQ(
      grade_format_names(),
      "text, json, csv, html, gradescope, prairielearn, csv-canvas, csv-moodle, csv-blackboard");
  ASSERT_NE(find_grade_format("csv"), nullptr);
  EXPECT_EQ(find_grade_format("csv")->layout, GradeLayout::kGradebook);
  EXPECT_EQ(find_grade_format("markdown"), nullptr);
  EXPECT_EQ(solution_format_names(), (std::vector<std::string>{"md", "html", "txt", "json"}));
  for (Format f : all_formats()) EXPECT_EQ(parse_format(format_extension(f)), f);
}

}  // namespace
}  // namespace raygrade
