// The methods' steps as geometry (core/method_layers.h): each of the three papers' methods
// returns its named layers when asked, none when not, and the same repair either way (so
// that metrics are unchanged with layers on or off).
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "methods/registry.h"
#include "metrics/evaluation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

namespace holebench {
namespace {

struct LayeredRuns {
  MethodResult without, with;
};

LayeredRuns run_both(const std::string& method_id, const Case& c) {
  const auto method = make_method(method_id);
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  LayeredRuns runs;
  NoUser first, second;
  runs.without = method->run(c.input, parameters, first);
  parameters.record_layers = true;
  runs.with = method->run(c.input, parameters, second);
  return runs;
}

const MethodLayer* find_layer(const MethodResult& result, const std::string& name) {
  const auto it = std::find_if(result.layers.begin(), result.layers.end(),
                               [&](const MethodLayer& l) { return l.name == name; });
  return it == result.layers.end() ? nullptr : &*it;
}

// The layer exists, has `kind` and at least `at_least` elements, and names a phase of the
// result as its step.
void expect_layer(const MethodResult& result, const std::string& name, LayerKind kind,
                  std::size_t at_least) {
  const MethodLayer* layer = find_layer(result, name);
  ASSERT_NE(layer, nullptr) << name;
  EXPECT_EQ(layer->kind, kind) << name;
  EXPECT_GE(layer->size(), at_least) << name;
  EXPECT_TRUE(std::any_of(result.phases.begin(), result.phases.end(),
                          [&](const PhaseTiming& p) { return p.phase == layer->step; }))
      << name << ": step '" << layer->step << "' is not a phase of the method";
  for (const auto& t : layer->surface.triangles) {
    for (int v : t) {
      EXPECT_GE(v, 0);
      EXPECT_LT(v, static_cast<int>(layer->surface.points.size()));
    }
  }
}

// The same repair, hole reports and metrics with layers on or off.
void expect_same_repair(const Case& c, const LayeredRuns& runs) {
  EXPECT_TRUE(runs.without.layers.empty());
  const Mesh& a = runs.without.repaired;
  const Mesh& b = runs.with.repaired;
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (auto v : a.vertices())
    EXPECT_EQ(a.point(v), b.point(VertexHandle(v.idx())));
  ASSERT_EQ(runs.without.holes.size(), runs.with.holes.size());
  for (std::size_t i = 0; i < runs.with.holes.size(); ++i) {
    EXPECT_EQ(runs.without.holes[i].closed, runs.with.holes[i].closed);
    EXPECT_EQ(runs.without.holes[i].new_faces, runs.with.holes[i].new_faces);
    EXPECT_EQ(runs.without.holes[i].fallback, runs.with.holes[i].fallback);
    EXPECT_EQ(runs.without.holes[i].note, runs.with.holes[i].note);
  }
  const Evaluation off = evaluate(c, runs.without);
  const Evaluation on = evaluate(c, runs.with);
  ASSERT_EQ(off.values.size(), on.values.size());
  for (std::size_t i = 0; i < off.values.size(); ++i) {
    EXPECT_EQ(off.values[i].name, on.values[i].name);
    EXPECT_EQ(off.values[i].value, on.values[i].value) << off.values[i].name;
  }
}

// The slice paper's figure 2 on the box corner hole: segments (II), missing edges and corner
// (III), slices, section curves and the lofted surface (IV), the trimmed patch (V-VI).
TEST(MethodLayers, SliceLoftShowsEveryStepOnACornerHole) {
  const Case c = generators::make_case("box/corner");
  const LayeredRuns runs = run_both("slice_loft", c);
  expect_same_repair(c, runs);
  expect_layer(runs.with, "segments", LayerKind::Polylines, 3);
  expect_layer(runs.with, "missing_edges", LayerKind::Polylines, 3);
  expect_layer(runs.with, "missing_corner", LayerKind::Points, 1);
  expect_layer(runs.with, "slices", LayerKind::Polylines, 3);
  expect_layer(runs.with, "section_curves", LayerKind::Points, 1);
  expect_layer(runs.with, "lofted_surface", LayerKind::Surface, 2);
  expect_layer(runs.with, "trimmed_patch", LayerKind::Surface, 1);
  // The missing corner is the corner of the box (as CornerHoleRecoversTheCorner measures).
  const double diagonal = bounding_box_diagonal(c.complete);
  const MethodLayer& corner = *find_layer(runs.with, "missing_corner");
  EXPECT_LT((corner.points[0] - c.holes[0].missing_corners[0]).norm(), 2e-3 * diagonal);
  // The patch layer is the repair's new faces.
  EXPECT_EQ(find_layer(runs.with, "trimmed_patch")->size(), count_new_faces(runs.with.repaired));
}

// The crest-line paper's steps on the fandisk hole across two creases: crest lines (3.2),
// feature points (3.4.1), feature lines (3.4.3), sub-holes (3.4.4), patch (3.5).
TEST(MethodLayers, CrestFeatureShowsCrestAndFeatureLines) {
  const Case c = generators::make_case("crease/fandisk/2");
  const LayeredRuns runs = run_both("crest_feature", c);
  expect_same_repair(c, runs);
  expect_layer(runs.with, "crest_lines", LayerKind::Polylines, 2);
  expect_layer(runs.with, "feature_points", LayerKind::Points, 2);
  expect_layer(runs.with, "feature_lines", LayerKind::Polylines, 1);
  expect_layer(runs.with, "sub_holes", LayerKind::Polylines, 2);
  expect_layer(runs.with, "patch", LayerKind::Surface, 1);
  // Each sub-hole loop is closed; there is one more sub-hole than feature lines that split.
  for (const auto& loop : find_layer(runs.with, "sub_holes")->polylines) {
    ASSERT_GE(loop.size(), 4u);
    EXPECT_EQ(loop.front(), loop.back());
  }
}

// The B-Rep paper's steps: a guided hole (k = 3, large) shows its faces, transitions (and S)
// and arrow; a closed one (small) shows no arrow.
TEST(MethodLayers, BrepGuidanceShowsFacesTransitionsAndArrows) {
  const Case large = generators::make_case("brep/k3/inner/convex-convex-convex/large");
  const LayeredRuns guided = run_both("brep_guidance", large);
  expect_same_repair(large, guided);
  expect_layer(guided.with, "faces", LayerKind::Polylines, 3);
  expect_layer(guided.with, "transitions", LayerKind::Points, 4);  // T_1..T_3 and S
  expect_layer(guided.with, "arrows", LayerKind::Polylines, 1);
  const MethodLayer& arrow = *find_layer(guided.with, "arrows");
  ASSERT_TRUE(guided.with.holes[0].arrow);
  EXPECT_EQ(arrow.polylines[0][0], guided.with.holes[0].arrow->position);

  const Case small = generators::make_case("brep/k3/inner/convex-convex-convex/small");
  const LayeredRuns closed = run_both("brep_guidance", small);
  expect_same_repair(small, closed);
  EXPECT_EQ(find_layer(closed.with, "arrows")->size(), 0u);
}

// Baselines have no steps of a paper to show: no layers, whatever is asked.
TEST(MethodLayers, BaselinesReturnNone) {
  const Case c = generators::make_case("box/corner");
  EXPECT_TRUE(run_both("liepa_cgal", c).with.layers.empty());
}

}  // namespace
}  // namespace holebench
