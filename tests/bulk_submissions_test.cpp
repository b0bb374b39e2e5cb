// Grading the zip of a Canvas or Moodle assignment's "download all submissions": each file tied
// to its student by the platform's own file naming (Canvas: "<lastfirst>[_LATE]_<user id>_
// <submission id>_<file>"; Moodle: "<full name>_<participant>_assignsubmission_file/<file>"),
// graded to the same scores as the same files one by one, and to the scores worked out by hand.
// The zips are written by Python's zipfile, deflated, as the platforms write theirs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "roster_fixture.h"
#include "run_binary.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_raygrade;
using testing::run_shell;
using testing::TempDir;
using testing::write_text;

using testing::kClassPlane;
using testing::kClassSphere;

// A student of the class, as Canvas and Moodle name them, with the answers handed in.
struct Student : testing::FixtureStudent {
  std::string canvas_id, canvas_name, participant, answers;
  double points;  // by hand: 2 for the sphere, 3 for the plane, nothing for no answer
};

std::vector<Student> six() {
  auto both = fmt::format("{}, {}", kClassSphere, kClassPlane);
  auto c = testing::class_students();
  return {
      {c[0], "1001", "lovelaceada", "101", both, 5},
      {c[1], "1002", "turingalan", "102", kClassSphere, 2},
      {c[2], "1003", "hoppergrace", "103", kClassPlane, 3},
      {c[3], "1004", "dijkstraedsger", "104", both, 5},
      {c[4], "1005", "liskovbarbara", "105", kClassPlane, 3},
      {c[5], "1006", "knuthdonald", "106", "", 0},
  };
}

// Writes a deflated zip `zip` of the files `entries` ({name in the zip, file}).
constexpr const char* kZip = R"(/usr/bin/python3 -c '
import sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w", zipfile.ZIP_DEFLATED) as z:
    for i in range(2, len(sys.argv), 2):
        z.write(sys.argv[i + 1], sys.argv[i])
' )";

// The "total" of each student in a gradebook in raygrade's CSV layout, by id.
std::map<std::string, std::string> totals(const std::string& csv) {
  std::map<std::string, std::string> out;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // the header: student,id,email,file,sphere-1,plane-1,total,...
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    std::string cell;
    while (cells.size() < 7 && std::getline(row, cell, ',')) cells.push_back(cell);
    if (cells.size() == 7) out[cells[1]] = cells[6];
  }
  return out;
}

class BulkSubmissions : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::write_class_assignment(dir_.path());
    std::string canvas_roster = "id,name,email,canvas_id\n";
    std::string worksheet =
        "Identifier,Full name,Email address,Status,Grade,Maximum Grade,Last modified "
        "(grade)\n";
    fs::create_directories(dir_.path() / "subs");
    for (const auto& s : students_) {
      canvas_roster += fmt::format("{},{},{},{}\n", s.id, s.name, s.email, s.canvas_id);
      worksheet +=
          fmt::format("Participant {},{},{},Submitted,,5.00,-\n", s.participant, s.name, s.email);
      write_text(
          dir_.path() / "subs" / (s.id + ".json"),
          fmt::format(R"({{"student": {{"id": "{}"}}, "answers": {{{}}}}})", s.id, s.answers));
    }
    write_text(dir_.path() / "roster.csv", testing::class_roster_csv());
    write_text(dir_.path() / "roster-canvas.csv", canvas_roster);
    write_text(dir_.path() / "worksheet.csv", worksheet);
    write_text(dir_.path() / "notes.txt", "not a submission\n");
  }

  // Zips `entries` ({name in the zip, file under the test's folder}) into `zip`.
  void zip(const std::string& zip,
           const std::vector<std::pair<std::string, std::string>>& entries) {
    std::string command = std::string(kZip) + "'" + zip + "'";
    for (const auto& [name, file] : entries) command += " '" + name + "' '" + file + "'";
    auto r = run_shell(command, dir_.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }

  // Each student's total, each file graded alone.
  std::map<std::string, std::string> one_by_one() {
    std::map<std::string, std::string> out;
    for (const auto& s : students_) {
      auto r =
          run_raygrade(fmt::format("grade --assignment hw.json subs/{}.json --format csv --now "
                                   "2026-12-01T00:00:00Z",
                                   s.id),
                       dir_.path());
      EXPECT_EQ(r.exit_code, 0) << r.err;
      auto t = totals(r.out);
      if (t.count(s.id)) out[s.id] = t[s.id];
    }
    return out;
  }

  std::map<std::string, std::string> by_hand() const {
    std::map<std::string, std::string> out;
    for (const auto& s : students_) out[s.id] = fmt::format("{}", s.points);
    return out;
  }

  std::vector<Student> students_ = six();
  TempDir dir_{"bulk"};
};

// Canvas: the files named by Canvas's user id (a late one among them), tied through the
// roster's canvas_id column; a file named by no student is an error for that file alone.
TEST_F(BulkSubmissions, CanvasZipGradesAsTheFilesOneByOne) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& s : students_) {
    std::string late = s.id == "s2" ? "_LATE" : "";
    entries.push_back({fmt::format("{}{}_{}_{}_answers.json", s.canvas_name, late, s.canvas_id,
                                   9000 + std::stoi(s.canvas_id)),
                       "subs/" + s.id + ".json"});
  }
  entries.push_back({"notes.txt", "notes.txt"});
  zip("canvas.zip", entries);
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster-canvas.csv canvas.zip --format csv "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;  // notes.txt names no student
  EXPECT_NE(r.err.find("canvas.zip/notes.txt: error: not graded: the file's name names no "
                       "student"),
            std::string::npos)
      << r.err;
  auto zipped = totals(r.out);
  EXPECT_EQ(zipped, by_hand()) << r.out;
  EXPECT_EQ(zipped, one_by_one());
  EXPECT_NE(r.out.find("canvas.zip/turingalan_LATE_1002_10002_answers.json"), std::string::npos)
      << r.out;
  // Canvas's own layout carries the Canvas user ID that tied each file, in its ID column.
  auto book = run_raygrade(
      "grade --assignment hw.json --roster roster-canvas.csv canvas.zip --format csv-canvas "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  for (const auto& s : students_) {
    EXPECT_NE(book.out.find(
                  fmt::format("\n{},{},{},{},,{}\n", s.name, s.canvas_id, s.id, s.email, s.points)),
              std::string::npos)
        << s.id << "\n"
        << book.out;
  }
}

// Without a canvas_id column, Canvas's name ("lovelaceada") finds the student; a file whose
// submission names another student than the one Canvas says handed it in is refused.
TEST_F(BulkSubmissions, CanvasByNameAndNotSomeoneElsesFile) {
  zip("canvas.zip", {{"lovelaceada_1001_9001_answers.json", "subs/s1.json"},
                     {"turingalan_1002_9002_answers.json", "subs/s4.json"},
                     {"nobodyknown_1009_9009_answers.json", "subs/s3.json"}});
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster.csv canvas.zip --format csv "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  auto t = totals(r.out);
  EXPECT_EQ(t["s1"], "5");
  EXPECT_EQ(t["s2"], "0");  // s4's file, handed in by Alan
  EXPECT_NE(r.err.find("the submission names student 's4', but Canvas says student 's2'"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("Canvas's 'nobodyknown' (user 1009; the roster has no canvas_id column "
                       "to find it by) is no roster student"),
            std::string::npos)
      << r.err;
}

// Moodle: folders (its default) and flat names mixed, tied through the grading worksheet's
// participant numbers and emails.
TEST_F(BulkSubmissions, MoodleZipGradesAsTheFilesOneByOne) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& s : students_) {
    char cut = s.id == "s3" || s.id == "s5" ? '_' : '/';
    entries.push_back(
        {fmt::format("{}_{}_assignsubmission_file{}answers.json", s.name, s.participant, cut),
         "subs/" + s.id + ".json"});
  }
  entries.push_back({"Ada Lovelace_101_assignsubmission_onlinetext_onlinetext.html", "notes.txt"});
  zip("moodle.zip", entries);
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster.csv moodle.zip --format csv-moodle "
      "--moodle-worksheet worksheet.csv --now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;  // the online text is no .json submission
  EXPECT_NE(r.err.find("onlinetext.html is not a .json submission"), std::string::npos) << r.err;
  // The worksheet filled in: each participant's Grade, by hand.
  for (const auto& s : students_) {
    EXPECT_NE(r.out.find(fmt::format("Participant {},{},{},Submitted,{},5.00,-", s.participant,
                                     s.name, s.email, s.points)),
              std::string::npos)
        << s.id << "\n"
        << r.out;
  }
  // And raygrade's own gradebook, without the worksheet (by full name), the same as one by one.
  auto own = run_raygrade(
      "grade --assignment hw.json --roster roster.csv moodle.zip --format csv "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  auto zipped = totals(own.out);
  EXPECT_EQ(zipped, by_hand()) << own.out << own.err;
  EXPECT_EQ(zipped, one_by_one());
}

// A zip needs the assignment and its roster; one that is not a zip is an error of its own.
TEST_F(BulkSubmissions, ZipNeedsTheRosterAndMustBeAZip) {
  zip("canvas.zip", {{"lovelaceada_1001_9001_answers.json", "subs/s1.json"}});
  auto r = run_raygrade("grade --assignment hw.json canvas.zip --format csv", dir_.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("needs --assignment and --roster"), std::string::npos) << r.err;
  write_text(dir_.path() / "broken.zip", "PK not really");
  auto b = run_raygrade(
      "grade --assignment hw.json --roster roster.csv broken.zip canvas.zip --format csv "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("broken.zip: error: cannot read the zip archive"), std::string::npos)
      << b.err;
  EXPECT_EQ(totals(b.out)["s1"], "5") << b.out;
}

}  // namespace
}  // namespace raygrade
