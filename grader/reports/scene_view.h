// The 3D view of a problem's scene: the objects, the given ray, the lights and the camera as
// JSON, which the pages' script (web/viewer/, bundled into kSceneViewScript) draws with three.js.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "problems/problem.h"

namespace raygrade {

// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct SceneView {
  nlohmann::json data;      // what web/viewer/scene_view.js reads (docs/web.md, "The 3D view")
  std::string description;  // the same in words, for a reader who cannot see the canvas
};

// The view of `problem`, or nothing when its task has nothing to draw (Task::scene_givens).
// Without `answers` it holds the givens alone, as the task answers for them (a handout or
// practice page: no hit, no normal, no ray the student is asked for); with `answers`, also the
// hits, their normals and the rays the answer holds.
std::optional<SceneView> scene_view(const Problem& problem, bool answers);

// The view as HTML: a <figure> with the canvas's container, its caption (the description and the
// controls) and its data; `id` must be unique in the page. The page loads kSceneViewScript once,
// after the last view.
std::string scene_view_html(const SceneView& view, const std::string& id, const std::string& title);

// The style of the views, once per page.
inline constexpr std::string_view kSceneViewStyle =
    ".scene-view-figure{margin:1rem 0}.scene-view{width:100%;max-width:720px;"
    "min-height:3rem;border:1px solid #ccc;background:#f6f6f2}"
    ".scene-view canvas{display:block;width:100%;height:auto}"
    ".scene-view canvas:focus-visible{outline:3px solid #1f5fbf;outline-offset:2px}"
    "@media print{.scene-view-figure{display:none}}";

}  // namespace raygrade
