// Typed reading of JSON values with file and path in every diagnostic.
#include "json/cursor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raygrade {
namespace {

const char* type_name(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

}  // namespace

std::string pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

Cursor::Cursor(std::shared_ptr<const SourceFile> file, const nlohmann::json* value,
               std::string path)
    : file_(std::move(file)), value_(value), path_(std::move(path)) {}

Cursor::Cursor(std::shared_ptr<const SourceFile> file)
    : file_(std::move(file)), value_(&file_->root), path_("") {}

const std::string& Cursor::file_name() const { return file_->name; }

bool Cursor::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

std::optional<Cursor> Cursor::find(std::string_view key) const {
  if (!value_->is_object()) fail(fmt::format("expected an object, found {}", type_name(*value_)));
  auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return Cursor(file_, &*it, path_ + "/" + pointer_token(key));
}

Cursor Cursor::at(std::string_view key) const {
  auto c = find(key);
  if (!c) fail(fmt::format("missing required key '{}'", key), "missing-key");
  return *c;
}

std::vector<Cursor> Cursor::items() const {
  if (!value_->is_array()) fail(fmt::format("expected an array, found {}", type_name(*value_)));
  std::vector<Cursor> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back(file_, &(*value_)[i], fmt::format("{}/{}", path_, i));
  }
  return out;
}

double Cursor::number() const {
  if (!value_->is_number()) {
    fail(fmt::format("expected a number, found {}", type_name(*value_)), "type");
  }
  double v = value_->get<double>();
  if (!std::isfinite(v))
    fail("number out of range: beyond what a double holds (about ±1.8e308)", "range");
  return v;
}

double Cursor::positive_number() const {
  double v = number();
  if (!(v > 0)) fail(fmt::format("must be positive, found {}", v), "degenerate");
  return v;
}

int Cursor::integer() const {
  if (!value_->is_number_integer()) {
    fail(fmt::format("expected an integer, found {}", type_name(*value_)), "type");
  }
  auto v = value_->get<long long>();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    fail("integer out of range", "range");
  }
  return static_cast<int>(v);
}

bool Cursor::boolean() const {
  if (!value_->is_boolean()) {
    fail(fmt::format("expected true or false, found {}", type_name(*value_)), "type");
  }
  return value_->get<bool>();
}

std::string Cursor::string() const {
  if (!value_->is_string()) {
    fail(fmt::format("expected a string, found {}", type_name(*value_)), "type");
  }
  return value_->get<std::string>();
}

Vec3d Cursor::vec3() const {
  if (!value_->is_array() || value_->size() != 3) {
    fail(value_->is_array()
             ? fmt::format("expected 3 numbers [x, y, z], found {} elements", value_->size())
             : fmt::format("expected 3 numbers [x, y, z], found {}", type_name(*value_)),
         "type");
  }
  auto e = items();
  return {e[0].number(), e[1].number(), e[2].number()};
}

Vec3d Cursor::nonzero_vec3() const {
  Vec3d v = vec3();
  if (v.x == 0 && v.y == 0 && v.z == 0) fail("must not be the zero vector", "degenerate");
  if (!std::isfinite(length_squared(v))) fail("vector too long: its length overflows", "range");
  return v;
}

double Cursor::number_or(std::string_view key, double fallback) const {
  auto c = find(key);
  return c ? c->number() : fallback;
}

std::string Cursor::string_or(std::string_view key, std::string fallback) const {
  auto c = find(key);
  return c ? c->string() : std::move(fallback);
}

bool Cursor::boolean_or(std::string_view key, bool fallback) const {
  auto c = find(key);
  return c ? c->boolean() : fallback;
}

void Cursor::allow_only(std::initializer_list<std::string_view> allowed) const {
  std::vector<std::string> keys(allowed.begin(), allowed.end());
  allow_only(keys);
}

void Cursor::allow_only(const std::vector<std::string>& allowed) const {
  if (!value_->is_object()) fail(fmt::format("expected an object, found {}", type_name(*value_)));
  for (const auto& [key, value] : value_->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    Cursor member(file_, &value, path_ + "/" + pointer_token(key));
    std::string hint = closest_match(key, allowed);
    member.fail(hint.empty() ? fmt::format("unknown key '{}'", key)
                             : fmt::format("unknown key '{}' (did you mean '{}'?)", key, hint),
                "unknown-key");
  }
}

Diagnostic Cursor::diagnostic(std::string message, std::string code, Severity severity) const {
  auto [line, column] = file_->locate(path_);
  return Diagnostic{file_->name,        path_,          line, column, severity,
                    std::move(message), std::move(code)};
}

void Cursor::fail(std::string message, std::string code) const {
  throw Error(diagnostic(std::move(message), std::move(code)));
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace raygrade
