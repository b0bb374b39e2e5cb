// The class the gradebook and bulk-submission tests grade: a bank of two problems whose answers
// are worked by hand, the assignment that gives them points, and the six students of
// tests/data/gradebook/roster.csv.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "run_binary.h"

namespace raygrade::testing {

// The ray (0,0,0) + t (1,0,0) meets the unit sphere at (2,0,0) at t = 1 and 3, and the plane
// x = 2 at t = 2.
inline constexpr const char* kClassBank = R"({"problems": [
  {"id": "sphere-1", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
   "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}},
  {"id": "plane-1", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
   "object": {"type": "plane", "point": [2, 0, 0], "normal": [-1, 0, 0]}}]})";
// Their right answers, each a member of a submission's "answers".
inline constexpr const char* kClassSphere = R"("sphere-1": {"hits": [{"t": 1, "point": [1, 0, 0]},
                                                       {"t": 3, "point": [3, 0, 0]}]})";
inline constexpr const char* kClassPlane = R"("plane-1": {"hits": [{"t": 2, "point": [2, 0, 0]}]})";

// Writes the bank (bank.json) and the assignment hw.json into `dir`: the sphere for 2 points,
// the plane for 3, and the title `title` when it is not empty.
inline void write_class_assignment(const std::filesystem::path& dir,
                                   const std::string& title = "") {
  write_text(dir / "bank.json", kClassBank);
  write_text(
      dir / "hw.json",
      std::string(R"({"assignment": "hw", "bank": "bank.json", )") +
          (title.empty() ? std::string() : R"("title": ")" + title + R"(", )") +
          R"("problems": [{"id": "sphere-1", "points": 2}, {"id": "plane-1", "points": 3}]})");
}

struct FixtureStudent {
  std::string id, name, email;
};

// The six students, in the roster's order.
inline std::vector<FixtureStudent> class_students() {
  return {
      {"s1", "Ada Lovelace", "ada@example.edu"},
      {"s2", "Alan Turing", "alan@example.edu"},
      {"s3", "Grace Hopper", "grace@example.edu"},
      {"s4", "Edsger Dijkstra", "edsger@example.edu"},
      {"s5", "Barbara Liskov", "barbara@example.edu"},
      {"s6", "Donald Knuth", "don@example.edu"},
  };
}

// Their roster, as tests/data/gradebook/roster.csv has it: id, name, email.
inline std::string class_roster_csv() {
  std::string csv = "id,name,email\n";
  for (const auto& s : class_students()) csv += s.id + "," + s.name + "," + s.email + "\n";
  return csv;
}

}  // namespace raygrade::testing
