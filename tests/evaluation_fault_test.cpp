// A formula evaluated with values it cannot take is a bug of raygrade (an InternalError), never
// a fault of the input (an Error): nothing that catches bad input catches it by mistake.
#include <gtest/gtest.h>

#include <type_traits>

#include "core/error.h"
#include "derivation/expr.h"

namespace raygrade {
namespace {

static_assert(std::is_base_of_v<InternalError, EvaluationFault>);
static_assert(!std::is_base_of_v<Error, EvaluationFault>);

// |a| of a vector is its length; a vector where a number goes (a + 1 with a a vector), and a
// symbol with no value, are faults of the formula.
TEST(EvaluationFault, AVectorWhereANumberGoesAndAnUnknownSymbol) {
  Env env;
  env["a"] = Value(Vec3d{3, 4, 0});
  EXPECT_DOUBLE_EQ(evaluate(norm(sym("a")), env).scalar, 5);
  EXPECT_THROW(evaluate(sqrt(sym("a")), env), EvaluationFault);
  EXPECT_THROW(evaluate(sym("b") + E(1.0), env), EvaluationFault);
  try {
    evaluate(sym("b"), env);
    FAIL() << "no fault";
  } catch (const Error&) {
    FAIL() << "caught as bad input";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown symbol 'b'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raygrade
