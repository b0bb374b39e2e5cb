// The roster's paging: the Link header's rel="next" target (RFC 8288, as NRPS 2.0 pages by it),
// and who is a learner.
#include <gtest/gtest.h>

#include "serve/http_client.h"
#include "serve/roster.h"

namespace serve_roster_test {

using raygrade::serve::is_learner;
using raygrade::serve::Member;
using raygrade::serve::next_link;
using raygrade::serve::origin_of;

TEST(ServeRoster, NextLinkIsTheTargetWhoseRelIsNext) {
  const std::string base = "https://lms.example/api/nrps/c1?limit=2";
  EXPECT_EQ(next_link(R"(<https://lms.example/p?page=2>; rel="next")", base),
            "https://lms.example/p?page=2");
  // Several links, next not the first; rel unquoted, in capitals, or among several types.
  EXPECT_EQ(next_link(R"(<https://lms.example/d>; rel="differences", <https://lms.example/n>; )"
                      R"(rel=NEXT)",
                      base),
            "https://lms.example/n");
  EXPECT_EQ(next_link(R"(<https://lms.example/x>; title="a, b"; rel="last next")", base),
            "https://lms.example/x");
  // A relative target, resolved against the page's URL.
  EXPECT_EQ(next_link(R"(</api/nrps/c1?page=3>; rel="next")", base),
            "https://lms.example/api/nrps/c1?page=3");
  EXPECT_EQ(next_link(R"(<c1?page=4>; rel="next")", base),
            "https://lms.example/api/nrps/c1?page=4");
  // No next link: the last page.
  EXPECT_EQ(next_link(R"(<https://lms.example/d>; rel="differences")", base), "");
  EXPECT_EQ(next_link(R"(<https://lms.example/n>; rel="nextish")", base), "");
  EXPECT_EQ(next_link("", base), "");
}

// RFC 6454, 4: scheme, host and port; the scheme's default port is the same origin.
TEST(ServeRoster, OriginIsSchemeHostAndPort) {
  EXPECT_EQ(origin_of("https://LMS.example/api/nrps?x=1"), "https://lms.example");
  EXPECT_EQ(origin_of("https://lms.example:443/a"), "https://lms.example");
  EXPECT_EQ(origin_of("http://lms.example:80"), "http://lms.example");
  EXPECT_EQ(origin_of("http://lms.example:8080/a"), "http://lms.example:8080");
  EXPECT_NE(origin_of("http://lms.example/a"), origin_of("https://lms.example/a"));
  EXPECT_NE(origin_of("https://lms.example/a"), origin_of("https://lms.example.evil/a"));
  EXPECT_NE(origin_of("https://lms.example/a"), origin_of("https://lms.example@evil/a"));
  EXPECT_THROW(origin_of("ftp://lms.example/a"), std::exception);
}

TEST(ServeRoster, LearnerByTheLisRoleOrItsShortName) {
  Member m;
  m.roles = R"(["http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"])";
  EXPECT_TRUE(is_learner(m));
  m.roles = R"(["Learner"])";
  EXPECT_TRUE(is_learner(m));
  m.roles = R"(["http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"])";
  EXPECT_FALSE(is_learner(m));
  m.roles = "not json";
  EXPECT_FALSE(is_learner(m));
}

}  // namespace serve_roster_test
