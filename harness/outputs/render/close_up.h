// Close-ups of a job's holes beside the whole model, the patch coloured by its distance to
// the complete model (heat_map.h), open holes outlined, guidance arrows drawn in.
#pragma once

#include "core/case.h"
#include "core/method_result.h"
#include "harness/outputs/render/heat_map.h"
#include "harness/outputs/render/input_view.h"
#include "harness/outputs/render/snapshot.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace holebench::embree {
class TriangleScene;
}

namespace holebench::render {

struct CloseUpOptions {
  int view_size = 320;       ///< each view (close-up or whole model) is square, in pixels
  int samples_per_axis = 2;  ///< supersampling of every view
  int max_close_ups = 2;  ///< close-ups of the first holes of the case; the rest in the whole view
  int colour_bar_width = 84;
  /// A loop point counts as visible when nothing of the holed mesh lies between the eye and
  /// it closer than this share of the bounding-box diagonal to the point.
  double visibility_tolerance_rel_diag = 2e-3;
  /// Draw a job's views over the case's views of its input where the repair appends to the
  /// input (every input face kept at its index, none of them marked new: the picture of the
  /// repaired mesh at the cost of its new faces, input_view.h); false: every view from the
  /// whole repaired mesh. The same pictures either way, but for a sample whose ray meets an
  /// input face and a new face at the same distance (the input face shows).
  bool draw_over_input_views = true;
};

/// The view of one hole, chosen from the ground truth (which pictures may use; methods may
/// not): the camera outside the model on the side the missing surface faces, looking into
/// the hole. Candidate directions: the area-weighted mean outward normal of the removed
/// faces, that normal tilted by about 27 degrees four ways, and the mean normal of each
/// removed region; the first with the largest share of the hole's boundary visible (not
/// hidden by the holed mesh) wins. The hole's boundary fills about two thirds of the view.
struct HoleView {
  Camera camera;
  /// The hole's boundary in the complete model: the vertices of the edges between a removed
  /// face and a kept one (or the model's own boundary).
  std::vector<Point> boundary_points;
  double visible_share = 0.0;  ///< of boundary_points, seen from the camera
};
HoleView hole_view(const Case& c, std::size_t hole, const CloseUpOptions& options = {});

/// The whole model seen along `direction`, framed on its bounding sphere.
Camera whole_model_camera(const Case& c, const Point& direction);

/// The camera of hole_view(c, hole), or the whole model seen along (-1, -1, -1) where the
/// case has no such hole.
Camera hole_or_whole_camera(const Case& c, std::size_t hole = 0);

/// What the pictures of one case's jobs share, whatever the method: the complete model's
/// Embree scene (the patch's distances), the case's heat scale, the close-up views of its
/// first holes and the whole model's camera, and (options.draw_over_input_views) each view of
/// the input, sample by sample. Built once per case instance for a group of jobs
/// (harness/run/job.h).
class CasePicture {
 public:
  CasePicture(const Case& c, const CloseUpOptions& options = {});
  ~CasePicture();
  CasePicture(const CasePicture&) = delete;
  CasePicture& operator=(const CasePicture&) = delete;

  const embree::TriangleScene& complete_scene() const { return *complete_scene_; }
  const HeatScale& scale() const { return scale_; }
  /// hole_view of the first min(holes, options.max_close_ups) holes.
  const std::vector<HoleView>& hole_views() const { return hole_views_; }
  /// The whole model seen from the first hole's side.
  const Camera& whole_camera() const { return whole_camera_; }
  /// The input seen from each hole view's camera, then from whole_camera(), its faces in the
  /// kept faces' colour; empty unless options.draw_over_input_views.
  const std::vector<InputView>& input_views() const { return input_views_; }

 private:
  std::unique_ptr<embree::TriangleScene> complete_scene_;
  HeatScale scale_;
  std::vector<HoleView> hole_views_;
  Camera whole_camera_;
  std::vector<InputView> input_views_;
};

/// The picture of a job: one close-up per hole (up to options.max_close_ups), the whole
/// model seen from the first hole's side, and the case's colour bar (case_heat_scale), side
/// by side. Kept faces grey, the patch (new faces) by its distance to the complete model,
/// open boundary loops of the repaired mesh in magenta, guidance arrows in blue.
Image job_picture(const Case& c, const MethodResult& result, const CloseUpOptions& options = {});
/// The same with what the case's pictures share (built from `c` with the same options): the
/// same picture.
Image job_picture(const Case& c, const MethodResult& result, const CasePicture& shared,
                  const CloseUpOptions& options = {});

/// The colour of kept faces in job pictures and in the viewer.
Rgb kept_colour();
/// The colour of open holes' outlines.
Rgb open_hole_colour();

}  // namespace holebench::render
