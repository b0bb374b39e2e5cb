// The handout page and the answers template.
#include "assignments/handout.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "assignments/answer_form.h"
#include "assignments/handout_assets.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "derivation/formula.h"
#include "json/numbers.h"
#include "json/source.h"
#include "kinds/fields/field_type.h"
#include "reports/scene_view.h"
#include "reports/scene_view_assets.h"
#include "reports/svg_figure.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

json identity_json(const StudentIdentity& s) {
  json j = json::object();
  if (!s.name.empty()) j["name"] = s.name;
  if (!s.id.empty()) j["id"] = s.id;
  if (!s.email.empty()) j["email"] = s.email;
  return j;
}

std::string points_text(const AssignmentSpec& spec, std::size_t i, const Problem& p) {
  if (i < spec.problems.size() && spec.problems[i].points) {
    double pts = *spec.problems[i].points;
    return fmt::format("{:g} point{}", pts, pts == 1 ? "" : "s");
  }
  (void)p;
  return "";
}

// The due date in UTC, the text a browser without script shows; the page's script adds the
// student's local time from the datetime.
std::string due_html(const AssignmentSpec& spec) {
  if (!spec.due) return "";
  return fmt::format("<p class=\"due\">Due <time datetime=\"{}\">{}</time></p>\n",
                     iso_utc_time(*spec.due), html_escape(utc_time_text(*spec.due)));
}

// The assignment's text as the page reads it. A bank named by an absolute path would point
// outside the page's in-memory file system: such names are given relative to the assignment,
// as the page names the bank's files. Otherwise the text is the file's, byte for byte.
std::string page_assignment_text(const AssignmentSpec& spec, const std::string& text,
                                 const std::filesystem::path& home) {
  namespace fs = std::filesystem;
  auto doc = nlohmann::ordered_json::parse(text);
  bool absolute = false;
  auto page_name = [&](nlohmann::ordered_json& name) {
    fs::path written(name.get<std::string>());
    if (!written.is_absolute()) return;
    absolute = true;
    fs::path r = written.lexically_normal().lexically_relative(home);
    if (r.empty()) {
      throw Error(
          Diagnostic{spec.file, "/bank", 0, 0, Severity::kError,
                     "the bank '" + written.string() + "' has no name relative to the assignment",
                     "practice-bank"});
    }
    name = r.generic_string();
  };
  nlohmann::ordered_json& bank = doc["bank"];
  if (bank.is_string()) {
    page_name(bank);
  } else {
    for (auto& b : bank) page_name(b);
  }
  return absolute ? doc.dump(2) + "\n" : text;
}

}  // namespace

std::string statement_figure_svg(const Problem& p) {
  Sketch full = p.task->sketch();
  if (full.empty()) return "";
  Sketch s = full;
  s.items.clear();
  bool ray_kept = false;
  for (const auto& item : full.items) {
    switch (item.ink) {
      case Ink::kObject: s.items.push_back(item); break;
      case Ink::kPoint:
        // The ray's origin, the eye, the light: given in the statement.
        if (item.type == SketchItem::Type::kPoint) s.items.push_back(item);
        break;
      case Ink::kRay:
        // The first ray drawn is the one given; later ones (reflected, refracted) are answers.
        // It is drawn as a direction from its origin, without a length that could tell t.
        if (!ray_kept && !full.ray_is_answer && item.points.size() == 2) {
          SketchItem ray = item;
          ray.label.clear();
          Vec3d d = ray.points[1] - ray.points[0];
          double len = length(d);
          if (len > 0) ray.points[1] = ray.points[0] + d * (1.0 / len);
          ray.type = SketchItem::Type::kArrow;
          s.items.push_back(ray);
          ray_kept = true;
        }
        break;
      case Ink::kGuide:
        // A camera's image plane and f·d are given; other guides are the solution's.
        if (full.ray_is_answer) s.items.push_back(item);
        break;
      case Ink::kHit:
      case Ink::kMiss:
        break;  // construction lines, hits and rejected candidates belong to the solution
    }
  }
  if (s.items.empty()) return "";
  return render_svg(s, p.title.empty() ? p.id : p.title).svg;
}

PracticeAssets practice_assets(const AssignmentSpec& spec, std::string grader_js) {
  namespace fs = std::filesystem;
  PracticeAssets out;
  out.grader_js = std::move(grader_js);
  std::vector<Diagnostic> errors;
  std::vector<std::string> bank_files = list_bank_files(spec.bank, errors);
  if (!errors.empty()) throw Error(errors.front());
  // Each bank file relative to the assignment's folder; the assignment goes as many folders
  // deep as the most ".." among them, so that every name stays inside the page's folder.
  fs::path home = fs::absolute(fs::path(spec.file)).parent_path().lexically_normal();
  std::vector<fs::path> relative;
  std::size_t depth = 0;
  for (const auto& f : bank_files) {
    fs::path r = fs::absolute(fs::path(f)).lexically_normal().lexically_relative(home);
    if (r.empty()) {
      throw Error(Diagnostic{spec.file, "/bank", 0, 0, Severity::kError,
                             "the bank file '" + f + "' has no name relative to the assignment",
                             "practice-bank"});
    }
    std::size_t ups = 0;
    for (const auto& part : r) ups += part == "..";
    depth = std::max(depth, ups);
    relative.push_back(r);
  }
  fs::path folder;
  for (std::size_t k = 0; k < depth; ++k) folder /= fmt::format("d{}", k + 1);
  auto read = [](const std::string& file) { return load_json_file(file)->text; };
  out.assignment = (folder / fs::path(spec.file).filename()).generic_string();
  out.files.emplace_back(out.assignment, page_assignment_text(spec, read(spec.file), home));
  for (std::size_t i = 0; i < bank_files.size(); ++i) {
    out.files.emplace_back((folder / relative[i]).lexically_normal().generic_string(),
                           read(bank_files[i]));
  }
  return out;
}

Handout make_handout(const AssignmentSpec& spec, const std::vector<Problem>& problems,
                     const StudentIdentity* student, const PracticeAssets* practice) {
  Handout out;
  json data = {{"assignment", {{"id", spec.id}, {"title", spec.title}}},
               {"formula",
                {{"functions", formula_function_names()},
                 {"max_length", kMaxFormulaLength},
                 {"max_depth", kMaxFormulaDepth}}},
               {"field_types", field_types_json()}};
  data["student"] =
      student ? json{{"key", student_key(*student)}, {"identity", identity_json(*student)}}
              : json{{"key", ""}, {"identity", nullptr}};
  json listed = json::array();
  json answers = json::object();
  std::string sections;
  int views = 0;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const Problem& p = problems[i];
    json form = answer_form(p);
    listed.push_back({{"index", i}, {"id", p.id}, {"form", form}});
    answers[p.id] = blank_answer(form);
    std::string points = points_text(spec, i, p);
    std::string figure = statement_figure_svg(p);
    // The 3D view of the givens, after the sketch (the printed and text form of the scene).
    std::string view_html;
    if (std::optional<SceneView> view = scene_view(p, false)) {
      view_html =
          scene_view_html(*view, fmt::format("scene-{}", i), p.title.empty() ? p.id : p.title);
      ++views;
    }
    sections += fmt::format(
        "<section class=\"problem\" id=\"problem-{}\" data-problem=\"{}\">\n<h2>{}. {}{}</h2>\n"
        "<p class=\"muted\">Problem id: <code>{}</code></p>\n<p class=\"statement\">{}</p>\n{}"
        "<div class=\"form\" id=\"form-{}\"></div>\n</section>\n",
        i, html_escape(p.id), i + 1, html_escape(p.title.empty() ? p.id : p.title),
        points.empty() ? "" : fmt::format(" <span class=\"points\">({})</span>", points),
        html_escape(p.id), html_escape(p.statement),
        figure.empty() ? view_html : fmt::format("<figure>{}</figure>\n{}", figure, view_html), i);
  }
  data["problems"] = listed;
  std::string grader_script;
  if (practice) {
    json files = json::object();
    for (const auto& [name, text] : practice->files) files[name] = text;
    data["practice"] = {{"assignment", practice->assignment},
                        {"files", files},
                        {"unlock_after", kPracticeUnlockAfter}};
    for (const auto& [key, value] : practice->lms_data.items()) data["practice"][key] = value;
    // raygrade.js in a <script> element: nothing in it may close the element.
    if (practice->grader_js.find("</") != std::string::npos) {
      throw Error(Diagnostic{"", "", 0, 0, Severity::kError,
                             "the grader's script holds \"</\", which would end its <script> "
                             "element: is it raygrade.js?",
                             "practice-grader"});
    }
    grader_script = "<script>" + practice->grader_js + "</script>\n";
  }
  // The 3D view's script inline, once, after the last view: the page stays one file. As a
  // module it runs after the page's own script, which starts the grader first.
  if (views > 0) {
    grader_script += "<style>" + std::string(kSceneViewStyle) +
                     "</style>\n<script type=\"module\">" + std::string(kSceneViewScript) +
                     "</script>\n";
  }
  // The LMS's side runs first: the page's own script asks it for the answers to resume.
  std::string lms_script;
  std::string kept =
      "Your answers are kept in this browser; when you are done, download "
      "<code>answers.json</code> and hand it in.";
  if (practice && !practice->lms_script.empty()) {
    lms_script = "<script>" + std::string(practice->lms_script) + "</script>\n";
    if (!practice->kept.empty()) kept = practice->kept;
  }
  std::string who = student ? student->display() : "";
  std::string title = spec.title + (who.empty() ? "" : " — " + who);
  out.html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "script-src 'unsafe-inline' 'wasm-unsafe-eval'; style-src 'unsafe-inline'; img-src data:\">\n"
      "<title>{}</title>\n<style>{}</style>\n</head>\n<body>\n<header>\n<h1>{}</h1>\n{}{}"
      "<p>Type each answer as a number or as you would write it: <code>9 - sqrt(3)</code>, "
      "<code>2√2</code>, <code>1/3</code>, <code>pi/4</code>. Each input says at once whether "
      "it can be read; it does not say whether it is right. {}</p>\n"
      "</header>\n<main>\n{}<div id=\"actions\"><button type=\"button\" id=\"download\">Download "
      "answers.json</button><button type=\"button\" id=\"clear\">Clear my answers</button> "
      "<span id=\"saved\" class=\"muted\"></span></div>\n</main>\n"
      "<script type=\"application/json\" id=\"handout-data\">{}</script>\n{}{}<script>{}</script>\n"
      "</body>\n</html>\n",
      html_escape(title), kHandoutStyle, html_escape(spec.title),
      who.empty() ? "" : fmt::format("<p class=\"student\">For {}</p>\n", html_escape(who)),
      due_html(spec), kept, sections, script_json(data), grader_script, lms_script, kHandoutScript);
  out.template_json = json::object();
  if (student) out.template_json["student"] = identity_json(*student);
  out.template_json["answers"] = answers;
  return out;
}

}  // namespace raygrade
