#include "methods/external/external_method.h"

#include "core/errors.h"
#include "core/geometry.h"
#include "core/mesh_io.h"
#include "core/stopwatch.h"
#include "methods/external/output_patch.h"
#include "methods/external/program_run.h"

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>

namespace holebench {

namespace {

namespace fs = std::filesystem;

// A fresh folder for one run's files, removed with its contents when the run ends.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "holebench-external-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error("cannot create a temporary folder in " +
                               fs::temp_directory_path().string());
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

MethodResult failed(MethodResult result, const std::string& what, const fs::path& stderr_path) {
  result.status = MethodStatus::Failed;
  result.message = what;
  const std::string tail = last_lines(stderr_path);
  if (!tail.empty())
    result.message += "; its stderr ends:\n" + tail;
  return result;
}

}  // namespace

MethodResult run_external_method(const Mesh& holed, const ExternalMethodSpec& spec) {
  MethodResult result;
  result.repaired = holed;
  for (const auto& program : spec.required_programs) {
    if (!program_on_path(program)) {
      result.status = MethodStatus::Failed;
      result.message =
          "skipped: " + program + " is not installed (not on PATH), which " + spec.name + " needs";
      return result;
    }
  }
  const TemporaryFolder folder;
  const fs::path input = folder.path() / "input.ply";
  const fs::path output = folder.path() / "output.ply";
  const fs::path out_log = folder.path() / "stdout.txt";
  const fs::path err_log = folder.path() / "stderr.txt";

  auto start = SteadyClock::now();
  write_mesh(holed, input);
  result.phases.push_back({"write_input", seconds_since(start)});

  start = SteadyClock::now();
  const ProgramRun run = run_shell_command(
      expand_command(spec.command, input.string(), output.string()), out_log, err_log);
  result.phases.push_back({"program", seconds_since(start)});
  if (!run.succeeded())
    return failed(std::move(result), "the program failed: " + run.how_it_ended(), err_log);
  if (!fs::exists(output))
    return failed(std::move(result), "the program wrote no output file ({output})", err_log);

  start = SteadyClock::now();
  TriangleSoup soup;
  try {
    soup = read_soup(output);
  } catch (const InvalidInputError& e) {
    return failed(std::move(result), std::string("the program's output is not a mesh: ") + e.what(),
                  err_log);
  }
  result.phases.push_back({"read_output", seconds_since(start)});

  start = SteadyClock::now();
  OutputPatch patch;
  try {
    patch = recover_output_patch(holed, soup,
                                 spec.vertex_tolerance_rel_diag * bounding_box_diagonal(holed));
  } catch (const InvalidInputError& e) {
    return failed(std::move(result), std::string("the program's output is not a mesh: ") + e.what(),
                  err_log);
  }
  result.phases.push_back({"match_faces", seconds_since(start)});
  if (patch.input_faces_missing > 0) {
    return failed(std::move(result),
                  "the program's output changed or dropped " +
                      std::to_string(patch.input_faces_missing) + " of the input's " +
                      std::to_string(holed.n_faces()) +
                      " faces (they must come back unchanged: the same vertex positions, bit for "
                      "bit, and orientation)",
                  err_log);
  }
  MethodResult scored = result_of_output_patch(std::move(patch));
  scored.phases = std::move(result.phases);
  result = std::move(scored);
  return result;
}

}  // namespace holebench
