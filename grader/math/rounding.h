// The three roundings of the precision ladder's arithmetic: to nearest (ties to even), down
// (towards −∞) and up (towards +∞), as MPFR's MPFR_RNDN, MPFR_RNDD and MPFR_RNDU.
#pragma once

namespace raygrade {

enum class Rounding { kNearest, kDown, kUp };

}  // namespace raygrade
