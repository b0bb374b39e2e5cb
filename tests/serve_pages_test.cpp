// The LTI tool's pages: values from a platform or a student cannot end an element or run as
// script, and the student page may send its answers to the tool alone.
#include <gtest/gtest.h>

#include "serve/pages.h"

namespace serve_pages_test {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ServePages, LaunchJsonCannotCloseItsScriptElement) {
  nlohmann::json launch = {{"assignment", "</script><script>alert(1)</script><!--"}};
  std::string html = raygrade::serve::launch_script(launch);
  EXPECT_EQ(count(html, "</script>"), 1u);  // its own end tag alone
  EXPECT_EQ(count(html, "<!--"), 0u);
  // The text between the tags is still the same JSON.
  std::size_t start = html.find('>') + 1;
  std::string text = html.substr(start, html.rfind("</script>") - start);
  EXPECT_EQ(nlohmann::json::parse(text), launch);
}

TEST(ServePages, RefusalReasonIsTextNotMarkup) {
  std::string html = raygrade::serve::refusal_page(401, "kid <img src=x onerror=alert(1)>");
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_NE(html.find("&lt;img"), std::string::npos);
  EXPECT_NE(html.find("401"), std::string::npos);
}

TEST(ServePages, StudentPageMayConnectToItsOwnOriginOnly) {
  std::string handout =
      "<html><head><meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "script-src 'unsafe-inline'\"></head><body><p>problems</p></body></html>";
  std::string html = raygrade::serve::student_page(handout, {{"launch", "L"}});
  EXPECT_NE(html.find("default-src 'none'; connect-src 'self'; script-src"), std::string::npos);
  // The launch's element and the submit button come before the end of the body.
  EXPECT_LT(html.find("id=\"raygrade-launch\""), html.find("</body>"));
  EXPECT_LT(html.find("id=\"raygrade-submit\""), html.find("</body>"));
}

TEST(ServePages, DeepLinkReturnPostsTheTokenAsJwt) {
  std::string html =
      raygrade::serve::deep_link_return_page("https://lms.example/dl?a=1&b=\"2\"", "h.p.s");
  EXPECT_NE(html.find("action=\"https://lms.example/dl?a=1&amp;b=&quot;2&quot;\""),
            std::string::npos);
  EXPECT_NE(html.find("name=\"JWT\" value=\"h.p.s\""), std::string::npos);
}

}  // namespace serve_pages_test
