// Cursor: a JSON value together with the file and JSON path it came from, for typed reading
// with diagnostics that say exactly where a fault is.
#pragma once

#include <initializer_list>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "json/source.h"
#include "math/vec3.h"

namespace raygrade {

class Cursor {
 public:
  Cursor(std::shared_ptr<const SourceFile> file, const nlohmann::json* value, std::string path);
  // The root of a file.
  explicit Cursor(std::shared_ptr<const SourceFile> file);

  const nlohmann::json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& file_name() const;
  const std::shared_ptr<const SourceFile>& file() const { return file_; }

  bool is_object() const { return value_->is_object(); }
  bool is_array() const { return value_->is_array(); }
  bool has(std::string_view key) const;

  // The member `key`; a missing member is an error.
  Cursor at(std::string_view key) const;
  std::optional<Cursor> find(std::string_view key) const;
  // The elements of an array (an error if this is not an array).
  std::vector<Cursor> items() const;

  double number() const;  // finite
  double positive_number() const;
  int integer() const;
  bool boolean() const;
  std::string string() const;
  Vec3d vec3() const;
  Vec3d nonzero_vec3() const;

  double number_or(std::string_view key, double fallback) const;
  std::string string_or(std::string_view key, std::string fallback) const;
  bool boolean_or(std::string_view key, bool fallback) const;

  // Every member key must be in `allowed`; the first other one is an error that suggests the
  // closest allowed key ("unknown key 'raduis' (did you mean 'radius'?)").
  void allow_only(std::initializer_list<std::string_view> allowed) const;
  void allow_only(const std::vector<std::string>& allowed) const;

  Diagnostic diagnostic(std::string message, std::string code = "invalid",
                        Severity severity = Severity::kError) const;
  [[noreturn]] void fail(std::string message, std::string code = "invalid") const;

 private:
  std::shared_ptr<const SourceFile> file_;
  const nlohmann::json* value_;
  std::string path_;
};

// Levenshtein distance, for "did you mean" suggestions.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest candidate within a small edit distance, or empty.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

// A JSON pointer token with '~' and '/' escaped.
std::string pointer_token(std::string_view key);

}  // namespace raygrade
