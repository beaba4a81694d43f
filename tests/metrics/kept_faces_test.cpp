// The input faces a repair kept, against a brute-force search over every pair of faces.
#include "metrics/kept_faces.h"

#include "core/mesh_builder.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

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
