#include "metrics/shared_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <tbb/parallel_invoke.h>

namespace holebench {
namespace {

// SplitMix64's finaliser: every input bit reaches the low bits the table indexes by (points
// read from single-precision files have their low mantissa bits all zero).
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A point's exact bits hashed (+0.0 and -0.0 differ here; both are the same point, so at
// worst a shared face is missed and searched normally).
std::uint64_t hash_of(const Point& p) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < 3; ++i) {
    std::uint64_t word;
    std::memcpy(&word, &p[i], sizeof(double));
    h = mix(h ^ word);
  }
  return h;
}

bool same_bits(const Point& p, const Point& q) {
  return std::memcmp(&p, &q, sizeof(Point)) == 0;
}

// The vertices of a mesh by their exact points: open addressing with linear probing in a
// power-of-two table at most half full (one flat array, no allocation per entry: these
// lookups run on every evaluation). Of several vertices at one point the lowest index wins.
class VertexOfPoint {
 public:
  explicit VertexOfPoint(const Mesh& mesh) : points_(mesh.points()) {
    std::size_t capacity = 16;
    while (capacity < 2 * mesh.n_vertices())
      capacity *= 2;
    slots_.assign(capacity, -1);
    mask_ = capacity - 1;
    for (int v = 0; v < static_cast<int>(mesh.n_vertices()); ++v) {
      std::size_t slot = hash_of(points_[v]) & mask_;
      while (slots_[slot] >= 0 && !same_bits(points_[slots_[slot]], points_[v]))
        slot = (slot + 1) & mask_;
      if (slots_[slot] < 0)
        slots_[slot] = v;
    }
  }

  /// The vertex at exactly `p`, or -1.
  int find(const Point& p) const {
    for (std::size_t slot = hash_of(p) & mask_; slots_[slot] >= 0; slot = (slot + 1) & mask_) {
      if (same_bits(points_[slots_[slot]], p))
        return slots_[slot];
    }
    return -1;
  }

 private:
  const Point* points_;
  std::vector<int> slots_;
  std::size_t mask_ = 0;
};

// The three corners of every face, by face index, read straight off the halfedges (the
// face-vertex circulator costs several times more, and these loops run on every evaluation).
std::vector<std::array<int, 3>> corners_of_faces(const Mesh& mesh) {
  std::vector<std::array<int, 3>> corners(mesh.n_faces(), {-1, -1, -1});
  for (auto f : mesh.faces()) {
    const auto h0 = mesh.halfedge_handle(f);
    const auto h1 = mesh.next_halfedge_handle(h0);
    const auto h2 = mesh.next_halfedge_handle(h1);
    corners[f.idx()] = {mesh.to_vertex_handle(h0).idx(), mesh.to_vertex_handle(h1).idx(),
                        mesh.to_vertex_handle(h2).idx()};
  }
  return corners;
}

// The faces around each vertex, in increasing face order (compressed rows).
struct FacesOfVertex {
  std::vector<int> offset;  // faces of vertex v: face[offset[v] .. offset[v + 1])
  std::vector<int> face;
};

FacesOfVertex faces_of_vertex(const std::vector<std::array<int, 3>>& corners,
                              std::size_t vertex_count) {
  FacesOfVertex index;
  index.offset.assign(vertex_count + 1, 0);
  for (const auto& c : corners) {
    if (c[0] >= 0) {
      for (int v : c)
        ++index.offset[v + 1];
    }
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    index.offset[v + 1] += index.offset[v];
  index.face.resize(index.offset.back());
  std::vector<int> next(index.offset.begin(), index.offset.end() - 1);
  for (std::size_t f = 0; f < corners.size(); ++f) {
    if (corners[f][0] >= 0) {
      for (int v : corners[f])
        index.face[next[v]++] = static_cast<int>(f);
    }
  }
  return index;
}

// Matches A's face `f` (its corners in B's vertices) to B's face with the same three
// vertices, in either orientation, that no earlier face of A took: the lowest index among the
// faces around the first corner. Such a face holds corners[0] and, B's faces having distinct
// corners, is the same set when it holds the other two and they differ.
void match_face(std::size_t f, const std::array<int, 3>& corners, const FacesOfVertex& b_faces,
                const std::vector<std::array<int, 3>>& b_corners, SharedFaces& result) {
  if (corners[0] < 0 || corners[1] < 0 || corners[2] < 0)
    return;
  if (corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0])
    return;
  int match = -1;
  for (int i = b_faces.offset[corners[0]]; i < b_faces.offset[corners[0] + 1] && match < 0; ++i) {
    const auto& g = b_corners[b_faces.face[i]];
    const auto holds = [&g](int v) { return g[0] == v || g[1] == v || g[2] == v; };
    if (holds(corners[1]) && holds(corners[2]))
      match = b_faces.face[i];
  }
  if (match < 0 || result.a_face_of_b[match] >= 0)
    return;
  result.b_face_of_a[f] = match;
  result.a_face_of_b[match] = static_cast<int>(f);
  ++result.count;
}

}  // namespace

SharedFaces shared_faces(const Mesh& a, const Mesh& b) {
  SharedFaces result;
  result.b_face_of_a.assign(a.n_faces(), -1);
  result.a_face_of_b.assign(b.n_faces(), -1);
  // Side by side: A's vertices mapped to B's vertex at the same point (once per vertex, not
  // per corner); the faces' corners and B's faces around each vertex.
  std::vector<int> b_vertex_of_a(a.n_vertices());
  FacesOfVertex b_faces;
  tbb::parallel_invoke(
      [&] {
        const VertexOfPoint b_vertex_of_point(b);
        for (std::size_t v = 0; v < a.n_vertices(); ++v)
          b_vertex_of_a[v] = b_vertex_of_point.find(a.points()[v]);
      },
      [&] { result.a_corners = corners_of_faces(a); },
      [&] {
        result.b_corners = corners_of_faces(b);
        b_faces = faces_of_vertex(result.b_corners, b.n_vertices());
      });
  const auto& a_corners = result.a_corners;
  const auto& b_corners = result.b_corners;
  for (std::size_t f = 0; f < a_corners.size(); ++f) {
    if (a_corners[f][0] < 0)
      continue;
    std::array<int, 3> corners;
    for (int k = 0; k < 3; ++k)
      corners[k] = b_vertex_of_a[a_corners[f][k]];
    match_face(f, corners, b_faces, b_corners, result);
  }
  return result;
}

struct SharedFacesOfInput::Index {
  Index(const Mesh& input, const Mesh& b) : b_vertex_of_point(b) {
    for (std::size_t v = 0; v < input.n_vertices(); ++v)
      b_vertex_of_input.push_back(b_vertex_of_point.find(input.points()[v]));
    input_shared = shared_faces(input, b);
    b_faces = faces_of_vertex(input_shared.b_corners, b.n_vertices());
  }
  VertexOfPoint b_vertex_of_point;  // points into B's points: B outlives the index
  std::vector<int> b_vertex_of_input;
  SharedFaces input_shared;
  FacesOfVertex b_faces;
};

SharedFacesOfInput::SharedFacesOfInput(const Mesh& input, const Mesh& b)
    : index_(std::make_unique<Index>(input, b)) {}

SharedFacesOfInput::~SharedFacesOfInput() = default;

const SharedFaces& SharedFacesOfInput::of_input() const {
  return index_->input_shared;
}

std::optional<SharedFaces> SharedFacesOfInput::of_repair(const Mesh& repaired,
                                                         const KeptFaces& kept) const {
  const SharedFaces& input = index_->input_shared;
  const std::size_t input_faces = input.b_face_of_a.size();
  const std::size_t input_vertices = index_->b_vertex_of_input.size();
  if (!kept.appends_to_input() || repaired.n_faces() < input_faces ||
      repaired.n_vertices() < input_vertices)
    return std::nullopt;
  // The face maps only: the corners' tables stay the case's (copying two tables of the
  // model's size per job cost more than the matching).
  SharedFaces result;
  result.b_face_of_a = input.b_face_of_a;
  result.b_face_of_a.resize(repaired.n_faces(), -1);
  result.a_face_of_b = input.a_face_of_b;
  result.count = input.count;
  const Point* points = repaired.points();
  for (std::size_t f = input_faces; f < repaired.n_faces(); ++f) {
    const FaceHandle face(static_cast<int>(f));
    if (repaired.status(face).deleted())
      continue;
    const std::array<int, 3> own = triangle_vertex_indices(repaired, face);
    std::array<int, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const int v = own[k];
      corners[k] = static_cast<std::size_t>(v) < input_vertices
                       ? index_->b_vertex_of_input[v]
                       : index_->b_vertex_of_point.find(points[v]);
    }
    match_face(f, corners, index_->b_faces, input.b_corners, result);
  }
  return result;
}

std::vector<int> faces_of_b_within_reach(const Mesh& a, const Mesh& b,
                                         const std::vector<int>& b_face_of_a) {
  return faces_of_b_within_reach(a, b, b_face_of_a, corners_of_faces(a), corners_of_faces(b));
}

std::vector<int> faces_of_b_within_reach(const Mesh& a, const Mesh& b,
                                         const std::vector<int>& b_face_of_a,
                                         const std::vector<std::array<int, 3>>& a_corners,
                                         const std::vector<std::array<int, 3>>& b_corners) {
  Point lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  bool any_unshared = false;
  std::vector<char> on_shared_face(a.n_vertices(), 0);
  const Point* a_points = a.points();
  for (std::size_t f = 0; f < a_corners.size(); ++f) {
    if (a_corners[f][0] < 0)
      continue;
    const bool shared = b_face_of_a[f] >= 0;
    for (int v : a_corners[f]) {
      if (shared) {
        on_shared_face[v] = 1;
      } else {
        lo.minimize(a_points[v]);
        hi.maximize(a_points[v]);
      }
    }
    any_unshared = any_unshared || !shared;
  }
  std::vector<int> faces;
  if (!any_unshared)
    return faces;
  // The anchor s minimising the farthest distance from the box: R = that distance.
  double reach = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < on_shared_face.size(); ++v) {
    if (!on_shared_face[v])
      continue;
    const Point& s = a_points[v];
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
  const Point* b_points = b.points();
  for (std::size_t f = 0; f < b_corners.size(); ++f) {
    if (b_corners[f][0] < 0)
      continue;
    bool meets = true;
    if (bounded) {
      Point flo(std::numeric_limits<double>::infinity()),
          fhi(-std::numeric_limits<double>::infinity());
      for (int v : b_corners[f]) {
        flo.minimize(b_points[v]);
        fhi.maximize(b_points[v]);
      }
      for (int i = 0; i < 3 && meets; ++i)
        meets = flo[i] <= hi[i] && fhi[i] >= lo[i];
    }
    if (meets)
      faces.push_back(static_cast<int>(f));
  }
  return faces;
}

}  // namespace holebench
