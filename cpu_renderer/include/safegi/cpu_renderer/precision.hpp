// Whether the renderer's numbers can resolve a scene where it stands. Float
// spacing grows with distance from the origin (2⁻²³ of the coordinate): a
// 0.5 m box 1e7 m away lies on a 1 m grid and renders as garbage, silently.
// The check names the worst shape so the user can render in double
// (safegi-render-double) or move the scene towards the origin.
#pragma once

#include <optional>
#include <string>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// A shape is unresolved when the spacing of `Real` at its farthest coordinate
// is more than this fraction of its size (its bounding box's diagonal). At 1 %
// the Cornell box's error is measurably worse than double's (bench/precision_scale:
// 0.0237 against 0.0220 at 1e5 m); at 0.2 % (1e4 m) it is not.
inline constexpr double kUnresolvedFraction = 0.01;

struct PrecisionReport {
  int unresolved_shapes = 0;
  int worst_shape = -1;           // index into Scene::shapes
  double worst_size_m = 0;        // its bounding box's diagonal
  double worst_distance_m = 0;    // its farthest coordinate from the origin (largest |x|, |y|, |z|)
  double worst_spacing_m = 0;     // the spacing of Real there
};

// Shapes at shutter open and, when moving, at close; nothing when every shape is resolved.
std::optional<PrecisionReport> check_precision(const Scene& scene);

// The report as a warning and a help line; the float build's help names
// safegi-render-double.
std::string describe(const PrecisionReport& report, const Scene& scene);

}  // namespace safegi::render
