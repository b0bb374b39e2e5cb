// Collecting number literals with their JSON pointers, by a SAX pass over the text.
#include "check/literals.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <vector>

#include "json/cursor.h"

namespace raygrade {
namespace {

// Follows the JSON pointer of the current value through nested objects and arrays.
class LiteralCollector : public nlohmann::json_sax<nlohmann::json> {
 public:
  explicit LiteralCollector(NumberLiterals& out) : out_(out) {}

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t& s) override {
    out_[pointer()] = s;
    return value();
  }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    frames_.push_back(Frame{false, 0, {}});
    return true;
  }
  bool key(string_t& k) override {
    frames_.back().key = pointer_token(k);
    return true;
  }
  bool end_object() override {
    frames_.pop_back();
    return value();
  }
  bool start_array(std::size_t) override {
    frames_.push_back(Frame{true, 0, {}});
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return value();
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
  };

  std::string pointer() const {
    std::string p;
    for (const auto& f : frames_) {
      p += '/';
      p += f.array ? std::to_string(f.index) : f.key;
    }
    return p;
  }
  // A value ended: the next element of an enclosing array comes next.
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }

  NumberLiterals& out_;
  std::vector<Frame> frames_;
};

}  // namespace

NumberLiterals scan_number_literals(std::string_view text) {
  NumberLiterals out;
  LiteralCollector collector(out);
  if (!nlohmann::json::sax_parse(text.begin(), text.end(), &collector)) return {};
  return out;
}

int printed_decimals(std::string_view literal) {
  std::size_t e = literal.find_first_of("eE");
  std::string_view mantissa = literal.substr(0, e);
  int decimals = 0;
  if (auto dot = mantissa.find('.'); dot != std::string_view::npos) {
    decimals = static_cast<int>(mantissa.size() - dot - 1);
  }
  if (e != std::string_view::npos) {
    decimals -= std::atoi(std::string(literal.substr(e + 1)).c_str());
  }
  return decimals;
}

int significant_digits(std::string_view literal) {
  std::string_view mantissa = literal.substr(0, literal.find_first_of("eE"));
  int digits = 0;
  bool leading = true;
  for (char c : mantissa) {
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++digits;
  }
  return std::max(digits, 1);
}

double half_unit(std::string_view literal) {
  return 0.5 * std::pow(10.0, -printed_decimals(literal));
}

}  // namespace raygrade
