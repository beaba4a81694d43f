// The error heat map of the pictures and of the 3D viewer: a patch coloured by its distance
// to the complete model, on one scale for every method of a case.
#pragma once

#include "core/case.h"
#include "harness/outputs/render/image.h"

#include <array>
#include <string>
#include <vector>

namespace holebench::render {

/// The scale of a case's heat map: distances relative to the bounding-box diagonal of the
/// complete model, from 0 to `max_rel_diag` (larger ones take the top colour).
struct HeatScale {
  double max_rel_diag = 0.01;
};

/// The scale of a case, from its ground truth only (so every method of the case, each
/// rendered in its own process, gets the same one): half the largest hole's radius (the
/// largest distance from a removed face's vertex to the removed faces' centroid), relative
/// to the diagonal, rounded up to 1, 2 or 5 times a power of ten. A flat cap over a hole
/// with a corner reaches about this far from the truth.
HeatScale case_heat_scale(const Case& c);

/// The colour stops of the map, evenly spaced from 0 (blue: on the complete model) to 1
/// (red: at or beyond the scale's maximum). The viewer's script uses the same stops.
const std::vector<Rgb>& heat_stops();

/// The colour of a distance on a scale (piecewise linear between the stops).
Rgb heat_colour(double distance_rel_diag, const HeatScale& scale);

/// A label for a scale value: "0", "0.02", "5e-05".
std::string heat_label(double value_rel_diag);

/// A vertical colour bar (top = the maximum) with the labels 0, half and the maximum beside
/// it, `width` x `height` pixels on a white background.
Image colour_bar(const HeatScale& scale, int width, int height);

}  // namespace holebench::render
