// Grading the kinds `intersect` (every hit) and `first-hit` (the nearest object's hit): t
// values matched regardless of order, points, normals, the object, and the mistakes a
// student's t values reveal.
#include <fmt/format.h>

#include <cmath>

#include "core/error.h"
#include "derivation/number_format.h"
#include "grading/kind_grader.h"
#include "grading/mistakes.h"
#include "grading/parts.h"
#include "grading/steps.h"
#include "kinds/part_names.h"
#include "problems/ray_cast.h"
#include "shapes/transformed.h"

namespace raygrade {
namespace {

// Two unit normals this far apart are different directions: the normal a matrix gives differs
// from the inverse transpose's by far more (the ellipsoid's (−1.8, 1.6, 0)/|·| against
// (−1, 2, 0)/√5 by 0.2) unless A is a rotation with a uniform scale, where they agree.
constexpr double kDistinctNormals = 1e-6;

// The normal of a transformed object's hit taken to the world by A instead of (A⁻¹)ᵀ, when
// that differs from the right one: the normal-not-inverse-transpose mistake.
// The object's own normal there is n' ∝ Aᵀ·n (n ∝ (A⁻¹)ᵀ·n'), so no second intersection is
// needed to find it.
std::optional<Vec3d> normal_by_matrix(const Shape* shape, const Hit& ref) {
  const auto* moved = dynamic_cast<const TransformedShape*>(shape);
  if (!moved) return std::nullopt;
  const Affine& a = moved->transform().to_world;
  Vec3d wrong = normalized(a.linear(a.transpose_linear().linear(ref.normal)));
  if (length(wrong - ref.normal) <= kDistinctNormals) return std::nullopt;
  return wrong;
}

// How wrong the discriminant of a student's hand computation may be, relative to the size of
// its terms b² and 4|ac|: four significant figures carried through. Near a tangent
// (discriminant ≈ 0) a root moves by the square root of this, so the tolerance of t widens
// to (√(Δ + δΔ) − √Δ) / 2|a|; far from a tangent the widening is below the usual tolerance.
constexpr double kTangentInputError = 1e-4;
// A quadratic whose discriminant is this small relative to b² + 4|ac| has a double root (the
// ray touches the surface): rounding in double leaves about 1e-16 of it, hand work far more.
constexpr double kDoubleRootDiscriminant = 1e-12;
// A widened tolerance reaches at most this fraction of the way to the nearest other
// candidate (another root, another object's hit): half, so that no value is nearer to the
// accepted root than to the other.
constexpr double kWideningReach = 0.5;
// Roots this close (relative to 1 + |t|) are one root computed by two methods.
constexpr double kSameRoot = 1e-9;
// A ray's direction this close to length 1 is a unit direction: t along it is the distance, and
// a t typed as a distance is no mistake.
constexpr double kUnitDirection = 1e-9;
// A length (a normal's) or a sum (barycentric weights') this far from 1 is told to the student:
// a unit vector or weights typed to three decimals stay within it.
constexpr double kNotedOffOne = 1e-3;
// The credit of a ray lying in the surface answered by the other convention than the
// problem's ("contained" where it counts no intersection, or "hits": [] where it counts the
// line): right by the other half of ray tracers, so half.
constexpr double kOtherConventionCredit = 0.5;
// Feedback shows numbers with the significant figures of worked solutions (NumberFormat's
// default), as a fixed number of decimals shared by every number of the problem.
constexpr int kDisplayFigures = 4;
constexpr int kMaxDisplayDecimals = 6;

// One way a wrong value comes about: a named mistake (`id`), or none (another object's hit).
struct Reading {
  std::string id;
  std::string message;
};

struct StudentHit {
  std::optional<StudentNumber> t;
  std::string t_fault;
  std::optional<AnswerReader::Vector> point, normal, barycentric;
  std::optional<AnswerReader::Number> u, v;
};

std::string norm_name(const std::string& s) { return name_as_compared(s); }

class HitsGrader final : public KindGrader {
 public:
  explicit HitsGrader(const Problem& p);
  void grade(const AnswerReader& a, GradeResult& out) const override;

 private:
  std::vector<const Shape*> read_reference();
  void collect_candidates(const std::vector<const Shape*>& shapes, std::vector<double>& surface);
  double read_conditioning();
  bool same_root(double a, double b) const;
  void limit_widening();
  void choose_display_decimals();
  void grade_object(const AnswerReader& a, GradeResult& out) const;
  void grade_hits(const std::vector<StudentHit>& hits, const StepsGrade* steps,
                  GradeResult& out) const;
  // How the student's hits meet the reference's by t.
  struct TMatch {
    std::vector<int> match;      // per student hit: the reference hit it is, or -1
    std::vector<bool> used;      // per reference hit: whether a student hit is it
    std::vector<Match> verdict;  // per student hit
    std::vector<bool> twice;     // per student hit: a tangent's double root listed again
    std::size_t n_twice = 0;
    std::vector<std::string> feedback;  // the part t's
  };
  TMatch match_t(const std::vector<StudentHit>& hits) const;
  bool grade_t(const std::vector<StudentHit>& hits, const StepsGrade* steps, TMatch& m,
               GradeResult& out) const;
  void match_by_point(const std::vector<StudentHit>& hits, TMatch& m) const;
  void grade_claimed_miss(const StepsGrade* steps, GradeResult& out) const;
  std::optional<std::size_t> hit_of_weights(const StudentHit& h) const;
  void read_hits_from_weights(std::vector<StudentHit>& hits, GradeResult& out) const;
  void grade_contained(bool says_line, bool no_hits, GradeResult& out) const;
  void grade_barycentric(const std::vector<StudentHit>& hits, const std::vector<int>& match,
                         GradeResult& out) const;
  // What a part earns over the hits: credit, the hits that give it, and why it lost any.
  struct Tally {
    double credit = 0;
    std::size_t given = 0;
    std::vector<std::string> feedback;
  };
  std::vector<Reading> readings_of(const StudentNumber& t, std::size_t i,
                                   const std::vector<int>& match) const;
  void grade_point(const StudentHit& h, int jj, const std::vector<int>& match, Tally& tally,
                   GradeResult& out) const;
  void grade_normal(const StudentHit& h, int jj, Tally& tally, GradeResult& out) const;
  void add_part(const char* name, Tally tally, std::size_t n_stu, GradeResult& out) const;
  // A widening of t moves each coordinate of the point by at most |D|'s largest component.
  double widen_point(std::size_t j) const {
    const Vec3d& d = ray_.direction;
    return widen_[j] * std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  }
  bool nearer_another_t(double t, std::size_t j) const;
  bool is_candidate(double t) const {
    return std::any_of(candidates_.begin(), candidates_.end(),
                       [&](double c) { return std::abs(c - t) <= kSameRoot * (1 + std::abs(t)); });
  }
  bool nearer_another_point(const Vec3d& p, std::size_t j) const;
  std::optional<double> other_root_at(const StudentNumber (&p)[3], const Tolerance& tp) const;
  std::string fmt_t(double t) const { return format_number(t, numbers_); }

  const Task* task_;
  bool first_hit_ = false;
  Ray ray_;
  std::vector<Hit> ref_;
  bool contained_ = false;
  std::vector<std::string> names_;
  int ref_object_ = -1;
  const Shape* shape_ = nullptr;  // the object whose hits are asked for
  std::vector<double> widen_;
  // |A⁻¹D| of a transformed object's ray in object space, where it is neither 1 nor |D|
  // (t along its unit direction is then a mistake of its own); else 0.
  double object_space_scale_ = 0;
  bool double_root_ = false;  // one hit, where the ray touches the surface (a tangent)
  double spread_ = 0;         // how far apart a double root's two computed roots may lie
  Conventions conventions_;
  std::vector<double> behind_;      // roots with t < t_min: behind the origin
  std::vector<double> far_;         // roots past the first hit of the same object
  std::vector<double> others_;      // every object's hit that is none of the reference hits
  std::vector<double> candidates_;  // every root of every right derivation, every hit
  std::vector<std::pair<std::string, double>> other_objects_;  // the hits of objects hit later
  std::vector<MethodDerivation> methods_;
  std::vector<MistakenSolution> mistaken_;
  NumberFormat numbers_;
};

HitsGrader::HitsGrader(const Problem& p) : task_(p.task.get()), conventions_(p.conventions) {
  context_.problem = &p;
  context_.tolerance = read_tolerance_policy(p);
  if (p.precision >= 0) numbers_.decimals = p.precision;
  std::vector<std::string> names;
  for (const auto& spec : kind_parts(p.kind)) names.push_back(spec.name);
  context_.points = read_points_policy(p, default_points(p.kind, names));
  std::vector<const Shape*> shapes = read_reference();
  std::vector<double> surface;
  collect_candidates(shapes, surface);
  spread_ = read_conditioning();
  limit_widening();
  for (std::size_t k = 0; k < shapes.size() && first_hit_; ++k) {
    if (static_cast<int>(k) == ref_object_) continue;
    for (const auto& h : shapes[k]->intersect(ray_).hits)
      other_objects_.emplace_back(names_[k], h.t);
  }
  if (const auto* moved = dynamic_cast<const TransformedShape*>(shape_)) {
    double k = length(moved->transform().ray_to_object(ray_).direction);
    double dlen = length(ray_.direction);
    if (std::abs(k - 1) > kSameRoot && std::abs(k - dlen) > kSameRoot * (1 + dlen)) {
      object_space_scale_ = k;
    }
  }
  // The other points where the ray meets a surface: a value nearer one of them than the hit is
  // not the hit. (A derivation's other roots, a cap's plane where the ray misses the cap, say,
  // are no point of any surface, and only limit the widening.)
  for (double c : surface) {
    if (std::none_of(ref_.begin(), ref_.end(), [&](const Hit& h) { return same_root(c, h.t); })) {
      others_.push_back(c);
    }
  }
  if (p.precision < 0) choose_display_decimals();
  if (!first_hit_) methods_ = solutions_by_method(*task_);
  mistaken_ = mistaken_solutions(*task_);
}

// The reference: the hits of the one object, or the first hit of the first object hit. Returns
// every object of the problem.
std::vector<const Shape*> HitsGrader::read_reference() {
  const RayCast* cast = task_->ray_cast();
  if (!cast) throw InternalError("the hits grader was given a problem that casts no ray");
  std::vector<const Shape*> shapes;
  ray_ = cast->cast_ray();
  for (std::size_t i = 0; i < cast->object_count(); ++i) shapes.push_back(&cast->object_at(i));
  if (!cast->asks_first_object()) {
    Intersection x = shapes.front()->intersect(ray_);
    ref_ = x.hits;
    contained_ = x.contained;
    shape_ = shapes.front();
    return shapes;
  }
  first_hit_ = true;
  FirstHit f = cast->first_met(ray_);
  for (std::size_t i = 0; i < cast->object_count(); ++i) names_.emplace_back(cast->object_name(i));
  ref_object_ = f.index;
  if (f.index >= 0) {
    ref_.push_back(f.hit);
    shape_ = shapes[static_cast<std::size_t>(f.index)];
  }
  return shapes;
}

// Roots every method computes, kept when they are not hits: behind the origin, or far. All of
// them, and every object's hits, are the candidates a widened tolerance must not reach; the
// hits alone are the points of a surface.
void HitsGrader::collect_candidates(const std::vector<const Shape*>& shapes,
                                    std::vector<double>& surface) {
  for (const Shape* s : shapes) {
    Intersection x = s->intersect(ray_);
    for (const auto& h : x.hits) {
      candidates_.push_back(h.t);
      surface.push_back(h.t);
    }
    for (const auto& m : s->methods()) {
      Derivation d;
      try {
        d = s->derive(ray_, m);
      } catch (const Error&) {
        continue;  // a method that does not apply to this ray
      }
      for (double t : derivation_roots(d)) {
        candidates_.push_back(t);
        if (t < ray_.t_min) behind_.push_back(t);
        if (first_hit_ && !x.hits.empty() && t > x.hits.front().t + kSameRoot * (1 + std::abs(t))) {
          far_.push_back(t);
        }
      }
    }
  }
}

// The conditioning of the roots: a quadratic's a, b, c and discriminant, when it has one, set
// each hit's widening and whether it is a double root. Returns how far apart a double root's
// two computed roots may lie.
double HitsGrader::read_conditioning() {
  widen_.assign(ref_.size(), 0);
  if (!shape_) return 0;
  std::optional<Shape::QuadraticSteps> q = shape_->quadratic();
  Derivation d;
  try {
    if (q) d = shape_->derive(ray_, q->method);
  } catch (const Error&) {
  }
  const Step *a = q ? d.find(q->a) : nullptr, *b = q ? d.find(q->b) : nullptr,
             *c = q ? d.find(q->c) : nullptr;
  if (!(a && b && c && a->value.is_scalar() && a->value.scalar != 0)) return 0;
  double A = a->value.scalar, B = b->value.scalar, C = c->value.scalar;
  double disc = std::max(0.0, B * B - 4 * A * C);
  double delta = kTangentInputError * (B * B + 4 * std::abs(A * C));
  double w = (std::sqrt(disc + delta) - std::sqrt(disc)) / (2 * std::abs(A));
  widen_.assign(ref_.size(), w);
  double spread_limit = kDoubleRootDiscriminant * (B * B + 4 * std::abs(A * C));
  double_root_ = ref_.size() == 1 && std::abs(B * B - 4 * A * C) <= spread_limit;
  return double_root_ ? std::sqrt(spread_limit) / std::abs(A) : 0;
}

// A candidate within this of a hit is that hit, computed by another method (or a tangent's
// double root).
bool HitsGrader::same_root(double a, double b) const {
  return std::abs(a - b) <= std::max(spread_, kSameRoot * (1 + std::abs(b)));
}

// A widened tolerance never reaches another candidate: at most half way to the nearest one,
// however near (when the problem's own tolerance already spans both, that tolerance stands,
// and nothing is added to it).
void HitsGrader::limit_widening() {
  for (std::size_t j = 0; j < ref_.size(); ++j) {
    for (double c : candidates_) {
      if (!same_root(c, ref_[j].t)) {
        widen_[j] = std::min(widen_[j], kWideningReach * std::abs(c - ref_[j].t));
      }
    }
  }
}

// One display precision for every number of a message: without the problem's own, the
// decimals that show the smallest hit's t with four significant figures (7.268 and 10.732, not
// 7.268 beside 10.73).
void HitsGrader::choose_display_decimals() {
  double smallest = 0;
  for (const auto& h : ref_) {
    if (h.t != 0 && (smallest == 0 || std::abs(h.t) < smallest)) smallest = std::abs(h.t);
  }
  if (smallest > 0) {
    numbers_.decimals =
        std::clamp(kDisplayFigures - 1 - static_cast<int>(std::floor(std::log10(smallest))), 0,
                   kMaxDisplayDecimals);
  }
}

// The reference hit whose barycentric weights a hit gives ((w_a, w_b, w_c), or u = w_b and
// v = w_c), within the point's tolerance.
std::optional<std::size_t> HitsGrader::hit_of_weights(const StudentHit& h) const {
  const Tolerance& tol = context_.tolerance.for_field(part_names::kPoint);
  for (std::size_t j = 0; j < ref_.size(); ++j) {
    if (!ref_[j].barycentric) continue;
    const auto& w = *ref_[j].barycentric;
    if (h.barycentric && h.barycentric->ok &&
        compare_vector(h.barycentric->c, Vec3d{w[0], w[1], w[2]}, tol).match == Match::kRight)
      return j;
    if (!h.barycentric && h.u && h.v && h.u->value && h.v->value &&
        compare_number(*h.u->value, w[1], 1, tol).match == Match::kRight &&
        compare_number(*h.v->value, w[2], 1, tol).match == Match::kRight)
      return j;
  }
  return std::nullopt;
}

// A triangle's hit given by its weights alone, with neither t nor the point: the weights name
// the point P = w_a·a + w_b·b + w_c·c, and with it t. Where they are a hit's weights, that
// hit's t and point are given in another form, and graded as given (exactly: the weights'
// own digits are graded in `barycentric`).
void HitsGrader::read_hits_from_weights(std::vector<StudentHit>& hits, GradeResult& out) const {
  for (std::size_t i = 0; i < hits.size(); ++i) {
    StudentHit& h = hits[i];
    if (h.t || !h.t_fault.empty() || h.point || (!h.barycentric && !h.u && !h.v)) continue;
    std::optional<std::size_t> j = hit_of_weights(h);
    if (!j) continue;
    const Hit& ref = ref_[*j];
    auto exact = [](double value, std::string text) {
      return StudentNumber{value, TypedDigits{}, std::move(text)};
    };
    h.t = exact(ref.t, fmt_t(ref.t));
    AnswerReader::Vector p;
    p.ok = true;
    for (int k = 0; k < 3; ++k) p.c[k] = exact(ref.point[k], format_number(ref.point[k], numbers_));
    h.point = p;
    out.notes.push_back(fmt::format(
        "Hit {} is given by its barycentric weights alone: they are a hit's weights, so its t "
        "and its point P = w_a·a + w_b·b + w_c·c are read from them.",
        i + 1));
  }
}

// A value nearer to another point where the ray meets a surface (the exit, another object's hit)
// than to reference hit j is never that hit, whatever the tolerance.
bool HitsGrader::nearer_another_t(double t, std::size_t j) const {
  double d = std::abs(t - ref_[j].t);
  return std::any_of(others_.begin(), others_.end(), [&](double c) { return std::abs(t - c) < d; });
}

bool HitsGrader::nearer_another_point(const Vec3d& p, std::size_t j) const {
  double d = length(p - ref_[j].point);
  return std::any_of(others_.begin(), others_.end(),
                     [&](double c) { return length(p - ray_.at(c)) < d; });
}

// The other candidate whose point the student's point is (within the tolerance), if any.
std::optional<double> HitsGrader::other_root_at(const StudentNumber (&p)[3],
                                                const Tolerance& tp) const {
  for (double c : others_) {
    if (compare_vector(p, ray_.at(c), tp).match != Match::kWrong) return c;
  }
  return std::nullopt;
}

void HitsGrader::grade(const AnswerReader& a, GradeResult& out) const {
  if (first_hit_) {
    a.allow_only({part_names::kObject, "hits", "tie", part_names::kSteps});
  } else {
    a.allow_only({"hits", "contained", part_names::kSteps});
  }
  std::optional<StepsGrade> steps;
  if (a.has(part_names::kSteps)) {
    if (first_hit_) {
      out.notes.emplace_back("Steps are not graded for first-hit problems; the final answer is.");
    } else {
      steps = grade_steps(context_, *task_, methods_, mistaken_, a.at(part_names::kSteps));
      out.parts.push_back(steps->part);
      for (auto& m : steps->mistakes) out.mistakes.push_back(m);
    }
  }
  if (first_hit_) grade_object(a, out);
  bool says_line = a.has("contained") && a.at("contained").json() == true;
  if (!first_hit_ && contained_ && says_line && !a.has("hits")) {
    return grade_contained(true, true, out);
  }
  if (!a.has("hits")) {
    for (const char* part :
         {part_names::kT, part_names::kPoint, part_names::kNormal, part_names::kBarycentric}) {
      out.parts.push_back(missing_part(context_, part));
    }
    return;
  }
  std::vector<StudentHit> hits;
  for (const auto& h : a.at("hits").items()) {
    h.allow_only({part_names::kT, part_names::kPoint, part_names::kNormal, part_names::kBarycentric,
                  part_names::kU, part_names::kV, "part"});
    StudentHit s;
    if (h.has(part_names::kT)) {
      auto n = h.at(part_names::kT).number();
      s.t = n.value;
      s.t_fault = n.fault;
    }
    if (h.has(part_names::kPoint)) s.point = h.at(part_names::kPoint).vector();
    if (h.has(part_names::kNormal)) s.normal = h.at(part_names::kNormal).vector();
    if (h.has(part_names::kBarycentric)) s.barycentric = h.at(part_names::kBarycentric).vector();
    if (h.has(part_names::kU)) s.u = h.at(part_names::kU).number();
    if (h.has(part_names::kV)) s.v = h.at(part_names::kV).number();
    hits.push_back(std::move(s));
  }
  read_hits_from_weights(hits, out);
  if (!first_hit_ && contained_) return grade_contained(says_line, hits.empty(), out);
  if (hits.empty() && !ref_.empty()) return grade_claimed_miss(steps ? &*steps : nullptr, out);
  grade_hits(hits, steps ? &*steps : nullptr, out);
}

// A ray lying in a plane (or along a cylinder's side) meets it along a whole line. Textbooks
// and most ray tracers report that as no intersection; others as the line. By default both
// are right, with a note that teaches the case; the problem's convention may make one strict.
void HitsGrader::grade_contained(bool says_line, bool no_hits, GradeResult& out) const {
  std::string line = shape_ ? contained_line(shape_->type())
                            : "The ray lies in the object's plane: it meets it along a whole line";
  using C = Conventions::Contained;
  double credit = 1;
  std::string message;
  if (!no_hits) {
    credit = 0;
    message = line + ": there is no single t to give.";
  } else if (says_line) {
    credit = conventions_.contained == C::kMiss ? kOtherConventionCredit : 1;
    message = credit < 1 ? line + "; this problem counts that as no intersection: \"hits\": []."
                         : "Right: " + line + ".";
  } else {
    credit = conventions_.contained == C::kLine ? kOtherConventionCredit : 1;
    message = credit < 1 ? line + "; say so with \"contained\": true."
                         : "Right, as most ray tracers count it. " + line +
                               ", which \"contained\": true says exactly.";
  }
  out.parts.push_back(make_part(context_, part_names::kT, credit, {message}));
  // No single point to give: the point and normal follow the verdict on the line.
  for (const char* part : {part_names::kPoint, part_names::kNormal}) {
    if (context_.points.of(part) == 0) continue;
    out.parts.push_back(
        make_part(context_, part, credit,
                  {credit < 1 ? "No single point: see t." : "Right: no single point."}));
  }
}

// "hits": [] where the ray hits: a claimed miss is an answer, and is graded as one.
void HitsGrader::grade_claimed_miss(const StepsGrade* steps, GradeResult& out) const {
  std::vector<std::string> ts;
  for (const auto& h : ref_) ts.push_back(fmt_t(h.t));
  std::string said =
      fmt::format("You say the ray misses; it hits at t = {}.", fmt::join(ts, " and "));
  double credit = 0;
  std::vector<std::string> fb{said};
  if (steps && steps->carried) {
    // The student's own steps: do they lead to no hit?
    bool any_hit = false;
    std::vector<std::string> roots;
    for (double t : derivation_roots(*steps->carried)) {
      roots.push_back(fmt_t(t));
      any_hit |= t >= ray_.t_min && t <= ray_.t_max;
    }
    if (!any_hit) {
      credit = context_.points.carried_forward;
      out.carried_forward = true;
      fb.push_back(roots.empty()
                       ? "Your own steps give no real root, so no hit follows from them (error "
                         "carried forward)."
                       : fmt::format("Your own steps give t = {}, behind the origin, so no hit "
                                     "follows from them (error carried forward).",
                                     fmt::join(roots, " and ")));
    }
  }
  out.parts.push_back(make_part(context_, part_names::kT, credit, fb));
  for (const char* part : {part_names::kPoint, part_names::kNormal, part_names::kBarycentric}) {
    if (context_.points.of(part) == 0) continue;
    out.parts.push_back(make_part(context_, part, credit,
                                  {fmt::format("No {} where a miss is claimed: see t.", part)}));
  }
}

void HitsGrader::grade_object(const AnswerReader& a, GradeResult& out) const {
  if (!a.has(part_names::kObject)) {
    out.parts.push_back(missing_part(context_, part_names::kObject, "No object named."));
    return;
  }
  const auto& v = a.at(part_names::kObject).json();
  std::string right = ref_object_ >= 0 ? names_[static_cast<std::size_t>(ref_object_)] : "";
  if (v.is_string() && norm_name(v.get<std::string>()).empty()) {
    out.parts.push_back(missing_part(context_, part_names::kObject,
                                     ref_object_ < 0
                                         ? "The object is blank: write null when no object is hit."
                                         : "The object is blank: name the object hit first."));
    return;
  }
  if (v.is_null() || (v.is_string() && norm_name(v.get<std::string>()) == "none")) {
    out.parts.push_back(make_part(
        context_, part_names::kObject, ref_object_ < 0 ? 1 : 0,
        {ref_object_ < 0 ? "Right: no object is hit." : fmt::format("{} is hit.", right)}));
    return;
  }
  std::string name = a.at(part_names::kObject).string();
  bool ok = ref_object_ >= 0 && norm_name(name) == norm_name(right);
  out.parts.push_back(make_part(
      context_, part_names::kObject, ok ? 1 : 0,
      {ok                ? fmt::format("Right: {} is hit first.", right)
       : ref_object_ < 0 ? "No object is hit."
                         : fmt::format("The first object hit is {}, not {}.", right, name)}));
}

// Every reading that explains a wrong t (`t`, the student's hit i): each named mistake that
// gives it, another object's hit, the same hit listed twice.
std::vector<Reading> HitsGrader::readings_of(const StudentNumber& t, std::size_t i,
                                             const std::vector<int>& match) const {
  const Tolerance& tt = context_.tolerance.for_field(part_names::kT);
  auto near = [&](double r) { return compare_number(t, r, r, tt).match == Match::kRight; };
  const std::string& typed = t.text;
  double dlen = length(ray_.direction);
  std::vector<Reading> readings;
  for (double r : behind_) {
    if (!near(r)) continue;
    readings.push_back(
        {"negative-t",
         fmt::format("t = {} solves the equation, but t < {} puts it behind the ray's origin.",
                     typed, fmt_t(ray_.t_min))});
    break;
  }
  for (double r : far_) {
    if (!near(r)) continue;
    readings.push_back(
        {"far-root", fmt::format("t = {} is where the ray leaves the object; it enters at t = {}.",
                                 typed, ref_.empty() ? "?" : fmt_t(ref_.front().t))});
    break;
  }
  if (std::abs(dlen - 1) > kUnitDirection) {
    for (const auto& h : ref_) {
      if (!near(h.t * dlen)) continue;
      readings.push_back(
          {"unit-direction-t",
           fmt::format("t = {} is the distance along D/|D|; with |D| = {} the ray's t is {}.",
                       typed, format_number(dlen, numbers_), fmt_t(h.t))});
      break;
    }
  }
  if (object_space_scale_ > 0) {
    for (const auto& h : ref_) {
      if (!near(h.t * object_space_scale_)) continue;
      readings.push_back(
          {"object-space-unit-t",
           fmt::format("t = {} is the distance along A⁻¹D/|A⁻¹D| in the object's own space; "
                       "with |A⁻¹D| = {} the ray's t is {}.",
                       typed, format_number(object_space_scale_, numbers_), fmt_t(h.t))});
      break;
    }
  }
  for (const auto& ms : mistaken_) {
    bool fits = false;
    for (const auto& part : ms.parts) {
      for (double r : derivation_roots(part.derivation)) {
        // A root the mistake leaves as it was (a ball of radius 1 has r = r²) is no sign of it.
        fits = fits || (near(r) && !is_candidate(r));
      }
    }
    bool again = std::any_of(readings.begin(), readings.end(),
                             [&](const Reading& x) { return x.id == ms.id; });
    if (fits && !again) {
      readings.push_back({ms.id, fmt::format("your t = {} is what it gives.", typed)});
    }
  }
  for (const auto& [object, at] : other_objects_) {
    if (!near(at)) continue;
    readings.push_back({"", fmt::format("t = {} is where the ray meets {}, which is not the first "
                                        "object it hits.",
                                        typed, object)});
    break;
  }
  for (std::size_t k = 0; k < match.size(); ++k) {
    if (k == i || match[k] < 0 || !near(ref_[static_cast<std::size_t>(match[k])].t)) continue;
    readings.push_back({"", fmt::format("t = {} is listed twice; it is one hit.", typed)});
    break;
  }
  return readings;
}

void HitsGrader::grade_hits(const std::vector<StudentHit>& hits, const StepsGrade* steps,
                            GradeResult& out) const {
  std::size_t n_stu = hits.size();
  TMatch m = match_t(hits);
  bool any_t = grade_t(hits, steps, m, out);
  // Points and normals of the hits the student found; when no t was given, matched by point.
  if (!any_t) match_by_point(hits, m);
  Tally points, normals;
  for (std::size_t i = 0; i < n_stu; ++i) {
    const StudentHit& h = hits[i];
    if (h.point) grade_point(h, m.match[i], m.match, points, out);
    if (h.normal) grade_normal(h, m.match[i], normals, out);
  }
  add_part(part_names::kPoint, std::move(points), n_stu, out);
  add_part(part_names::kNormal, std::move(normals), n_stu, out);
  grade_barycentric(hits, m.match, out);
}

// Match t values to reference hits regardless of order.
HitsGrader::TMatch HitsGrader::match_t(const std::vector<StudentHit>& hits) const {
  const Tolerance& tt = context_.tolerance.for_field(part_names::kT);
  std::size_t n_ref = ref_.size(), n_stu = hits.size();
  TMatch m;
  m.match.assign(n_stu, -1);
  m.used.assign(n_ref, false);
  m.verdict.assign(n_stu, Match::kWrong);
  m.twice.assign(n_stu, false);
  // Right matches first, then those right to the digits given; each value to the nearest free
  // hit it fits.
  for (Match wanted : {Match::kRight, Match::kInsufficientPrecision}) {
    for (std::size_t i = 0; i < n_stu; ++i) {
      if (!hits[i].t || m.match[i] >= 0) continue;
      double value = hits[i].t->value;
      int best = -1;
      NumberVerdict best_verdict;
      for (std::size_t j = 0; j < n_ref; ++j) {
        if (m.used[j] || nearer_another_t(value, j)) continue;
        NumberVerdict v =
            compare_part(Comparison::kHits, *hits[i].t, ref_[j].t, tt, widen_[j]).verdict;
        if (v.match != wanted) continue;
        if (best >= 0 &&
            std::abs(value - ref_[j].t) >= std::abs(value - ref_[static_cast<std::size_t>(best)].t))
          continue;
        best = static_cast<int>(j);
        best_verdict = v;
      }
      if (best < 0) continue;
      m.match[i] = best;
      m.used[static_cast<std::size_t>(best)] = true;
      m.verdict[i] = best_verdict.match;
      if (best_verdict.match == Match::kInsufficientPrecision)
        m.feedback.push_back("t: " + best_verdict.message);
    }
  }
  // A tangent's double root listed twice (t = 5, 5), as many textbooks list it: one hit.
  if (double_root_ && m.used[0]) {
    for (std::size_t i = 0; i < n_stu; ++i) {
      if (!hits[i].t || m.match[i] >= 0) continue;
      if (compare_number(*hits[i].t, ref_[0].t, ref_[0].t, tt, widen_[0]).match != Match::kRight)
        continue;
      m.match[i] = 0;
      m.verdict[i] = Match::kRight;
      m.twice[i] = true;
      ++m.n_twice;
      m.feedback.push_back(fmt::format(
          "t = {} twice is right: the ray touches the surface, where the quadratic's two roots "
          "coincide (a double root); it is one hit.",
          hits[i].t->text));
    }
  }
  return m;
}

// The part t: each matched value's credit, the rest explained (error carried forward, a named
// mistake, another reading), and the hits not found. Returns whether any t was given.
bool HitsGrader::grade_t(const std::vector<StudentHit>& hits, const StepsGrade* steps, TMatch& m,
                         GradeResult& out) const {
  const Tolerance& tt = context_.tolerance.for_field(part_names::kT);
  std::size_t n_ref = ref_.size(), n_stu = hits.size();
  bool any_t = false;
  // A mistake found in t is named, and said in the part's feedback too.
  auto t_mistake = [&](const FoundMistake& mistake) {
    m.feedback.push_back(mistake.message);
    out.mistakes.push_back(mistake);
  };
  double t_credit = 0;
  std::vector<double> carried_roots;
  if (steps && steps->carried) carried_roots = derivation_roots(*steps->carried);
  std::vector<std::size_t> without_t;  // hits that give no t (nor an unreadable one)
  for (std::size_t i = 0; i < n_stu; ++i) {
    if (!hits[i].t) {
      if (!hits[i].t_fault.empty())
        m.feedback.push_back("t: " + hits[i].t_fault);
      else
        without_t.push_back(i);
      continue;
    }
    any_t = true;
    const std::string& typed = hits[i].t->text;
    if (m.twice[i]) continue;
    if (m.match[i] >= 0) {
      t_credit += m.verdict[i] == Match::kRight ? 1 : tt.precision_credit;
      continue;
    }
    auto near = [&](double r) {
      return compare_number(*hits[i].t, r, r, tt).match == Match::kRight;
    };
    if (std::any_of(carried_roots.begin(), carried_roots.end(), near)) {
      t_credit += context_.points.carried_forward;
      out.carried_forward = true;
      m.feedback.push_back(fmt::format(
          "t = {} follows correctly from your own earlier steps (error carried forward).", typed));
      continue;
    }
    // A named mistake is asserted only when it is the one reading that fits.
    std::vector<Reading> readings = readings_of(*hits[i].t, i, m.match);
    if (readings.empty()) {
      m.feedback.push_back(fmt::format("t = {} is not a hit of this ray.", typed));
    } else if (readings.size() == 1 && !readings.front().id.empty()) {
      t_mistake(make_mistake(readings.front().id, part_names::kT, readings.front().message));
    } else if (readings.size() == 1) {
      m.feedback.push_back(readings.front().message);
    } else {
      std::vector<std::string> fit;
      fit.reserve(readings.size());
      for (const auto& x : readings) {
        fit.push_back(x.id.empty() ? x.message
                                   : fmt::format("{} ({})", mistake_info(x.id).title, x.message));
      }
      m.feedback.push_back(fmt::format(
          "t = {} is not a hit. More than one reading explains it, so none is named: {}", typed,
          fmt::join(fit, "; or ")));
    }
  }
  // Beside hits that give their t, one that gives none counts as a hit with a wrong t.
  if (any_t) {
    for (std::size_t i : without_t) m.feedback.push_back(fmt::format("Hit {} gives no t.", i + 1));
  }
  std::size_t denom = std::max(n_ref, n_stu - m.n_twice);
  for (std::size_t j = 0; j < n_ref; ++j) {
    if (!m.used[j] && any_t) {
      m.feedback.push_back(first_hit_
                               ? fmt::format("The first hit is at t = {}.", fmt_t(ref_[j].t))
                               : fmt::format("The ray also hits at t = {}.", fmt_t(ref_[j].t)));
    }
  }
  if (n_ref == 0 && n_stu == 0) {
    out.parts.push_back(make_part(context_, part_names::kT, 1, {"Right: the ray does not hit."}));
  } else if (!any_t) {
    out.parts.push_back(
        missing_part(context_, part_names::kT, m.feedback.empty() ? "" : m.feedback.front()));
  } else {
    if (t_credit >= static_cast<double>(denom) && m.n_twice == 0 && m.feedback.empty()) {
      m.feedback.emplace_back(n_ref == 1 ? "Right." : "Right: every hit, in any order.");
    }
    if (n_ref == 0) m.feedback.emplace_back("The ray does not hit this object.");
    out.parts.push_back(
        make_part(context_, part_names::kT, t_credit / static_cast<double>(denom), m.feedback));
  }
  return any_t;
}

// Without any t, each student hit is matched to the nearest free reference hit by its point.
void HitsGrader::match_by_point(const std::vector<StudentHit>& hits, TMatch& m) const {
  const Tolerance& tp = context_.tolerance.for_field(part_names::kPoint);
  std::size_t n_ref = ref_.size(), n_stu = hits.size();
  for (std::size_t i = 0; i < n_stu; ++i) {
    if (!hits[i].point || !hits[i].point->ok) continue;
    const Vec3d& p = hits[i].point->value();
    int best = -1;
    for (std::size_t j = 0; j < n_ref; ++j) {
      if (m.used[j] || nearer_another_point(p, j)) continue;
      if (compare_vector(hits[i].point->c, ref_[j].point, tp, widen_point(j)).match ==
          Match::kWrong)
        continue;
      if (best >= 0 &&
          length(p - ref_[j].point) >= length(p - ref_[static_cast<std::size_t>(best)].point))
        continue;
      best = static_cast<int>(j);
    }
    if (best < 0) continue;
    m.match[i] = best;
    m.used[static_cast<std::size_t>(best)] = true;
  }
}

// One hit's point, matched to reference hit `jj` (or to none, −1): its credit and what is
// wrong with it go into `tally`.
void HitsGrader::grade_point(const StudentHit& h, int jj, const std::vector<int>& match,
                             Tally& tally, GradeResult& out) const {
  const Tolerance& tp = context_.tolerance.for_field(part_names::kPoint);
  ++tally.given;
  if (!h.point->ok) {
    tally.feedback.push_back("point: " + h.point->fault);
  } else if (jj >= 0) {
    auto j = static_cast<std::size_t>(jj);
    NumberVerdict v =
        compare_part(Comparison::kPoint, h.point->c, ref_[j].point, tp, widen_point(j)).verdict;
    if (v.match != Match::kWrong && nearer_another_point(h.point->value(), j)) {
      v.match = Match::kWrong;
    }
    if (v.match == Match::kRight) {
      tally.credit += 1;
    } else if (v.match == Match::kInsufficientPrecision) {
      tally.credit += tp.precision_credit;
      tally.feedback.push_back("point: " + v.message);
    } else if (std::optional<double> c = other_root_at(h.point->c, tp)) {
      tally.feedback.push_back(
          fmt::format("The point {} is where the ray is at t = {}; the hit at t = {} is {}.",
                      format_vector(h.point->value(), numbers_), fmt_t(*c), fmt_t(ref_[j].t),
                      format_vector(ref_[j].point, numbers_)));
    } else {
      tally.feedback.push_back(fmt::format("The point at t = {} is {}.", fmt_t(ref_[j].t),
                                           format_vector(ref_[j].point, numbers_)));
    }
  } else if (h.t) {
    // Consistent with the student's own t: P = O + tD. Nothing is carried from t = 0,
    // whose point is the ray's own origin.
    Vec3d own = ray_.at(h.t->value);
    if (h.t->value == 0) {
      tally.feedback.emplace_back(
          "Your t = 0 puts the point at the ray's own origin: nothing is carried forward "
          "from it.");
    } else if (compare_vector(h.point->c, own, tp).match == Match::kRight) {
      tally.credit += context_.points.carried_forward;
      out.carried_forward = true;
      tally.feedback.push_back(fmt::format(
          "The point follows correctly from your t = {} (error carried forward).", h.t->text));
    } else {
      tally.feedback.push_back(fmt::format("The point {} is not O + tD for your t = {}.",
                                           format_vector(h.point->value(), numbers_), h.t->text));
    }
  } else if (std::any_of(match.begin(), match.end(), [&](int j) {
               return j >= 0 && compare_vector(h.point->c, ref_[static_cast<std::size_t>(j)].point,
                                               tp, widen_point(static_cast<std::size_t>(j)))
                                        .match != Match::kWrong;
             })) {
    tally.feedback.push_back(fmt::format("The point {} is listed twice; it is one hit.",
                                         format_vector(h.point->value(), numbers_)));
  } else {
    tally.feedback.push_back(fmt::format("The point {} is not a hit of this ray.",
                                         format_vector(h.point->value(), numbers_)));
  }
}

// One hit's normal, matched to reference hit `jj` (or to none, −1), graded as a direction.
void HitsGrader::grade_normal(const StudentHit& h, int jj, Tally& tally, GradeResult& out) const {
  const Tolerance& tn = context_.tolerance.for_field(part_names::kNormal);
  ++tally.given;
  if (!h.normal->ok) {
    tally.feedback.push_back("normal: " + h.normal->fault);
    return;
  }
  if (jj < 0) {
    tally.feedback.push_back(fmt::format("The normal of a hit that is not one is not graded{}.",
                                         h.t ? fmt::format(" (t = {})", h.t->text) : ""));
    return;
  }
  auto j = static_cast<std::size_t>(jj);
  Vec3d mine = h.normal->value();
  // Graded as a direction: any positive multiple of the unit normal is right, and its
  // digits are judged as any number's.
  Vec3d r = ref_[j].normal;
  PartVerdict dv = compare_part(Comparison::kDirection, h.normal->c, r, tn);
  double len = dv.length;
  if (len == 0) {
    tally.feedback.emplace_back("A normal cannot be the zero vector.");
    return;
  }
  if (dv.verdict.match == Match::kRight) {
    tally.credit += 1;
    if (std::abs(len - 1) > kNotedOffOne) {
      tally.feedback.push_back(fmt::format("Your normal has length {}; as a direction it is right.",
                                           format_number(len, numbers_)));
    }
  } else if (dv.verdict.match == Match::kInsufficientPrecision) {
    tally.credit += tn.precision_credit;
    tally.feedback.push_back("normal: " + dv.verdict.message);
  } else if (dv.opposite) {
    NormalRule rule = shape_ ? normal_rule_of(*shape_) : NormalRule{};
    if (!rule.mistake.empty()) {
      const std::string& id = rule.mistake;
      out.mistakes.push_back(make_mistake(
          id, part_names::kNormal,
          fmt::format("your normal {} points the opposite way to {}.{}",
                      format_vector(mine, numbers_), format_vector(r, numbers_), rule.sentence)));
      tally.credit += mistake_info(id).credit;
      tally.feedback.push_back(
          fmt::format("Your normal points the opposite way to {}.", format_vector(r, numbers_)));
    } else {
      tally.feedback.push_back(
          fmt::format("Your normal points the opposite way to the plane's "
                      "normal {}.",
                      format_vector(r, numbers_)));
    }
  } else if (auto by_matrix = normal_by_matrix(shape_, ref_[j]);
             by_matrix &&
             compare_direction(h.normal->c, *by_matrix, tn).verdict.match == Match::kRight) {
    const char* id = "normal-not-inverse-transpose";
    out.mistakes.push_back(make_mistake(
        id, part_names::kNormal,
        fmt::format("your normal {} is the object's normal taken to the world by the matrix "
                    "A; by the inverse transpose (A⁻¹)ᵀ it is {}.",
                    format_vector(mine, numbers_), format_vector(r, numbers_))));
    tally.credit += mistake_info(id).credit;
    tally.feedback.push_back(
        fmt::format("The normal at t = {} is {}: normals go back by the "
                    "inverse transpose of the transform's matrix.",
                    fmt_t(ref_[j].t), format_vector(r, numbers_)));
  } else {
    tally.feedback.push_back(
        fmt::format("The normal at t = {} is {}.", fmt_t(ref_[j].t), format_vector(r, numbers_)));
  }
}

// The part `name` from what its hits earned: a share per reference hit (or per hit given, when
// more are given), missing when none gives it.
void HitsGrader::add_part(const char* name, Tally tally, std::size_t n_stu,
                          GradeResult& out) const {
  std::size_t n_ref = ref_.size(), d = std::max(n_ref, tally.given);
  if (n_ref == 0 && n_stu == 0) {  // no hit and none given: nothing was missed
    if (context_.points.of(name) > 0) out.parts.push_back(make_part(context_, name, 1, {}));
    return;
  }
  if (tally.given == 0) {
    if (context_.points.of(name) > 0) out.parts.push_back(missing_part(context_, name));
    return;
  }
  if (tally.credit >= static_cast<double>(d) && tally.feedback.empty())
    tally.feedback.emplace_back("Right.");
  if (tally.given < n_ref) {
    tally.feedback.push_back(fmt::format(
        "The ray has {} hits; {} of them {} given.", n_ref, tally.given,
        tally.given == 1 ? fmt::format("has its {}", name) : fmt::format("have their {}s", name)));
  }
  out.parts.push_back(
      make_part(context_, name, tally.credit / static_cast<double>(d), std::move(tally.feedback)));
}

// Barycentric weights (w_a, w_b, w_c) of a triangle hit, in the order of the vertices, or
// u = w_b and v = w_c alone: an exercise may ask for either.
void HitsGrader::grade_barycentric(const std::vector<StudentHit>& hits,
                                   const std::vector<int>& match, GradeResult& out) const {
  const Tolerance& tol = context_.tolerance.for_field(part_names::kPoint);
  std::size_t given = 0;
  double credit = 0;
  std::vector<std::string> fb;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const StudentHit& h = hits[i];
    if (!h.barycentric && !h.u && !h.v) continue;
    ++given;
    if (match[i] < 0 || !ref_[static_cast<std::size_t>(match[i])].barycentric) {
      fb.emplace_back(ref_.empty() || !ref_.front().barycentric
                          ? "Barycentric weights belong to a triangle's hit."
                          : "Weights of a hit that is not one are not graded.");
      continue;
    }
    auto w = *ref_[static_cast<std::size_t>(match[i])].barycentric;
    Vec3d want{w[0], w[1], w[2]};
    NumberFormat f = numbers_;
    if (h.barycentric) {
      if (!h.barycentric->ok) {
        fb.push_back("barycentric: " + h.barycentric->fault);
        continue;
      }
      NumberVerdict v = compare_vector(h.barycentric->c, want, tol);
      if (v.match == Match::kRight) {
        credit += 1;
        continue;
      }
      if (v.match == Match::kInsufficientPrecision) {
        credit += tol.precision_credit;
        fb.push_back("barycentric: " + v.message);
        continue;
      }
      Vec3d got = h.barycentric->value();
      double sum = got.x + got.y + got.z;
      std::string why = std::abs(sum - 1) > kNotedOffOne
                            ? fmt::format(
                                  " Your weights add up to {}; barycentric weights add up "
                                  "to 1.",
                                  format_number(sum, f))
                            : " They are in the order of the vertices a, b, c: w_a weighs a.";
      fb.push_back(fmt::format("The weights (w_a, w_b, w_c) are {}, not {}.{}",
                               format_vector(want, f), format_vector(got, f), why));
      continue;
    }
    // u = w_b and v = w_c (P = a + u(b − a) + v(c − a), as Möller and Trumbore write it).
    bool right = true;
    for (const auto& [given_uv, ref, name] :
         {std::tuple{&h.u, want.y, part_names::kU}, std::tuple{&h.v, want.z, part_names::kV}}) {
      if (!*given_uv) {
        right = false;
        // not a part: the vertex whose weight u or v is, b or c
        std::string_view vertex = std::string_view(name) == part_names::kU ? "b" : "c";
        fb.push_back(fmt::format("No {} given (the weight of {}).", name, vertex));
        continue;
      }
      const AnswerReader::Number& n = **given_uv;
      if (!n.value) {
        right = false;
        fb.push_back(fmt::format("{}: {}", name, n.fault));
        continue;
      }
      if (compare_number(*n.value, ref, 1, tol).match != Match::kRight) {
        right = false;
        fb.push_back(fmt::format("{} is {}, not {} (P = a + u(b − a) + v(c − a)).", name,
                                 format_number(ref, f), n.value->text));
      }
    }
    if (right) credit += 1;
  }
  if (given == 0) {
    out.parts.push_back(missing_part(context_, part_names::kBarycentric));
    return;
  }
  std::size_t d = std::max(ref_.size(), given);
  if (credit >= static_cast<double>(d) && fb.empty()) fb.emplace_back("Right.");
  out.parts.push_back(
      make_part(context_, part_names::kBarycentric, credit / static_cast<double>(d), fb));
}

}  // namespace

std::shared_ptr<const KindGrader> make_hits_grader(const Problem& p) {
  return std::make_shared<HitsGrader>(p);
}

}  // namespace raygrade
