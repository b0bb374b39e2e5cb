// read_typed_box: one typed box read as a submission carries it (the pages' reader and
// `raygrade read-typed`), against values known by hand: the bits of 1/3, 1, -2.5 and 4 in IEEE
// 754 double precision, and what the grader refuses.
#include "grading/typed_box.h"

#include <gtest/gtest.h>

namespace raygrade::typed_box_test {

TEST(TypedBox, NumbersAndVectorsWithTheirBits) {
  nlohmann::json third = typed_reading_json(read_typed_box(TypedBox::kNumber, R"("1/3")"));
  EXPECT_EQ(third, (nlohmann::json{{"ok", true}, {"values", {"3fd5555555555555"}}}));
  nlohmann::json v =
      typed_reading_json(read_typed_box(TypedBox::kVector, R"(["1", " -2.5 ", "2\u00b2"])"));
  EXPECT_EQ(v, (nlohmann::json{
                   {"ok", true},
                   {"values", {"3ff0000000000000", "c004000000000000", "4010000000000000"}}}));
}

TEST(TypedBox, AFormulaIsValuedWithEverySymbolOne) {
  TypedReading r = read_typed_box(TypedBox::kFormula, R"("2px + vx")", {"px", "vx"});
  ASSERT_TRUE(r.accepted) << r.message;
  EXPECT_EQ(r.values, std::vector<double>{3.0});
  EXPECT_FALSE(read_typed_box(TypedBox::kFormula, R"("2py")", {"px"}).accepted);
}

TEST(TypedBox, WhatTheGraderRefuses) {
  // Beyond a double, as literals: refused, not rounded to 0 or infinity.
  EXPECT_EQ(read_typed_box(TypedBox::kNumber, R"("1e-324")").fault, "read");
  EXPECT_EQ(read_typed_box(TypedBox::kNumber, R"("1e309")").fault, "read");
  // A product of infinities parses, but has no finite value.
  TypedReading inf = read_typed_box(TypedBox::kNumber, R"("1e308*10")");
  EXPECT_EQ(inf.fault, "finite");
  EXPECT_EQ(inf.message, "no finite value");
  // A dot and a star pasted together are not a power.
  EXPECT_FALSE(read_typed_box(TypedBox::kNumber, "\"2*\u00b73\"").accepted);
  // A byte-order mark, a no-break space, a line break: not spaces to the grader.
  EXPECT_FALSE(read_typed_box(TypedBox::kNumber, R"("\ufeff1")").accepted);
  EXPECT_FALSE(read_typed_box(TypedBox::kNumber, R"("1\u00a0")").accepted);
  EXPECT_FALSE(read_typed_box(TypedBox::kNumber, R"("1\n")").accepted);
  // A lone surrogate: the submission holding it is not JSON.
  EXPECT_EQ(read_typed_box(TypedBox::kNumber, R"("\ud800")").fault, "json");
  // 501 π are 501 characters but 1,002 bytes: over the limit of 1,000 bytes.
  std::string pis = "\"";
  for (int i = 0; i < 501; ++i) pis += "\u03c0";
  EXPECT_FALSE(read_typed_box(TypedBox::kNumber, pis + "\"").accepted);
  // Two numbers for a vector, a number for a string.
  EXPECT_EQ(read_typed_box(TypedBox::kVector, R"(["1", "2"])").fault, "type");
  EXPECT_TRUE(read_typed_box(TypedBox::kNumber, "2.5").accepted);
}

}  // namespace raygrade::typed_box_test
