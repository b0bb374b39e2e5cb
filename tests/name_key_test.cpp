// Names compared as people read them (core/name_key.h): the keys below are Unicode's own
// (CaseFolding.txt, NormalizationTest's NFKC forms), written out by hand as UTF-8 bytes.
#include "core/name_key.h"

#include <gtest/gtest.h>

#include <string>

#include "assignments/roster.h"

namespace raygrade {
namespace {

TEST(NameKey, FoldsCaseAndNormalForm) {
  // É as U+00C9 and as E + U+0301 fold alike, to é (U+00E9).
  EXPECT_EQ(name_key("\xC3\x89mile"), "\xC3\xA9mile");
  EXPECT_EQ(name_key("E\xCC\x81mile"), "\xC3\xA9mile");
  // ß folds to "ss" (CaseFolding.txt, status F), as does SS.
  EXPECT_EQ(name_key("Stra\xC3\x9F"
                     "e"),
            "strasse");
  EXPECT_EQ(name_key("STRASSE"), "strasse");
  // Σ and final ς both fold to σ.
  EXPECT_EQ(name_key("\xCE\xA3"), name_key("\xCF\x82"));
  // The ligature ﬁ (U+FB01) is "fi" in NFKC.
  EXPECT_EQ(name_key("\xEF\xAC\x81"
                     "nn"),
            "finn");
  // Zero-width and bidi controls are ignored: U+200B, U+202E (RLO), U+2066 (LRI).
  EXPECT_EQ(name_key("A\xE2\x80\x8B"
                     "da\xE2\x80\xAE\xE2\x81\xA6"),
            "ada");
  EXPECT_EQ(name_key("\xE2\x80\x8B"), "");
  // Not UTF-8: ASCII lowered, the rest byte for byte.
  EXPECT_EQ(name_key("Jos\xE9"), "jos\xE9");
  EXPECT_EQ(name_key(""), "");
}

// A submission's name matches the roster's in any case and Unicode form; a name that is only
// ignorable characters names nobody (it is no field at all), and an empty email never matches
// a roster student without one.
TEST(NameKey, RosterMatchesNamesByKeyAndEmptyNothing) {
  std::vector<StudentIdentity> roster = {{"\xC3\x89mile Zola", "z1", ""},
                                         {"Ada Lovelace", "s1", "ada@example.edu"}};
  RosterMatch m = match_on_roster(roster, StudentIdentity{"E\xCC\x81MILE ZOLA", "", ""});
  ASSERT_TRUE(m.entry) << m.problem;
  EXPECT_EQ(m.entry->id, "z1");
  m = match_on_roster(roster, StudentIdentity{"\xE2\x80\x8B", "", "  "});
  EXPECT_FALSE(m.entry);
  EXPECT_EQ(m.problem, "the submission names no student");
}

}  // namespace
}  // namespace raygrade
