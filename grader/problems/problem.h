// Problem: one exercise of the bank: its common keys and the kind-specific task.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "derivation/derivation.h"
#include "json/cursor.h"
#include "problems/kind.h"
#include "problems/parameters.h"
#include "problems/scene_givens.h"
#include "shapes/ray.h"
#include "shapes/sketch.h"

namespace raygrade {

class RayCast;

// A drawing in a worked solution, in the forms the renderers use.
struct Figure {
  std::string caption;
  std::string svg;   // a complete <svg> element with its text escaped (HTML pages)
  std::string dot;   // Graphviz source
  std::string text;  // lines for a terminal (text and Markdown solutions)
};

// One part of a worked solution: a derivation, with a heading when a problem has several
// (one per object of a first-hit problem), and any figures drawn before its steps.
struct SolutionPart {
  SolutionPart() = default;
  SolutionPart(std::string heading_, Derivation derivation_, std::vector<Figure> figures_ = {})
      : heading(std::move(heading_)),
        derivation(std::move(derivation_)),
        figures(std::move(figures_)) {}

  std::string heading;
  Derivation derivation;
  std::vector<Figure> figures;
};

// Conventions on which textbooks differ, so that an exercise can say which it follows
// (docs/grading.md): a problem's "conventions", or a bank file's for all its problems.
struct Conventions {
  // A ray lying in a plane, or running along a cylinder's side, meets it along a whole line.
  // kEither: "contained": true and "no intersection" ([]) are both right (the default);
  // kLine: only "contained": true is; kMiss: only [] is.
  enum class Contained { kEither, kLine, kMiss };
  Contained contained = Contained::kEither;
  // A point of a ray tree whose surface faces away from a light (N·L ≤ 0) while a shadow ray
  // toward that light would also meet another object. kEither: "in shadow" and "not in
  // shadow" are both right (the default); kShadowRay: the shadow ray decides (in shadow);
  // kNormalFirst: N·L is tested first, so the ray is never cast (not in shadow).
  enum class FacingAway { kEither, kShadowRay, kNormalFirst };
  FacingAway facing_away = FacingAway::kEither;
};

// The kind-specific part of a problem: what it asks and how to answer it.
class Task {
 public:
  virtual ~Task() = default;
  virtual std::string_view kind() const = 0;
  // The reference answer, in the shape documented for the kind.
  virtual nlohmann::json answer() const = 0;
  // The methods the worked solution may use; the first is the default.
  virtual std::vector<std::string> methods() const = 0;
  // The worked solution by `method` (empty: the problem's or the kind's default).
  virtual std::vector<SolutionPart> derive(std::string_view method,
                                           const Overrides* overrides = nullptr) const = 0;
  // Sentences that sum up the answer (the last part's conclusion, for most kinds).
  virtual std::vector<std::string> conclusion() const;
  // The sketch of the worked solution: the objects, the ray, the hit points. Empty (no
  // sketch) unless the kind draws one.
  virtual Sketch sketch() const { return {}; }
  // The precision the answer's hit-or-miss decision needed ("double", "double-double", "mpfr",
  // "exact-boundary"), for kinds that know it.
  virtual std::optional<std::string> level() const { return std::nullopt; }
  // The course's conventions, for a kind whose reference answer depends on one (a ray tree's
  // point that faces away from a light whose shadow ray is blocked anyway): called once, right
  // after the task is read, so that its answer, worked solution and sketch follow them.
  virtual void follow(const Conventions& /*conventions*/) {}
  // The ray and objects of a problem that casts one ray at objects; null for other kinds.
  virtual const RayCast* ray_cast() const { return nullptr; }
  // What the 3D view draws of the givens (problems/scene_givens.h); nullopt for a problem with
  // nothing to draw in 3D. Every kind answers, so that a new one decides what its view shows.
  virtual std::optional<SceneGivens> scene_givens() const = 0;
};

// Reads a "conventions" object on top of `base`. Throws Error naming the path of a fault.
Conventions read_conventions(const Cursor& c, Conventions base);

// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct Problem {
  std::string id;
  std::string kind;
  std::string title;
  std::string statement;
  std::string method;  // the worked solution's method; empty for the kind's default
  int precision = -1;  // decimals shown in worked solutions; -1 for significant digits
  std::optional<nlohmann::json> expected;
  nlohmann::json tolerance;      // as written; the grader reads it
  nlohmann::json points;         // as written; the grader reads it
  nlohmann::json tests;          // sample answers with the scores they must get
  Conventions conventions;       // the bank file's, then the problem's own
  Conventions file_conventions;  // the bank file's alone (to read the problem again)
  nlohmann::json source;         // the whole problem object as written
  std::string file;              // where it came from
  std::string path;              // its JSON pointer in that file ("" or "/problems/3")
  std::shared_ptr<const SourceFile> source_file;
  std::unique_ptr<Task> task;
  // A problem with parameters (problems/parameters.h): the set, the problem as written (with
  // its "=r" and "{r}"), and the values this Problem was read with (the defaults in a bank).
  std::shared_ptr<const ParameterSet> parameters;
  std::shared_ptr<const SourceFile> template_file;
  const nlohmann::json* template_json = nullptr;  // inside template_file
  ParameterValues values;
};

// The keys every problem may carry.
const std::vector<std::string>& common_problem_keys();

// Reads a ray {origin, direction, t_min, t_max}; rejects a zero direction and t_min > t_max.
Ray read_ray(const Cursor& ray);

// Reads one problem object. Throws Error naming the file and path on any fault. A problem with
// parameters is read with their defaults; `defaults` are the bank file's conventions.
Problem read_problem(const Cursor& problem, const Conventions& defaults = {});

// Reads a problem with parameters for one set of values: the plain problem they give, with
// the file and path of the problem as written. Throws Error at the path of any fault.
Problem read_problem_variant(const Problem& base, const ParameterValues& values);

// Every problem of a set of files and folders (folders are searched recursively for *.json,
// in sorted order). Faulty files and problems are reported in `errors` and skipped; the rest
// are read. Ids must be unique across the whole set.
struct Bank {
  std::vector<Problem> problems;
  std::vector<Diagnostic> errors;
  std::vector<std::string> files;
};
Bank load_bank(const std::vector<std::string>& paths);

// The files a set of files and folders names, as load_bank reads them; a missing path is
// reported in `errors` (code "unreadable").
std::vector<std::string> list_bank_files(const std::vector<std::string>& paths,
                                         std::vector<Diagnostic>& errors);

// The problem objects of a file: the items of its "problems" list, or the root itself.
// Throws Error when the list is malformed or the wrapper has unknown keys.
std::vector<Cursor> problem_items(const Cursor& root);

nlohmann::json vec_json(const Vec3d& v);
nlohmann::json hit_json(const Hit& h);
nlohmann::json intersection_json(const Intersection& x);

}  // namespace raygrade
