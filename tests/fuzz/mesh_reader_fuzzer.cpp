// Fuzz target: a mesh reader (the format by HOLEBENCH_FUZZ_EXTENSION: .off .obj .stl .ply).
// Property: any bytes are either a mesh or an InvalidInputError; never a crash, a sanitizer
// report, another exception, or memory taken from a count in a header.
#include "core/errors.h"
#include "core/mesh_io.h"
#include "tests/fuzz/fuzz_input_file.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path =
      holebench::fuzz::write_input(data, size, std::string("input") + HOLEBENCH_FUZZ_EXTENSION);
  try {
    holebench::read_mesh(path);
  } catch (const holebench::InvalidInputError&) {
    // the expected refusal
  }
  return 0;
}
