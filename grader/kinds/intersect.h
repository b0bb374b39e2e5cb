// Kinds `intersect` (one object) and `first-hit` (the nearest of several named objects).
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"
#include "problems/ray_cast.h"
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

class IntersectTask final : public Task, public RayCast {
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
  std::optional<SceneGivens> scene_givens() const override;

  const Ray& ray() const { return ray_; }
  const Shape& object() const { return *object_; }

  const RayCast* ray_cast() const override { return this; }
  const Ray& cast_ray() const override { return ray_; }
  std::size_t object_count() const override { return 1; }
  const Shape& object_at(std::size_t /*i*/) const override { return *object_; }
  std::string_view object_name(std::size_t /*i*/) const override { return {}; }
  bool asks_first_object() const override { return false; }
  FirstHit first_met(const Ray& ray) const override;

 private:
  Ray ray_;
  std::unique_ptr<Shape> object_;
  std::string method_;
};

struct NamedShape {
  std::string name;
  std::unique_ptr<Shape> shape;
};

// The nearest hit of each object and the first of them all (FirstHit: problems/ray_cast.h).
FirstHit first_hit(const Ray& ray, const std::vector<NamedShape>& objects);

class FirstHitTask final : public Task, public RayCast {
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
  std::optional<SceneGivens> scene_givens() const override;

  const Ray& ray() const { return ray_; }
  const std::vector<NamedShape>& objects() const { return objects_; }

  const RayCast* ray_cast() const override { return this; }
  const Ray& cast_ray() const override { return ray_; }
  std::size_t object_count() const override { return objects_.size(); }
  const Shape& object_at(std::size_t i) const override { return *objects_.at(i).shape; }
  std::string_view object_name(std::size_t i) const override { return objects_.at(i).name; }
  bool asks_first_object() const override { return true; }
  FirstHit first_met(const Ray& ray) const override { return first_hit(ray, objects_); }

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
