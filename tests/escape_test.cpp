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
}

TEST(Escape, XmlDropsControlsAndRepairsUtf8) {
  EXPECT_EQ(xml_escape("a<b>&\"'"), "a&lt;b&gt;&amp;&quot;&apos;");
  EXPECT_EQ(xml_escape("bell\x07 esc\x1b tab\t"), "bell esc tab\t");
  EXPECT_EQ(xml_escape("Andr\xE9"), "Andr\xEF\xBF\xBD");  // U+FFFD for the Latin-1 byte
  EXPECT_EQ(xml_escape("√"), "√");
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
  EXPECT_EQ(csv_cell("\t=1"), "'\t=1");
  EXPECT_EQ(csv_cell(R"x(=HYPERLINK("http://x","y"))x"), R"x("'=HYPERLINK(""http://x"",""y"")")x");
  EXPECT_EQ(csv_cell("Ada, Countess"), "\"Ada, Countess\"");
  EXPECT_EQ(csv_cell("Ada"), "Ada");
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
}

}  // namespace
}  // namespace raygrade
