#include "metrics/shared_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace holebench {
namespace {

// A point's exact bits as a hash key (+0.0 and -0.0 differ here; both are the same
// point, so at worst a shared face is missed and searched normally).
struct PointKey {
  std::array<std::uint64_t, 3> bits;
  bool operator==(const PointKey& other) const { return bits == other.bits; }
};

PointKey key_of(const Point& p) {
  PointKey key;
  for (int i = 0; i < 3; ++i)
    std::memcpy(&key.bits[i], &p[i], sizeof(double));
  return key;
}

struct PointKeyHash {
  std::size_t operator()(const PointKey& key) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (auto word : key.bits) {
      h ^= word + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
      h *= 0xBF58476D1CE4E5B9ull;
    }
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

// B's face with the three vertices (any orientation), or -1.
int face_with_vertices(const Mesh& b, VertexHandle v0, VertexHandle v1, VertexHandle v2) {
  for (auto h : {b.find_halfedge(v0, v1), b.find_halfedge(v1, v0)}) {
    if (!h.is_valid() || b.is_boundary(h))
      continue;
    if (b.to_vertex_handle(b.next_halfedge_handle(h)) == v2)
      return b.face_handle(h).idx();
  }
  return -1;
}

}  // namespace

SharedFaces shared_faces(const Mesh& a, const Mesh& b) {
  SharedFaces result;
  result.b_face_of_a.assign(a.n_faces(), -1);
  result.a_face_of_b.assign(b.n_faces(), -1);
  std::unordered_map<PointKey, int, PointKeyHash> vertex_of_point;
  vertex_of_point.reserve(2 * b.n_vertices());
  for (auto v : b.vertices())
    vertex_of_point.emplace(key_of(b.point(v)), v.idx());
  for (auto f : a.faces()) {
    std::array<VertexHandle, 3> corners;
    int k = 0;
    bool all_found = true;
    for (auto v : f.vertices()) {
      const auto it = vertex_of_point.find(key_of(a.point(v)));
      if (it == vertex_of_point.end()) {
        all_found = false;
        break;
      }
      corners[k++] = b.vertex_handle(it->second);
    }
    if (!all_found)
      continue;
    const int match = face_with_vertices(b, corners[0], corners[1], corners[2]);
    if (match < 0 || result.a_face_of_b[match] >= 0)
      continue;
    result.b_face_of_a[f.idx()] = match;
    result.a_face_of_b[match] = f.idx();
    ++result.count;
  }
  return result;
}

std::vector<int> faces_of_b_within_reach(const Mesh& a, const Mesh& b,
                                         const std::vector<int>& b_face_of_a) {
  Point lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  bool any_unshared = false;
  std::vector<char> on_shared_face(a.n_vertices(), 0);
  for (auto f : a.faces()) {
    const bool shared = b_face_of_a[f.idx()] >= 0;
    for (auto v : f.vertices()) {
      if (shared) {
        on_shared_face[v.idx()] = 1;
      } else {
        lo.minimize(a.point(v));
        hi.maximize(a.point(v));
      }
    }
    any_unshared = any_unshared || !shared;
  }
  std::vector<int> faces;
  if (!any_unshared)
    return faces;
  // The anchor s minimising the farthest distance from the box: R = that distance.
  double reach = std::numeric_limits<double>::infinity();
  for (auto v : a.vertices()) {
    if (!on_shared_face[v.idx()])
      continue;
    const Point& s = a.point(v);
    double farthest2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = std::max(std::abs(s[i] - lo[i]), std::abs(s[i] - hi[i]));
      farthest2 += d * d;
    }
    reach = std::min(reach, std::sqrt(farthest2));
  }
  const bool bounded = std::isfinite(reach);
  if (bounded) {
    reach *= 1.0 + 1e-9;  // rounding of the sums above
    lo -= Point(reach, reach, reach);
    hi += Point(reach, reach, reach);
  }
  for (auto f : b.faces()) {
    bool meets = true;
    if (bounded) {
      Point flo(std::numeric_limits<double>::infinity()),
          fhi(-std::numeric_limits<double>::infinity());
      for (auto v : f.vertices()) {
        flo.minimize(b.point(v));
        fhi.maximize(b.point(v));
      }
      for (int i = 0; i < 3 && meets; ++i)
        meets = flo[i] <= hi[i] && fhi[i] >= lo[i];
    }
    if (meets)
      faces.push_back(f.idx());
  }
  return faces;
}

}  // namespace holebench
