#include "harness/outputs/render/close_up.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "tests/metrics/test_repairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

namespace holebench::render {
namespace {

/// The boundary loops of the holed mesh that belong to hole `hole`: those with a vertex
/// among the hole's boundary points in the complete model (the input is clean here).
std::vector<BoundaryLoop> loops_of_hole(const Case& c, const HoleView& view) {
  const double tolerance = 1e-9 * bounding_box(c.complete).diagonal();
  std::vector<BoundaryLoop> out;
  for (const auto& loop : find_boundary_loops(c.input)) {
    const Point p = c.input.point(c.input.from_vertex_handle(loop.halfedges.front()));
    const bool on_hole = std::any_of(view.boundary_points.begin(), view.boundary_points.end(),
                                     [&](const Point& q) { return (p - q).norm() <= tolerance; });
    if (on_hole)
      out.push_back(loop);
  }
  return out;
}

struct LoopInView {
  std::size_t samples = 0;
  std::size_t in_image = 0;
  std::size_t visible = 0;  ///< in the image and not hidden (the depth buffer)
};

/// Samples each loop edge at its start and middle, projects the samples into the picture of
/// the holed mesh and compares their depth with the depth buffer's. A sample on the boundary
/// is seen when the first thing its pixel hit is not closer to the eye than the sample
/// itself, up to 1 % of the camera distance (the pixel's footprint on a slanted face next to
/// the boundary).
LoopInView loop_in_view(const Case& c, const std::vector<BoundaryLoop>& loops,
                        const Camera& camera) {
  SnapshotOptions options;
  options.width = options.height = 240;
  options.samples_per_axis = 1;
  const Rendering picture = render_with_depth(c.input, camera, options);
  const double tolerance = 0.01 * camera.distance;
  LoopInView out;
  for (const auto& loop : loops) {
    for (auto h : loop.halfedges) {
      const Point a = c.input.point(c.input.from_vertex_handle(h));
      const Point b = c.input.point(c.input.to_vertex_handle(h));
      for (const Point& p : {a, (a + b) * 0.5}) {
        ++out.samples;
        const auto projection = project(camera, options.width, options.height, p);
        if (!projection)
          continue;
        const int x = static_cast<int>(projection->x);
        const int y = static_cast<int>(projection->y);
        if (x < 0 || y < 0 || x >= options.width || y >= options.height)
          continue;
        ++out.in_image;
        // The pixel or one next to it (a loop edge right behind a silhouette).
        bool seen = false;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int px = std::clamp(x + dx, 0, options.width - 1);
            const int py = std::clamp(y + dy, 0, options.height - 1);
            seen = seen || picture.depth_at(px, py) >= projection->depth - tolerance;
          }
        }
        out.visible += seen ? 1 : 0;
      }
    }
  }
  return out;
}

bool is_outer(const HoleTruth& hole) {
  return hole.labels && hole.labels->orientation == Orientation::Outer;
}

// The close-up of every outer hole of the B-Rep enumeration (the cases whose labels say
// orientation outer) shows the hole: every sample of its boundary loops projects into the
// picture, and at least 95 % of them are not hidden by the model (an edge of the loop seen
// edge-on may hide a few samples next to it).
TEST(CloseUp, EveryOuterBrepHoleIsInViewAndNotHidden) {
  generators::CatalogOptions brep_only;
  brep_only.include_cad = false;
  brep_only.families = {"brep"};
  const generators::CaseCatalog catalog(brep_only);
  std::size_t outer_holes = 0;
  for (const auto& descriptor : catalog.cases()) {
    if (descriptor.id.rfind("brep/", 0) != 0)
      continue;
    const Case c = catalog.make(descriptor.id);
    for (std::size_t hole = 0; hole < c.holes.size(); ++hole) {
      if (!is_outer(c.holes[hole]))
        continue;
      SCOPED_TRACE(descriptor.id + " hole " + std::to_string(hole));
      ++outer_holes;
      const HoleView view = hole_view(c, hole);
      const auto loops = loops_of_hole(c, view);
      ASSERT_FALSE(loops.empty());
      const LoopInView seen = loop_in_view(c, loops, view.camera);
      EXPECT_EQ(seen.in_image, seen.samples);
      EXPECT_GE(seen.visible, 0.95 * static_cast<double>(seen.samples));
    }
  }
  // CASES.md's outer holes: k = 1, 2, 3 with every boundary kind, and the variants.
  EXPECT_GE(outer_holes, 20u);
}

// The view of an inner hole looks at it from outside: the camera's eye is outside the
// complete model's bounding box and the hole's loop is in view.
TEST(CloseUp, InnerCornerHoleIsSeenFromOutside) {
  const Case c = generators::make_case("box/corner");
  const HoleView view = hole_view(c, 0);
  const BoundingBox box = bounding_box(c.complete);
  const Point eye = eye_of(view.camera);
  bool outside = false;
  for (int axis = 0; axis < 3; ++axis)
    outside = outside || eye[axis] < box.min[axis] || eye[axis] > box.max[axis];
  EXPECT_TRUE(outside);
  EXPECT_DOUBLE_EQ(view.visible_share, 1.0);
  const LoopInView seen = loop_in_view(c, find_boundary_loops(c.input), view.camera);
  EXPECT_EQ(seen.visible, seen.samples);
}

// A job's picture: a close-up and the whole model (view_size each, 4 pixels apart) and the
// colour bar; the patch of a cap over the corner shows the heat map's colours.
// Leaves freed heap memory filled with `byte`, where the next small allocations may land.
void dirty_the_heap(unsigned char byte) {
  std::vector<std::unique_ptr<unsigned char[]>> blocks;
  for (int i = 0; i < 4096; ++i) {
    blocks.emplace_back(new unsigned char[64]);
    std::memset(blocks.back().get(), byte, 64);
  }
}

// The camera of a close-up depends on the case alone. It once summed the region normals into
// map entries whose Point() was uninitialised (OpenMesh), and on this corner case the chosen
// view changed from run to run, with the heap's leftovers: the same job gave other pictures.
TEST(CloseUp, CameraDependsOnTheCaseAloneNotOnTheHeap) {
  const Case c =
      generators::make_case("brep/k3/outer/reflex-reflex-reflex/inner-inner-inner/large");
  ASSERT_GE(c.holes.size(), 2u);
  for (std::size_t hole = 0; hole < c.holes.size(); ++hole) {
    dirty_the_heap(0x00);
    const HoleView clean = hole_view(c, hole);
    for (unsigned char byte : {0x40, 0xc0, 0x3f}) {  // 32.5, -8577.5, 4.8e-4 as doubles
      dirty_the_heap(byte);
      const HoleView again = hole_view(c, hole);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(again.camera.direction[k], clean.camera.direction[k])
            << "hole " << hole << ", heap byte " << int(byte);
      }
      EXPECT_EQ(again.visible_share, clean.visible_share);
    }
  }
}

TEST(CloseUp, JobPictureHasTheViewsAndTheColourBar) {
  const Case c = generators::make_case("box/corner");
  MethodResult nothing;
  nothing.repaired = c.input;
  CloseUpOptions options;
  options.view_size = 64;
  options.samples_per_axis = 1;
  const Image picture = job_picture(c, nothing, options);
  EXPECT_EQ(picture.width, 2 * (64 + 4) + options.colour_bar_width);
  EXPECT_EQ(picture.height, 64);
}

// Pictures drawn with what the case's pictures share (as a group of jobs draws them) are the
// pictures drawn alone, byte for byte: a patch coloured by its distance, the open input.
TEST(CloseUp, JobPictureWithTheCasesSharedPartsIsTheSame) {
  const Case c = generators::make_case("cad/fandisk/edge_convex/small", 0, 5.0);
  MethodResult filled;
  filled.repaired = c.complete;
  for (const auto& hole : c.holes) {
    for (int f : hole.removed_faces)
      filled.repaired.data(filled.repaired.face_handle(f)).provenance = Provenance::New;
  }
  CloseUpOptions options;
  options.view_size = 96;
  const CasePicture shared(c, options);
  EXPECT_EQ(shared.hole_views().size(),
            std::min(c.holes.size(), static_cast<std::size_t>(options.max_close_ups)));
  MethodResult open;
  open.repaired = c.input;
  // One shared part for two jobs, in turn: it carries nothing of the first to the second.
  for (const MethodResult* result : {&filled, &open, &filled}) {
    const Image alone = job_picture(c, *result, options);
    const Image with_shared = job_picture(c, *result, shared, options);
    ASSERT_EQ(alone.width, with_shared.width);
    EXPECT_TRUE(alone.pixels == with_shared.pixels);
  }
}

// A job's picture drawn over the case's views of its input (where the repair appends to the
// input) is the picture drawn from the whole repaired mesh, byte for byte: an exact closing
// and a fan appended to the input, the open input, and a repair that does not append (the
// complete model, which takes the whole mesh either way).
TEST(CloseUp, JobPictureOverTheInputsViewsIsTheWholeRepairsPicture) {
  for (const char* id : {"box/corner", "cad/fandisk/edge_convex/small"}) {
    const Case c = generators::make_case(id, 0, 5.0);
    CloseUpOptions whole;
    whole.view_size = 80;
    whole.draw_over_input_views = false;
    CloseUpOptions over = whole;
    over.draw_over_input_views = true;
    const CasePicture shared_whole(c, whole), shared_over(c, over);
    EXPECT_TRUE(shared_whole.input_views().empty());
    EXPECT_EQ(shared_over.input_views().size(), shared_over.hole_views().size() + 1);
    std::vector<MethodResult> results(4);
    results[0].repaired = test::exact_appended_closing(c);
    results[1].repaired = test::fan_closing(c.input);
    for (std::size_t f = c.input.n_faces(); f < results[1].repaired.n_faces(); ++f)
      results[1].repaired.data(FaceHandle(static_cast<int>(f))).provenance = Provenance::New;
    results[2].repaired = c.input;
    results[3].repaired = c.complete;
    for (const auto& hole : c.holes)
      for (int f : hole.removed_faces)
        results[3].repaired.data(FaceHandle(f)).provenance = Provenance::New;
    for (const auto& result : results) {
      const Image a = job_picture(c, result, shared_whole, whole);
      const Image b = job_picture(c, result, shared_over, over);
      ASSERT_EQ(a.width, b.width);
      EXPECT_TRUE(a.pixels == b.pixels) << id;
    }
  }
}

}  // namespace
}  // namespace holebench::render
