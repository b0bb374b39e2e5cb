// Numbers in the JSON raygrade writes, and JSON written into a page.
#pragma once

#include <string>

namespace raygrade {

// Every -0.0 in `j` (a nlohmann::json or ordered_json) made 0.0: a weight or coordinate that is
// zero is written "0.0", never "-0.0", whichever side the arithmetic reached it from.
template <class Json>
void drop_negative_zeros(Json& j) {
  if (j.is_number_float()) {
    if (j.template get<double>() == 0) j = 0.0;
  } else if (j.is_structured()) {
    for (auto& element : j) drop_negative_zeros(element);
  }
}

template <class Json>
Json without_negative_zeros(Json j) {
  drop_negative_zeros(j);
  return j;
}

// `j` as the text of a <script type="application/json"> element: compact, without negative
// zeros, ill-formed UTF-8 replaced, and no "<", ">" or "&" that could end the element or start
// markup (each written as its \u escape, which JSON.parse reads back unchanged).
template <class Json>
std::string script_json(const Json& j) {
  std::string text = without_negative_zeros(j).dump(-1, ' ', false, Json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace raygrade
