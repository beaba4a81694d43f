#include "harness/run/scored_repairs.h"

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/mesh_io.h"
#include "harness/outputs/file_bytes.h"
#include "harness/outputs/file_names.h"
#include "harness/results/record_json.h"
#include "methods/external/output_patch.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <utility>

namespace holebench::harness {

namespace {

namespace fs = std::filesystem;

constexpr const char* kMeshExtensions[] = {".ply", ".off", ".obj", ".stl"};
constexpr const char* kMethodRecordSuffix = ".method.json";

MethodResult failed_result(const Mesh& holed, std::string message) {
  MethodResult result;
  result.repaired = holed;
  result.status = MethodStatus::Failed;
  result.message = std::move(message);
  return result;
}

// Where the case made again from its id is not the one the repair was made from, the scores
// would measure the wrong case: the job is invalid_input.
void check_exported_input(const Mesh& holed, const fs::path& exported) {
  const Mesh read = read_mesh(exported);
  bool same = read.n_vertices() == holed.n_vertices() && read.n_faces() == holed.n_faces();
  for (std::size_t v = 0; same && v < holed.n_vertices(); ++v) {
    const VertexHandle vh(static_cast<int>(v));
    same = read.point(vh) == holed.point(vh);
  }
  for (std::size_t f = 0; same && f < holed.n_faces(); ++f) {
    const FaceHandle fh(static_cast<int>(f));
    same = triangle_vertex_indices(read, fh) == triangle_vertex_indices(holed, fh);
  }
  if (!same) {
    throw InvalidInputError(exported.string() +
                            ": the exported holed mesh is not the case made again from its id, "
                            "seed and noise (exported by another version of holebench, or from "
                            "another --mesh file?)");
  }
}

// The record the method left (its side file), or nothing where there is none.
std::optional<JobRecord> read_method_record(const fs::path& path) {
  std::error_code ignored;
  if (!fs::exists(path, ignored))
    return std::nullopt;
  try {
    return record_from_json_text(read_bytes(path));
  } catch (const std::exception& e) {
    throw InvalidInputError(path.string() + ": not a method record: " + e.what());
  }
}

MethodStatus method_status_of(JobStatus status) {
  switch (status) {
    case JobStatus::Ok:
      return MethodStatus::Ok;
    case JobStatus::Partial:
      return MethodStatus::Partial;
    default:
      return MethodStatus::Failed;
  }
}

// What the side file says of the method, into the job's record and the method's result.
void take_method_record(const JobRecord& method, JobRecord& record, MethodResult& result) {
  record.user = method.user;
  record.user_interventions = method.user_interventions;
  record.user_interventions_by_kind = method.user_interventions_by_kind;
  record.method_seconds = method.method_seconds;
  record.method_run_seconds = method.method_run_seconds;
  if (record.job.method_options.empty())
    record.job.method_options = method.job.method_options;
  result.status = method_status_of(method.status);
  result.message = method.message;
  result.holes = method.holes;
  result.phases = method.phases;
}

}  // namespace

std::vector<fs::path> repaired_mesh_candidates(const fs::path& dir, const Job& job) {
  std::vector<fs::path> candidates;
  for (const std::string& stem : {file_stem_of_id(job.id()), file_stem_of_id(job.case_id)}) {
    for (const char* extension : kMeshExtensions)
      candidates.push_back(dir / (stem + extension));
  }
  return candidates;
}

fs::path method_record_path(const fs::path& mesh_path) {
  fs::path path = mesh_path;
  path.replace_extension();
  path += kMethodRecordSuffix;
  return path;
}

void write_repaired_files(const fs::path& dir, const JobRecord& method_record,
                          const MethodResult& result) {
  const fs::path mesh_path = dir / (file_stem_of_id(method_record.job.id()) + ".ply");
  if (result.status != MethodStatus::Failed)
    write_mesh(result.repaired, mesh_path);
  write_file_atomically(method_record_path(mesh_path), record_to_json_line(method_record) + '\n');
}

MethodResult read_scored_repair(const Job& job, const Mesh& holed, const ScoredRepairs& repairs,
                                JobRecord& record) {
  // The job's user, unless the side file names the one that answered the method.
  record.user = job.user;
  const auto exported = repairs.exported_inputs.find(job.case_instance());
  if (exported != repairs.exported_inputs.end())
    check_exported_input(holed, exported->second);
  const std::vector<fs::path> candidates = repaired_mesh_candidates(repairs.repaired_dir, job);
  fs::path mesh_path;
  std::error_code ignored;
  for (const auto& candidate : candidates) {
    if (fs::exists(candidate, ignored)) {
      mesh_path = candidate;
      break;
    }
  }
  // The side file of the job's own name says the method failed even where it left no mesh.
  const std::optional<JobRecord> method =
      read_method_record(method_record_path(mesh_path.empty() ? candidates.front() : mesh_path));
  MethodResult result;
  if (method && method_status_of(method->status) == MethodStatus::Failed) {
    result = failed_result(holed, "");
    take_method_record(*method, record, result);
    return result;
  }
  if (mesh_path.empty()) {
    return failed_result(holed, "no repaired mesh for this job in " +
                                    repairs.repaired_dir.string() + " (looked for " +
                                    candidates.front().filename().string() + " and " +
                                    candidates[std::size(kMeshExtensions)].filename().string() +
                                    ", also as .off, .obj, .stl)");
  }
  OutputPatch patch;
  try {
    patch = recover_output_patch(holed, read_soup(mesh_path));
  } catch (const InvalidInputError& e) {
    return failed_result(holed, std::string("the repaired mesh is not a mesh: ") + e.what());
  }
  if (patch.input_faces_missing > 0) {
    return failed_result(
        holed, mesh_path.string() + " changed or dropped " +
                   std::to_string(patch.input_faces_missing) + " of the input's " +
                   std::to_string(holed.n_faces()) +
                   " faces (they must come back unchanged: the same vertex positions, bit for bit, "
                   "and orientation)");
  }
  result = result_of_output_patch(std::move(patch));
  if (method)
    take_method_record(*method, record, result);
  return result;
}

}  // namespace holebench::harness
