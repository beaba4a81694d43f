// core/occt/isolated_read.h: files on which OpenCASCADE 7.6 dereferences a null handle, found
// by the fuzz targets fuzz_brep_step, fuzz_brep_iges and fuzz_brep_brep (their inputs are in
// tests/core/occt/fuzz_crashes/, each a box written by OpenCASCADE with a few bytes changed),
// are one-line errors naming the file instead of a crash of holebench; and reading in a child
// process gives the same mesh, bit for bit, as reading in this one.
#include "core/occt/isolated_read.h"

#include "core/errors.h"
#include "core/occt/brep_file_reader.h"
#include "core/occt/brep_mesh.h"
#include "tests/core/occt/test_parts.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace holebench::occt {
namespace {

const std::filesystem::path kCrashes =
    std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "tests" / "core" / "occt" / "fuzz_crashes";

// StepShape_FaceBound::Bound (STEP), IGESSolid_Face::NbLoops (IGES),
// Geom2d_OffsetCurve::SetBasisCurve (BREP): each a SIGSEGV inside OpenCASCADE under ASan;
// built without it (the release preset), OpenCASCADE loops on the STEP file instead, which the
// time limit stops.
TEST(IsolatedRead, FilesThatCrashOpenCascadeAreOneLineErrors) {
  for (const char* name :
       {"step_face_bound.step", "iges_solid_face.iges", "geom2d_offset_curve.brep"}) {
    SCOPED_TRACE(name);
    const auto path = kCrashes / name;
    ASSERT_TRUE(std::filesystem::exists(path));
    TessellationOptions options;
    options.time_limit_seconds = 20.0;  // without ASan, OpenCASCADE loops on the STEP file
    try {
      read_brep_mesh(path, options);
      ADD_FAILURE() << "read";
    } catch (const InvalidInputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

TEST(IsolatedRead, TheSameMeshAsReadingInThisProcess) {
  const auto dir = test::fresh_temp_dir("isolated_read");
  const auto path = dir / "part.step";
  test::write_step(test::block_with_pocket_and_hole(), path);
  const TessellationOptions options;
  const TessellatedSoup here = tessellate_shape_soup(read_brep_shape(path), options);
  const TessellatedSoup there = read_and_tessellate_isolated(path, options);
  ASSERT_EQ(here.soup.points.size(), there.soup.points.size());
  for (std::size_t i = 0; i < here.soup.points.size(); ++i)
    EXPECT_EQ(here.soup.points[i], there.soup.points[i]);
  EXPECT_EQ(here.soup.triangles, there.soup.triangles);
  EXPECT_EQ(here.soup.regions, there.soup.regions);
  EXPECT_EQ(here.face_surfaces, there.face_surfaces);
}

TEST(IsolatedRead, TheChildsErrorsComeBackAsTheyWere) {
  const auto dir = test::fresh_temp_dir("isolated_read_errors");
  try {
    read_and_tessellate_isolated(dir / "missing.step", {});
    ADD_FAILURE() << "read";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.step"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace holebench::occt
