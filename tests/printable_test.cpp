// printable() and is_valid_utf8(): what a diagnostic may quote of a student's text.
#include <gtest/gtest.h>

#include "core/escape.h"

namespace raygrade {
namespace {

TEST(Printable, KeepsWellFormedUtf8) { EXPECT_EQ(printable("t_hc = √3, élan"), "t_hc = √3, élan"); }

TEST(Printable, EscapesControlCharactersAndTerminalSequences) {
  EXPECT_EQ(printable("a\x1b[2Jb\n"), "a\\x1B[2Jb\\x0A");
  EXPECT_EQ(printable("\xC2\x9B"
                      "31m"),
            "\\u009B31m");  // C1 CSI
}

TEST(Printable, EscapesIllFormedBytes) {
  EXPECT_EQ(printable("Andr\xE9"), "Andr\\xE9");
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");           // overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a surrogate
  EXPECT_EQ(printable("\xE2\x88"), "\\xE2\\x88");           // cut short
}

TEST(Printable, CutsLongText) { EXPECT_EQ(printable("abcdefgh", 3), "abc..."); }

TEST(Utf8, ValidAndInvalid) {
  EXPECT_TRUE(is_valid_utf8(""));
  EXPECT_TRUE(is_valid_utf8("\xF0\x9F\x98\x80"));   // U+1F600
  EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));  // above U+10FFFF
  EXPECT_FALSE(is_valid_utf8("\x80"));
  EXPECT_FALSE(is_valid_utf8("\xFF"));
}

}  // namespace
}  // namespace raygrade
