// Repairs made elsewhere, scored as a run's jobs (`holebench evaluate --cases`): the method's
// result of a job is read from files instead of running the method, and the job goes on as any
// other (the same evaluation, snapshots and records). And the files a run writes for that
// (`holebench run --repaired-meshes`), so that a run's repairs can be scored again.
//
// The naming rule, in a folder of repaired meshes, for the job of case C, method M, user U,
// noise N and seed S (docs/evaluate.md):
//   1. <stem of the job id "C|M|U|N|S">.<ext>   (what `run --repaired-meshes` writes), then
//   2. <stem of the case id C>.<ext>            (one repaired mesh per exported case),
// where a stem is the id with each '/' and '|' made '_' (harness/outputs/file_names.h) and
// <ext> is ply, off, obj or stl, tried in that order. Beside the mesh, <stem>.method.json (the
// job's record as the method left it: status, message, hole reports, phases, user, timings)
// is read where it exists; without it, the hole reports are those the mesh shows (every
// boundary loop of the input: closed or not, methods/external/output_patch.h).
#pragma once

#include "core/method_result.h"
#include "harness/results/record.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace holebench::harness {

/// Where a run reads its jobs' results from instead of running their methods.
struct ScoredRepairs {
  std::filesystem::path repaired_dir;  ///< the repaired meshes, named as in the file comment
  /// By case instance (Job::case_instance): the holed mesh the repair was made from, as the
  /// case's export wrote it (input.ply); a job whose case, made again from its id, differs from
  /// it is invalid_input. A case instance not here is not checked.
  std::map<std::string, std::filesystem::path> exported_inputs;
};

/// The files of `job`'s repaired mesh that the naming rule tries in `dir`, in order.
std::vector<std::filesystem::path> repaired_mesh_candidates(const std::filesystem::path& dir,
                                                            const Job& job);

/// The side file of a repaired mesh: <mesh's stem>.method.json beside it.
std::filesystem::path method_record_path(const std::filesystem::path& mesh_path);

/// Writes what `run --repaired-meshes` keeps of a job whose method ran, into the existing folder
/// `dir`: <job stem>.ply (the
/// repaired mesh, binary PLY with double coordinates and regions; not where the method failed)
/// and <job stem>.method.json (`method_record`: the record before the evaluation).
void write_repaired_files(const std::filesystem::path& dir, const JobRecord& method_record,
                          const MethodResult& result);

/// The method's result of `job` read from `repairs` for the holed mesh `holed` (the case's
/// input), and what its side file says of the method into `record` (user, interventions,
/// phases, method times, the job's method options). A missing mesh is a failed result that
/// says where it looked; a mesh that is not one, or that changed or dropped input faces, a
/// failed result that says so. Throws InvalidInputError where `holed` is not the exported
/// input of the job's case.
MethodResult read_scored_repair(const Job& job, const Mesh& holed, const ScoredRepairs& repairs,
                                JobRecord& record);

}  // namespace holebench::harness
