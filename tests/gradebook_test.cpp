// The gradebook of a class with --roster: one row per roster student in roster order, a status
// for each, 0 for what is missing, and one submission counted per student, checked against
// gradebooks written by hand (tests/data/gradebook/README.md).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "roster_fixture.h"
#include "run_binary.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_raygrade;
using testing::TempDir;
using testing::write_text;

const fs::path kData = fs::path(RAYGRADE_SOURCE_DIR) / "tests/data/gradebook";

using testing::kClassPlane;
using testing::kClassSphere;

std::string handed(const std::string& student, const std::string& answers,
                   const std::string& submitted = "") {
  return fmt::format(R"({{"student": {}, {}"answers": {{{}}}}})", student,
                     submitted.empty() ? "" : fmt::format(R"("submitted": "{}", )", submitted),
                     answers);
}

class Gradebook : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::write_class_assignment(dir_.path(), "Rays, spheres and planes");
    fs::copy(kData / "roster.csv", dir_.path() / "roster.csv");
    fs::path subs = dir_.path() / "subs";
    fs::create_directories(subs);
    std::string both = fmt::format("{}, {}", kClassSphere, kClassPlane);
    write_text(subs / "ada.json", handed(R"({"id": "s1"})", both));
    write_text(subs / "alan-1.json", handed(R"({"id": "s2"})", both, "2026-11-20T10:00:00Z"));
    write_text(subs / "alan-2.json",
               handed(R"({"id": "s2"})", kClassSphere, "2026-11-21T10:00:00Z"));
    write_text(subs / "grace.json",
               handed(R"({"email": "grace@example.edu"})",
                      fmt::format(R"({}, "plane-1": {{"hits": [{{"t": ""}}]}})", kClassSphere)));
    write_text(subs / "barbara.json", handed(R"({"id": "s5", "email": "ada@example.edu"})", both));
    write_text(subs / "don.json", handed(R"("Donald Knuth")", both));
  }
  testing::RunResult grade(const std::string& extra) {
    return run_raygrade(
        fmt::format("grade --assignment hw.json --roster roster.csv subs --format csv {}", extra),
        dir_.path());
  }
  // The class graded with Moodle's worksheet `worksheet` (a file of the test data) in `format`.
  testing::RunResult with_worksheet(const char* worksheet, const std::string& format) {
    fs::copy(kData / worksheet, dir_.path() / "worksheet.csv");
    return run_raygrade(
        fmt::format("grade --assignment hw.json --roster roster.csv subs --format "
                    "{} --moodle-worksheet worksheet.csv --now 2026-12-01T00:00:00Z",
                    format),
        dir_.path());
  }
  // Standard error of grading with a worksheet of this text, which must be refused (exit 2)
  // before anything is written.
  std::string refused_worksheet(const std::string& text) {
    write_text(dir_.path() / "refused.csv", text);
    auto r = run_raygrade(
        "grade --assignment hw.json --roster roster.csv subs --format csv-moodle "
        "--moodle-worksheet refused.csv --out out",
        dir_.path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(fs::exists(dir_.path() / "out" / "gradebook.csv"));
    return r.err;
  }
  TempDir dir_{"gradebook"};
};

// The roster in the test data is the fixture's (tests/roster_fixture.h), which other tests write.
TEST(GradebookData, TheRosterIsTheFixtures) {
  EXPECT_EQ(read_text(kData / "roster.csv"), testing::class_roster_csv());
}

TEST_F(Gradebook, OneRowPerRosterStudentWithTheLatestSubmission) {
  auto r = grade("--now 2026-12-01T00:00:00Z");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // Barbara's file is rejected
  EXPECT_EQ(r.out, read_text(kData / "latest.csv")) << r.err;
  EXPECT_NE(r.err.find("student 's2': graded: latest of 2 submissions"), std::string::npos)
      << r.err;
}

TEST_F(Gradebook, TheBestSubmissionWhenAsked) {
  auto r = grade("--pick best --now 2026-12-01T00:00:00Z --out book");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(read_text(dir_.path() / "book" / "gradebook.csv"), read_text(kData / "best.csv"));
}

// Feedback pages are named by the student's id, whatever their name, and an index links each
// with its score (Ada: both right, 5 / 5; Grace: the sphere alone, 2 / 5).
TEST_F(Gradebook, FeedbackPagesAreNamedByIdAndIndexed) {
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster.csv subs --format html --out pages "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const char* page : {"s1.html", "s2.html", "s2-2.html", "s3.html", "s6.html"})
    EXPECT_TRUE(fs::exists(dir_.path() / "pages" / page)) << page;
  std::string index = read_text(dir_.path() / "pages" / "index.html");
  EXPECT_NE(index.find("<a href=\"s1.html\">Ada Lovelace</a></td><td>s1</td><td>5 / 5</td>"),
            std::string::npos)
      << index;
  EXPECT_NE(index.find("<a href=\"s3.html\">Grace Hopper</a></td><td>s3</td><td>2 / 5</td>"),
            std::string::npos)
      << index;
  EXPECT_NE(index.find("not graded"), std::string::npos) << index;  // Barbara's file
  EXPECT_NE(index.find("<main>"), std::string::npos);
}

// The same class in each platform's import layout, each file written by hand from the table
// of the README (the latest submission counts: Alan has 2).
TEST_F(Gradebook, EachPlatformsImportLayout) {
  for (const char* platform : {"canvas", "moodle", "blackboard"}) {
    auto r = run_raygrade(fmt::format("grade --assignment hw.json --roster roster.csv subs "
                                      "--format csv-{} --now 2026-12-01T00:00:00Z",
                                      platform),
                          dir_.path());
    EXPECT_EQ(r.exit_code, 2) << platform << ": " << r.err;
    EXPECT_EQ(r.out, read_text(kData / fmt::format("{}.csv", platform))) << platform;
  }
  // Without a roster there is no class to lay out.
  auto r = run_raygrade("grade --assignment hw.json subs --format csv-canvas", dir_.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("needs --assignment and --roster"), std::string::npos) << r.err;
}

// What Canvas's gradebook importer does with a column title (tests/data/gradebook/README.md):
// with --canvas-assignment-id the column is "Title (id)", matched by the id; a title Canvas
// would read as another assignment's id, or drop for a word of its own columns, is refused
// before anything is graded, as is an id that is not a number.
TEST_F(Gradebook, CanvasReadsTheColumnAsMeant) {
  auto canvas = [&](const std::string& extra) {
    return run_raygrade(fmt::format("grade --assignment hw.json --roster roster.csv subs "
                                    "--format csv-canvas --now 2026-12-01T00:00:00Z {}",
                                    extra),
                        dir_.path());
  };
  auto r = canvas("--canvas-assignment-id 4711");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // Barbara's file is rejected
  EXPECT_EQ(r.out, read_text(kData / "canvas-assignment-id.csv")) << r.err;
  for (const char* id : {"47a", "", "4 7", "\xEF\xBC\x94\xEF\xBC\x97"}) {  // ４７: not ASCII
    auto bad = canvas(fmt::format("--canvas-assignment-id '{}'", id));
    EXPECT_EQ(bad.exit_code, 2) << id;
    EXPECT_EQ(bad.out, "") << id;
    EXPECT_NE(bad.err.find("--canvas-assignment-id"), std::string::npos) << id << bad.err;
  }
  auto other = run_raygrade(
      "grade --assignment hw.json --roster roster.csv subs --format csv-moodle "
      "--canvas-assignment-id 4711",
      dir_.path());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("--canvas-assignment-id goes with --format csv-canvas"),
            std::string::npos)
      << other.err;

  // "Lab (2)" is read as the assignment of id 2: refused without an id, taken with one (the
  // importer's greedy title then keeps "Lab (2)" and reads 4711).
  testing::write_class_assignment(dir_.path(), "Lab (2)");
  auto lab = canvas("");
  EXPECT_EQ(lab.exit_code, 2);
  EXPECT_EQ(lab.out, "");
  EXPECT_NE(lab.err.find("Canvas reads the title \"Lab (2)\" as the assignment of id 2"),
            std::string::npos)
      << lab.err;
  auto lab_id = canvas("--canvas-assignment-id 4711");
  EXPECT_NE(lab_id.out.find(",Lab (2) (4711)\n"), std::string::npos) << lab_id.out << lab_id.err;
  // A title without the space before "(" is not read as an id.
  testing::write_class_assignment(dir_.path(), "Lab(2)");
  EXPECT_NE(canvas("").out.find(",Lab(2)\n"), std::string::npos);

  // Each of NON_ASSIGNMENT_COLUMN_HEADERS, anywhere in the title, even with an id; a
  // different case is kept (the importer's match is case-sensitive).
  for (const char* words :
       {"Current Score", "Current Points", "Current Grade", "Final Score", "Final Points",
        "Final Grade", "Override Score", "Override Grade", "Override Status"}) {
    testing::write_class_assignment(dir_.path(), fmt::format("Rays: {} check", words));
    auto dropped = canvas("--canvas-assignment-id 4711");
    EXPECT_EQ(dropped.exit_code, 2) << words;
    EXPECT_EQ(dropped.out, "") << words;
    EXPECT_NE(dropped.err.find(fmt::format("contains \"{}\"", words)), std::string::npos)
        << words << ": " << dropped.err;
  }
  testing::write_class_assignment(dir_.path(), "Rays: final grade check");
  EXPECT_NE(canvas("").out.find(",Rays: final grade check\n"), std::string::npos);
}

// Blackboard's documented upload layout (tests/data/gradebook/README.md): every field quoted;
// with --blackboard-column-id the column is matched by its Column ID, and without one the upload
// makes a new text column, which the grader is told. A title holding '|' (where Blackboard's
// Column ID starts) is refused.
TEST_F(Gradebook, BlackboardQuotesEveryFieldAndMatchesTheColumnId) {
  auto blackboard = [&](const std::string& extra) {
    return run_raygrade(fmt::format("grade --assignment hw.json --roster roster.csv subs "
                                    "--format csv-blackboard --now 2026-12-01T00:00:00Z {}",
                                    extra),
                        dir_.path());
  };
  auto r = blackboard("--blackboard-column-id 123456");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // Barbara's file is rejected
  EXPECT_EQ(r.out, read_text(kData / "blackboard-column-id.csv")) << r.err;
  EXPECT_EQ(r.err.find("new text column"), std::string::npos) << r.err;
  auto bare = blackboard("");
  EXPECT_EQ(bare.out, read_text(kData / "blackboard.csv"));
  EXPECT_NE(bare.err.find("warning: without --blackboard-column-id, Blackboard adds the column as "
                          "a new text column"),
            std::string::npos)
      << bare.err;
  auto bad = blackboard("--blackboard-column-id 12x");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.out, "");
  auto other = run_raygrade(
      "grade --assignment hw.json --roster roster.csv subs --format csv-canvas "
      "--blackboard-column-id 123456",
      dir_.path());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("--blackboard-column-id goes with --format csv-blackboard"),
            std::string::npos)
      << other.err;
  testing::write_class_assignment(dir_.path(), "Rays |99");
  auto pipe = blackboard("--blackboard-column-id 123456");
  EXPECT_EQ(pipe.exit_code, 2);
  EXPECT_EQ(pipe.out, "");
  EXPECT_NE(pipe.err.find("'|'"), std::string::npos) << pipe.err;
  // A quotation mark in a field is doubled inside the quotes; a formula stays text.
  testing::write_class_assignment(dir_.path(), R"(=Rays \"quoted\")");
  auto quoted = blackboard("--blackboard-column-id 123456");
  EXPECT_NE(quoted.out.find(R"("'=Rays ""quoted"" [Total Pts: 5 Score] |123456")"),
            std::string::npos)
      << quoted.out << quoted.err;
}

// Moodle's grading worksheet as downloaded (moodle-worksheet.csv, written by hand in Moodle's
// columns): each row found by its email (in any case) gets its student's total from the table of
// the README; a row of no roster student stays as it was, and Donald, who has no row, is named.
TEST_F(Gradebook, MoodlesWorksheetFilledIn) {
  auto r = with_worksheet("moodle-worksheet.csv", "csv-moodle");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // Barbara's file is rejected
  EXPECT_EQ(r.out, read_text(kData / "moodle-worksheet-filled.csv"));
  EXPECT_NE(r.err.find("worksheet row 7 (guest@example.edu) is no roster student's"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("student 's6' (don@example.edu) has no row on the worksheet"),
            std::string::npos)
      << r.err;
  // A worksheet without the column Moodle matches rows by is refused before anything is graded.
  std::string bad = refused_worksheet("Full name,Email address,Grade\nAda,ada@example.edu,\n");
  EXPECT_NE(bad.find("refused.csv:1: error: the worksheet has no \"Identifier\" column"),
            std::string::npos)
      << bad;
  // Only the Moodle layout takes a worksheet.
  auto other = run_raygrade(
      "grade --assignment hw.json --roster roster.csv subs --format "
      "csv-canvas --moodle-worksheet worksheet.csv",
      dir_.path());
  EXPECT_EQ(other.exit_code, 2);
}

// Moodle reads Grade out of the worksheet's own "Maximum Grade": a Moodle assignment out of 100
// for raygrade's 5 points takes each total times 20 (Ada 5 -> 100, Alan and Grace 2 -> 40), and
// a maximum that is no number of points (a scale) is refused before anything is graded.
TEST_F(Gradebook, MoodlesWorksheetOutOfItsOwnMaximum) {
  auto r = with_worksheet("moodle-worksheet-100.csv", "csv-moodle");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // Barbara's file is rejected
  EXPECT_EQ(r.out, read_text(kData / "moodle-worksheet-100-filled.csv"));
  EXPECT_NE(r.err.find("the worksheet's Maximum Grade is 100, the assignment's 5 points"),
            std::string::npos)
      << r.err;
  std::string scale = refused_worksheet(
      "Identifier,Full name,Email address,Grade,Maximum Grade,Last modified (grade)\n"
      "Participant 101,Ada Lovelace,ada@example.edu,,Competent,-\n");
  EXPECT_NE(scale.find("refused.csv:2: error: row 2's Maximum Grade \"Competent\" is not a "
                       "number of points"),
            std::string::npos)
      << scale;
}

// What Moodle's "Upload multiple feedback files in a zip" reads of each file in the zip: the
// participant number and plugin from its first folder's name split at '_' (fullname, number,
// plugin type, plugin name), as assignfeedback_file's importer splits it; one line per file,
// "number plugin file", and "same" when the file is the page raygrade wrote.
constexpr const char* kMoodleReads = R"(/usr/bin/python3 -c '
import pathlib, sys, zipfile
for name in sorted(zipfile.ZipFile("out/moodle-feedback.zip").namelist()):
    folder, file = name.split("/", 1)
    info = folder.split("_", 4)
    same = zipfile.ZipFile("out/moodle-feedback.zip").read(name) == (pathlib.Path("out") / file).read_bytes()
    print(info[1], info[2] + "_" + info[3], file, "same" if same else "differs")
')";

// With --format html, the pages go into a zip laid out for Moodle: by the README's table, Ada
// (participant 101), Alan (102, two files) and Grace (103) have pages; Barbara's file is
// rejected and Edsger handed nothing in, so they have none; Donald has no worksheet row.
TEST_F(Gradebook, AZipOfFeedbackFilesForMoodle) {
  auto r = with_worksheet("moodle-worksheet.csv", "html --out out");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // Barbara's file is rejected
  EXPECT_NE(r.err.find("the feedback page s6.html is no worksheet row's"), std::string::npos)
      << r.err;
  auto zip = testing::run_shell(kMoodleReads, dir_.path());
  ASSERT_EQ(zip.exit_code, 0) << zip.err;
  EXPECT_EQ(zip.out,
            "101 assignfeedback_file s1.html same\n"
            "102 assignfeedback_file s2-2.html same\n"
            "102 assignfeedback_file s2.html same\n"
            "103 assignfeedback_file s3.html same\n");
  // Without --out there is no folder for the zip.
  auto no_out = run_raygrade(
      "grade --assignment hw.json --roster roster.csv subs --format html "
      "--moodle-worksheet worksheet.csv",
      dir_.path());
  EXPECT_EQ(no_out.exit_code, 2);
}

TEST_F(Gradebook, AnUnknownChoiceIsRefused) {
  auto r = grade("--pick newest");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown --pick 'newest'"), std::string::npos) << r.err;
}

// Without a roster there is no student's set of submissions to choose from: --pick would do
// nothing, so it is refused rather than ignored.
TEST_F(Gradebook, PickWithoutARosterIsRefused) {
  auto r = run_raygrade("grade --assignment hw.json subs --format csv --pick best", dir_.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--pick chooses among a roster student's submissions: it needs --roster"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace raygrade
