// The list of field types: a form's field of a type the list has not is an internal error, never
// taken for another type, and a field's blank answer and typed box follow from its shape and
// value, whatever its name.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/internal_error.h"
#include "grading/typed_box.h"
#include "kinds/fields/field_type.h"
#include "kinds/form.h"

namespace raygrade {
namespace field_types_test {

using json = nlohmann::json;

TEST(FieldTypes, ATypeTheListHasNotIsAnInternalError) {
  EXPECT_THROW(field_type_of(json{{"type", "slider"}, {"key", "x"}}), InternalError);
  EXPECT_THROW(field_type_of(json{{"key", "x"}}), InternalError);
  EXPECT_THROW(field_type_of(json{{"type", 3}, {"key", "x"}}), InternalError);
  // A name differing in case is another name.
  EXPECT_THROW(field_type_of(json{{"type", "Vector"}, {"key", "x"}}), InternalError);
  EXPECT_THROW(blank_of(json{{"type", "slider"}, {"key", "x"}}), InternalError);
}

TEST(FieldTypes, EveryNameIsOnceInTheTable) {
  std::set<std::string> seen;
  for (const FieldTypeEntry& e : field_type_table()) {
    EXPECT_TRUE(seen.insert(std::string(e.name)).second) << e.name;
    EXPECT_EQ(find_field_type(e.name), &e);
  }
  EXPECT_EQ(seen.size(), 9u);
  EXPECT_EQ(find_field_type("slider"), nullptr);
}

// The blanks, worked by hand from docs/assignments.md: "" for a number, three for a vector, one
// blank row of an open table's columns, each fixed row with its numbers' blanks (a yes/no has
// none), nothing for a choice or a tree.
TEST(FieldTypes, BlanksFollowShapeAndValue) {
  EXPECT_EQ(blank_of(form::field<field_types::Number>("t", "t")), json(""));
  EXPECT_EQ(blank_of(form::field<field_types::Formula>("x", "x =")), json(""));
  EXPECT_EQ(blank_of(form::field<field_types::Vector>("ray/origin", "o")),
            json::array({"", "", ""}));
  EXPECT_TRUE(blank_of(form::field<field_types::YesNo>("tir", "?")).is_null());
  EXPECT_TRUE(blank_of(form::object_choice({"a", "b"})).is_null());

  json hits = form::hits_field(false, true, true);
  EXPECT_EQ(blank_of(hits), json::parse(R"([{"t": "", "point": ["", "", ""],
                                              "normal": ["", "", ""]}])"));

  json rows = form::field<field_types::Rows>("lights", "Each light");
  rows["rows"] = json::parse(R"([{"label": "light A", "fixed": {"light": "A"}},
                                 {"label": "light B", "fixed": {"light": "B"}}])");
  rows["columns"] = json::array({form::field<field_types::Number>("n_dot_l", "N·L"),
                                 form::field<field_types::YesNo>("reaches", "reaches?"),
                                 form::field<field_types::Vector>("diffuse", "diffuse")});
  EXPECT_EQ(blank_of(rows), json::parse(R"([
      {"light": "A", "n_dot_l": "", "diffuse": ["", "", ""]},
      {"light": "B", "n_dot_l": "", "diffuse": ["", "", ""]}])"));
}

// The typed reader reads the types whose one value is typed, by the table: a number, three
// numbers, a formula; no other type has a box.
TEST(FieldTypes, TheTypedReaderTakesItsBoxesFromTheTable) {
  int typed = 0;
  for (const FieldTypeEntry& e : field_type_table()) {
    TypedBox box{};
    bool has_box = typed_box_from_name(e.name, box);
    EXPECT_EQ(has_box, e.shape == FieldShape::kOne && e.typed()) << e.name;
    typed += has_box ? 1 : 0;
  }
  EXPECT_EQ(typed, 3);
  TypedBox box{};
  ASSERT_TRUE(typed_box_from_name(field_type_entry<field_types::Vector>().name, box));
  EXPECT_EQ(box, TypedBox::kVector);
  TypedReading r = read_typed_box(box, R"(["1/2", "-3", "2^2"])");
  ASSERT_TRUE(r.accepted) << r.message;
  EXPECT_EQ(r.values, (std::vector<double>{0.5, -3.0, 4.0}));
  EXPECT_FALSE(typed_box_from_name("slider", box));
}

}  // namespace field_types_test
}  // namespace raygrade
