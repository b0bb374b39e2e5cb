// The list of platforms: what `raygrade export` and `raygrade grade` take from it, and a
// gradebook layout no platform declares refused as bad input rather than written as another's.
#include "assignments/platforms/platforms.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/error.h"

namespace raygrade {
namespace platforms_test {

// Two students, one graded 4 of 5 points, one with nothing handed in.
ClassRows two_students() {
  ClassRows book;
  book.points = 5.0;
  book.rows.push_back({StudentIdentity{"Ada Lovelace", "s1", "ada@example.edu"}, "", 4.0});
  book.rows.push_back({StudentIdentity{"", "s2", "s2@example.edu"}, "", 0.0});
  return book;
}

TEST(Platforms, AnUnknownGradebookLayoutIsBadInput) {
  try {
    (void)platform_gradebook("csv-nowhere", two_students(), "Quiz", "");
    FAIL() << "a layout no platform declares was written";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().code, "unknown-format");
    // The message names the layouts there are.
    EXPECT_NE(e.diagnostic().message.find("csv-blackboard"), std::string::npos);
  }
}

// Blackboard's offline grade upload, written by hand from its documented columns: Last Name,
// First Name, Username, Student ID, then "TITLE [Total Pts: N Score] |COLUMN_ID", every field in
// quotation marks; a name's last word is the last name, and a student without a name shows the id.
TEST(Platforms, BlackboardLayoutFromTheList) {
  const GradebookLayout* layout = find_gradebook_layout("csv-blackboard");
  ASSERT_NE(layout, nullptr);
  EXPECT_EQ(platform_gradebook("csv-blackboard", two_students(), "Quiz", "42"),
            "\"Last Name\",\"First Name\",\"Username\",\"Student ID\","
            "\"Quiz [Total Pts: 5 Score] |42\"\n"
            "\"Lovelace\",\"Ada\",\"s1\",\"s1\",\"4\"\n"
            "\"s2\",\"\",\"s2\",\"s2\",\"0\"\n");
  // A Column ID is digits; a title may hold no '|' (Blackboard reads the id after it).
  EXPECT_FALSE(layout->check("Quiz", "4x2").error.empty());
  EXPECT_FALSE(layout->check("Quiz | 2", "42").error.empty());
  EXPECT_TRUE(layout->check("Quiz", "42").error.empty());
}

// Every grade format's name is written once; raygrade's own come first, then each platform's in
// the list's order; every export and layout is found by its name.
TEST(Platforms, EveryNameIsOnceInTheTables) {
  std::set<std::string_view> names;
  for (const GradeFormat& f : grade_formats()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
  }
  ASSERT_GE(grade_formats().size(), own_grade_formats().size());
  for (std::size_t i = 0; i < own_grade_formats().size(); ++i)
    EXPECT_EQ(grade_formats()[i].name, own_grade_formats()[i].name);
  std::set<std::string_view> platforms;
  for (const PlatformEntry& p : platform_table()) {
    EXPECT_TRUE(platforms.insert(p.name).second) << p.name;
    EXPECT_EQ(find_platform(p.name), &p);
    if (p.lms_export) {
      ASSERT_NE(find_lms_export(p.name), nullptr);
      EXPECT_EQ(find_lms_export(p.name)->title, p.title);
    }
    if (p.gradebook) {
      ASSERT_NE(find_grade_format(p.gradebook->format), nullptr);
      EXPECT_EQ(find_grade_format(p.gradebook->format)->layout, GradeLayout::kClassGradebook);
    }
    if (p.bulk) {
      EXPECT_EQ(p.bulk->title, p.title);
    }
  }
  EXPECT_EQ(find_lms_export("nowhere"), nullptr);
}

}  // namespace platforms_test
}  // namespace raygrade
