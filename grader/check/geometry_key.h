// The geometry of a problem as a string: two problems with the same key ask the same thing.
#pragma once

#include <string>

#include "problems/problem.h"

namespace raygrade {

// The kind, method, ray (its direction scaled to unit length, its t range with it) and
// object(s) in canonical form, numbers to 12 significant digits; first-hit objects in any
// order. Ids, titles and statements do not count.
std::string geometry_key(const Problem& p);

}  // namespace raygrade
