// Checking an assignment: its file, its problems in the bank, and a sample of variants.
#pragma once

#include <cstddef>
#include <string>

#include "check/check.h"

namespace raygrade {

// Sample students whose variants `raygrade check` draws for every problem with parameters:
// "sample-001" to "sample-032". Enough to meet a parameter range that often fails its checks,
// few enough to check a homework in a few seconds.
constexpr int kSampleStudents = 32;

// Draws of each problem's parameters that `raygrade check` checks one by one (the stated answer
// on each, the reasons draws are rejected, parameters whose values collapse), and how many
// draws with a wrong stated answer it names before it only counts them.
constexpr int kCheckDraws = 200;
constexpr std::size_t kReportedWrongDraws = 10;

// One result per problem of the assignment (its variants' findings), and the assignment
// file's own faults. Findings of the bank's other problems are `raygrade check BANK`'s.
CheckReport check_assignment(const std::string& path);

}  // namespace raygrade
