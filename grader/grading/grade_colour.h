// Grading a colour [r, g, b]: channel by channel within the tolerance, the feedback naming the
// channels that are wrong; one number where a colour is asked is the named mistake
// scalar-for-colour. Shared by the kinds whose answers are colours (shade, ray-tree).
#pragma once

#include <string>
#include <vector>

#include "derivation/number_format.h"
#include "grading/answer_reader.h"
#include "grading/mistakes.h"
#include "grading/tolerance.h"

namespace raygrade {

struct ColourVerdict {
  double credit = 0;
  std::vector<std::string> feedback;  // empty when right
  std::vector<FoundMistake> mistakes;
};

// `name` is the part as the student sees it ("intensity").
ColourVerdict grade_colour(const std::string& name, const AnswerReader& given, const Vec3d& want,
                           const Tolerance& tolerance, const NumberFormat& numbers);

}  // namespace raygrade
