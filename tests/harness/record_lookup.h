// Test helpers: a job record's values by name.
#pragma once

#include "harness/results/record.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace holebench::harness::test_support {

/// The value named `name` in `entries` (metrics: name/value; stages: phase/seconds); a
/// test failure and -1 when it is absent.
template <typename Entry, typename Key, typename Value>
double value_named(const std::vector<Entry>& entries, Key Entry::*key, Value Entry::*value,
                   const std::string& name, const JobRecord& record) {
  for (const auto& entry : entries) {
    if (entry.*key == name)
      return entry.*value;
  }
  ADD_FAILURE() << "no " << name << " in " << record.job.id();
  return -1.0;
}

inline double metric(const JobRecord& record, const std::string& name) {
  if (const double* value = record.metric(name))
    return *value;
  ADD_FAILURE() << "no " << name << " in " << record.job.id();
  return -1.0;
}

inline double stage(const JobRecord& record, const std::string& name) {
  return value_named(record.stages, &PhaseTiming::phase, &PhaseTiming::seconds, name, record);
}

}  // namespace holebench::harness::test_support
