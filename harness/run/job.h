// Running one job: a case x a method x a seed, into the record it produces
// (harness/results/record.h).
#pragma once

#include "core/statistics.h"  // median_of: a job's method time over repetitions
#include "generators/case_catalog.h"
#include "harness/results/record.h"
#include "harness/run/scored_repairs.h"
#include "methods/external/external_method_spec.h"
#include "methods/method.h"
#include "metrics/case_evaluation.h"
#include "metrics/evaluation.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace holebench::render {
class CasePicture;
}

namespace holebench::harness {

struct JobOptions {
  const generators::CaseCatalog* catalog = nullptr;  ///< nullptr: the default catalog
  EvaluationOptions evaluation;
  std::filesystem::path snapshot_dir;  ///< empty: no snapshot
  /// The output folder that gets the report's 3D viewer meshes (meshes/, written with the
  /// snapshot and timed in its stage; outputs/viewer/viewer_mesh.h); empty: none.
  std::filesystem::path viewer_mesh_dir;
  /// Where the method's steps go (`--layers`): the method is asked for its layers
  /// (MethodParameters::record_layers) and each job writes <stem>.png (layers_picture.h) and
  /// <stem>.obj (layers_obj.h) here, timed in its "layers" stage; empty: none asked.
  std::filesystem::path layers_dir;
  /// Runs of the method per job, for steadier timings: the record's method time is their
  /// median; the first run's result is the one evaluated (the methods are deterministic).
  int method_repetitions = 1;
  /// Where each job writes its repaired mesh and its method's record (`--repaired-meshes`,
  /// harness/run/scored_repairs.h), so that the run's repairs can be scored again; empty: none.
  std::filesystem::path repaired_mesh_dir;
  /// Set: the jobs' results are read from these files instead of running their methods
  /// (`holebench evaluate --cases`, harness/run/scored_repairs.h); the rest of a job is the same.
  const ScoredRepairs* scored_repairs = nullptr;
};

/// The case of a job, made once for every job that shares it (the same case id, noise level
/// and seed: harness/run/job_groups.h), or why it could not be made.
struct PreparedCase {
  Case c;
  double seconds = 0.0;  ///< wall time of making it
  /// What the evaluations of its jobs share (metrics/case_evaluation.h), built once for a
  /// group of jobs (share_case_work); nullptr: each job's evaluation builds its own.
  std::shared_ptr<const CaseEvaluation> evaluation;
  double evaluation_seconds = 0.0;  ///< wall time of building `evaluation`
  /// What the pictures of its jobs share (harness/outputs/render/close_up.h), built once for
  /// a group of jobs that render snapshots; nullptr: each job's picture builds its own.
  std::shared_ptr<const render::CasePicture> picture;
  double picture_seconds = 0.0;  ///< wall time of building `picture`
  /// Set when the case could not be made: the status (invalid_input, out_of_memory) and
  /// message every job of it gets.
  std::optional<std::pair<JobStatus, std::string>> failure;
};

/// Makes the case of `job` (its id, noise level and seed). Never throws.
PreparedCase prepare_case(const Job& job, const JobOptions& options);

/// Builds what the evaluations and the pictures of a prepared case's jobs share
/// (PreparedCase::evaluation, PreparedCase::picture where `options` render snapshots), for a
/// group of jobs on one case. Where one cannot be built (out of memory, an exception), the
/// jobs build their own, as they would without it. The records are the same either way.
/// Never throws.
void share_case_work(PreparedCase& prepared, const JobOptions& options);

/// Runs the method of `job` on a prepared case, evaluates, renders. The first job of a
/// group (`first_of_group`) carries the making of the case in its "case" stage and the
/// building of the shared evaluation in its "evaluation" stage, the others 0 for them, so
/// that the stages of a run add up to its work (and the building of the shared picture in
/// its "snapshot" stage). Never throws: every failure becomes the
/// record's status and message.
JobRecord run_job_on_case(const Job& job, const PreparedCase& prepared, bool first_of_group,
                          const JobOptions& options);

/// Generates the case, runs the method with no user, evaluates, renders. Never throws:
/// every failure becomes the record's status and message.
JobRecord run_job(const Job& job, const JobOptions& options);

}  // namespace holebench::harness
