// Tolerances: when a student's number counts as the reference number. Three modes (relative
// plus absolute, significant figures, decimal places), per problem and per field, and the
// "insufficient precision" verdict for a right answer given with too few digits.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "derivation/formula.h"
#include "derivation/number_format.h"
#include "problems/problem.h"

namespace raygrade {

// WeBWorK's default: a relative tolerance of 0.1% (its `tolerance` of 0.001, `tolType`
// relative). Hand computations with four significant figures pass; three usually do.
constexpr double kDefaultRelative = 1e-3;
// The absolute floor for a reference of zero (a hit at t = 0, a zero component of a step):
// WeBWorK's zero level is 1e-14 with a tolerance of 1e-12; hand-typed answers are coarser,
// so raygrade accepts |x| ≤ 1e-6 for a zero reference. Relative tolerances of a vector's
// component refer to the vector's length, so zero components of (0, 0, 7.27) need no floor.
constexpr double kDefaultAbsolute = 1e-6;
// Half a unit of the last digit, with PrairieLearn's margin of 2% (its sigfig and decdig
// comparisons allow 0.51 units) so that a correctly rounded answer is never refused because
// of binary floating point.
constexpr double kHalfUnit = 0.51;

enum class ToleranceMode { kRelAbs, kSigFigs, kDecimals };

struct Tolerance {
  ToleranceMode mode = ToleranceMode::kRelAbs;
  double rtol = kDefaultRelative;
  double atol = kDefaultAbsolute;
  int digits = 0;               // significant figures or decimal places, by mode
  double precision_credit = 0;  // credit for a right answer with too few digits (0 to 1)
};

// A number as the student gave it.
struct StudentNumber {
  double value = 0;
  TypedDigits digits;  // literal = false for expressions ("1/3") and exact integers
  std::string text;    // as typed, for messages
};

enum class Match { kRight, kInsufficientPrecision, kWrong };

struct NumberVerdict {
  Match match = Match::kWrong;
  double allowed = 0;   // the largest error accepted
  std::string message;  // for kInsufficientPrecision: what more is needed
};

// The largest accepted error for `reference`. `scale` is what relative tolerances refer to
// (|reference| for a scalar, the vector's length for a component); `widen` is an allowance
// from the problem's conditioning (near a tangent).
double allowed_error(double reference, double scale, const Tolerance& t, double widen = 0);

NumberVerdict compare_number(const StudentNumber& s, double reference, double scale,
                             const Tolerance& t, double widen = 0);

// Compares vectors component by component, relative to the reference's length.
NumberVerdict compare_vector(const StudentNumber (&s)[3], const Vec3d& reference,
                             const Tolerance& t, double widen = 0);

// A direction: any positive multiple of `reference` is right. The student's vector is scaled
// to unit length and compared with the unit reference by the same rule as any number, so a
// unit vector rounded to too few digits is "too imprecise", as a rounded t is.
struct DirectionVerdict {
  NumberVerdict verdict;
  double length = 0;      // the student's vector's length (0: not a direction)
  bool opposite = false;  // a positive multiple of −reference
};
DirectionVerdict compare_direction(const StudentNumber (&s)[3], const Vec3d& reference,
                                   const Tolerance& t);

// How far a unit vector's length may be from 1 (relative) and still be a unit vector.
constexpr double kUnitAnswerLength = 1e-3;

// One value of an answer against its reference by the rule of its part (Comparison): a number
// by the tolerance (kScalar, and each t of kHits); three numbers each by the tolerance relative
// to the vector's length (kPoint, kWeights); any positive multiple of the reference
// (kDirection); the reference scaled to length 1 (kUnitDirection). The graders and the mistake
// search (grading/discover.h) both compare through it, so that a change explains an answer
// exactly when the grader would count the change's numbers right.
struct PartVerdict {
  NumberVerdict verdict;
  double length = 0;      // a direction's length (0: the zero vector, never right)
  bool opposite = false;  // a direction that is a positive multiple of −reference
  bool not_unit = false;  // kUnitDirection: the right way, but not of length 1 (kWrong)
};
PartVerdict compare_part(Comparison how, const StudentNumber& s, double reference,
                         const Tolerance& t, double widen = 0);
PartVerdict compare_part(Comparison how, const StudentNumber (&s)[3], const Vec3d& reference,
                         const Tolerance& t, double widen = 0);

// An object's name as the graders compare it (Comparison::kName): case, spaces, '-' and '_'
// ignored. The first-hit grader and the mistake search both compare names by it.
std::string name_as_compared(const std::string& s);
bool same_object_name(const std::string& a, const std::string& b);

// "relative 0.1%", "3 significant figures", "2 decimal places".
std::string describe(const Tolerance& t);

// How to show `reference` in feedback on an answer compared with `t`: with at least the
// decimals the comparison tells apart (5 decimals graded, 5 shown: "0.87677", not "0.8768"),
// and never fewer than `base` shows.
NumberFormat shown_at(const Tolerance& t, double reference, NumberFormat base);

// A problem's tolerances: the default for every field, and overrides by field name.
struct TolerancePolicy {
  Tolerance base;
  std::map<std::string, Tolerance, std::less<>> fields;
  const Tolerance& for_field(std::string_view field) const;
};

// The field names a problem's `tolerance` object may name.
const std::vector<std::string>& tolerance_fields();

// Reads a problem's `tolerance` (a number: relative; or an object, see docs/grading.md).
// Without one, a problem with `precision` k is graded to k decimal places, others by the
// defaults above. Throws Error naming the file and path of a fault.
TolerancePolicy read_tolerance_policy(const Problem& p);

}  // namespace raygrade
