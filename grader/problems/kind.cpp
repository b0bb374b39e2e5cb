// The names of the comparisons of parts.
#include "problems/kind.h"

namespace raygrade {

const char* to_string(Comparison c) {
  switch (c) {
    case Comparison::kScalar: return "scalar";
    case Comparison::kPoint: return "point";
    case Comparison::kDirection: return "direction";
    case Comparison::kUnitDirection: return "unit direction";
    case Comparison::kHits: return "set of hits";
    case Comparison::kWeights: return "weights";
    case Comparison::kName: return "name";
    case Comparison::kFlag: return "flag";
    case Comparison::kNames: return "set of names";
    case Comparison::kFormula: return "formula";
    case Comparison::kTree: return "tree";
    case Comparison::kSteps: return "steps";
    case Comparison::kRows: return "rows";
  }
  return "scalar";
}

}  // namespace raygrade
