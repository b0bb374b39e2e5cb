// Worked solutions as rendered: the seeds' numbers (acceptance), every kind in every format,
// escaping of user text, determinism and the solutions folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "reports/json_report.h"
#include "reports/render.h"
#include "reports/solutions_folder.h"
#include "run_binary.h"
#include "test_util.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;

using testing::kSource;

const Problem& find(const Bank& bank, const std::string& id) {
  for (const auto& p : bank.problems) {
    if (p.id == id) return p;
  }
  throw std::runtime_error("no problem " + id);
}

std::string render(const Problem& p, Format f, const std::string& method = "") {
  Solution s = make_solution(p, method, number_format_for(p));
  return render_document(f, {&s});
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Seed 000, sphere case 1, as the seed works it: L = ⟨2, 0, 0⟩, t_ca = 2, d² = 0, t_hc = 1,
// t0 = 1, t1 = 3.
TEST(WorkedSolution, SeedSphereCase1MatchesTheSeed) {
  Bank bank = load_bank({kSource + "/problems/seeds/seed000-spheres.json"});
  const Problem& p = find(bank, "seed000-sphere-1");
  std::string txt = render(p, Format::kText);
  EXPECT_TRUE(has(txt, "L = C − O = ⟨2, 0, 0⟩ − ⟨0, 0, 0⟩ = ⟨2, 0, 0⟩\n")) << txt;
  EXPECT_TRUE(has(txt, "t_ca = L · D = ⟨2, 0, 0⟩ · ⟨1, 0, 0⟩ = 2\n")) << txt;
  EXPECT_TRUE(has(txt, "d² = L² − t_ca² = 4 − 2² = 0\n")) << txt;
  EXPECT_TRUE(has(txt, "t_hc = √(r² − d²) = √(1 − 0) = 1\n")) << txt;
  EXPECT_TRUE(has(txt, "t_0 = t_ca − t_hc = 2 − 1 = 1\n")) << txt;
  EXPECT_TRUE(has(txt, "t_1 = t_ca + t_hc = 2 + 1 = 3\n")) << txt;
  EXPECT_TRUE(has(txt, "enters the sphere at t = 1, at P = (1, 0, 0), and leaves at t = 3")) << txt;
  std::string md = render(p, Format::kMarkdown);
  EXPECT_TRUE(has(md,
                  "$$L = C - O = \\langle 2, 0, 0 \\rangle - \\langle 0, 0, 0 \\rangle = "
                  "\\langle 2, 0, 0 \\rangle$$"))
      << md;
  EXPECT_TRUE(has(md, "$$d^{2} = L^{2} - {t_{\\text{ca}}}^2 = 4 - {2}^2 = 0$$")) << md;
  std::string html = render(p, Format::kHtml);
  // Each "= ..." of a step is a link of its own, where a long chain may break.
  EXPECT_TRUE(has(html,
                  "<div class=\"chain\"><math displaystyle=\"true\"><mrow><msub><mi>t</mi><mi "
                  "mathvariant=\"normal\">hc</mi></msub></mrow></math><math "
                  "displaystyle=\"true\"><mrow><mo form=\"infix\">=</mo>"))
      << html;
  EXPECT_TRUE(has(html, "<mo form=\"infix\">=</mo><mn>1</mn></mrow></math>")) << html;
}

// Seed 000, plane case 1 in the D form: D = −N·V0 = −(−1·2) = 2 and t = −(N·O + D)/(N·R)
// = −2/(−1) = 2. (The seed writes D = −2; two sign slips cancel there.)
TEST(WorkedSolution, SeedPlaneCase1InTheDForm) {
  Bank bank = load_bank({kSource + "/problems/seeds/seed000-planes.json"});
  const Problem& p = find(bank, "seed000-plane-1");
  ASSERT_EQ(p.method, "implicit");
  std::string txt = render(p, Format::kText);
  EXPECT_TRUE(has(txt, "D = −(N · V_0) = −(⟨−1, 0, 0⟩ · ⟨2, 0, 0⟩) = 2\n")) << txt;
  EXPECT_TRUE(
      has(txt, "t = (−(N · O + D)) / (N · R) = (−(⟨−1, 0, 0⟩ · ⟨0, 0, 0⟩ + 2)) / (−1) = 2\n"))
      << txt;
  EXPECT_FALSE(has(txt, "D = −2")) << txt;
  std::string md = render(p, Format::kMarkdown);
  EXPECT_TRUE(has(md, "= 2$$")) << md;
}

// Seed 001's third sphere: t_hc = √3 and t0 = 9 − √3 ≈ 7.27 (the problem asks for 2 decimals).
TEST(WorkedSolution, ExactFormsBesideDecimals) {
  Bank bank = load_bank({kSource + "/problems/seeds/seed001-first-hit.json"});
  const Problem& p = find(bank, "seed001-first-hit");
  std::string txt = render(p, Format::kText, "geometric");
  EXPECT_TRUE(has(txt, "t_hc = √(r² − d²) = √(4 − 1) = √3 ≈ 1.73\n")) << txt;
  EXPECT_TRUE(has(txt, "t_0 = t_ca − t_hc = 9 − 1.73 = 9 − √3 ≈ 7.27\n")) << txt;
  EXPECT_TRUE(has(txt, "The ray first hits sphere 3 at t = 9 − √3 ≈ 7.27")) << txt;
}

// A ray tangent in exact arithmetic: C − O = (10, 5, 0) along the unit direction (2, 1, 0)/√5,
// so t_ca = 25/√5 = √125 and d² = 125 − 125 = 0 (−1.4e-14 in doubles); with r = 1,
// t_hc = √(1 − 0) = 1. The zero is written as an exact 0, with no "≈" and no parentheses.
TEST(WorkedSolution, ZeroUpToRoundingIsWrittenZero) {
  Problem p = testing::problem(R"({"id": "z", "kind": "intersect", "method": "geometric",
    "ray": {"origin": [0, 0, 0], "direction": [0.8944271909999159, 0.4472135954999579, 0]},
    "object": {"type": "sphere", "center": [10, 5, 0], "radius": 1}})");
  std::string txt = render(p, Format::kText);
  EXPECT_TRUE(has(txt, "d² = L² − t_ca² = 125 − 11.18² = 0\n")) << txt;
  EXPECT_TRUE(has(txt, "t_hc = √(r² − d²) = √(1 − 0) = 1\n")) << txt;
  EXPECT_FALSE(has(txt, "≈ 0\n")) << txt;
  EXPECT_FALSE(has(txt, "(0)")) << txt;
}

// In HTML a long step is a chain of formulas the page may wrap: d_r = f·d + x_diff·v +
// y_diff·u becomes the links "d_r", "= f·d", "+ x_diff·v", "+ y_diff·u", then the numbers
// the same way, then "= value" whole.
TEST(WorkedSolution, HtmlChainBreaksBeforeEqualsAndBetweenTerms) {
  Bank bank = load_bank({kSource + "/problems/camera-ray.json"});
  std::string html = render(find(bank, "camera-ray-corner"), Format::kHtml);
  const std::string link = "</mrow></math><math displaystyle=\"true\"><mrow>";
  EXPECT_TRUE(has(html, link + "<mo form=\"infix\">+</mo><msub><mi>y</mi><mi "
                               "mathvariant=\"normal\">diff</mi>"))
      << html;
  EXPECT_TRUE(has(html, link + "<mo form=\"infix\">+</mo><mrow><mo>(</mo>"))
      << html;  // + (−240) · ⟨0, 1, 0⟩
  EXPECT_FALSE(has(html, "<math display=\"block\">")) << html;
}

// Seed 004's triangle: q = (1/6, 1/3, 1/2) = (1/6)·a + (1/3)·b + (1/2)·c for the unit vertices
// a, b, c; the conclusion gives the weights it computed.
TEST(WorkedSolution, TriangleConclusionGivesTheBarycentricWeights) {
  Bank bank = load_bank({kSource + "/problems/seeds/seed004-surfaces.json"});
  const Problem& p = find(bank, "seed004-triangle");
  std::string txt = render(p, Format::kText);
  // t = 1/6: the numbers "1 / 6" are not repeated before the exact form that says the same.
  EXPECT_TRUE(has(txt, "t = (n · (a − O)) / (n · D) = 1 / 6 ≈ 0.1667\n")) << txt;
  EXPECT_TRUE(has(txt,
                  "In barycentric weights, P = w_a·a + w_b·b + w_c·c with w_a = 1/6 ≈ "
                  "0.1667, w_b = 1/3 ≈ 0.3333, w_c = 0.5.\n"))
      << txt;
}

// Acceptance 3, in the library: every kind of the bank renders in every format, with its
// formulas (LaTeX, MathML) and, in HTML, a sketch.
TEST(WorkedSolution, EveryKindInEveryFormat) {
  Bank bank = load_bank({kSource + "/problems"});
  ASSERT_TRUE(bank.errors.empty());
  std::map<std::string, const Problem*> by_kind;
  for (const auto& p : bank.problems) by_kind.emplace(p.kind, &p);
  for (const auto& p : bank.problems) by_kind.emplace(p.kind + " " + p.task->methods().front(), &p);
  for (const char* kind : {"intersect", "first-hit", "camera-ray", "ray-tree", "reflect", "refract",
                           "shade", "derive"}) {
    EXPECT_TRUE(by_kind.count(kind)) << "the bank has no " << kind << " problem";
  }
  for (const char* method : {"geometric", "point-normal", "implicit", "edge-tests",
                             "crossing-number", "quadratic", "slab"}) {
    EXPECT_TRUE(by_kind.count(std::string("intersect ") + method)) << method;
  }
  for (const auto& [kind, p] : by_kind) {
    SCOPED_TRACE(kind);
    EXPECT_TRUE(has(render(*p, Format::kMarkdown), "$$")) << p->id;
    std::string html = render(*p, Format::kHtml);
    EXPECT_TRUE(has(html, "<div class=\"chain\"><math displaystyle=\"true\"><mrow>")) << p->id;
    EXPECT_TRUE(has(html, "<svg")) << p->id;
    EXPECT_FALSE(has(html, "<script")) << p->id;
    EXPECT_TRUE(has(render(*p, Format::kText), " = ")) << p->id;
    auto j = nlohmann::json::parse(render(*p, Format::kJson));
    EXPECT_EQ(j["id"], p->id);
    std::size_t steps = 0;
    for (const auto& part : j["methods"][0]["parts"]) steps += part["steps"].size();
    EXPECT_GT(steps, 0u) << p->id;
  }
}

TEST(WorkedSolution, UserTextIsEscapedInEveryFormat) {
  Problem p = testing::problem(R"({
    "id": "x<1>", "kind": "first-hit", "title": "<script>alert(1)</script> *bold* \u001b[31m",
    "statement": "a & b",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "objects": [{"name": "<b>ball</b> $x$", "type": "sphere", "center": [0, 0, 5], "radius": 1}]})");
  std::string html = render(p, Format::kHtml);
  EXPECT_FALSE(has(html, "<script>"));
  EXPECT_FALSE(has(html, "<b>ball"));
  EXPECT_TRUE(has(html, "&lt;b&gt;ball&lt;/b&gt;"));
  EXPECT_TRUE(has(html, "a &amp; b"));
  std::string md = render(p, Format::kMarkdown);
  EXPECT_TRUE(has(md, "\\<script\\>"));
  EXPECT_TRUE(has(md, "\\<b\\>ball\\</b\\> \\$x\\$"));
  EXPECT_FALSE(has(render(p, Format::kText), "\x1b"));
  auto j = nlohmann::json::parse(render(p, Format::kJson));
  EXPECT_EQ(j["title"], "<script>alert(1)</script> *bold* \x1b[31m");  // data, kept as written
}

class SolutionsFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("raygrade-solutions-{}", ::testing::UnitTest::GetInstance()->random_seed());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Absolute paths given to `raygrade solutions` are written relative to the working folder in
// every file's first line: no generated file names where on this machine it was written.
TEST(SolutionsCommand, HeaderNamesNoAbsolutePath) {
  testing::TempDir dir("solutions-header");
  fs::create_directories(dir.path() / "bank");
  fs::copy_file(kSource + "/problems/seeds/seed000-spheres.json",
                dir.path() / "bank" / "spheres.json");
  testing::RunResult r =
      testing::run_raygrade("solutions '" + (dir.path() / "bank").string() + "' --out '" +
                                (dir.path() / "out").string() + "' --format md",
                            dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string readme = testing::read_text(dir.path() / "out" / "README.md");
  EXPECT_EQ(readme.rfind("<!-- Generated by raygrade with `raygrade solutions bank --out out`", 0),
            0u)
      << readme.substr(0, 200);
  EXPECT_EQ(readme.find(dir.path().string()), std::string::npos);
}

TEST_F(SolutionsFolder, WritesChecksAndRemovesOnlyGeneratedFiles) {
  Bank bank = load_bank({kSource + "/problems/seeds/seed000-spheres.json"});
  std::vector<Diagnostic> errors;
  auto files = solution_files(bank.problems, all_formats(), "raygrade solutions x --out y", errors);
  ASSERT_TRUE(errors.empty());
  ASSERT_EQ(files.size(), 5u * 4u + 1u);  // five problems, four formats, the index
  // Deterministic: the same bytes from a second run.
  auto again = solution_files(bank.problems, all_formats(), "raygrade solutions x --out y", errors);
  for (std::size_t i = 0; i < files.size(); ++i) EXPECT_EQ(files[i].bytes, again[i].bytes);
  for (const auto& f : files) {
    EXPECT_NE(f.bytes.substr(0, f.bytes.find('\n'))
                  .find("Generated by raygrade with `raygrade solutions x --out y`"),
              std::string::npos)
        << f.name;
  }

  EXPECT_EQ(check_solution_folder(dir_.string(), files).written.size(), files.size());
  FolderSync first = write_solution_folder(dir_.string(), files);
  EXPECT_EQ(first.written.size(), files.size());
  EXPECT_TRUE(check_solution_folder(dir_.string(), files).written.empty());

  std::ofstream(dir_ / "seed000-sphere-1.md") << "edited by hand\n";
  std::ofstream(dir_ / "old.md") << "<!-- Generated by raygrade with `...` -->\n";
  std::ofstream(dir_ / "notes.md") << "a person's notes\n";
  FolderSync stale = check_solution_folder(dir_.string(), files);
  EXPECT_EQ(stale.written, std::vector<std::string>{"seed000-sphere-1.md"});
  EXPECT_EQ(stale.removed, std::vector<std::string>{"old.md"});

  FolderSync second = write_solution_folder(dir_.string(), files);
  EXPECT_EQ(second.written.size(), 1u);
  EXPECT_EQ(second.unchanged, files.size() - 1);
  EXPECT_FALSE(fs::exists(dir_ / "old.md"));
  EXPECT_TRUE(fs::exists(dir_ / "notes.md"));
  EXPECT_TRUE(check_solution_folder(dir_.string(), files).written.empty());
}

// A hit on the edge between the first two vertices: the ray from (1, 0, −5) along +z meets
// the triangle (0,0,0), (2,0,0), (0,2,0) at (1, 0, 0), t = 5, halfway along that edge, so the
// weights are (½, ½, 0). The third comes out of the arithmetic as −0, which is never written.
TEST(SolveJson, NoNegativeZero) {
  testing::TempDir dir("solve-negative-zero");
  testing::write_text(dir.path() / "edge.json", R"({"problems": [{"id": "edge",
      "kind": "intersect",
      "object": {"type": "triangle", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]]},
      "ray": {"origin": [1, 0, -5], "direction": [0, 0, 1]}}]})");
  for (const char* format : {"json", "txt", "md", "html"}) {
    auto r = testing::run_raygrade(fmt::format("solve edge.json --format {}", format), dir.path());
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    // A zero with a minus sign: -0, −0, -0.0, −0.000 (not −0.447).
    static const std::regex negative_zero(R"((^|[^\d.])(-|−)0(\.0+)?($|[^\d.]))");
    std::smatch m;
    EXPECT_FALSE(std::regex_search(r.out, m, negative_zero)) << format << ": " << m.str();
    if (std::string(format) == "json") {
      auto hit = nlohmann::json::parse(r.out)["solutions"][0]["answer"]["hits"][0];
      EXPECT_EQ(hit["t"], 5.0);
      EXPECT_EQ(hit["barycentric"], nlohmann::json::array({0.5, 0.5, 0.0}));
      EXPECT_FALSE(std::signbit(hit["barycentric"][2].get<double>()));
    }
  }
}

}  // namespace
}  // namespace raygrade
