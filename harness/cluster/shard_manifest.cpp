#include "harness/cluster/shard_manifest.h"

#include "core/atomic_file.h"

#include "core/errors.h"
#include "harness/run/shard.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace holebench::harness {

std::filesystem::path shard_manifest_path(const std::filesystem::path& dir) {
  return dir / "shards.json";
}

std::filesystem::path shard_dir(const std::filesystem::path& dir, std::size_t index) {
  return dir / shard_folder_name(index);
}

std::filesystem::path slurm_script_path(const std::filesystem::path& dir) {
  return dir / "slurm" / "shards.sbatch";
}

std::filesystem::path slurm_log_path(const std::filesystem::path& dir, std::size_t index) {
  return dir / "slurm" / (shard_folder_name(index) + ".log");
}

std::filesystem::path slurm_log_pattern(const std::filesystem::path& dir) {
  return dir / "slurm" / "shard-%a.log";
}

std::vector<std::string> shard_job_ids(const ShardManifest& manifest, std::size_t index) {
  std::vector<std::string> instances;
  instances.reserve(manifest.job_ids.size());
  for (const auto& id : manifest.job_ids)
    instances.push_back(case_instance_of_job_id(id));
  const auto shards = shard_of_each(instances, manifest.shard_count);
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < manifest.job_ids.size(); ++i) {
    if (shards[i] == index)
      ids.push_back(manifest.job_ids[i]);
  }
  return ids;
}

void write_shard_manifest(const std::filesystem::path& dir, const ShardManifest& manifest) {
  nlohmann::ordered_json j;
  j["suite"] = manifest.suite;
  j["suite_file"] = manifest.suite_file.string();
  j["shard_count"] = manifest.shard_count;
  j["holebench"] = manifest.holebench.string();
  j["run_arguments"] = manifest.run_arguments;
  j["sbatch_options"] = manifest.sbatch_options;
  auto& submissions = j["submissions"] = nlohmann::ordered_json::array();
  for (const auto& s : manifest.submissions) {
    submissions.push_back(
        {{"slurm_job_id", s.slurm_job_id}, {"array", s.array}, {"submitted_utc", s.submitted_utc}});
  }
  j["job_ids"] = manifest.job_ids;
  std::filesystem::create_directories(dir);
  const auto path = shard_manifest_path(dir);
  write_file_atomically(path, j.dump(2) + "\n");  // readers never see half a manifest
}

ShardManifest read_shard_manifest(const std::filesystem::path& dir) {
  const auto path = shard_manifest_path(dir);
  std::ifstream in(path);
  if (!in) {
    throw InvalidInputError(path.string() +
                            " not found: not the folder of a sharded run (holebench slurm "
                            "submit --out DIR writes it)");
  }
  try {
    const auto j = nlohmann::json::parse(in);
    ShardManifest manifest;
    manifest.suite = j.at("suite").get<std::string>();
    manifest.suite_file = j.value("suite_file", std::string());
    manifest.shard_count = j.at("shard_count").get<std::size_t>();
    if (manifest.shard_count == 0)
      throw std::invalid_argument("shard_count is 0");
    manifest.job_ids = j.at("job_ids").get<std::vector<std::string>>();
    manifest.holebench = j.value("holebench", std::string());
    manifest.run_arguments = j.value("run_arguments", std::vector<std::string>{});
    manifest.sbatch_options = j.value("sbatch_options", std::vector<std::string>{});
    for (const auto& s : j.value("submissions", nlohmann::json::array())) {
      manifest.submissions.push_back({s.value("slurm_job_id", std::string()),
                                      s.value("array", std::string()),
                                      s.value("submitted_utc", std::string())});
    }
    return manifest;
  } catch (const std::exception& e) {
    throw InvalidInputError(path.string() + ": not a shard manifest (" + e.what() + ")");
  }
}

}  // namespace holebench::harness
