#include "harness/job.h"

#include "core/errors.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "harness/render/snapshot.h"
#include "methods/registry.h"

#include <fmt/format.h>

#include <chrono>
#include <exception>

namespace holebench::harness {

std::string Job::id() const {
  return fmt::format("{}|{}|{}|{}", case_id, method_id, noise_percent, seed);
}

const char* to_string(JobStatus status) {
  switch (status) {
    case JobStatus::Ok:
      return "ok";
    case JobStatus::Partial:
      return "partial";
    case JobStatus::MethodFailed:
      return "method_failed";
    case JobStatus::InvalidInput:
      return "invalid_input";
    case JobStatus::Error:
      return "error";
  }
  return "unknown";
}

namespace {

// The view of a case: along the area-weighted mean normal of the removed faces in the
// complete model, tilted a little so that edges and depth read in the picture. It uses
// ground truth, which the harness may; it is the same for every method of the case.
render::Camera case_camera(const Case& c) {
  Point normal(0, 0, 0);
  Point centroid(0, 0, 0);
  double area = 0.0;
  for (const auto& hole : c.holes) {
    for (int index : hole.removed_faces) {
      const FaceHandle f = c.complete.face_handle(index);
      const double a = face_area(c.complete, f);
      normal += face_normal(c.complete, f) * a;
      centroid += face_centroid(c.complete, f) * a;
      area += a;
    }
  }
  if (area == 0.0 || normal.norm() == 0.0) {
    normal = Point(1, 1, 1);
    centroid = bounding_box(c.complete).center();
  } else {
    centroid /= area;
  }
  normal /= normal.norm();
  // Enough context around the hole to read it, never more than the whole model.
  double extent = 0.0;
  for (const auto& hole : c.holes) {
    for (int index : hole.removed_faces) {
      extent = std::max(
          extent, (face_centroid(c.complete, c.complete.face_handle(index)) - centroid).norm());
    }
  }
  const BoundingBox box = bounding_box(c.complete);
  const double radius = std::min(0.55 * box.diagonal() + (box.center() - centroid).norm(),
                                 std::max(3.0 * extent, 0.3 * box.diagonal()));
  const Point tilt = Point(0.35, -0.45, 0.3);
  const Point direction = -(normal + tilt * 0.6);
  return render::frame_sphere(centroid, radius, direction);
}

void copy_holes(const MethodResult& result, JobRecord& record) {
  for (const auto& hole : result.holes) {
    record.holes.push_back(
        {hole.hole_index, hole.loop_size, hole.closed, hole.new_faces, hole.note});
  }
}

}  // namespace

JobRecord run_job(const Job& job, const JobOptions& options) {
  JobRecord record;
  record.job = job;
  Case c;
  try {
    c = options.catalog ? options.catalog->make(job.case_id, job.seed, job.noise_percent)
                        : generators::make_case(job.case_id, job.seed, job.noise_percent);
    record.case_family = c.family;
    record.case_kind = c.kind;
  } catch (const std::exception& e) {
    record.status = JobStatus::InvalidInput;
    record.message = e.what();
    return record;
  }

  try {
    const auto method = make_method(job.method_id);
    NoUser user;
    record.user = user.kind();
    const auto start = std::chrono::steady_clock::now();
    MethodResult result = method->run(c.input, user);
    record.method_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    record.user_interventions = user.interventions();
    record.phases = result.phases;
    copy_holes(result, record);
    record.message = result.message;
    if (result.status == MethodStatus::Failed) {
      record.status = JobStatus::MethodFailed;
      return record;
    }
    record.status = result.status == MethodStatus::Partial ? JobStatus::Partial : JobStatus::Ok;
    record.metrics = evaluate(c, result.repaired, options.evaluation).values;
    record.metrics.push_back({"time_method_s", record.method_seconds});
    if (!options.snapshot_dir.empty()) {
      std::string name = job.id();
      for (char& ch : name) {
        if (ch == '/' || ch == '|')
          ch = '_';
      }
      const auto path = options.snapshot_dir / (name + ".png");
      render::write_png(render::render_snapshot(result.repaired, case_camera(c)), path);
      record.snapshot = (options.snapshot_dir.filename() / path.filename()).generic_string();
    }
  } catch (const InvalidInputError& e) {
    record.status = JobStatus::InvalidInput;
    record.message = e.what();
  } catch (const std::exception& e) {
    record.status = JobStatus::Error;
    record.message = e.what();
  }
  return record;
}

}  // namespace holebench::harness
