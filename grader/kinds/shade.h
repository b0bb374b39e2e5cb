// Kind `shade`: the Phong intensity at one point, term by term: k_a·I_a, and for each light
// that reaches the point k_d·I_p·(N·L) and k_s·I_p·(R·V)^n. When any intensity or coefficient
// is a colour (scenes/colour.h), every term is a colour [r, g, b], worked channel by channel.
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"
#include "scenes/pattern.h"
#include "scenes/scene.h"

namespace raygrade {

// The kind `shade` (kinds/kind.h).
struct ShadeKind {
  static constexpr std::string_view kName = "shade";
  static constexpr std::string_view kSummary = "the Phong intensity at a point, term by term";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() {
    return {"point", "normal", "eye", "material", "lights", "ambient_light", "object_transform"};
  }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

struct ShadeLight {
  Light light;
  bool blocked = false;  // the exercise says its shadow ray is blocked
};

class ShadeTask final : public Task {
 public:
  // `normal` as the problem gives it (any length).
  ShadeTask(Vec3d point, Vec3d normal, Vec3d eye, Material m, Intensity ambient_light,
            std::vector<ShadeLight> lights)
      : point_(point),
        normal_(normalized(normal)),
        given_normal_(normal),
        eye_(eye),
        m_(m),
        ambient_light_(ambient_light),
        lights_(std::move(lights)) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return ShadeKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"phong"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;
  // Whether any intensity or coefficient is a colour: then every term is a colour [r, g, b].
  bool colour() const;
  // The material's `colour` (one colour or a pattern), on an object moved by `object`: its
  // colour at the point multiplies k_a and k_d (`m` of the constructor is the material with
  // those products already taken; `base` is the material as given).
  void set_surface(SurfaceColour surface, Transform object, Material base);

 private:
  Vec3d point_, normal_, given_normal_, eye_;
  Material m_;

  // The surface colour at the point, worked as steps (from the pattern, when there is one).
  void surface_steps(Deriver& d) const;

  Intensity ambient_light_;
  std::vector<ShadeLight> lights_;
  std::optional<SurfaceColour> surface_;
  Transform object_;
  Material base_;
  Vec3d object_point_{}, pattern_point_{};
  PatternValue surface_value_;
};

}  // namespace raygrade
