// Numbers in the JSON raygrade writes.
#pragma once

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

}  // namespace raygrade
