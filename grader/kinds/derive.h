// Kind `derive`: formula answers. The problem names quantities of an object's derivation
// (seed 000: the cylinder quadratic's a, b, c); the student answers each with a formula in
// the derivation's scalar symbols (px, py, vx, vy, r; cx, cy for an axis through (cx, cy)).
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"
#include "shapes/shape.h"

namespace raygrade {

// The kind `derive` (kinds/kind.h).
struct DeriveKind {
  static constexpr std::string_view kName = "derive";
  static constexpr std::string_view kSummary = "quantities of a derivation as formulas";
  static constexpr GraderFamily kGrader = GraderFamily::kFormula;
  static std::vector<std::string> keys() { return {"ray", "object", "find"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

// A quantity asked for, with its reference formula from the derivation.
struct DerivedQuantity {
  std::string name;     // the step name: "b"
  E formula;            // in the symbols below
  std::string display;  // the formula as text: "2·(p_x·v_x + p_y·v_y)"
};

// A symbol a formula may use: a scalar given of the derivation.
struct FormulaSymbol {
  std::string name;     // what students type: "px"
  std::string display;  // how worked solutions show it: "p_x" (also accepted when typed)
  std::string note;
  double example = 0;  // its value in the problem's worked example
};

class DeriveTask final : public Task {
 public:
  DeriveTask(Ray ray, std::unique_ptr<Shape> object, std::vector<DerivedQuantity> quantities,
             std::vector<FormulaSymbol> symbols)
      : ray_(ray),
        object_(std::move(object)),
        quantities_(std::move(quantities)),
        symbols_(std::move(symbols)) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return DeriveKind::kName; }
  // {"a": "v_x² + v_y²", ...}: each quantity's formula as text.
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return object_->methods(); }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

  const std::vector<DerivedQuantity>& quantities() const { return quantities_; }
  const std::vector<FormulaSymbol>& symbols() const { return symbols_; }

 private:
  Ray ray_;
  std::unique_ptr<Shape> object_;
  std::vector<DerivedQuantity> quantities_;
  std::vector<FormulaSymbol> symbols_;
};

}  // namespace raygrade
