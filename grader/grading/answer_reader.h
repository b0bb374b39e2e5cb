// AnswerReader: a student's answer (JSON) with the file and JSON path of every value, for
// reading typed numbers and vectors and reporting faults exactly where they are.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "grading/tolerance.h"

namespace raygrade {

class AnswerReader {
 public:
  AnswerReader(const nlohmann::json& value, const std::string* file, std::string path)
      : value_(&value), file_(file), path_(std::move(path)) {}

  const nlohmann::json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  bool has(std::string_view key) const;
  AnswerReader at(std::string_view key) const;  // the key must exist
  std::vector<AnswerReader> items() const;      // must be an array
  std::string string() const;                   // must be a string
  // The object's keys must be among `allowed`; the first other one is an error.
  void allow_only(const std::vector<std::string>& allowed) const;
  [[noreturn]] void fail(const std::string& message, const std::string& code = "invalid") const;

  // A number as a student types it: a JSON number or a string like "1/3". A string that does
  // not parse gives `fault` (pointing at the character); other JSON types throw Error.
  struct Number {
    std::optional<StudentNumber> value;
    std::string fault;
  };
  Number number() const;

  // Three typed numbers. (The index __i0 is the compiler's, in the copy constructor it writes
  // for the array member.)
  // NOLINTNEXTLINE(bugprone-reserved-identifier)
  struct Vector {
    bool ok = false;
    StudentNumber c[3];
    std::string fault;
    Vec3d value() const { return {c[0].value, c[1].value, c[2].value}; }
  };
  Vector vector() const;

 private:
  const nlohmann::json* value_;
  const std::string* file_;
  std::string path_;
};

// A student number from text (as typed); `fault` says what is wrong when it does not parse.
AnswerReader::Number parse_student_number(std::string_view text);

}  // namespace raygrade
