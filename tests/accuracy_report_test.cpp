// The accuracy page: its table, plot and conclusions rendered from a report whose times and
// errors are set by hand, so that every ratio it quotes is known beforehand.
#include <gtest/gtest.h>

#include <string>

#include "accuracy/report.h"

namespace raygrade {
namespace {

// Every ladder level on six primitives (the first six of the list, however long it grows) at 2 ns
// (random) and 4 ns (hard), except the reference double: 3 ns on random sphere rays (1.5 times
// naive double) and 20 ns on hard plane rays (5 times); plus one peer on triangles.
AccuracyReport hand_made_report() {
  AccuracyReport r;
  r.random_per_primitive = 10;
  for (std::size_t i = 0; i < 6; ++i) {
    Primitive p = kAllPrimitives[i];
    r.hard_per_primitive[p] = 3;
    for (const auto& level : ladder_levels()) {
      ReportRow row{level.name, p, false, 2, 4, {}, {}, std::nullopt};
      row.random.judged = 10;
      row.hard.judged = 3;
      if (level.name == "reference double" && p == primitive_of<Sphere>()) row.ns_random = 3;
      if (level.name == "reference double" && p == primitive_of<Plane>()) row.ns_hard = 20;
      if (level.name == "naive double") row.hard.wrong_decisions = 1;
      r.rows.push_back(row);
    }
  }
  ReportRow peer{"Möller–Trumbore", primitive_of<Triangle>(), true, 1, 1, {}, {}, std::nullopt};
  peer.hard.judged = 3;
  peer.hard.wrong_decisions = 2;
  r.rows.push_back(peer);
  r.adaptive_levels_hard = {{"double", 15}, {"double-double", 3}};
  r.command = "raygrade bench --out docs/accuracy.md";
  return r;
}

TEST(AccuracyReport, TableHasEveryLevelOnEveryPrimitiveAndThePeer) {
  std::string md = render_accuracy_markdown(hand_made_report(), "accuracy.svg");
  ASSERT_GE(ladder_levels().size(), 6u);
  for (const auto& [p, count] : hand_made_report().hard_per_primitive) {
    for (const auto& level : ladder_levels()) {
      std::string row = "| " + std::string(primitive_name(p)) + " | " + level.name + " | ";
      EXPECT_NE(md.find(row), std::string::npos) << row;
    }
  }
  EXPECT_NE(md.find("| triangle | Möller–Trumbore (peer) | 1 | 1 |"), std::string::npos);
  EXPECT_NE(md.find("!["), std::string::npos);
  EXPECT_NE(md.find("(accuracy.svg)"), std::string::npos);
}

// The random sets' share of hits, least and largest, from the truth's counts: 1 of 10 plane
// rays hit, 7 of 10 sphere rays, 4 of 10 triangle rays.
TEST(AccuracyReport, SaysHowManyRandomRaysHit) {
  AccuracyReport r = hand_made_report();
  r.random_hits = {
      {primitive_of<Sphere>(), 7}, {primitive_of<Plane>(), 1}, {primitive_of<Triangle>(), 4}};
  std::string md = render_accuracy_markdown(r, "accuracy.svg");
  EXPECT_NE(md.find("rays from a few units away, from 10% (plane) to 70% (sphere) of them hits)"),
            std::string::npos);
  EXPECT_EQ(md.find("half of them hits"), std::string::npos);
}

TEST(AccuracyReport, ConclusionsQuoteTheLargestRatiosAndWhere) {
  std::string md = render_accuracy_markdown(hand_made_report(), "accuracy.svg");
  std::size_t conclusions = md.find("## Conclusions");
  ASSERT_NE(conclusions, std::string::npos);
  std::string text = md.substr(conclusions);
  // 3 / 2 on random sphere rays; 20 / 4 on hard plane rays; 6 wrong decisions of naive double.
  EXPECT_NE(text.find("at most 1.50 (sphere) times naive double on the same random rays"),
            std::string::npos)
      << text;
  // The geometric mean of 1.5 and five 1s: 1.5^(1/6) = 1.0699.
  EXPECT_NE(text.find("(1.07 on average over the 6 primitives)"), std::string::npos) << text;
  EXPECT_NE(text.find("up to 5.00 (plane) times"), std::string::npos) << text;
  EXPECT_NE(text.find("naive double makes 6 wrong"), std::string::npos) << text;
}

TEST(AccuracyReport, PlotHasAPointPerRow) {
  AccuracyReport r = hand_made_report();
  std::string svg = render_accuracy_svg(r);
  ASSERT_EQ(svg.rfind("<svg", 0), 0u);
  std::size_t titles = 0;
  for (std::size_t at = svg.find("<title>"); at != std::string::npos;
       at = svg.find("<title>", at + 1))
    ++titles;
  EXPECT_EQ(titles, r.rows.size());
}

}  // namespace
}  // namespace raygrade
