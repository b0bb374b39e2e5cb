// The per-thread precision of Mpfr numbers.
#include "math/mpfr_number.h"

namespace raygrade {
namespace {

constexpr int kDefaultMpfrBits = 256;
thread_local int current_bits = kDefaultMpfrBits;

}  // namespace

int mpfr_precision() { return current_bits; }

MpfrPrecision::MpfrPrecision(int bits) : saved_(current_bits) { current_bits = bits; }

MpfrPrecision::~MpfrPrecision() { current_bits = saved_; }

}  // namespace raygrade
