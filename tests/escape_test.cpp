// Escaping of student-controlled text for each output format, and safe file names: each
// expected string is written out by hand from the format's rules.
#include "core/escape.h"

#include <gtest/gtest.h>

namespace raygrade {
namespace {

TEST(Escape, HtmlTurnsMarkupIntoText) {
  EXPECT_EQ(html_escape("<script>alert(1)</script>"), "&lt;script&gt;alert(1)&lt;/script&gt;");
  EXPECT_EQ(html_escape(R"(" onload='x' & y)"), "&quot; onload=&#39;x&#39; &amp; y");
  EXPECT_EQ(html_escape("Zoë √3"), "Zoë √3");
  EXPECT_EQ(html_escape("Eve\x1b[2J\x07 \x7f\tx\n"), "Eve[2J \tx\n");
  // C1 controls dropped; U+00A0 (no-break space, C2 A0) kept.
  EXPECT_EQ(html_escape("a\xc2\x9b"
                        "2J\xc2\x80"
                        "b \xc2\xa0"
                        "c"),
            "a2Jb \xc2\xa0"
            "c");
}

TEST(Escape, XmlDropsControlsAndRepairsUtf8) {
  EXPECT_EQ(xml_escape("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&apos;");
  EXPECT_EQ(xml_escape("bell\x07 esc\x1b tab\t"), "bell esc tab\t");
  EXPECT_EQ(xml_escape("Andr\xE9"), "Andr\xEF\xBF\xBD");  // U+FFFD for the Latin-1 byte
  EXPECT_EQ(xml_escape("√"), "√");
}

// XML 1.0's Char (production 2): tab, line feed, carriage return, U+0020 to U+D7FF, U+E000 to
// U+FFFD and U+10000 up; a lone surrogate cannot be in UTF-8 at all. Everything else is dropped
// (controls) or becomes U+FFFD (bytes that are no character, the noncharacters U+FFFE, U+FFFF),
// and counted.
TEST(Escape, XmlTextIsWhatXml10Allows) {
  std::size_t changed = 0;
  EXPECT_EQ(xml_text("T\x01itle\x07 tab\t line\n", &changed), "Title tab\t line\n");
  EXPECT_EQ(changed, 2u);
  EXPECT_EQ(xml_text("a\xEF\xBF\xBE b\xEF\xBF\xBF c\xEF\xBF\xBD", &changed),
            "a\xEF\xBF\xBD b\xEF\xBF\xBD c\xEF\xBF\xBD");
  EXPECT_EQ(changed, 2u);
  // A lone surrogate's bytes (U+D800 as CESU-8 would write it) and a byte of Latin-1.
  EXPECT_EQ(xml_text("\xED\xA0\x80|\xFF|", &changed),
            "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD|\xEF\xBF\xBD|");
  EXPECT_EQ(changed, 4u);
  // Kept: the last character below the surrogates, the first above them, and one above U+FFFF.
  EXPECT_EQ(xml_text("\xED\x9F\xBF\xEE\x80\x80\xF0\x9F\x98\x80", &changed),
            "\xED\x9F\xBF\xEE\x80\x80\xF0\x9F\x98\x80");
  EXPECT_EQ(changed, 0u);
  EXPECT_EQ(xml_escape("\xEF\xBF\xBF<"), "\xEF\xBF\xBD&lt;");
}

TEST(Escape, MarkdownKeepsTextOnItsLine) {
  EXPECT_EQ(markdown_escape("**bold** [x](javascript:alert(1))"),
            "\\*\\*bold\\*\\* \\[x\\]\\(javascript:alert\\(1\\)\\)");
  EXPECT_EQ(markdown_escape("<img src=x>"), "\\<img src=x\\>");
  EXPECT_EQ(markdown_escape("a|b\n# c"), "a\\|b \\# c");
}

TEST(Escape, LatexTextMode) {
  EXPECT_EQ(latex_escape("$\\input{/etc/passwd}$"),
            "\\$\\textbackslash{}input\\{/etc/passwd\\}\\$");
  EXPECT_EQ(latex_escape("50% & #1 x_2 ^ ~"),
            "50\\% \\& \\#1 x\\_2 \\textasciicircum{} \\textasciitilde{}");
}

TEST(Escape, CsvNeutralisesFormulas) {
  EXPECT_EQ(csv_cell("=1+1"), "'=1+1");
  EXPECT_EQ(csv_cell("+1"), "'+1");
  EXPECT_EQ(csv_cell("-2+3"), "'-2+3");
  EXPECT_EQ(csv_cell("@SUM(A1)"), "'@SUM(A1)");
  // A control character first is written out, so no spreadsheet skips it to reach a formula.
  EXPECT_EQ(csv_cell("\t=1"), "\\x09=1");
  EXPECT_EQ(csv_cell(std::string("\0=1+1", 5)), "\\x00=1+1");
  EXPECT_EQ(csv_cell("\n=1+1"), "\\x0A=1+1");
  EXPECT_EQ(csv_cell("\r=1+1"), "\\x0D=1+1");
  EXPECT_EQ(csv_cell(R"x(=HYPERLINK("http://x","y"))x"), R"x("'=HYPERLINK(""http://x"",""y"")")x");
  EXPECT_EQ(csv_cell("Ada, Countess"), "\"Ada, Countess\"");
  EXPECT_EQ(csv_cell("Ada"), "Ada");
}

TEST(Escape, TextDropsTerminalControls) {
  EXPECT_EQ(text_escape("Sphere\x1b[31m red\x07\tx\n"), "Sphere[31m red\tx\n");
  EXPECT_EQ(text_escape("a\xc2\x9b"
                        "2J \xc2\xa0"
                        "b"),
            "a2J \xc2\xa0"
            "b");
}

TEST(Escape, CsvCellsCarryNoTerminalControls) {
  // ESC [ 2 J clears the screen, ESC ] 0 ; ... BEL retitles it; U+009B is the C1 form of ESC [.
  EXPECT_EQ(csv_cell("Eve\x1b[2J"), "Eve\\x1B[2J");
  EXPECT_EQ(csv_cell("\x1b]0;owned\x07"), "\\x1B]0;owned\\x07");
  EXPECT_EQ(csv_cell("a\xc2\x9b"
                     "2Jb"),
            "a\\u009B2Jb");
  EXPECT_EQ(csv_cell("line\nbreak"), "line\\x0Abreak");
}

TEST(Escape, SafeFileNamesStayInTheirFolder) {
  EXPECT_EQ(safe_file_name("../../etc/passwd"), "_._.._etc_passwd");
  EXPECT_EQ(safe_file_name(".."), "_..");
  EXPECT_EQ(safe_file_name("."), "_.");
  EXPECT_EQ(safe_file_name(""), "_");
  EXPECT_EQ(safe_file_name(".hidden"), "_hidden");
  EXPECT_EQ(safe_file_name("/abs"), "_abs");
  EXPECT_EQ(safe_file_name("a\\b"), "a_b");
  EXPECT_EQ(safe_file_name("s001"), "s001");
  EXPECT_EQ(safe_file_name(std::string(300, 'x')).size(), 100u);
  // A leading '-' would be an option to a command and a formula to a spreadsheet.
  EXPECT_EQ(safe_file_name("-rf"), "_rf");
  EXPECT_EQ(csv_cell(safe_file_name("-s1")), "_s1");
}

// U+202E (E2 80 AE), RIGHT-TO-LEFT OVERRIDE, and U+2066 (E2 81 A6), LEFT-TO-RIGHT ISOLATE, make
// "Eve<RLO>gnp.exe" show as "Eveexe.png": no output shows them as they act. U+200F (E2 80 8F),
// the right-to-left mark of Hebrew and Arabic text, reorders nothing and is kept.
TEST(Escape, ReorderingControlsNeverReachAnOutput) {
  const std::string rlo = "Eve\xE2\x80\xAEgnp.exe\xE2\x81\xA6x";
  EXPECT_EQ(html_escape(rlo), "Evegnp.exex");
  EXPECT_EQ(xml_escape(rlo), "Evegnp.exex");
  EXPECT_EQ(text_escape(rlo), "Evegnp.exex");
  EXPECT_EQ(markdown_escape(rlo), "Evegnp\\.exex");
  EXPECT_EQ(printable(rlo), "Eve\\u202Egnp.exe\\u2066x");
  EXPECT_EQ(csv_cell(rlo), "Eve\\u202Egnp.exe\\u2066x");
  EXPECT_EQ(html_escape("\xD7\xA9\xE2\x80\x8F"), "\xD7\xA9\xE2\x80\x8F");
}

// Markdown is read on terminals too: ESC, NUL, DEL and C1 controls (here CSI, C2 9B) never pass.
TEST(Escape, MarkdownDropsTerminalControls) {
  EXPECT_EQ(markdown_escape(std::string("a\x1b[2Jb\0c\x7f\xc2\x9b"
                                        "d",
                                        12)),
            "a\\[2Jbcd");
}

// Braces as entities on top of html_escape, for text a platform's template would substitute
// (Moodle's {x} and {=1+1}, PrairieLearn's {{x}}); markup escaped, controls dropped as ever.
TEST(Escape, HtmlEscapeBracesLeavesNoBraceForATemplate) {
  EXPECT_EQ(html_escape_braces("{=1+1} {{answer}} <b>&"),
            "&#123;=1+1&#125; &#123;&#123;answer&#125;&#125; &lt;b&gt;&amp;");
  EXPECT_EQ(html_escape_braces("a\x01{b\x07}"), "a&#123;b&#125;");
  EXPECT_EQ(html_escape_braces(""), "");
}

}  // namespace
}  // namespace raygrade
