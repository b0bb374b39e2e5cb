// Nested media: the list of transparent objects a ray is inside, innermost last, and the
// refractive indices n1 and n2 on either side of each boundary it crosses (the "containers"
// of The Ray Tracer Challenge, ch. 11).
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace raygrade {

// One boundary crossed: the media before and after, and the indices on either side.
struct Crossing {
  int object = -1;
  double t = 0;
  bool enters = false;      // the object is on the list after the crossing
  double n1 = 1, n2 = 1;    // the innermost medium's index before and after
  std::vector<int> before;  // the media the ray is in before the crossing, innermost last
  std::vector<int> after;
};

// An object is a medium when it is transparent and has an inside: a solid, or a plane that
// bounds a half-space. Other objects are crossed without changing the list.
bool is_medium(const SceneObject& o);

// The refractive index of the innermost medium on the list; the scene's when it is empty.
double medium_index(const Scene& scene, const std::vector<int>& media);

// Crossing `object`: it leaves the list when it is on it (wherever it is), else it is added
// as the innermost. n1 is the innermost index before, n2 after.
Crossing cross_boundary(const Scene& scene, const std::vector<int>& media, int object, double t);

// The media that contain the ray's origin, the one the ray leaves last outermost (properly
// nested media).
std::vector<int> media_at_origin(const Scene& scene, const Ray& ray);

// Every boundary along the ray's line in [t_min, t_max], nearest first, starting from the
// media that contain the origin.
std::vector<Crossing> crossings(const Scene& scene, const Ray& ray);

// "glass A (inside water B)", "the space between objects (n = 1)": the list in words.
std::string media_words(const Scene& scene, const std::vector<int>& media);

}  // namespace raygrade
