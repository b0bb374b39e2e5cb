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
    for (const auto& [name, file] : entries) command += fmt::format(" '{}' '{}'", name, file);
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
    entries.emplace_back(fmt::format("{}{}_{}_{}_answers.json", s.canvas_name, late, s.canvas_id,
                                     9000 + std::stoi(s.canvas_id)),
                         "subs/" + s.id + ".json");
  }
  entries.emplace_back("notes.txt", "notes.txt");
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
    entries.emplace_back(
        fmt::format("{}_{}_assignsubmission_file{}answers.json", s.name, s.participant, cut),
        "subs/" + s.id + ".json");
  }
  entries.emplace_back("Ada Lovelace_101_assignsubmission_onlinetext_onlinetext.html", "notes.txt");
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

// An empty field ties nothing: a worksheet row without an email address is no roster student's,
// not the one roster student who has no email (issue 47), in the Moodle zip and in the feedback
// zip for Moodle alike.
TEST_F(BulkSubmissions, BlankEmailOwnsNothing) {
  std::string roster = testing::class_roster_csv();
  roster.replace(roster.find("don@example.edu"), std::string("don@example.edu").size(), "");
  write_text(dir_.path() / "roster-blank.csv", roster);
  std::string sheet = read_text(dir_.path() / "worksheet.csv");
  sheet += "Participant 107,Mallory Intruder,,Submitted,,5.00,-\n";
  sheet.replace(sheet.find("don@example.edu"), std::string("don@example.edu").size(), "");
  write_text(dir_.path() / "worksheet-blank.csv", sheet);
  // Mallory's file (with s1's right answers, naming nobody) and Donald's own.
  write_text(dir_.path() / "mallory.json",
             fmt::format(R"({{"answers": {{{}, {}}}}})", kClassSphere, kClassPlane));
  zip("moodle.zip", {{"Mallory Intruder_107_assignsubmission_file/answers.json", "mallory.json"},
                     {"Donald Knuth_106_assignsubmission_file/answers.json", "subs/s6.json"}});
  // Donald's feedback page is not made of Mallory's file (nor of his own: row 106 has no email
  // either, so nothing ties it to him).
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster-blank.csv moodle.zip --format html --out "
      "zipped --moodle-worksheet worksheet-blank.csv --now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(dir_.path() / "zipped" / "s6.html"));
  EXPECT_NE(r.err.find("Mallory Intruder_107_assignsubmission_file/answers.json: error: not "
                       "graded: Moodle participant 107"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("no email address"), std::string::npos) << r.err;
  // Donald's file: row 106 has no email either, so it is tied to nobody.
  EXPECT_NE(r.err.find("Moodle participant 106"), std::string::npos) << r.err;
  // The feedback zip for Moodle: Donald's page (he has no email) goes in no row's folder.
  auto html = run_raygrade(
      "grade --assignment hw.json --roster roster-blank.csv subs/s6.json subs/s1.json --format "
      "html --out pages --moodle-worksheet worksheet-blank.csv --now 2026-12-01T00:00:00Z",
      dir_.path());
  auto list = run_shell(
      "/usr/bin/python3 -c 'import zipfile; print(\"\\n\".join(zipfile.ZipFile("
      "\"pages/moodle-feedback.zip\").namelist()))'",
      dir_.path());
  ASSERT_EQ(list.exit_code, 0) << list.err << html.err;
  EXPECT_EQ(list.out.find("Mallory"), std::string::npos) << list.out;
  EXPECT_EQ(list.out.find("_106_"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("Ada Lovelace_101_assignfeedback_file/s1.html"), std::string::npos)
      << list.out;
}

// Canvas writes a name in lower case without spaces; the roster's name is matched to it by
// Unicode's full case folding and normalisation (issue 47), not by ASCII's lower case alone:
// "zolaémile" is "Émile Zola" whichever of NFC or NFD either is written in, "straußhans" is
// "Hans STRAUSS" (ß folds to ss), and a name that folds to nothing matches nobody.
TEST_F(BulkSubmissions, CanvasNamesOutsideAscii) {
  const std::string e_nfc = "\xC3\x89", e_nfd = "E\xCC\x81";              // É
  const std::string e_small_nfc = "\xC3\xA9", e_small_nfd = "e\xCC\x81";  // é
  write_text(dir_.path() / "roster-u.csv",
             "id,name,email\n"
             "z1," +
                 e_nfc +
                 "mile Zola,zola@example.edu\n"
                 "z2," +
                 e_nfd +
                 "mile Zolb,zolb@example.edu\n"
                 "z3,Hans STRAUSS,hans@example.edu\n"
                 "z4,___,blank@example.edu\n");
  for (const char* id : {"z1", "z2", "z3"})
    write_text(dir_.path() / (std::string(id) + ".json"),
               fmt::format(R"({{"answers": {{{}}}}})", kClassSphere));
  write_text(dir_.path() / "z4.json", fmt::format(R"({{"answers": {{{}}}}})", kClassPlane));
  zip("canvas.zip", {{"zola" + e_small_nfd + "mile_2001_9001_answers.json", "z1.json"},
                     {"zolb" + e_small_nfc + "mile_2002_9002_answers.json", "z2.json"},
                     {"strau\xC3\x9F"
                      "hans_2003_9003_answers.json",
                      "z3.json"},
                     {"---_2004_9004_answers.json", "z4.json"}});
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster-u.csv canvas.zip --format csv "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  auto t = totals(r.out);
  EXPECT_EQ(t["z1"], "2") << r.out << r.err;
  EXPECT_EQ(t["z2"], "2") << r.out << r.err;
  EXPECT_EQ(t["z3"], "2") << r.out << r.err;
  EXPECT_EQ(t["z4"], "0") << r.out << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;  // "---" is nobody
  EXPECT_NE(r.err.find("Canvas's '---'"), std::string::npos) << r.err;
}

// A zip is read whole before anything is written: --out beside it is accepted whether it is
// written as an absolute or a relative path; only the zip itself is refused. A folder of
// submissions keeps --out out of it, written either way.
TEST_F(BulkSubmissions, OutBesideAZipAbsoluteOrRelative) {
  zip("canvas.zip", {{"lovelaceada_1001_9001_answers.json", "subs/s1.json"}});
  const std::string base =
      "grade --assignment hw.json --roster roster-canvas.csv canvas.zip "
      "--format html --now 2026-12-01T00:00:00Z --out ";
  auto relative = run_raygrade(base + "out-rel", dir_.path());
  EXPECT_EQ(relative.exit_code, 0) << relative.err;
  EXPECT_TRUE(fs::exists(dir_.path() / "out-rel" / "s1.html")) << relative.err;
  auto absolute = run_raygrade(base + "'" + (dir_.path() / "out-abs").string() + "'", dir_.path());
  EXPECT_EQ(absolute.exit_code, 0) << absolute.err;
  EXPECT_TRUE(fs::exists(dir_.path() / "out-abs" / "s1.html")) << absolute.err;
  auto itself = run_raygrade(base + "canvas.zip", dir_.path());
  EXPECT_EQ(itself.exit_code, 2) << itself.err;
  EXPECT_NE(itself.err.find("inside the submissions"), std::string::npos) << itself.err;
  const std::string folder =
      "grade --assignment hw.json --roster roster.csv subs --format html "
      "--now 2026-12-01T00:00:00Z --out ";
  auto in_rel = run_raygrade(folder + "subs/out", dir_.path());
  auto in_abs = run_raygrade(folder + "'" + (dir_.path() / "subs/out").string() + "'", dir_.path());
  for (const auto& r : {in_rel, in_abs}) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("inside the submissions"), std::string::npos) << r.err;
  }
}

// A file of the zip that is no JSON is its student's rejected submission (the platform says
// whose it is), not "no submission".
TEST_F(BulkSubmissions, AnEntryThatWillNotParseIsRejectedNotMissing) {
  write_text(dir_.path() / "broken.json", "{\"answers\": {");
  zip("canvas.zip", {{"lovelaceada_1001_9001_answers.json", "broken.json"},
                     {"turingalan_1002_9002_answers.json", "subs/s2.json"}});
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster-canvas.csv canvas.zip --format csv "
      "--now 2026-12-01T00:00:00Z",
      dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::string ada_row;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("Ada Lovelace,s1,", 0) == 0) ada_row = line;
  EXPECT_NE(ada_row.find("rejected"), std::string::npos) << r.out;
  EXPECT_EQ(ada_row.find("no submission"), std::string::npos) << r.out;
  EXPECT_EQ(totals(r.out)["s2"], "2") << r.out;
}

// One platform's naming for a whole zip: a file of a Canvas zip that its student named to look
// like Moodle's "<name>_<participant>_assignsubmission_file_<file>" is still the Canvas user's,
// not Moodle participant 102's (Alan's, on the worksheet).
TEST_F(BulkSubmissions, ACanvasFileNamedLikeMoodlesIsCanvas) {
  // Ada's file names no student, so only the zip's naming says whose it is.
  write_text(dir_.path() / "nameless.json",
             fmt::format(R"({{"answers": {{{}, {}}}}})", kClassSphere, kClassPlane));
  zip("canvas.zip",
      {{"lovelaceada_1001_9001_x_102_assignsubmission_file_answers.json", "nameless.json"},
       {"hopper grace_1003_9003_answers.json", "subs/s3.json"}});
  auto r = run_raygrade(
      "grade --assignment hw.json --roster roster-canvas.csv canvas.zip --format csv-moodle "
      "--moodle-worksheet worksheet.csv --now 2026-12-01T00:00:00Z",
      dir_.path());
  // Alan (participant 102) handed in nothing: his grade stays 0; Ada's file is Ada's.
  EXPECT_NE(r.out.find("Participant 102,Alan Turing,alan@example.edu,Submitted,0,5.00,-"),
            std::string::npos)
      << r.out << r.err;
  EXPECT_NE(r.out.find("Participant 101,Ada Lovelace,ada@example.edu,Submitted,5,5.00,-"),
            std::string::npos)
      << r.out << r.err;
  EXPECT_NE(r.out.find("Participant 103,Grace Hopper,grace@example.edu,Submitted,3,5.00,-"),
            std::string::npos)
      << r.out << r.err;
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
