// Hostile JSON text: every fault is a clean Error naming file, line, column and fault, never a
// crash, and nothing is accepted silently (duplicate keys, overflowing numbers).
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/escape.h"
#include "json/cursor.h"
#include "json/scan.h"
#include "json/source.h"

namespace raygrade {
namespace {

// The diagnostic `text` is rejected with; fails the test if it is accepted.
Diagnostic rejection(const std::string& text, const JsonLimits& limits = {}) {
  try {
    parse_json_text("in.json", text, limits);
  } catch (const Error& e) {
    return e.diagnostic();
  }
  ADD_FAILURE() << "accepted: " << text.substr(0, 80);
  return {};
}

TEST(JsonLimits, MillionDeepArrayIsACleanError) {
  std::string text(1000000, '[');
  text += std::string(1000000, ']');
  Diagnostic d = rejection(text);
  EXPECT_EQ(d.code, "limit");
  EXPECT_EQ(d.file, "in.json");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.column, 65);  // the 65th '[' is one level too deep for the limit of 64
}

TEST(JsonLimits, DepthAtTheLimitIsAccepted) {
  std::string text = std::string(64, '[') + std::string(64, ']');
  EXPECT_NO_THROW(parse_json_text("in.json", text));
}

TEST(JsonLimits, LongStringIsRejectedAtItsQuote) {
  JsonLimits limits;
  limits.max_string = 10;
  EXPECT_NO_THROW(parse_json_text("in.json", "{\"a\": \"0123456789\"}", limits));
  Diagnostic d = rejection("{\"a\":\n \"01234567890\"}", limits);
  EXPECT_EQ(d.code, "limit");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 2);
}

TEST(JsonLimits, FileSizeOverTheLimit) {
  JsonLimits limits;
  limits.max_bytes = 100;
  Diagnostic d = rejection("[" + std::string(200, ' ') + "]", limits);
  EXPECT_EQ(d.code, "limit");
  EXPECT_NE(d.message.find("202 bytes"), std::string::npos) << d.message;
}

TEST(JsonLimits, TooManyItemsInOneArray) {
  JsonLimits limits;
  limits.max_items = 3;
  EXPECT_NO_THROW(parse_json_text("in.json", "[1,2,3]", limits));
  EXPECT_EQ(rejection("[1,2,3,4]", limits).code, "limit");
  EXPECT_EQ(rejection("{\"a\":1,\"b\":2,\"c\":3,\"d\":4}", limits).code, "limit");
  // Commas inside strings are not items.
  EXPECT_NO_THROW(parse_json_text("in.json", "[\",,,,,,\"]", limits));
}

TEST(JsonLimits, SubmissionLimitsAreTighter) {
  JsonLimits s = JsonLimits::submission(), bank;
  EXPECT_LT(s.max_bytes, bank.max_bytes);
  EXPECT_LT(s.max_items, bank.max_items);
  EXPECT_EQ(rejection(std::string(2u << 20, ' '), s).code, "limit");
}

TEST(JsonLimits, DuplicateKeyNamesPathLineAndColumn) {
  Diagnostic d = rejection("{\"answers\": [\n  {\"t\": 1,\n   \"t\": 2}]}");
  EXPECT_EQ(d.code, "duplicate-key");
  EXPECT_EQ(d.path, "/answers/0/t");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 4);
  EXPECT_NE(d.message.find("'t'"), std::string::npos) << d.message;
}

// "\u0061" is "a": the same key written two ways is still a duplicate.
TEST(JsonLimits, DuplicateKeyWrittenWithAnEscape) {
  EXPECT_EQ(rejection(R"({"a": 1, "\u0061": 2})").code, "duplicate-key");
}

TEST(JsonLimits, SameKeyInSiblingObjectsIsFine) {
  EXPECT_NO_THROW(parse_json_text("in.json", R"([{"a": 1}, {"a": 2}, {"b": {"a": 3}, "a": 4}])"));
}

TEST(JsonLimits, DuplicateKeyAfterAnArrayInTheSameObject) {
  Diagnostic d = rejection(R"({"a": [1, {"a": 0}], "b": 2, "a": 3})");
  EXPECT_EQ(d.code, "duplicate-key");
  EXPECT_EQ(d.path, "/a");
  EXPECT_EQ(d.column, 30);
}

// 1e400 is beyond a double: it reads as infinity, and the typed reader names its path.
TEST(JsonLimits, NumberBeyondADoubleIsARangeErrorAtItsPath) {
  auto f = parse_json_text("in.json", "{\"t\": [1,\n 1e400]}");
  Cursor t1 = Cursor(f).at("t").items()[1];
  try {
    (void)t1.number();
    FAIL() << "1e400 read as a number";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().code, "range");
    EXPECT_EQ(e.diagnostic().path, "/t/1");
    EXPECT_EQ(e.diagnostic().line, 2);
  }
}

// 1e5000 is beyond even a long double: the file is rejected, naming the number's place.
TEST(JsonLimits, NumberBeyondALongDoubleRejectsTheFileWithItsPlace) {
  Diagnostic d = rejection("{\"t\": [1,\n 1e5000]}");
  EXPECT_EQ(d.code, "range");
  EXPECT_EQ(d.path, "/t/1");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 2);
  EXPECT_EQ(rejection("[-1e5000]").code, "range");
}

// Found by fuzzing: the second parse (with long doubles) goes past the big number and meets
// the syntax error the first parse never reached.
TEST(JsonLimits, BigNumberThenASyntaxErrorIsASyntaxError) {
  Diagnostic d = rejection("[1e400, }");
  EXPECT_EQ(d.code, "bad-json");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.column, 9);
  EXPECT_EQ(rejection("-1e400\"").code, "bad-json");
}

// nlohmann reads a NUL byte as the end of the text: what follows must not pass unseen.
TEST(JsonLimits, NulByteIsRejectedWhereItIs) {
  Diagnostic d = rejection(std::string("{\"a\": 1}\n\0{\"a\": 2}", 18));
  EXPECT_EQ(d.code, "bad-json");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 1);
  EXPECT_NO_THROW(parse_json_text("in.json", R"({"a": "\u0000"})"));
}

// 1e-400 underflows to zero, which is a fine double: accepted as 0.
TEST(JsonLimits, UnderflowingNumberIsZero) {
  auto f = parse_json_text("in.json", "[1e-400]");
  EXPECT_EQ(f->root[0].get<double>(), 0.0);
}

TEST(JsonLimits, NanAndInfinityTokensAreNamed) {
  for (std::string word : {"NaN", "nan", "Infinity", "-Infinity", "inf"}) {
    Diagnostic d = rejection("{\"t\": " + word + "}");
    EXPECT_EQ(d.code, "bad-json") << word;
    EXPECT_NE(d.message.find("NaN or infinity"), std::string::npos) << word << ": " << d.message;
    EXPECT_EQ(d.line, 1);
  }
}

TEST(JsonLimits, InvalidUtf8IsNamedWithItsPlace) {
  Diagnostic d = rejection("{\"name\":\n \"Andr\xE9\"}");  // Latin-1 é
  EXPECT_EQ(d.code, "bad-encoding");
  EXPECT_EQ(d.line, 2);
  EXPECT_NE(d.message.find("UTF-8"), std::string::npos) << d.message;
  EXPECT_TRUE(is_valid_utf8(d.message));
  EXPECT_TRUE(is_valid_utf8(format_diagnostic(d)));
}

TEST(JsonLimits, Utf16FileIsNamed) {
  Diagnostic d = rejection(std::string("\xFF\xFE{\0}\0", 6));
  EXPECT_EQ(d.code, "bad-encoding");
  EXPECT_NE(d.message.find("UTF-16"), std::string::npos);
}

TEST(JsonLimits, Utf8ByteOrderMarkIsAccepted) {
  auto f = parse_json_text("in.json", "\xEF\xBB\xBF{\"a\": 1}");
  EXPECT_EQ(f->root["a"], 1);
}

TEST(JsonLimits, EmptyFileIsNamed) {
  Diagnostic d = rejection(" \n");
  EXPECT_NE(d.message.find("empty"), std::string::npos) << d.message;
}

TEST(JsonLimits, RawControlCharacterInAString) {
  Diagnostic d = rejection("{\"name\": \"a\x1b[31mb\"}");
  EXPECT_EQ(d.code, "bad-json");
  // The message never carries the escape byte itself to the terminal.
  EXPECT_EQ(format_diagnostic(d).find('\x1b'), std::string::npos);
}

TEST(JsonScan, LimitsNeedNoValidJson) {
  JsonLimits limits;
  EXPECT_FALSE(check_limits("]]]]}}}{\"", limits));
  EXPECT_FALSE(check_limits("\"\\", limits));
  EXPECT_FALSE(find_duplicate_or_overflow("{\"a\" \"a\" \"a"));
  EXPECT_FALSE(find_duplicate_or_overflow("]]]}}"));
}

}  // namespace
}  // namespace raygrade
