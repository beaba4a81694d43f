#include "harness/run/job.h"

#include "core/errors.h"
#include "core/geometry.h"
#include "core/stopwatch.h"
#include "generators/case_catalog.h"
#include "harness/outputs/file_names.h"
#include "harness/outputs/layers_obj.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/image.h"
#include "harness/outputs/render/layers_picture.h"
#include "harness/outputs/viewer/viewer_mesh.h"
#include "harness/run/memory_limit.h"
#include "harness/run/oracle_user.h"
#include "methods/common/cgal_random.h"
#include "methods/external/external_method.h"
#include "methods/registry.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <new>

namespace holebench::harness {

namespace {

using Clock = std::chrono::steady_clock;

// Runs the method of `job` on its case (options.method_repetitions times, the first run's
// result kept) and records what the method says into `record`: user, interventions, times.
MethodResult run_method(const Job& job, const Case& c, const JobOptions& options,
                        JobRecord& record) {
  const std::unique_ptr<Method> method =
      job.external ? std::make_unique<ExternalMethod>(*job.external) : make_method(job.method_id);
  const std::unique_ptr<User> user = make_user(job.user, c);
  record.user = user->kind();
  const auto start = Clock::now();
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  parameters.record_layers = !options.layers_dir.empty();
  seed_cgal_default_random();
  MethodResult result = method->run(c.input, parameters, *user);
  record.method_run_seconds.push_back(seconds_since(start));
  // Further runs for the timing only, each as the first: a fresh user, the same seed.
  for (int run = 1; run < options.method_repetitions; ++run) {
    const std::unique_ptr<User> again_user = make_user(job.user, c);
    const auto again = Clock::now();
    seed_cgal_default_random();
    method->run(c.input, parameters, *again_user);
    record.method_run_seconds.push_back(seconds_since(again));
  }
  record.method_seconds = median_of(record.method_run_seconds);
  double method_total = 0.0;
  for (double seconds : record.method_run_seconds)
    method_total += seconds;
  record.stages.push_back({stage_names::kMethod, method_total});
  record.user_interventions = user->interventions();
  record.user_interventions_by_kind = user->interventions_by_kind();
  return result;
}

}  // namespace

PreparedCase prepare_case(const Job& job, const JobOptions& options) {
  PreparedCase prepared;
  try {
    const auto start = Clock::now();
    seed_cgal_default_random();
    prepared.c = options.catalog ? options.catalog->make(job.case_id, job.seed, job.noise_percent)
                                 : generators::make_case(job.case_id, job.seed, job.noise_percent);
    prepared.seconds = seconds_since(start);
  } catch (const std::bad_alloc& e) {
    prepared.failure = {JobStatus::OutOfMemory,
                        std::string("an allocation failed while making the case: ") + e.what()};
  } catch (const std::exception& e) {
    prepared.failure = {JobStatus::InvalidInput, e.what()};
  }
  return prepared;
}

void share_case_work(PreparedCase& prepared, const JobOptions& options) {
  if (prepared.failure)
    return;
  try {
    const auto start = Clock::now();
    prepared.evaluation = std::make_shared<const CaseEvaluation>(prepared.c, options.evaluation);
    prepared.evaluation_seconds = seconds_since(start);
  } catch (const std::exception&) {
    prepared.evaluation.reset();  // each job evaluates on its own, and reports its failure
  }
  if (options.snapshot_dir.empty())
    return;
  try {
    const auto start = Clock::now();
    prepared.picture = std::make_shared<const render::CasePicture>(prepared.c);
    prepared.picture_seconds = seconds_since(start);
  } catch (const std::exception&) {
    prepared.picture.reset();  // each job draws on its own, and reports its failure
  }
}

JobRecord run_job(const Job& job, const JobOptions& options) {
  const PreparedCase prepared = prepare_case(job, options);
  return run_job_on_case(job, prepared, true, options);
}

JobRecord run_job_on_case(const Job& job, const PreparedCase& prepared, bool first_of_group,
                          const JobOptions& options) {
  JobRecord record;
  record.job = job;
  if (prepared.failure) {
    record.status = prepared.failure->first;
    record.message = prepared.failure->second;
    return record;
  }
  const Case& c = prepared.c;
  record.case_family = c.family;
  record.case_kind = c.kind;
  record.stages.push_back({stage_names::kCase, first_of_group ? prepared.seconds : 0.0});

  try {
    const auto start = Clock::now();
    const MethodResult result =
        options.scored_repairs ? read_scored_repair(job, c.input, *options.scored_repairs, record)
                               : run_method(job, c, options, record);
    if (options.scored_repairs)
      record.stages.push_back({stage_names::kMethod, seconds_since(start)});
    record.phases = result.phases;
    record.holes = result.holes;
    record.message = result.message;
    // An external program that ran out of memory under the job's limit says so.
    record.status = result.status == MethodStatus::Partial          ? JobStatus::Partial
                    : result.status == MethodStatus::Ok             ? JobStatus::Ok
                    : message_reports_out_of_memory(result.message) ? JobStatus::OutOfMemory
                                                                    : JobStatus::MethodFailed;
    if (!options.repaired_mesh_dir.empty())
      write_repaired_files(options.repaired_mesh_dir, record, result);
    if (result.status == MethodStatus::Failed)
      return record;
    const auto evaluation_start = Clock::now();
    Evaluation evaluation = prepared.evaluation
                                ? evaluate(c, result, options.evaluation, *prepared.evaluation)
                                : evaluate(c, result, options.evaluation);
    record.metrics = std::move(evaluation.values);
    const bool shares_case_work = first_of_group && prepared.evaluation;
    if (shares_case_work)
      record.evaluation_phases.push_back(
          {evaluation_phases::kSharedCaseWork, prepared.evaluation_seconds});
    for (auto& phase : evaluation.phases)
      record.evaluation_phases.push_back(std::move(phase));
    record.stages.push_back(
        {stage_names::kEvaluation,
         seconds_since(evaluation_start) + (shares_case_work ? prepared.evaluation_seconds : 0.0)});
    record.metrics.push_back({metric_names::kTimeMethodS, record.method_seconds});
    if (!options.snapshot_dir.empty()) {
      const auto path = options.snapshot_dir / (file_stem_of_id(job.id()) + ".png");
      const auto snapshot_start = Clock::now();
      render::write_png(prepared.picture ? render::job_picture(c, result, *prepared.picture)
                                         : render::job_picture(c, result),
                        path);
      if (!options.viewer_mesh_dir.empty())
        viewer::write_job_meshes(c, result.repaired, job, options.viewer_mesh_dir, {},
                                 prepared.picture ? &prepared.picture->complete_scene() : nullptr);
      record.stages.push_back(
          {stage_names::kSnapshot,
           seconds_since(snapshot_start) + (first_of_group ? prepared.picture_seconds : 0.0)});
      record.snapshot = (options.snapshot_dir.filename() / path.filename()).generic_string();
    }
    if (!options.layers_dir.empty()) {
      const auto layers_start = Clock::now();
      const std::string stem = file_stem_of_id(job.id());
      render::write_png(render::layers_picture(c, result), options.layers_dir / (stem + ".png"));
      write_layers_obj(result.layers, options.layers_dir / (stem + ".obj"));
      record.stages.push_back({stage_names::kLayers, seconds_since(layers_start)});
    }
  } catch (const InvalidInputError& e) {
    record.status = JobStatus::InvalidInput;
    record.message = e.what();
  } catch (const std::bad_alloc& e) {
    record.status = JobStatus::OutOfMemory;
    record.message = std::string("an allocation failed: ") + e.what();
  } catch (const std::exception& e) {
    record.status = JobStatus::Error;
    record.message = e.what();
  }
  return record;
}

}  // namespace holebench::harness
