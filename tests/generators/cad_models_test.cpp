#include "generators/cad/cad_models.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace holebench::generators {
namespace {

bool cad_data_present() {
  return std::filesystem::exists(default_cad_data_dir() / "fandisk.off");
}

// The CGAL data set's models load, are closed, and keep their shape through remeshing:
// the remeshed surface stays within a small fraction of the diagonal of the original.
TEST(CadModels, EveryModelPreparesIntoAClosedSegmentedMesh) {
  if (!cad_data_present())
    GTEST_SKIP() << "CGAL data set not extracted (run scripts/setup.sh)";
  for (const auto& source : cgal_cad_models(default_cad_data_dir())) {
    SCOPED_TRACE(source.name);
    const auto model = prepare_cad_model(source);
    EXPECT_TRUE(find_boundary_loops(model->mesh).empty());
    EXPECT_GT(model->features.segmentation.region_count, 3);
    EXPECT_FALSE(model->features.chains.empty());
    // The remeshing target is 1 % of the diagonal.
    double length = 0.0;
    for (auto e : model->mesh.edges())
      length += model->mesh.calc_edge_length(e);
    const double mean = length / model->mesh.n_edges() / model->diagonal;
    EXPECT_GT(mean, 0.004);
    EXPECT_LT(mean, 0.02);
  }
}

// Fandisk (Hoppe): its creases are sharp edges of both kinds.
TEST(CadModels, FandiskHasConvexAndReflexCreasesAndEveryTargetMakesAValidCase) {
  if (!cad_data_present())
    GTEST_SKIP() << "CGAL data set not extracted (run scripts/setup.sh)";
  CatalogOptions options;
  const CaseCatalog catalog(options);
  int cases = 0;
  for (const auto& d : catalog.cases()) {
    if (d.id.rfind("cad/fandisk/", 0) != 0)
      continue;
    SCOPED_TRACE(d.id);
    const Case c = catalog.make(d.id);
    EXPECT_FALSE(c.holes[0].removed_faces.empty());
    EXPECT_EQ(c.input.n_faces() + c.holes[0].removed_faces.size(), c.complete.n_faces());
    EXPECT_GE(find_boundary_loops(c.input).size(), 1u);
    ++cases;
  }
  EXPECT_GE(cases, 14);  // face, both edges, corners, multi, curved, island x 2 sizes
  bool convex = false, reflex = false;
  for (const auto& d : catalog.cases()) {
    convex |= d.id == "cad/fandisk/edge_convex/small";
    reflex |= d.id == "cad/fandisk/edge_reflex/small";
  }
  EXPECT_TRUE(convex && reflex);
}

}  // namespace
}  // namespace holebench::generators
