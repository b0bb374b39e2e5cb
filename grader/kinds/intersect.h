// Kinds `intersect` (one object) and `first-hit` (the nearest of several named objects).
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"
#include "shapes/shape.h"

namespace raygrade {

// The kind `intersect` (kinds/kind.h).
struct IntersectKind {
  static constexpr std::string_view kName = "intersect";
  static constexpr std::string_view kSummary = "every hit of a ray with one object";
  static constexpr GraderFamily kGrader = GraderFamily::kHits;
  static std::vector<std::string> keys() { return {"ray", "object"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

// The kind `first-hit` (kinds/kind.h).
struct FirstHitKind {
  static constexpr std::string_view kName = "first-hit";
  static constexpr std::string_view kSummary = "the object a ray hits first";
  static constexpr GraderFamily kGrader = GraderFamily::kHits;
  static std::vector<std::string> keys() { return {"ray", "objects"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

class IntersectTask final : public Task {
 public:
  IntersectTask(Ray ray, std::unique_ptr<Shape> object, std::string method)
      : ray_(ray), object_(std::move(object)), method_(std::move(method)) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return IntersectKind::kName; }
  nlohmann::json answer() const override;
  std::optional<std::string> level() const override;
  std::vector<std::string> methods() const override { return object_->methods(); }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;

  const Ray& ray() const { return ray_; }
  const Shape& object() const { return *object_; }

 private:
  Ray ray_;
  std::unique_ptr<Shape> object_;
  std::string method_;
};

struct NamedShape {
  std::string name;
  std::unique_ptr<Shape> shape;
};

// The nearest hit of each object and the first of them all.
struct FirstHit {
  int index = -1;  // into the objects; -1 when nothing is hit
  Hit hit;
  bool tie = false;                         // another object is hit at the same t
  std::vector<std::optional<Hit>> nearest;  // per object
  // The highest level of the adaptive ladder the decisions needed (docs/precision.md), when the
  // study covers every object.
  std::optional<std::string> level;
};
FirstHit first_hit(const Ray& ray, const std::vector<NamedShape>& objects);

class FirstHitTask final : public Task {
 public:
  FirstHitTask(Ray ray, std::vector<NamedShape> objects, std::string method)
      : ray_(ray), objects_(std::move(objects)), method_(std::move(method)) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return FirstHitKind::kName; }
  nlohmann::json answer() const override;
  std::optional<std::string> level() const override;
  std::vector<std::string> methods() const override;
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;

  const Ray& ray() const { return ray_; }
  const std::vector<NamedShape>& objects() const { return objects_; }

 private:
  Ray ray_;
  std::vector<NamedShape> objects_;
  std::string method_;
};

// Reads a list of objects, each with a unique `name`.
std::vector<NamedShape> read_named_objects(const Cursor& list);

// The one object of a kind that has a single object (intersect, derive): a name would label it
// among others, and there are none, so a name is an unused key.
std::unique_ptr<Shape> read_lone_object(const Cursor& object);

}  // namespace raygrade
