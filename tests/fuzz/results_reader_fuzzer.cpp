// Fuzz target: the results readers (what merge, compare, report, history and validate read):
// read_results_json and validate_results_files on a results.json, and one records.jsonl line.
// Property: any bytes are either read or refused with an InvalidInputError naming the file
// (a records.jsonl line: any std::exception, the line is skipped); never a crash.
#include "core/errors.h"
#include "harness/results/record_json.h"
#include "harness/results/results_reader.h"
#include "harness/results/validate_results.h"
#include "tests/fuzz/fuzz_input_file.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = holebench::fuzz::write_input(data, size, "results.json");
  try {
    holebench::harness::read_results_json(path);
  } catch (const holebench::InvalidInputError& e) {
    if (std::string(e.what()).find(path.string()) == std::string::npos)
      std::abort();
  }
  try {
    const auto report = holebench::harness::validate_results_files({path});
    for (const auto& violation : report.violations)
      holebench::harness::format_violation(violation);
  } catch (const holebench::InvalidInputError&) {
  }
  try {
    holebench::harness::record_from_json_text(
        std::string(reinterpret_cast<const char*>(data), size));
  } catch (const std::exception&) {
  }
  return 0;
}
