// Tessellation of planar polyhedra: watertight, one region per face, faces flat and
// outward, areas preserved, edges about `spacing` long, deterministic.
#include "generators/brep/polyhedron.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "core/mesh_builder.h"
#include "generators/brep/brep_models.h"
#include "generators/brep/voxel_solid.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace holebench::generators::brep {
namespace {

struct NamedModel {
  std::string name;
  std::function<Polyhedron()> make;
};

std::vector<NamedModel> closed_models() {
  return {{"box", make_box_model},
          {"corner_notch", make_corner_notch_model},
          {"block_on_plate", make_block_on_plate_model},
          {"pocket", make_pocket_model},
          {"tunnel", make_tunnel_model},
          {"bridge", make_bridge_model},
          {"tunnel_rib", make_tunnel_rib_model},
          {"beam_rib", make_beam_rib_model},
          {"corner_frames", [] { return make_corner_frames_model(false); }},
          {"corner_frames_reflex", [] { return make_corner_frames_model(true); }},
          {"notch_frames", [] { return make_notch_frames_model(false); }},
          {"notch_frames_reflex", [] { return make_notch_frames_model(true); }},
          {"twisted", make_twisted_model},
          {"triangular_prism", make_triangular_prism_model},
          {"pyramid5", [] { return make_pyramid_model(5); }}};
}

// Closed solids of genus 0 have chi = 2; the tunnel, the bridge and the two rib models (a
// tunnel through the rib, a beam from the pocket rim to the rib) have genus 1: chi = 0; the
// frame models (three frames joined at their tongues: a thickened sphere with four holes)
// have genus 3: chi = -4.
int expected_euler(const std::string& name) {
  if (name.rfind("corner_frames", 0) == 0 || name.rfind("notch_frames", 0) == 0)
    return -4;
  return name == "tunnel" || name == "bridge" || name == "tunnel_rib" || name == "beam_rib" ? 0 : 2;
}

TEST(Polyhedron, TessellationOfAClosedSolidIsWatertightWithOneRegionPerFace) {
  for (const auto& model : closed_models()) {
    SCOPED_TRACE(model.name);
    const Polyhedron polyhedron = model.make();
    const Mesh mesh = tessellate(polyhedron, {0.5});
    EXPECT_TRUE(find_boundary_loops(mesh).empty());
    const int euler = static_cast<int>(mesh.n_vertices()) - static_cast<int>(mesh.n_edges()) +
                      static_cast<int>(mesh.n_faces());
    EXPECT_EQ(euler, expected_euler(model.name));
    EXPECT_EQ(region_count(mesh), static_cast<int>(polyhedron.faces.size()));
  }
}

TEST(Polyhedron, TrianglesLieFlatInTheirFaceWithItsOutwardNormal) {
  for (const auto& model : closed_models()) {
    SCOPED_TRACE(model.name);
    const Polyhedron polyhedron = model.make();
    const Mesh mesh = tessellate(polyhedron, {0.5});
    for (auto f : mesh.faces()) {
      const PlanarFace& face = polyhedron.faces[region(mesh, f)];
      const Point n = face_normal(face);
      EXPECT_GT(OpenMesh::dot(holebench::face_normal(mesh, f), n), 1.0 - 1e-9);
      for (auto v : f.vertices())
        EXPECT_NEAR(OpenMesh::dot(mesh.point(v) - face.outer[0], n), 0.0, 1e-9);
    }
  }
}

TEST(Polyhedron, AreaPerRegionEqualsThePolygonArea) {
  for (const auto& model : closed_models()) {
    SCOPED_TRACE(model.name);
    const Polyhedron polyhedron = model.make();
    const Mesh mesh = tessellate(polyhedron, {0.5});
    std::vector<double> area(polyhedron.faces.size(), 0.0);
    for (auto f : mesh.faces())
      area[region(mesh, f)] += holebench::face_area(mesh, f);
    for (std::size_t i = 0; i < area.size(); ++i)
      EXPECT_NEAR(area[i], face_area(polyhedron.faces[i]), 1e-9 * (1.0 + area[i]));
  }
}

// Boundary edges are exactly spacing long on unit cells; interior edges come from a
// hexagonal lattice of that spacing, shortened by at most the boundary clearance.
TEST(Polyhedron, EdgeLengthsAreAboutTheSpacing) {
  const double spacing = 0.25;
  const Mesh mesh = tessellate(make_corner_notch_model(), {spacing});
  double shortest = HUGE_VAL, longest = 0.0, sum = 0.0;
  for (auto e : mesh.edges()) {
    const double length = mesh.calc_edge_length(e);
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
    sum += length;
  }
  EXPECT_GT(shortest, 0.3 * spacing);
  EXPECT_LT(longest, 1.7 * spacing);
  EXPECT_NEAR(sum / mesh.n_edges(), spacing, 0.15 * spacing);
}

TEST(Polyhedron, SameInputGivesTheSameBytes) {
  const auto a = to_soup(tessellate(make_tunnel_model(), {0.3}));
  const auto b = to_soup(tessellate(make_tunnel_model(), {0.3}));
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(a.points[i][c], b.points[i][c]);
  }
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.regions, b.regions);
}

TEST(Polyhedron, AnOpenModelTessellatesWithItsBoundary) {
  Polyhedron open = make_box_model();
  open.faces.pop_back();  // the +z face
  const Mesh mesh = tessellate(open, {0.5});
  EXPECT_EQ(find_boundary_loops(mesh).size(), 1u);
}

TEST(VoxelSolid, FacesGetInnerLoopsAroundPocketsAndBlocks) {
  // The pocket's opening is an inner loop of the plate's top (z = 3).
  const Polyhedron pocket = make_pocket_model();
  int with_inner = 0;
  for (const auto& face : pocket.faces)
    with_inner += face.inner.empty() ? 0 : 1;
  EXPECT_EQ(with_inner, 1);
  EXPECT_EQ(pocket.faces.size(), 6u + 5u);  // plate: 6; pocket: floor and 4 walls
}

TEST(VoxelSolid, CellsTouchingAlongAnEdgeAreRejected) {
  VoxelSolid solid({2, 2, 1});
  solid.fill({0, 0, 0}, {1, 1, 1}).fill({1, 1, 0}, {2, 2, 1});
  EXPECT_THROW(to_polyhedron(solid), std::invalid_argument);
}

TEST(PolyhedronTopology, FacesAroundABoxCornerAreCounterClockwiseFromOutside) {
  const Polyhedron box = make_box_model();
  const PolyhedronTopology topology(box);
  const auto edges = topology.edges_around(Point(6, 6, 6));
  ASSERT_EQ(edges.size(), 3u);
  // Seen from (1, 1, 1), +x -> +y -> +z is counter-clockwise.
  const Point n0 = topology.normal(edges[0].face), n1 = topology.normal(edges[1].face);
  EXPECT_GT(OpenMesh::dot(OpenMesh::cross(n0, n1), Point(1, 1, 1)), 0.0);
  for (const auto& edge : edges)
    EXPECT_EQ(topology.convexity(topology.previous(edge)), Convexity::Convex);
}

}  // namespace
}  // namespace holebench::generators::brep
