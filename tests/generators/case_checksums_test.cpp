// The same cases on every machine: the FNV-1a checksums of the meshes of a fixed list of
// cases (the holed input and the complete model, each as `holebench cases export` writes
// them: binary PLY) equal the values stored in case_checksums.txt beside this file. The list
// covers every call the generators make to an elementary function (core/portable_math.h):
// the pyramid's base (sin, cos), the revolved solids' rings (sin, cos, hypot) and the
// punched holes' irregular outlines (sin, atan2), clean and with 5 % noise.
//
// A change of a generator changes checksums on purpose: the failure prints every new value in
// the file's format, to be reviewed and copied into case_checksums.txt.
#include "core/mesh_io.h"
#include "generators/case_catalog.h"
#include "generators/random.h"
#include "tests/harness/text_file.h"

#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace holebench::generators {
namespace {

const std::filesystem::path kStored =
    std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "tests" / "generators" / "case_checksums.txt";

// FNV-1a (64 bit) of a mesh as written to binary PLY.
std::uint64_t mesh_checksum(const Mesh& mesh) {
  const auto path = std::filesystem::temp_directory_path() / "holebench_case_checksum.ply";
  write_mesh(mesh, path);
  return stable_hash(harness::test_support::read_text(path));
}

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

// "id noise input complete" lines; '#' starts a comment.
std::map<std::pair<std::string, int>, std::pair<std::string, std::string>> stored() {
  std::map<std::pair<std::string, int>, std::pair<std::string, std::string>> values;
  std::ifstream in(kStored);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#')
      continue;
    std::istringstream fields(line);
    std::string id, input, complete;
    int noise = 0;
    if (fields >> id >> noise >> input >> complete)
      values[{id, noise}] = {input, complete};
  }
  return values;
}

TEST(CaseChecksums, TheCasesAreTheSameBytesAsStored) {
  const auto expected = stored();
  ASSERT_GE(expected.size(), 20u) << kStored;
  std::string now;
  int differing = 0;
  for (const auto& [key, sums] : expected) {
    const auto& [id, noise] = key;
    const Case c = make_case(id, 0, noise);
    const std::string input = hex(mesh_checksum(c.input));
    const std::string complete = hex(mesh_checksum(c.complete));
    now += id + " " + std::to_string(noise) + " " + input + " " + complete + "\n";
    if (input != sums.first || complete != sums.second) {
      ++differing;
      ADD_FAILURE() << id << " at " << noise << " % noise: input " << input << " (stored "
                    << sums.first << "), complete " << complete << " (stored " << sums.second
                    << ")";
    }
  }
  if (differing > 0)
    std::printf("The cases' checksums now (%d differ):\n%s", differing, now.c_str());
}

}  // namespace
}  // namespace holebench::generators
