// The face-removal family (file/<stem>/faces/<ids>): whole B-Rep faces removed from the
// parts the tests build (tests/core/occt/test_parts.h), labelled from the topology and
// checked by the label test of the punched cases (label_geometry.h).
#include "generators/face_removal.h"

#include "core/boundary_loops.h"
#include "core/plane_fit.h"
#include "generators/case_catalog.h"
#include "tests/core/occt/test_parts.h"
#include "tests/generators/label_geometry.h"

#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace holebench::generators {
namespace {

CatalogOptions parts_catalog(const std::filesystem::path& dir) {
  CatalogOptions options;
  options.include_cad = false;
  options.families = {"file"};
  options.user_meshes = {dir};
  return options;
}

const std::filesystem::path& parts_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = occt::test::fresh_temp_dir("face_removal");
    for (const auto& part : occt::test::test_parts())
      occt::test::write_step(part.shape, d / (part.name + ".step"));
    // The four parts have no coplanar faces (no inner face-removal hole) and no k = 2 loop.
    occt::test::write_step(occt::test::block_with_pad_pocket_and_split_faces(),
                           d / "split_block.step");
    return d;
  }();
  return dir;
}

bool is_face_removal(const std::string& id) {
  return id.find("/faces/") != std::string::npos;
}

// Boundary kinds read off the input: the sign of the area of the kept face's own boundary
// through the hole's halfedge, about the face's fitted normal.
void expect_boundary_kinds_agree(const Case& c, const BoundaryLoop& loop) {
  const HoleLabels& labels = *c.holes[0].labels;
  if (labels.orientation == Orientation::Inner) {
    EXPECT_TRUE(labels.boundary_kinds.empty());
    return;
  }
  const auto visits = label_geometry::visits_along(c.input, loop);
  std::vector<int> regions;
  for (const auto& v : visits)
    regions.push_back(v.region);
  const int rotation = label_geometry::rotation_of(regions, labels.regions);
  ASSERT_GE(rotation, 0);
  ASSERT_EQ(labels.boundary_kinds.size(), visits.size());
  const auto planes = fit_region_planes(c.complete);
  for (std::size_t i = 0; i < visits.size(); ++i) {
    const auto& visit = visits[(i + rotation) % visits.size()];
    const auto kind = label_geometry::boundary_kind(c.input, loop.halfedges[visit.first],
                                                    planes[visit.region].plane.normal);
    EXPECT_EQ(kind, labels.boundary_kinds[i]) << "visit " << i;
  }
}

// The family on the generated parts: every case is one loop along at most 3 planar faces whose
// labels agree with the meshes, and together they cover k = 1, 2, 3, inner and outer, convex
// and reflex transitions.
TEST(FaceRemovalCases, CoverTheEnumerationOnTheGeneratedPartsWithLabelsFromTheMeshes) {
  const CaseCatalog catalog(parts_catalog(parts_dir()));
  EXPECT_TRUE(catalog.skipped().empty());
  std::set<std::string> combos;
  std::set<std::pair<int, Orientation>> k_orientation;
  std::map<int, std::set<Convexity>> convexities;
  std::set<Decision> decisions;
  std::map<std::string, int> cases_per_model;
  int cases = 0;
  for (const auto& descriptor : catalog.cases()) {
    if (!is_face_removal(descriptor.id))
      continue;
    SCOPED_TRACE(descriptor.id);
    ++cases;
    const Case c = catalog.make(descriptor.id);
    EXPECT_EQ(c.kind, descriptor.kind);
    ASSERT_EQ(c.holes.size(), 1u);
    ASSERT_TRUE(c.holes[0].labels.has_value());
    const HoleLabels& labels = *c.holes[0].labels;
    const auto loops = find_boundary_loops(c.input);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_EQ(c.input.n_faces() + c.holes[0].removed_faces.size(), c.complete.n_faces());
    label_geometry::expect_punched_labels_agree(c, loops[0]);
    expect_boundary_kinds_agree(c, loops[0]);
    // The removed triangles are exactly the named faces.
    std::set<int> removed_regions;
    for (int f : c.holes[0].removed_faces)
      removed_regions.insert(region(c.complete, c.complete.face_handle(f)));
    EXPECT_EQ(face_set_name({removed_regions.begin(), removed_regions.end()}),
              descriptor.id.substr(descriptor.id.rfind('/') + 1));
    EXPECT_LE(labels.k, 3);
    EXPECT_EQ(labels.expected_decision, labels.orientation == Orientation::Inner &&
                                                !labels.linearly_dependent_faces &&
                                                labels.size < labels.structure_size
                                            ? Decision::CloseAutomatically
                                            : Decision::Guide);
    k_orientation.insert({labels.k, labels.orientation});
    decisions.insert(labels.expected_decision);
    ++cases_per_model[descriptor.id.substr(0, descriptor.id.find("/faces/"))];
    for (auto t : labels.transitions)
      convexities[labels.k].insert(t);
    combos.insert(descriptor.description.substr(descriptor.description.rfind('(')));
  }
  for (const auto& combo : combos)
    std::cout << "  " << combo << "\n";
  EXPECT_GT(cases, 0);
  for (const auto& [model, count] : cases_per_model)
    EXPECT_LE(count, kMaxFaceRemovalCases) << model;
  EXPECT_EQ(decisions.size(), 2u) << "both decisions";
  for (int k = 1; k <= 3; ++k) {
    EXPECT_TRUE(k_orientation.count({k, Orientation::Inner})) << "k = " << k << " inner";
    EXPECT_TRUE(k_orientation.count({k, Orientation::Outer})) << "k = " << k << " outer";
  }
  for (int k = 2; k <= 3; ++k) {
    EXPECT_TRUE(convexities[k].count(Convexity::Convex)) << "k = " << k << " convex";
    EXPECT_TRUE(convexities[k].count(Convexity::Reflex)) << "k = " << k << " reflex";
  }
}

// The same id and seed give the same case, bit for bit; the listing is the same twice.
TEST(FaceRemovalCases, SameIdAndSeedGiveTheSameCase) {
  const CaseCatalog catalog(parts_catalog(parts_dir()));
  std::vector<std::string> ids;
  for (const auto& descriptor : catalog.cases()) {
    if (is_face_removal(descriptor.id))
      ids.push_back(descriptor.id);
  }
  ASSERT_FALSE(ids.empty());
  std::vector<std::string> again;
  const CaseCatalog second(parts_catalog(parts_dir()));
  for (const auto& descriptor : second.cases()) {
    if (is_face_removal(descriptor.id))
      again.push_back(descriptor.id);
  }
  EXPECT_EQ(ids, again);
  const std::string& id = ids[ids.size() / 2];
  const Case a = catalog.make(id, 3, 25.0);
  const Case b = catalog.make(id, 3, 25.0);
  ASSERT_EQ(a.input.n_vertices(), b.input.n_vertices());
  ASSERT_EQ(a.input.n_faces(), b.input.n_faces());
  for (auto v : a.input.vertices())
    EXPECT_EQ(a.input.point(v), b.input.point(b.input.vertex_handle(v.idx())));
  for (auto f : a.input.faces())
    EXPECT_EQ(region(a.input, f), region(b.input, b.input.face_handle(f.idx())));
  EXPECT_EQ(a.holes[0].removed_faces, b.holes[0].removed_faces);
  EXPECT_EQ(a.holes[0].labels->regions, b.holes[0].labels->regions);
  EXPECT_EQ(a.holes[0].labels->size, b.holes[0].labels->size);
  // Noise moves the input only.
  const Case clean = catalog.make(id, 3, 0.0);
  EXPECT_EQ(clean.holes[0].removed_faces, a.holes[0].removed_faces);
}

// Face set names are canonical; a set the family does not keep is refused with its reason.
TEST(FaceRemovalCases, NamesAreCanonicalAndOtherSetsAreRefused) {
  EXPECT_EQ(face_set_name({3, 7, 8}), "3-7-8");
  EXPECT_EQ(parse_face_set_name("3-7-8"), (std::vector<int>{3, 7, 8}));
  EXPECT_FALSE(parse_face_set_name("7-3"));
  EXPECT_FALSE(parse_face_set_name("03"));
  EXPECT_FALSE(parse_face_set_name("1-2-3-4"));
  EXPECT_FALSE(parse_face_set_name("1--2"));
  EXPECT_FALSE(parse_face_set_name(""));
  const CaseCatalog catalog(parts_catalog(parts_dir()));
  // No single face of the block is kept: the top and bottom faces, with the pocket and the
  // through hole in them, leave several loops, the cylinder two, every other face has four
  // neighbours (k = 4). Each is refused with a reason naming the model and the faces.
  int refused = 0;
  for (int face = 0; face < 12; ++face) {
    try {
      catalog.make("file/block_with_pocket_and_hole/faces/" + std::to_string(face));
    } catch (const std::invalid_argument& e) {
      ++refused;
      EXPECT_NE(std::string(e.what()).find("block_with_pocket_and_hole, faces"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(refused, 12);
  EXPECT_THROW(catalog.make("file/block_with_pocket_and_hole/faces/1-0"), std::invalid_argument);
  EXPECT_THROW(catalog.make("file/block_with_pocket_and_hole/faces/999"), std::invalid_argument);
}

}  // namespace
}  // namespace holebench::generators
