// Number literals as printed in a JSON file: how many digits each input was written with.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace raygrade {

// The text of every non-integer number literal of a JSON document ("0.8", "7.2679", "1e-3"),
// by JSON pointer. Integer literals ("2", "-3") are not listed: they are exact.
using NumberLiterals = std::map<std::string, std::string>;

// Scans `text` (already known to be valid JSON). Returns an empty map if it does not parse.
NumberLiterals scan_number_literals(std::string_view text);

// The decimal place of a literal's last printed digit: 1 for "0.8", 4 for "7.2679", 3 for
// "1e-3", -1 for "1.5e2" (printed to the tens), 0 for an integer.
int printed_decimals(std::string_view literal);

// The significant digits a literal is printed with: 1 for "0.8", 3 for "0.00125" and "1.50",
// 5 for "7.2679".
int significant_digits(std::string_view literal);

// Half a unit in the last printed digit: 0.05 for "0.8", 0.00005 for "7.2679".
double half_unit(std::string_view literal);

}  // namespace raygrade
