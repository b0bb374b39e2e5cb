// The diagnostic codes of the bank check, with what each means.
#include "check/check.h"

namespace raygrade {

const std::vector<DiagnosticCode>& check_codes() {
  static const std::vector<DiagnosticCode> codes = {
      // Reading: the file and the problem format.
      {"unreadable", "a file or folder cannot be opened or read (exit code 2)"},
      {"limit", "a file is over a size, nesting or string length limit (exit code 2)"},
      {"bad-json", "the file is not valid JSON"},
      {"type", "a value has the wrong type (a string where a number belongs)"},
      {"missing-key", "a required key is missing"},
      {"unknown-key", "a key the format does not know, with the closest known one"},
      {"range", "a number is out of range (not finite, a precision above 15)"},
      {"invalid", "a value breaks a rule of the format (t_max below t_min, an empty id)"},
      {"degenerate", "degenerate geometry: zero direction or radius, collinear vertices"},
      {"undefined-normal",
       "an interpolate problem's vertex normals blend to no direction at its point: they cancel, "
       "or one is too short to be made unit"},
      {"off-surface", "the point of a normal problem is not on the object's surface (how far off)"},
      {"unknown-kind", "an unknown problem kind"},
      {"unknown-type", "an unknown object type"},
      {"unknown-method", "a method the problem's kind does not have"},
      {"duplicate-id", "two problems share an id"},
      {"duplicate-name", "two objects of a first-hit problem share a name"},
      // The stated answer.
      {"wrong-expected", "the stated answer differs from the reference beyond the tolerance"},
      {"negative-t", "a hit is listed at t < t_min: behind the ray's origin"},
      {"beyond-t-max", "a hit is listed at t > t_max"},
      // Ill-posed problems.
      {"nearly-tangent",
       "the ray passes within the tolerance of a boundary (tangent, edge, vertex): a small "
       "rounding turns a hit into a miss or two hits into one"},
      {"near-tie", "two objects of a first-hit problem are hit within the tolerance of each other"},
      {"tie", "two objects are first hit at exactly the same t (warning)"},
      {"ill-conditioned",
       "moving an input by half a unit in its last printed digit changes the outcome, or moves "
       "the answer over 100 times as much as the input"},
      {"inexact-boundary",
       "a note beside wrong-expected: the ray passes within 1e-9 of a boundary, so a tangent "
       "exact in decimals may not be exact in binary"},
      {"duplicate-geometry", "the same ray, object and method as another problem"},
      {"no-solution", "no worked solution for the problem in the solutions folder"},
      {"no-solutions-folder",
       "the solutions folder does not exist (a warning by default, an error when named with "
       "--solutions)"},
      {"solutions-folder",
       "a note: the solutions folder the check found, and the places it looked in first"},
      // Self-tests.
      {"self-test", "a sample answer gets a different score or mistake than its test states"},
      // Assignments.
      {"unknown-problem", "an assignment names a problem its bank does not have"},
      {"no-variant", "no draw of a problem's parameters passes the checks in 100 tries"},
      {"not-nice", "a variant's answer has more decimals than its nice_numbers allow"},
  };
  return codes;
}

}  // namespace raygrade
