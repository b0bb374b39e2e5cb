// The JSON path of the error that reading an object gives, for the tests of the primitives.
#pragma once

#include <string>

#include "core/error.h"
#include "test_util.h"

namespace raygrade::testing {

// The path of the Error that reading `text` as an object throws, or "no error".
inline std::string shape_error_path(const std::string& text) {
  try {
    shape(text);
  } catch (const Error& e) {
    return e.diagnostic().path;
  }
  return "no error";
}

}  // namespace raygrade::testing
