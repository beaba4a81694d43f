#include "metrics/hausdorff_distance.h"

#include "core/distances.h"
#include "core/geometry.h"
#include "metrics/cell_queue.h"
#include "metrics/cell_table.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/growing_box.h"
#include "metrics/shared_faces.h"
#include "metrics/triangle_cell.h"
#include "metrics/triangle_geometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace holebench {
namespace {

// The parts of a cell's bound (DirectedSearch::bound_of) that do not depend on how much is
// settled: bound (ii) then (i) with the matching face and at the corners, each of the three
// shared-edge bounds (iii) (infinity where its two faces do not qualify), and the centroid's
// distance with the single-triangle bound of its nearest face (infinity where it has none).
struct BoundSteps {
  double corners = 0.0;
  std::array<double, 3> shared_edge{};
  double centroid_distance = 0.0;
  double centroid_triangle = 0.0;
};

// A cell's recorded steps and the box of what they read of B0 beyond its corners' nearest
// faces: the ball its centroid's query read and the corners' nearest vertices.
struct RecordedCell {
  BoundSteps steps;
  GrowingBox reach;
};

}  // namespace

struct HausdorffCellBounds::Table {
  CellTable<RecordedCell> cells;
};

namespace {

class DirectedSearch {
 public:
  DirectedSearch(const embree::TriangleScene& scene, const HausdorffOptions& options)
      : scene_(scene), options_(options) {}

  DirectedHausdorff run(const Mesh& a, const KnownDistances& known,
                        const HausdorffCellBounds* first, const SurfaceChange* change) {
    // Corner distances of the original triangles are shared through the vertices.
    VertexDistances computed;
    const VertexDistances& vertices = vertex_distances(a, scene_, known, computed);
    result_.queries += computed.queries;
    for (double d : vertices.distance)
      result_.lower = std::max(result_.lower, d);
    std::vector<TriangleCell> initial;
    std::vector<int> initial_faces;  // the face of A of each first cell
    if (known.unshared_faces) {
      initial.reserve(known.unshared_faces->size());
      initial_faces = *known.unshared_faces;
      for (int f : *known.unshared_faces)
        initial.push_back(face_cell(a, FaceHandle(f), vertices));
    } else {
      initial.reserve(a.n_faces());
      initial_faces.reserve(a.n_faces());
      for (auto f : a.faces()) {
        if (known.b_face_of_a && (*known.b_face_of_a)[f.idx()] >= 0)
          continue;  // lies on B: distance zero everywhere
        initial.push_back(face_cell(a, f, vertices));
        initial_faces.push_back(f.idx());
      }
    }
    // The first cells' queries in parallel, queued in face order (the same queue, and so
    // the same result, whatever the number of threads).
    std::vector<Bound> bounds(initial.size());
    const double settled_now = settled();  // from the vertices: only grows afterwards
    // A cell that `first` holds (the same cell against the same B, or against a B0 that B
    // equals where the cell's steps read it) replays its recorded steps: the same bound as
    // bound_of() gives, without its queries.
    const HausdorffCellBounds::Table* table = first ? &first->table() : nullptr;
    std::vector<char> taken(initial.size(), 0);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, initial.size(), 256), [&](const auto& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) {
            if (table) {
              if (const RecordedCell* recorded =
                      find_against(table->cells, initial[i], initial_faces[i], change)) {
                RecordedSteps steps{recorded->steps};
                bounds[i] = bound_by_steps(initial[i], settled_now, steps);
                taken[i] = 1;
                continue;
              }
            }
            bounds[i] = bound_of(initial[i], settled_now);
          }
        });
    result_.cells_taken = static_cast<std::size_t>(std::count(taken.begin(), taken.end(), char{1}));
    // Queued all at once, in face order; the settled ones only leave their bound.
    for (std::size_t i = 0; i < initial.size(); ++i)
      prepare(initial[i], bounds[i]);
    const auto settled_cell = [this](const TriangleCell& cell) {
      if (cell.priority > settled())
        return false;
      settled_upper_ = std::max(settled_upper_, cell.priority);
      return true;
    };
    initial.erase(std::remove_if(initial.begin(), initial.end(), settled_cell), initial.end());
    queue_.start(std::move(initial));
    // Split the cell with the largest upper bound until none is above the largest distance
    // found plus the error bound.
    const bool bound_met = refine_largest_first(
        queue_,
        [this](const TriangleCell& top) {
          return top.priority <= result_.lower + options_.error_bound;
        },
        [this] { return result_.queries >= options_.max_queries; },
        [this](const TriangleCell& cell) { split(cell); });
    if (!bound_met)
      result_.converged = false;
    result_.upper =
        std::max({result_.lower, settled_upper_, queue_.empty() ? 0.0 : queue_.top().priority});
    return result_;
  }

 private:
  // `bound`: an upper bound on the answer (Lipschitz from a point already measured).
  embree::ClosestPoint query(const Point& p, double bound) {
    ++result_.queries;
    const auto closest = scene_.closest_point(p, bound);
    result_.lower = std::max(result_.lower, closest.distance);
    return closest;
  }

  // The largest distance from the cell's corners to triangle `face` of B: an upper bound
  // of d(., B) over the cell, since the distance to one triangle is convex. It stops at the
  // first corner at least `cap` away and returns that corner's distance: min(cap, bound) is
  // cap either way.
  // `first`: the corner taken first (the value is the same whatever the order; the nearest
  // face of corner i is best tried from another corner, which is likelier to stop early).
  double single_triangle_bound(const std::array<Point, 3>& corners, int face,
                               double cap = std::numeric_limits<double>::infinity(),
                               int first = 0) const {
    return single_triangle_bound(corners, scene_.triangle_of_face(face), cap, first);
  }
  static double single_triangle_bound(const std::array<Point, 3>& corners,
                                      const std::array<Point, 3>& t, double cap, int first = 0) {
    double bound = 0.0;
    for (int k = 0; k < 3; ++k) {
      bound = std::max(bound, point_triangle_distance(corners[(first + k) % 3], t));
      if (bound >= cap)
        break;
    }
    return bound;
  }

 public:
  // For each corner of the cell, the vertex of B nearest to it among its nearest face's
  // (ties: the smaller point, coordinate by coordinate, whatever the face's vertex order);
  // none where a corner has no nearest face.
  std::optional<std::array<VertexHandle, 3>> nearest_vertices(const TriangleCell& cell) const {
    const Mesh& b = scene_.mesh();
    const Point* points = b.points();
    std::array<VertexHandle, 3> nearest;
    for (int i = 0; i < 3; ++i) {
      if (cell.corner_face[i] < 0)
        return std::nullopt;
      double best = std::numeric_limits<double>::infinity();
      auto h = b.halfedge_handle(FaceHandle(cell.corner_face[i]));
      for (int c = 0; c < 3; ++c, h = b.next_halfedge_handle(h)) {
        const VertexHandle v = b.to_vertex_handle(h);
        const Point& p = points[v.idx()];
        const double d = (p - cell.corners[i]).sqrnorm();
        if (d < best || (d == best && p < points[nearest[i].idx()])) {
          best = d;
          nearest[i] = v;
        }
      }
    }
    return nearest;
  }

 private:
  // The face of B whose corners are `vertices` (the smaller index where both sides of their
  // first edge are), or -1: a face on the edge from the first vertex to the second whose third
  // corner is the third vertex (OpenMesh keeps one edge per pair of vertices).
  int face_of_vertices(const std::array<VertexHandle, 3>& vertices) const {
    if (vertices[0] == vertices[1] || vertices[1] == vertices[2] || vertices[2] == vertices[0])
      return -1;
    const Mesh& b = scene_.mesh();
    const HalfedgeHandle h = b.find_halfedge(vertices[0], vertices[1]);
    if (!h.is_valid())
      return -1;
    int found = -1;
    for (const HalfedgeHandle side : {h, b.opposite_halfedge_handle(h)}) {
      const FaceHandle f = b.face_handle(side);
      if (f.is_valid() && !b.status(f).deleted() &&
          b.to_vertex_handle(b.next_halfedge_handle(side)) == vertices[2] &&
          (found < 0 || f.idx() < found))
        found = f.idx();
    }
    return found;
  }

  // Bound (i) with the matching face: the face of B spanned by the corners' nearest vertices
  // (nearest_vertices()), where B has one. Where B is A moved or perturbed by less than its edges
  // (a noisy input against its complete model, a remeshed copy), it is the copy of the cell's face
  // and bounds the cell within the perturbation, where the corners' nearest faces (around the
  // copies of its corners) leave a bound of the order of its size. Infinity where there is none.
  double matching_face_bound(const TriangleCell& cell, double cap) const {
    const auto vertices = nearest_vertices(cell);
    if (!vertices)
      return std::numeric_limits<double>::infinity();
    const int face = face_of_vertices(*vertices);
    if (face < 0)
      return std::numeric_limits<double>::infinity();
    return single_triangle_bound(cell.corners, face_corners(scene_.mesh(), FaceHandle(face)), cap);
  }

  // Bound (iii): two triangles of B that share an edge (the same two points, bit for bit)
  // and lie nearly in one plane, as on a flat part of B triangulated otherwise than A. Their
  // union projected onto the first one's plane P is a quadrilateral Q; where Q is convex,
  // the distance to Q is convex, so its maximum over the cell is at a corner. Every point of
  // Q lies within delta of the second triangle or is a point of the first (delta: the second
  // triangle's third vertex from P), so d(x, B) <= d(x, Q) + delta. Without it, a cell that
  // straddles the shared edge is split until it is within the error bound of the edge,
  // which on a flat region triangulated otherwise takes cells along every such edge.
  // Infinity where the two triangles do not qualify.
  // Where the bound reaches `cap` before every corner is taken, a value at least `cap`:
  // min(cap, bound) is then cap either way.
  double shared_edge_bound(const std::array<Point, 3>& corners, int face1, int face2,
                           double cap = std::numeric_limits<double>::infinity()) const {
    const auto& t1 = scene_.triangle_of_face(face1);
    const auto& t2 = scene_.triangle_of_face(face2);
    constexpr double kNone = std::numeric_limits<double>::infinity();
    // The shared edge (a, b) and the third vertices p of t1 and q of t2.
    int shared1[2], shared2[2], count = 0;
    for (int i = 0; i < 3 && count <= 2; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (t1[i] == t2[j]) {
          if (count < 2) {
            shared1[count] = i;
            shared2[count] = j;
          }
          ++count;
        }
      }
    }
    if (count != 2)
      return kNone;
    const Point& a = t1[shared1[0]];
    const Point& b = t1[shared1[1]];
    const Point& p = t1[3 - shared1[0] - shared1[1]];
    const Point& q = t2[3 - shared2[0] - shared2[1]];
    Point n = OpenMesh::cross(b - a, p - a);
    const double twice_area = n.norm();
    if (!(twice_area > 0.0))
      return kNone;
    n /= twice_area;
    const double height = OpenMesh::dot(q - a, n);
    const double delta = std::abs(height);
    const Point q_on_plane = q - height * n;
    // Convex: p and q' strictly on either side of the line ab, and a and b of the line pq'
    // (each orientation well clear of rounding: 1e-9 of its scale).
    const double scale =
        std::max({(b - a).sqrnorm(), (p - a).sqrnorm(), (q_on_plane - a).sqrnorm()});
    const auto side = [&n](const Point& o, const Point& u, const Point& v) {
      return OpenMesh::dot(OpenMesh::cross(u - o, v - o), n);
    };
    const double clear = 1e-9 * scale;
    const double s1 = side(a, b, p), s2 = side(a, b, q_on_plane);
    const double s3 = side(p, q_on_plane, a), s4 = side(p, q_on_plane, b);
    if (!((s1 > clear && s2 < -clear) || (s1 < -clear && s2 > clear)) ||
        !((s3 > clear && s4 < -clear) || (s3 < -clear && s4 > clear)))
      return kNone;
    // Plus the rounding of the projection and of the distances (1e-12 of the size).
    const double pad = 1e-12 * std::sqrt(scale);
    double bound = 0.0;
    for (const Point& c : corners) {
      const double to_first = point_triangle_distance(c, t1);
      if (to_first <= bound)
        continue;  // min(to_first, to_second) leaves the largest as it is
      const double to_second = point_triangle_distance(c, {a, b, q_on_plane});
      bound = std::max(bound, std::min(to_first, to_second));
      if (bound + delta + pad >= cap)
        break;  // rounding is monotone: the whole bound is at least this
    }
    return bound + delta + pad;
  }

  // The cell's upper bound and the distance found at its centroid: at most one query, no
  // shared state (the first cells are bounded in parallel). `settled`: a cell whose upper
  // bound is at most this needs no more work (it will never be split), so the centroid
  // query is skipped when a corner's nearest triangle already gives such a bound.
  struct Bound {
    double upper = 0.0;
    double centroid_distance = 0.0;
    bool queried = false;
  };

  Bound bound_of(const TriangleCell& cell, double settled) const {
    LiveSteps steps{*this, cell};
    return bound_by_steps(cell, settled, steps);
  }

 public:
  // Every step of the cell's bound, whatever is settled (HausdorffCellBounds). `centroid`
  // (optional): the answer of the centroid's query, asked before (FirstPass::centroid).
  BoundSteps all_steps(const TriangleCell& cell,
                       const embree::ClosestPoint* centroid = nullptr) const {
    LiveSteps live{*this, cell, -1, centroid};
    BoundSteps steps;
    steps.corners = live.corners();
    for (int i = 0; i < 3; ++i)
      steps.shared_edge[i] = live.shared_edge(i, std::numeric_limits<double>::infinity());
    double cell_upper = steps.corners;
    for (double bound : steps.shared_edge)
      cell_upper = std::min(cell_upper, bound);
    steps.centroid_distance = live.centroid_distance(cell_upper);
    steps.centroid_triangle = live.centroid_triangle(std::numeric_limits<double>::infinity());
    return steps;
  }

 private:
  // The steps computed as bound_by_steps() asks for them.
  struct LiveSteps {
    const DirectedSearch& search;
    const TriangleCell& cell;
    int nearest_face = -1;
    const embree::ClosestPoint* known_centroid = nullptr;  // the centroid's answer, if asked

    // Bound (ii): every point lies within longest edge / sqrt(3) of a corner (the
    // equilateral triangle is the worst case), and the distance is 1-Lipschitz. Then bound
    // (i): the distance to one triangle of B is convex, so its maximum over the cell is at
    // a corner. Candidates: the matching face (first: where it applies it is the tightest,
    // and caps the others' corners), then the triangles nearest to the corners.
    double corners() const {
      const auto& c = cell.corners;
      const auto& d = cell.corner_distance;
      const double longest = std::sqrt(
          std::max({(c[1] - c[0]).sqrnorm(), (c[2] - c[1]).sqrnorm(), (c[0] - c[2]).sqrnorm()}));
      double upper = *std::max_element(d.begin(), d.end()) + longest * 0.57735026919;
      upper = std::min(upper, search.matching_face_bound(cell, upper));
      for (int i = 0; i < 3; ++i) {
        const int face = cell.corner_face[i];
        if (face >= 0 && (i == 0 || face != cell.corner_face[i - 1]))
          upper = std::min(upper, search.single_triangle_bound(c, face, upper, (i + 1) % 3));
      }
      return upper;
    }
    // Bound (iii) of the edge from corner i to the next.
    double shared_edge(int i, double cap) const {
      const int f1 = cell.corner_face[i], f2 = cell.corner_face[(i + 1) % 3];
      if (f1 >= 0 && f2 >= 0 && f1 != f2)
        return search.shared_edge_bound(cell.corners, f1, f2, cap);
      return std::numeric_limits<double>::infinity();
    }
    // The centroid's query, with an upper bound from the corners (1-Lipschitz) and
    // `cell_upper`, an upper bound over the whole cell (the steps before).
    double centroid_distance(double cell_upper) {
      if (known_centroid) {  // the same answer, whatever bound its query had
        nearest_face = known_centroid->face;
        return known_centroid->distance;
      }
      const Point centroid = cell_centroid(cell);
      const auto nearest = search.scene_.closest_point(
          centroid, std::min(cell_upper, distance_bound_from_corners(cell, centroid)));
      nearest_face = nearest.face;
      return nearest.distance;
    }
    // Bound (i) with the triangle nearest to the centroid (see single_triangle_bound's cap).
    double centroid_triangle(double cap) const {
      return nearest_face >= 0 ? search.single_triangle_bound(cell.corners, nearest_face, cap)
                               : std::numeric_limits<double>::infinity();
    }
  };

  // The steps as recorded by all_steps().
  struct RecordedSteps {
    const BoundSteps& steps;
    double corners() const { return steps.corners; }
    double shared_edge(int i, double) const { return steps.shared_edge[i]; }
    double centroid_distance(double) const { return steps.centroid_distance; }
    double centroid_triangle(double) const { return steps.centroid_triangle; }
  };

  // The bound from the steps in order, each only where the bound is not settled yet; a step
  // that does not apply is infinity, which leaves the bound as it is.
  template <class Steps>
  static Bound bound_by_steps(const TriangleCell& cell, double settled, Steps& steps) {
    const auto& d = cell.corner_distance;
    const double largest_corner = *std::max_element(d.begin(), d.end());
    Bound bound;
    bound.upper = steps.corners();
    if (bound.upper <= settled)
      return bound;
    for (int i = 0; i < 3 && bound.upper > settled; ++i)
      bound.upper = std::min(bound.upper, steps.shared_edge(i, bound.upper));
    if (bound.upper <= settled)
      return bound;
    bound.queried = true;
    bound.centroid_distance = steps.centroid_distance(bound.upper);
    if (bound.upper > largest_corner)
      bound.upper = std::min(bound.upper, steps.centroid_triangle(bound.upper));
    return bound;
  }

  double settled() const { return result_.lower + options_.error_bound; }

  // Counts the cell's centroid query and gives it its bound, its priority in the queue.
  void prepare(TriangleCell& cell, const Bound& bound) {
    if (bound.queried) {
      ++result_.queries;
      result_.lower = std::max(result_.lower, bound.centroid_distance);
    }
    cell.priority = bound.upper;
  }

  // A cell whose upper bound is settled will never be split (the largest distance found
  // only grows): only its bound is kept, for the answer's upper end. The queue holds the
  // cells that may still be split, which pop in the same order as among all cells (their
  // order is total), and so the search makes the same cells and the same answer.
  void push(TriangleCell cell) {
    prepare(cell, bound_of(cell, settled()));
    if (cell.priority <= settled()) {
      settled_upper_ = std::max(settled_upper_, cell.priority);
      return;
    }
    queue_.push(std::move(cell));
  }

  // The midpoints queried first (each bounded also by the cell's upper bound, its
  // priority), then each child bounded and queued in turn.
  void split(const TriangleCell& cell) {
    const auto query_midpoint = [this, &cell](const Point& p, double bound) {
      return query(p, std::min(bound, cell.priority));
    };
    for (const TriangleCell& child : split_at_midpoints(cell, query_midpoint))
      push(child);
  }

  const embree::TriangleScene& scene_;
  const HausdorffOptions& options_;
  DirectedHausdorff result_;
  CellQueue<TriangleCell> queue_;  // priority: the cell's upper bound
  double settled_upper_ = 0.0;     // the largest upper bound of the cells left out as settled
};

}  // namespace

DirectedHausdorff directed_hausdorff(const Mesh& a, const embree::TriangleScene& b_scene,
                                     const HausdorffOptions& options, const KnownDistances& known,
                                     const HausdorffCellBounds* first,
                                     const SurfaceChange* change) {
  return DirectedSearch(b_scene, options).run(a, known, first, change);
}

HausdorffCellBounds::HausdorffCellBounds(const Mesh& a0, const embree::TriangleScene& b0_scene,
                                         const FirstPass& first_pass)
    : table_(std::make_unique<Table>()) {
  // The cells as the search makes them: the same first pass over the vertices, the faces
  // lying on B0 left out (the search skips them).
  std::vector<TriangleCell> cells;
  std::vector<int> faces;
  cells.reserve(a0.n_faces());
  faces.reserve(a0.n_faces());
  for (auto f : a0.faces()) {
    if (first_pass.b_face_of_a[f.idx()] < 0) {
      cells.push_back(face_cell(a0, f, first_pass.vertices));
      faces.push_back(f.idx());
    }
  }
  const HausdorffOptions options;  // the steps do not depend on the error bound
  const DirectedSearch search(b0_scene, options);
  std::vector<RecordedCell> recorded(cells.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      recorded[i].steps = search.all_steps(cells[i], &first_pass.centroid[faces[i]]);
      // The centroid's query read the faces of B0 within its distance (as
      // LiveSteps::centroid_distance() places it), padded by 1e-9 of its scale so that a
      // face of B at that distance, up to rounding, meets the ball's box.
      const Point centroid = cell_centroid(cells[i]);
      const double d = recorded[i].steps.centroid_distance;
      const double radius =
          d + 1e-9 * (d + std::abs(centroid[0]) + std::abs(centroid[1]) + std::abs(centroid[2]));
      // The matching face's step read the faces of B0 on the corners' nearest vertices: a
      // face of B on them that B0 lacks (or the other way) lies within their box.
      if (const auto vertices = search.nearest_vertices(cells[i])) {
        for (VertexHandle v : *vertices)
          recorded[i].reach.add(b0_scene.mesh().point(v));
      }
      if (std::isfinite(radius)) {
        recorded[i].reach.add_ball(centroid, radius);
      } else {  // no answer within reach, or no finite point: it read all of B0
        constexpr double kInf = std::numeric_limits<double>::infinity();
        recorded[i].reach.lo = Point(-kInf, -kInf, -kInf);
        recorded[i].reach.hi = Point(kInf, kInf, kInf);
      }
    }
  });
  table_->cells.reserve(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    table_->cells.add(faces[i], key_of(cells[i]), recorded[i]);
}

HausdorffCellBounds::~HausdorffCellBounds() = default;

std::size_t HausdorffCellBounds::size() const {
  return table_->cells.size();
}

HausdorffResult hausdorff_distance(const Mesh& a, const Mesh& b, const HausdorffOptions& options) {
  const SharedFaces shared = shared_faces(a, b);
  HausdorffResult result;
  // Each direction searches A's unshared faces against only the part of B they can reach.
  const auto directed = [&options](const Mesh& from, const Mesh& to,
                                   const std::vector<int>& to_face_of_from,
                                   const std::vector<std::array<int, 3>>& from_corners,
                                   const std::vector<std::array<int, 3>>& to_corners) {
    const auto reachable =
        faces_of_b_within_reach(from, to, to_face_of_from, from_corners, to_corners);
    if (reachable.empty())
      return DirectedHausdorff{};  // every face of `from` lies on `to`
    // Built for this one search: the cheap build pays (SceneBuild).
    const embree::TriangleScene scene(to, reachable, embree::SceneBuild::fast_build);
    KnownDistances known;
    known.b_face_of_a = &to_face_of_from;
    return directed_hausdorff(from, scene, options, known);
  };
  // The two directions are independent: side by side (each gives the same answer alone).
  tbb::parallel_invoke(
      [&] {
        result.a_to_b = directed(a, b, shared.b_face_of_a, shared.a_corners, shared.b_corners);
      },
      [&] {
        result.b_to_a = directed(b, a, shared.a_face_of_b, shared.b_corners, shared.a_corners);
      });
  return result;
}

}  // namespace holebench
