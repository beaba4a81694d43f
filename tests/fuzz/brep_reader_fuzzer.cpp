// Fuzz target: the B-Rep reader through OpenCASCADE (the format by HOLEBENCH_FUZZ_EXTENSION:
// .step .iges .brep), reading and tessellating.
//
// By default the file is read in this process (read_brep_shape and tessellate_shape_soup), so
// that libFuzzer sees OpenCASCADE's coverage and finds its crashes. With
// HOLEBENCH_FUZZ_ISOLATED=1 the input goes through read_brep_mesh, which reads in a child
// process (core/occt/isolated_read.h): scripts/run_fuzz.sh replays every crash found that
// way, and a crash there, in holebench's own reader, is a finding. Property: any bytes are a
// mesh or an InvalidInputError.
#include "core/errors.h"
#include "core/occt/brep_file_reader.h"
#include "core/occt/brep_mesh.h"
#include "core/occt/shape_tessellation.h"
#include "tests/fuzz/fuzz_input_file.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool isolated = std::getenv("HOLEBENCH_FUZZ_ISOLATED") != nullptr;
  const auto path =
      holebench::fuzz::write_input(data, size, std::string("input") + HOLEBENCH_FUZZ_EXTENSION);
  try {
    if (isolated) {
      // Below the replay's own timeout (scripts/run_fuzz.sh), so that a file OpenCASCADE
      // loops on is the reader's error, not a timeout of the fuzzer.
      holebench::occt::TessellationOptions options;
      options.time_limit_seconds = 20.0;
      holebench::occt::read_brep_mesh(path, options);
    } else {
      holebench::occt::tessellate_shape_soup(holebench::occt::read_brep_shape(path), {});
    }
  } catch (const holebench::InvalidInputError&) {
  }
  return 0;
}
