// External methods (methods/external/): the command template, face matching, and each way a
// program can fail, with tiny shell and Python commands. The worked example
// (examples/fan_fill.py) is run here directly and, through the runner, in
// tests/harness/run/external_method_run_test.cpp.
#include "methods/external/external_method.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "core/mesh_builder.h"
#include "generators/case_catalog.h"
#include "methods/external/external_method_spec.h"
#include "methods/external/output_patch.h"
#include "methods/external/predefined_external_methods.h"
#include "methods/external/program_run.h"
#include "methods/registry.h"
#include "tests/methods/method_invariants.h"

#include <gtest/gtest.h>

#include <string>

namespace holebench {
namespace {

const std::string kExamples = std::string(HOLEBENCH_SOURCE_DIR) + "/examples";

ExternalMethodSpec spec_of(const std::string& command) {
  return {"test_program", command, 0.0, {}};
}

// A Python command that reads the input with the example's reader, edits (points, faces) by
// `edit` and writes them with the fan filled in: the example's own code with one change.
std::string python_edit(const std::string& edit) {
  return "python3 -c \"import sys; sys.path.insert(0, '" + kExamples +
         "'); import fan_fill as f; p, t = f.read_ply(sys.argv[1]); " + edit +
         "; f.write_ply(sys.argv[2], *f.fan_fill(p, t))\" {input} {output}";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ExternalMethodSpec, ParsesNameAndCommandWhoseSemicolonsStayInTheCommand) {
  const auto spec = parse_external_method_spec("name=my_fill;command=a {input}; b {output}");
  EXPECT_EQ(spec.name, "my_fill");
  EXPECT_EQ(spec.command, "a {input}; b {output}");
  EXPECT_EQ(spec.vertex_tolerance_rel_diag, 0.0);
  const auto tolerant = parse_external_method_spec(
      "name=f32;vertex_tolerance_rel_diag=1e-6;command=x {input} {output}");
  EXPECT_EQ(tolerant.vertex_tolerance_rel_diag, 1e-6);
}

TEST(ExternalMethodSpec, RejectsBadInputWithAOneLineReason) {
  for (const char* bad :
       {"command=x {input} {output}",                    // no name
        "name=a",                                        // no command
        "name=a;command=",                               // empty command
        "name=a;command=x {input} {out}",                // unknown placeholder
        "name=a;command=x {input}",                      // no {output}
        "name=A b;command=x {input} {output}",           // bad name
        "name=a;colour=red;command=x {input} {output}",  // unknown key
        "name=a;vertex_tolerance_rel_diag=-1;command=x {input} {output}", "just text"}) {
    try {
      parse_external_method_spec(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_FALSE(contains(e.what(), "\n")) << e.what();
    }
  }
}

TEST(ExternalMethodSpec, ExpandsPlaceholdersToQuotedPaths) {
  EXPECT_EQ(expand_command("f {input} {output}", "/tmp/a b/in.ply", "/tmp/it's.ply"),
            "f '/tmp/a b/in.ply' '/tmp/it'\\''s.ply'");
}

TEST(ProgramRun, LastLinesKeepsTheEndOfStderr) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_program_run_test";
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / "err.txt");
  const ProgramRun run = run_shell_command("for i in 1 2 3 4 5; do echo line $i >&2; done; exit 4",
                                           dir / "out.txt", dir / "err.txt");
  EXPECT_FALSE(run.succeeded());
  EXPECT_EQ(run.exit_code, 4);
  EXPECT_EQ(last_lines(dir / "err.txt", 2), "line 4\nline 5");
  EXPECT_EQ(last_lines(dir / "missing.txt"), "");
}

// The input itself as the output (faces and vertices in another order): every input face is
// recognised, nothing is new, the hole stays open.
TEST(OutputPatch, RecognisesTheInputInAnyOrder) {
  const Case c = generators::make_case("box/corner");
  TriangleSoup soup = to_soup(c.input);
  std::reverse(soup.triangles.begin(), soup.triangles.end());
  for (auto& t : soup.triangles)
    std::rotate(t.begin(), t.begin() + 1, t.end());
  const OutputPatch patch = recover_output_patch(c.input, soup);
  EXPECT_EQ(patch.input_faces_missing, 0u);
  EXPECT_EQ(patch.new_faces, 0u);
  ASSERT_EQ(patch.holes.size(), 1u);
  EXPECT_FALSE(patch.holes[0].closed);
  // A flipped face is a changed face.
  std::swap(soup.triangles[0][1], soup.triangles[0][2]);
  EXPECT_EQ(recover_output_patch(c.input, soup).input_faces_missing, 1u);
}

class FanFillExample : public ::testing::TestWithParam<std::string> {};

// examples/fan_fill.py run as an external method: closed, manifold, the input's faces kept
// (same index, same vertices, same positions), one new vertex per hole at the loop's centroid.
TEST_P(FanFillExample, ClosesEveryHoleAndKeepsTheInput) {
  const Case c = generators::make_case(GetParam());
  const ExternalMethod method(spec_of("python3 '" + kExamples + "/fan_fill.py' {input} {output}"));
  NoUser user;
  const MethodResult result = method.run(c.input, {}, user);
  ASSERT_EQ(result.status, MethodStatus::Ok) << result.message;
  test::expect_closed_manifold(result.repaired);
  test::expect_input_faces_unchanged(c.input, result.repaired);
  const auto loops = find_boundary_loops(c.input);
  ASSERT_EQ(result.holes.size(), loops.size());
  for (std::size_t i = 0; i < loops.size(); ++i) {
    EXPECT_TRUE(result.holes[i].closed);
    EXPECT_EQ(result.holes[i].new_faces, loops[i].size());  // a fan: one face per loop edge
    EXPECT_EQ(result.holes[i].new_vertices, 1u);
  }
  EXPECT_EQ(result.phases.size(), 4u);  // write_input, program, read_output, match_faces
}

INSTANTIATE_TEST_SUITE_P(SkeletonCases, FanFillExample,
                         ::testing::Values("box/face_interior", "box/edge", "box/corner"),
                         test::case_test_name);

// Each way a program can fail is a failed result whose message says which, and ends with the
// program's last lines of stderr where it wrote any.
struct FailureKind {
  const char* name;
  std::string command;
  std::string expected_in_message;
};

// The test's name in listings (instead of the object's bytes).
void PrintTo(const FailureKind& kind, std::ostream* out) {
  *out << kind.name;
}

class ExternalMethodFailures : public ::testing::TestWithParam<FailureKind> {};

TEST_P(ExternalMethodFailures, AreFailedResultsThatSayWhy) {
  const Case c = generators::make_case("box/face_interior");
  const MethodResult result = run_external_method(c.input, spec_of(GetParam().command));
  EXPECT_EQ(result.status, MethodStatus::Failed);
  EXPECT_TRUE(contains(result.message, GetParam().expected_in_message)) << result.message;
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, ExternalMethodFailures,
    ::testing::Values(
        FailureKind{"exit_code", "echo 'fill: out of luck' >&2; exit 3; : {input} {output}",
                    "exit code 3; its stderr ends:\nfill: out of luck"},
        FailureKind{"signal", "kill -SEGV $$; : {input} {output}", "killed by Segmentation"},
        FailureKind{"no_output", "echo 'wrote nothing' >&2; : {input} {output}",
                    "wrote no output file"},
        FailureKind{"garbage", "echo 'not a mesh' > {output}; : {input}",
                    "the program's output is not a mesh"},
        FailureKind{"moved_vertex", python_edit("p[0] = (p[0][0] + 1e-9, p[0][1], p[0][2])"),
                    "changed or dropped"},
        FailureKind{"dropped_face", python_edit("t = t[1:]"), "changed or dropped 1 of"},
        FailureKind{"no_fill", "cp {input} {output}", "1 of 1 holes left open"},
        FailureKind{"missing_program", "no_such_program_for_holebench {input} {output}",
                    "exit code 127"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(ExternalMethod, AMissingRequiredProgramIsNamed) {
  const Case c = generators::make_case("box/face_interior");
  ExternalMethodSpec spec = spec_of("true {input} {output}");
  spec.required_programs = {"no_such_program_for_holebench"};
  const MethodResult result = run_external_method(c.input, spec);
  EXPECT_EQ(result.status, MethodStatus::Failed);
  EXPECT_TRUE(contains(result.message, "skipped: no_such_program_for_holebench is not installed"))
      << result.message;
}

// Predefined external methods run by name only: never among the built-ins.
TEST(PredefinedExternalMethods, AreNotBuiltIns) {
  ASSERT_TRUE(find_predefined_external_method("meshlab_close_holes"));
  EXPECT_FALSE(find_predefined_external_method("liepa_cgal"));
  for (const auto& method : make_all_methods())
    EXPECT_NE(method->id(), "meshlab_close_holes");
  EXPECT_THROW(make_method("meshlab_close_holes"), std::invalid_argument);
}

// MeshLab's Close Holes through meshlabserver (skipped where it is not installed): closes the
// box's holes and keeps the input's faces (matched within its single precision).
TEST(PredefinedExternalMethods, MeshlabCloseHolesClosesTheBoxHoles) {
  if (!program_on_path("meshlabserver") || !program_on_path("xvfb-run"))
    GTEST_SKIP() << "meshlabserver or xvfb-run not installed (Debian packages meshlab, xvfb)";
  for (const char* id : {"box/face_interior", "box/corner"}) {
    const Case c = generators::make_case(id);
    const MethodResult result =
        run_external_method(c.input, *find_predefined_external_method("meshlab_close_holes"));
    ASSERT_EQ(result.status, MethodStatus::Ok) << id << ": " << result.message;
    EXPECT_TRUE(find_boundary_loops(result.repaired).empty()) << id;
    EXPECT_GT(count_new_faces(result.repaired), 0u) << id;
  }
}

}  // namespace
}  // namespace holebench
