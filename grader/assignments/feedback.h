// Feedback policies applied to graded answers, and an assignment's points.
#pragma once

#include "assignments/assignment.h"
#include "grading/result.h"

namespace raygrade {

// Rewrites a graded answer for a policy: kFull leaves it as it is; kMistakes keeps which part
// is right or wrong and the named mistakes with their general lessons, and drops every
// sentence that could hold a reference value; kScore keeps the points alone.
void apply_feedback_policy(GradeResult& r, FeedbackPolicy policy);

// Scales the points of a graded answer so that the problem is worth `points` in all.
void scale_points(GradeResult& r, double points);

}  // namespace raygrade
