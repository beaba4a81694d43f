// The input faces a repair kept, against a brute-force search over every pair of faces.
#include "metrics/kept_faces.h"

#include "core/mesh_builder.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace holebench {
namespace {

std::array<int, 3> corners(const Mesh& mesh, FaceHandle f) {
  std::array<int, 3> ids{};
  int k = 0;
  for (auto v : mesh.fv_range(f))
    ids[k++] = v.idx();
  return ids;
}

TriangleSoup soup_of(const Mesh& mesh) {
  TriangleSoup soup;
  for (auto v : mesh.vertices())
    soup.points.push_back(mesh.point(v));
  for (auto f : mesh.faces())
    soup.triangles.push_back(corners(mesh, f));
  return soup;
}

// The definition, face by face: a repaired face is kept when an input face has its vertex
// indices in the same order, every vertex at the same point; the first such face, once.
KeptFaces brute_force(const Mesh& input, const Mesh& repaired) {
  KeptFaces kept;
  kept.repaired_face_of_input.assign(input.n_faces(), -1);
  kept.input_face_of_repaired.assign(repaired.n_faces(), -1);
  int last = -1;
  for (auto f : repaired.faces()) {
    const auto ids = corners(repaired, f);
    for (auto g : input.faces()) {
      const bool same = corners(input, g) == ids && std::all_of(ids.begin(), ids.end(), [&](int i) {
                          return static_cast<std::size_t>(i) < input.n_vertices() &&
                                 input.point(VertexHandle(i)) == repaired.point(VertexHandle(i));
                        });
      if (!same)
        continue;
      if (kept.repaired_face_of_input[g.idx()] < 0) {
        kept.repaired_face_of_input[g.idx()] = f.idx();
        kept.input_face_of_repaired[f.idx()] = g.idx();
        kept.order_kept = kept.order_kept && g.idx() > last;
        last = g.idx();
      }
      break;
    }
  }
  return kept;
}

void expect_same(const KeptFaces& a, const KeptFaces& b) {
  EXPECT_EQ(a.repaired_face_of_input, b.repaired_face_of_input);
  EXPECT_EQ(a.input_face_of_repaired, b.input_face_of_repaired);
  EXPECT_EQ(a.order_kept, b.order_kept);
}

// A patch appended after the input's faces, as most methods return it: every input face
// kept at its own index, in order.
TEST(KeptFaces, AppendedPatchKeepsEveryInputFace) {
  const Case c = generators::make_case("box/corner");
  TriangleSoup soup = soup_of(c.input);
  // A triangle on a boundary halfedge of the hole (u -> v, no face yet).
  HalfedgeHandle h;
  for (auto e : c.input.halfedges())
    if (c.input.is_boundary(e)) {
      h = e;
      break;
    }
  const int a = c.input.from_vertex_handle(h).idx(), b = c.input.to_vertex_handle(h).idx();
  const Point edge = soup.points[b] - soup.points[a];
  Point aside = OpenMesh::cross(edge, Point(1, 2, 3));
  aside *= 0.1 * edge.norm() / aside.norm();
  soup.points.push_back((soup.points[a] + soup.points[b]) / 2.0 + aside);
  soup.triangles.push_back({a, b, static_cast<int>(soup.points.size()) - 1});
  const Mesh repaired = build_mesh(soup);
  const KeptFaces kept = kept_faces(c.input, repaired);
  for (auto f : c.input.faces())
    EXPECT_EQ(kept.repaired_face_of_input[f.idx()], f.idx());
  EXPECT_EQ(kept.input_face_of_repaired.back(), -1);
  EXPECT_TRUE(kept.order_kept);
  expect_same(kept, brute_force(c.input, repaired));
}

// The lists of faces not kept, from the maps.
void expect_lists(const KeptFaces& kept) {
  std::vector<int> repaired_not_kept, input_not_kept;
  for (std::size_t f = 0; f < kept.input_face_of_repaired.size(); ++f) {
    if (kept.input_face_of_repaired[f] < 0)
      repaired_not_kept.push_back(static_cast<int>(f));
  }
  for (std::size_t f = 0; f < kept.repaired_face_of_input.size(); ++f) {
    if (kept.repaired_face_of_input[f] < 0)
      input_not_kept.push_back(static_cast<int>(f));
  }
  EXPECT_EQ(kept.repaired_faces_not_kept, repaired_not_kept);
  EXPECT_EQ(kept.input_faces_not_kept, input_not_kept);
}

// Faces added to a copy of the input, as most methods repair: shown kept in place from the
// connectivity arrays, the same maps as the definition's.
TEST(KeptFaces, FacesAddedToACopyKeepTheInputInPlace) {
  for (const char* id : {"box/corner", "brep/weak/multiple-inner-boundaries/small"}) {
    const Case c = generators::make_case(id);
    Mesh repaired = c.input;
    for (auto h : c.input.halfedges()) {
      if (!c.input.is_boundary(h))
        continue;
      const Point middle = (c.input.point(c.input.from_vertex_handle(h)) +
                            c.input.point(c.input.to_vertex_handle(h))) *
                           0.5;
      const VertexHandle apex = repaired.add_vertex(middle + Point(0.01, 0.02, 0.03));
      repaired.add_face(c.input.from_vertex_handle(h), c.input.to_vertex_handle(h), apex);
      break;
    }
    ASSERT_EQ(repaired.n_faces(), c.input.n_faces() + 1) << id;
    const KeptFaces kept = kept_faces(c.input, repaired);
    EXPECT_TRUE(kept.appends_to_input()) << id;
    EXPECT_TRUE(kept.every_input_face_kept()) << id;
    EXPECT_EQ(kept.repaired_faces_not_kept, std::vector<int>{static_cast<int>(c.input.n_faces())});
    expect_same(kept, brute_force(c.input, repaired));
    expect_lists(kept);
  }
}

// An input face deleted and added again after the others (the same corners, a new index):
// not in place, found at its new index all the same; a moved vertex: nothing on it kept.
TEST(KeptFaces, AFaceAddedAgainOrAVertexMovedIsNotInPlace) {
  const Case c = generators::make_case("box/corner");
  Mesh again = c.input;
  again.request_face_status();
  again.request_edge_status();
  again.request_vertex_status();
  const FaceHandle face(5);
  const auto corners = triangle_vertex_indices(again, face);
  again.delete_face(face, false);
  again.add_face(VertexHandle(corners[0]), VertexHandle(corners[1]), VertexHandle(corners[2]));
  const KeptFaces kept = kept_faces(c.input, again);
  EXPECT_FALSE(kept.input_faces_in_place);
  EXPECT_FALSE(kept.appends_to_input());
  EXPECT_EQ(kept.repaired_face_of_input[5], static_cast<int>(c.input.n_faces()));
  expect_same(kept, brute_force(c.input, again));
  expect_lists(kept);

  Mesh moved = c.input;
  moved.point(VertexHandle(0)) += Point(0, 0, 1e-9);
  const KeptFaces moved_kept = kept_faces(c.input, moved);
  EXPECT_FALSE(moved_kept.appends_to_input());
  EXPECT_FALSE(moved_kept.input_vertices_kept);
  expect_same(moved_kept, brute_force(c.input, moved));
  expect_lists(moved_kept);
}

// The input's faces in reverse order, one rotated and one vertex moved: the faces not at
// their own index are found all the same, the rotated and the moved ones are not kept.
TEST(KeptFaces, ReorderedFacesAreFoundAndChangedOnesAreNot) {
  const Case c = generators::make_case("box/corner");
  TriangleSoup soup = soup_of(c.input);
  std::reverse(soup.triangles.begin(), soup.triangles.end());
  auto& rotated = soup.triangles[3];
  rotated = {rotated[1], rotated[2], rotated[0]};
  soup.points[soup.triangles[10][0]] += Point(0, 0, 1e-9);
  const Mesh repaired = build_mesh(soup);
  const KeptFaces kept = kept_faces(c.input, repaired);
  EXPECT_FALSE(kept.order_kept);
  EXPECT_EQ(kept.input_face_of_repaired[3], -1);
  EXPECT_EQ(kept.input_face_of_repaired[10], -1);
  EXPECT_EQ(kept.input_face_of_repaired[20], static_cast<int>(c.input.n_faces()) - 21);
  expect_same(kept, brute_force(c.input, repaired));
}

}  // namespace
}  // namespace holebench
