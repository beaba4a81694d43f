#include "generators/punched_case.h"

#include "core/boundary_loops.h"
#include "core/mesh_io.h"
#include "core/plane_fit.h"
#include "generators/box_solid.h"
#include "generators/case_catalog.h"
#include "tests/generators/label_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

namespace holebench::generators {
namespace {

CatalogOptions no_cad() {
  CatalogOptions options;
  options.include_cad = false;
  return options;
}

// "corner_ccr" -> {convex, convex, reflex}
std::multiset<Convexity> signature_of(const std::string& kind) {
  std::multiset<Convexity> s;
  for (char c : kind.substr(kind.find('_') + 1))
    s.insert(c == 'c' ? Convexity::Convex : Convexity::Reflex);
  return s;
}

// The labels of every labelled punched case (procedural solids and CAD models, one hole,
// one loop), read a second way off the meshes (label_geometry::expect_punched_labels_agree).
TEST(PunchedCases, LabelsAgreeWithTheGeometry) {
  using namespace label_geometry;
  const CaseCatalog catalog;
  int checked = 0;
  for (const auto& descriptor : catalog.cases()) {
    if (descriptor.family != "solid" && descriptor.family != "cad")
      continue;
    const Case c = catalog.make(descriptor.id);
    const auto loops = find_boundary_loops(c.input);
    if (c.holes.size() != 1 || loops.size() != 1 || !c.holes[0].labels)
      continue;
    SCOPED_TRACE(descriptor.id);
    expect_punched_labels_agree(c, loops[0]);
    ++checked;
  }
  // The procedural solids alone give more than a dozen labelled holes (the CAD models more
  // where the CGAL data set is there).
  EXPECT_GE(checked, 12);
}

// A rod 0.02 thick and 2 long: the edge hole's nominal radius (2 % of the diagonal, 0.04) is
// twice the rod's width, so the disc would cut the rod through (two boundary loops). The hole
// is punched again smaller until it is one hole across the edge, labelled, the labels agree
// with the meshes, and the same target gives the same hole.
TEST(PunchedCases, AHoleThatWouldCutThroughAThinRodIsMadeSmaller) {
  const AnalysedModel rod = analyse_model("rod", make_box({Point(2.0, 0.02, 0.02), 0.005}));
  const auto targets = find_punch_targets(rod);
  const auto edge = std::find_if(targets.begin(), targets.end(),
                                 [](const PunchTarget& t) { return t.kind == "edge_convex"; });
  ASSERT_NE(edge, targets.end());
  PunchedCaseOptions options;
  options.shrink_steps = 0;
  const Case cut = make_punched_case(rod, *edge, options);
  EXPECT_GE(find_boundary_loops(cut.input).size(), 2u);
  EXPECT_FALSE(cut.holes[0].labels.has_value());

  options = PunchedCaseOptions{};
  const Case c = make_punched_case(rod, *edge, options);
  const auto loops = find_boundary_loops(c.input);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_TRUE(c.holes[0].labels.has_value()) << c.holes[0].unlabelled_because;
  EXPECT_GE(c.holes[0].labels->k, 2);  // across the edge, perhaps around a third face
  EXPECT_LT(c.holes[0].removed_faces.size(), cut.holes[0].removed_faces.size());
  label_geometry::expect_punched_labels_agree(c, loops[0]);
  const Case again = make_punched_case(rod, *edge, options);
  EXPECT_EQ(again.holes[0].removed_faces, c.holes[0].removed_faces);
}

// A punched hole has labels or says why not, and the reason is the construction's: the
// curved faces of the cylinder and the cone, the island's two loops.
TEST(PunchedCases, AHoleWithoutLabelsSaysWhy) {
  const CaseCatalog catalog(no_cad());
  int curved = 0;
  for (const auto& descriptor : catalog.cases()) {
    if (descriptor.family != "solid")
      continue;
    SCOPED_TRACE(descriptor.id);
    const Case c = catalog.make(descriptor.id);
    ASSERT_EQ(c.holes.size(), 1u);
    const HoleTruth& hole = c.holes[0];
    EXPECT_NE(hole.labels.has_value(), !hole.unlabelled_because.empty());
    if (descriptor.kind == "island") {
      EXPECT_EQ(hole.unlabelled_because, "an island (two boundary loops) is outside the taxonomy");
    }
    if (descriptor.kind == "curved_face") {
      EXPECT_EQ(hole.unlabelled_because, "a removed face lies on a curved region");
      ++curved;
    }
  }
  EXPECT_GE(curved, 4);  // the cylinder's and the cone's, small and large
}

// Every punched case of the procedural solids against what its target kind promises.
TEST(PunchedCases, ProceduralSolidHolesMatchTheirTargets) {
  const CaseCatalog catalog(no_cad());
  int checked = 0;
  for (const auto& descriptor : catalog.cases()) {
    if (descriptor.family != "solid")
      continue;
    SCOPED_TRACE(descriptor.id);
    const Case c = catalog.make(descriptor.id);
    ASSERT_EQ(c.holes.size(), 1u);
    const HoleTruth& hole = c.holes[0];
    EXPECT_FALSE(hole.removed_faces.empty());
    EXPECT_EQ(c.input.n_faces() + hole.removed_faces.size(), c.complete.n_faces());
    const auto loops = find_boundary_loops(c.input);
    const std::string& kind = descriptor.kind;
    if (kind == "island") {
      EXPECT_EQ(loops.size(), 2u) << "an annulus leaves an outer loop and the island's";
      continue;
    }
    EXPECT_EQ(loops.size(), 1u);
    for (auto f : c.input.faces())
      ASSERT_EQ(region(c.input, f), kNoRegion) << "inputs carry no regions";
    const bool small =
        descriptor.id.size() > 6 && descriptor.id.substr(descriptor.id.size() - 6) == "/small";
    // Labels exist where the hole runs along planar faces only (not a cylinder's rim, nor the
    // helical sweep's curved sides).
    const bool planar = descriptor.id.find("cylinder") == std::string::npos &&
                        descriptor.id.find("cone") == std::string::npos &&
                        descriptor.id.find("helical_sweep") == std::string::npos;
    if (kind.rfind("corner_", 0) == 0) {
      ASSERT_EQ(hole.missing_corners.size(), 1u);
      EXPECT_EQ(hole.missing_edges.size(), 3u);
      EXPECT_EQ(hole.labels.has_value(), planar);
      if (!planar)
        continue;
      EXPECT_EQ(hole.labels->k, 3);
      const std::multiset<Convexity> transitions(hole.labels->transitions.begin(),
                                                 hole.labels->transitions.end());
      EXPECT_EQ(transitions, signature_of(kind));
    } else if (kind.rfind("edge_", 0) == 0) {
      EXPECT_TRUE(hole.missing_corners.empty());
      ASSERT_EQ(hole.missing_edges.size(), 1u);
      if (small && planar) {
        ASSERT_TRUE(hole.labels.has_value());
        EXPECT_EQ(hole.labels->k, 2);
        const Convexity expected = kind == "edge_convex" ? Convexity::Convex : Convexity::Reflex;
        for (Convexity t : hole.labels->transitions)
          EXPECT_EQ(t, expected);
      }
    } else if (kind == "face_interior") {
      EXPECT_TRUE(hole.missing_corners.empty());
      EXPECT_TRUE(hole.missing_edges.empty());
      ASSERT_TRUE(hole.labels.has_value());
      EXPECT_EQ(hole.labels->k, 1);
    }
    if (hole.labels && hole.labels->k <= 3) {
      // Small holes are below the structure size (closed automatically), large ones above.
      EXPECT_EQ(hole.labels->expected_decision,
                small ? Decision::CloseAutomatically : Decision::Guide);
      EXPECT_EQ(hole.labels->orientation, Orientation::Inner);
    }
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

TEST(PunchedCases, SameIdGivesTheSameCase) {
  const CaseCatalog catalog(no_cad());
  const Case a = catalog.make("solid/notched_block/corner_rrr/large");
  const Case b = catalog.make("solid/notched_block/corner_rrr/large");
  EXPECT_EQ(a.holes[0].removed_faces, b.holes[0].removed_faces);
  ASSERT_EQ(a.input.n_vertices(), b.input.n_vertices());
  for (auto v : a.input.vertices())
    EXPECT_EQ(a.input.point(v), b.input.point(b.input.vertex_handle(v.idx())));
}

std::filesystem::path temp_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holebench_catalog_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A user's folder: a good mesh gives file/<stem>/... cases; an open mesh, a file that is
// not a mesh, a non-manifold and a degenerate one are skipped with their reason, and the rest
// still works.
TEST(CaseCatalog, UserMeshesAreUsedAndBadOnesSkippedWithTheirReason) {
  const auto dir = temp_folder("user");
  write_mesh(make_box({Point(1.0, 1.0, 1.0), 0.05}), dir / "good_box.off");
  {
    std::ofstream(dir / "not_a_mesh.obj") << "hello, I am not a mesh\n";
    // Two triangles sharing an edge: an open surface.
    std::ofstream(dir / "open.off") << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n";
    // Three triangles on one edge: non-manifold.
    std::ofstream(dir / "fin.off")
        << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
    // A closed tetrahedron whose fourth vertex lies on an edge: a zero-area triangle.
    std::ofstream(dir / "flat.off") << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0.5 0 0\n"
                                       "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  }
  CatalogOptions options = no_cad();
  options.user_meshes = {dir};
  const CaseCatalog catalog(options);
  std::set<std::string> files;
  for (const auto& c : catalog.cases()) {
    if (c.family == "file")
      files.insert(c.id.substr(0, c.id.find('/', 5)));
  }
  EXPECT_EQ(files, (std::set<std::string>{"file/good_box"}));
  std::map<std::string, std::string> reasons;
  for (const auto& s : catalog.skipped())
    reasons[s.name] = s.reason;
  ASSERT_EQ(reasons.size(), 4u);
  EXPECT_NE(reasons["file/flat"].find("degenerate"), std::string::npos) << reasons["file/flat"];
  EXPECT_NE(reasons["file/open"].find("open"), std::string::npos);
  EXPECT_NE(reasons["file/fin"].find("non-manifold edge"), std::string::npos);
  EXPECT_NE(reasons["file/not_a_mesh"].find("not_a_mesh.obj"), std::string::npos);
  const Case c = catalog.make("file/good_box/corner_ccc/small");
  EXPECT_EQ(c.holes[0].missing_corners.size(), 1u);
}

TEST(CaseCatalog, MissingCadDataIsReportedNotFatal) {
  CatalogOptions options;
  options.cad_data_dir = "/nonexistent/holebench/cad";
  const CaseCatalog catalog(options);
  EXPECT_FALSE(catalog.cases().empty());
  std::size_t cad_skipped = 0;
  for (const auto& s : catalog.skipped())
    cad_skipped += s.name.rfind("cad/", 0) == 0 ? 1 : 0;
  EXPECT_EQ(cad_skipped, 8u);
  EXPECT_THROW(catalog.make("cad/fandisk/edge_convex/small"), std::exception);
}

}  // namespace
}  // namespace holebench::generators
