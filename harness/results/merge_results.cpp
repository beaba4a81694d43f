#include "harness/results/merge_results.h"

#include "harness/results/output_folder_lock.h"
#include "harness/results/results_file.h"

#include <map>

namespace holebench::harness {

std::string snapshot_relative_to(const std::string& snapshot, const std::filesystem::path& from_dir,
                                 const std::filesystem::path& to_dir) {
  if (snapshot.empty())
    return snapshot;
  const auto absolute = std::filesystem::absolute(from_dir / snapshot).lexically_normal();
  return absolute.lexically_relative(std::filesystem::absolute(to_dir).lexically_normal())
      .generic_string();
}

ResultsData merge_results(const std::vector<ResultsData>& sets) {
  ResultsData merged;
  if (!sets.empty())
    merged.context = sets.front().context;
  std::map<std::string, JobRecord> by_id;
  for (const auto& set : sets) {
    for (const auto& record : set.records)
      by_id[record.job.id()] = record;
  }
  for (auto& [id, record] : by_id)
    merged.records.push_back(std::move(record));
  return merged;
}

MergedFiles merge_results_files(const std::vector<std::filesystem::path>& files,
                                const std::filesystem::path& out_dir) {
  const OutputFolderLock lock(out_dir);
  std::vector<ResultsData> sets;
  for (const auto& path : files) {
    sets.push_back(read_results_json(path));
    for (auto& record : sets.back().records)
      record.snapshot = snapshot_relative_to(record.snapshot, path.parent_path(), out_dir);
  }
  MergedFiles result{merge_results(sets), out_dir / "results.json"};
  std::filesystem::create_directories(out_dir);
  write_results_json(result.results_json, result.merged.context, result.merged.records);
  write_results_csv(out_dir / "results.csv", result.merged.records);
  return result;
}

}  // namespace holebench::harness
