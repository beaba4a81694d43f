// Fuzz target: the suite reader (harness/run/suite.h). Property: any bytes are either a
// suite or an InvalidInputError naming the file, one line; never a crash or another exception.
#include "core/errors.h"
#include "harness/run/suite.h"
#include "tests/fuzz/fuzz_input_file.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = holebench::fuzz::write_input(data, size, "suite.json");
  try {
    const auto suite = holebench::harness::load_suite(path.string(), path.parent_path());
    if (suite.case_patterns.empty() || suite.noise_levels.empty() || suite.seeds.empty())
      std::abort();  // the reader refuses empty lists
  } catch (const holebench::InvalidInputError& e) {
    if (std::string(e.what()).find(path.string()) == std::string::npos)
      std::abort();  // every error names the file
  }
  return 0;
}
