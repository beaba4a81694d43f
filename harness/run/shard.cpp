#include "harness/run/shard.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <unordered_map>

namespace holebench::harness {
namespace {

// A non-negative decimal number, the whole of `text`; `what` names it in the error.
std::size_t parse_count(const std::string& text, const std::string& what,
                        const std::string& context) {
  if (text.empty() || !std::all_of(text.begin(), text.end(),
                                   [](unsigned char c) { return std::isdigit(c) != 0; })) {
    throw std::invalid_argument(context + ": " + what + " '" + text + "' is not a number");
  }
  if (text.size() > 9)
    throw std::invalid_argument(context + ": " + what + " '" + text + "' is too large");
  return static_cast<std::size_t>(std::stoul(text));
}

}  // namespace

ShardSpec parse_shard(const std::string& text) {
  const std::string context = "shard '" + text + "'";
  const auto slash = text.find('/');
  if (slash == std::string::npos) {
    throw std::invalid_argument(context +
                                ": expected I/N, shard I of N with 0 <= I < N (e.g. 0/4)");
  }
  ShardSpec shard;
  shard.index = parse_count(text.substr(0, slash), "the index I", context);
  shard.count = parse_count(text.substr(slash + 1), "the count N", context);
  if (shard.count == 0)
    throw std::invalid_argument(context + ": the count N must be at least 1");
  if (shard.index >= shard.count) {
    throw std::invalid_argument(context +
                                ": the index I must be below N (shards are numbered 0 to " +
                                std::to_string(shard.count - 1) + ")");
  }
  return shard;
}

std::string to_string(const ShardSpec& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

std::vector<std::size_t> shard_of_each(const std::vector<std::string>& case_instances,
                                       std::size_t shard_count) {
  std::unordered_map<std::string, std::size_t> instance_order;
  std::vector<std::size_t> shards;
  shards.reserve(case_instances.size());
  for (const auto& instance : case_instances) {
    const auto [it, added] = instance_order.try_emplace(instance, instance_order.size());
    shards.push_back(it->second % shard_count);
  }
  return shards;
}

std::vector<Job> jobs_of_shard(const std::vector<Job>& plan, const ShardSpec& shard) {
  if (shard.count == 0 || shard.index >= shard.count)
    throw std::invalid_argument("shard " + to_string(shard) + " does not exist");
  std::vector<std::string> instances;
  instances.reserve(plan.size());
  for (const auto& job : plan)
    instances.push_back(job.case_instance());
  const auto shards = shard_of_each(instances, shard.count);
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (shards[i] == shard.index)
      jobs.push_back(plan[i]);
  }
  return jobs;
}

std::string shard_folder_name(std::size_t index) {
  return "shard-" + std::to_string(index);
}

std::vector<std::size_t> parse_shard_list(const std::string& text, std::size_t shard_count) {
  const std::string context = "shard list '" + text + "'";
  std::vector<std::size_t> indices;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const auto dash = item.find('-');
    const std::size_t first = parse_count(item.substr(0, dash), "shard", context);
    const std::size_t last =
        dash == std::string::npos ? first : parse_count(item.substr(dash + 1), "shard", context);
    if (last < first)
      throw std::invalid_argument(context + ": the range '" + item + "' runs backwards");
    if (last >= shard_count) {
      throw std::invalid_argument(context + ": shard " + std::to_string(last) +
                                  " does not exist (shards are numbered 0 to " +
                                  std::to_string(shard_count - 1) + ")");
    }
    for (std::size_t i = first; i <= last; ++i)
      indices.push_back(i);
    start = comma + 1;
  }
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  return indices;
}

std::string shard_list_to_array_spec(const std::vector<std::size_t>& indices) {
  std::string spec;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1)
      ++j;
    if (!spec.empty())
      spec += ',';
    spec += std::to_string(indices[i]);
    if (j > i)
      spec += "-" + std::to_string(indices[j]);
    i = j + 1;
  }
  return spec;
}

}  // namespace holebench::harness
