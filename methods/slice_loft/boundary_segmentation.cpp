#include "methods/slice_loft/boundary_segmentation.h"

#include "core/region_segmentation.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace holebench::slice_loft {
namespace {

double dihedral_degrees_0_360(const Mesh& mesh, OpenMesh::EdgeHandle e) {
  double angle = signed_dihedral_angle(mesh, OpenMesh::make_smart(e, mesh)) * 180.0 / M_PI;
  return angle < 0.0 ? angle + 360.0 : angle;
}

struct Run {
  int region;
  std::vector<HalfedgeHandle> halfedges;
};

// The region-boundary edge at v between regions a and b (or the sharpest one at v).
OpenMesh::EdgeHandle region_edge_at(const Mesh& mesh, VertexHandle v,
                                    const std::vector<int>& face_region, int a, int b,
                                    const BoundarySegmentationOptions& options) {
  OpenMesh::EdgeHandle best, matching;
  double best_sharpness = -1.0;
  for (auto h : mesh.voh_range(v)) {
    const auto e = h.edge();
    if (mesh.is_boundary(e) || !is_region_boundary_edge(mesh, e, options))
      continue;
    const double angle = dihedral_degrees_0_360(mesh, e);
    const double sharpness = std::min(angle, 360.0 - angle);
    const int r0 = face_region[h.face().idx()], r1 = face_region[h.opp().face().idx()];
    if ((r0 == a && r1 == b) || (r0 == b && r1 == a)) {
      if (!matching.is_valid() || sharpness > best_sharpness)
        matching = e;
    }
    if (sharpness > best_sharpness) {
      best_sharpness = sharpness;
      best = e;
    }
  }
  return matching.is_valid() ? matching : best;
}

}  // namespace

bool is_region_boundary_edge(const Mesh& mesh, OpenMesh::EdgeHandle e,
                             const BoundarySegmentationOptions& options) {
  if (mesh.is_boundary(e))
    return false;
  const double angle = dihedral_degrees_0_360(mesh, e);
  return angle > options.min_threshold_degrees && angle < options.max_threshold_degrees;
}

std::vector<int> segment_mesh_regions(const Mesh& mesh,
                                      const BoundarySegmentationOptions& options) {
  // Angles in (MIN, MAX) of [0, 360) are region boundaries: for thresholds symmetric about
  // 180 this is core's unsigned-angle segmentation at MIN (the only case used here).
  SegmentationOptions segmentation;
  segmentation.sharp_angle_degrees =
      std::min(options.min_threshold_degrees, 360.0 - options.max_threshold_degrees);
  std::vector<int> face_region = segment_regions(mesh, segmentation).face_region;
  merge_small_regions(mesh, options.min_region_faces, face_region);
  return face_region;
}

void merge_small_regions(const Mesh& mesh, int min_faces, std::vector<int>& face_region) {
  if (min_faces <= 1)
    return;
  // Smallest first: each small region joins the neighbour it shares the most edges with.
  // Regions are merged through a union-find over region ids.
  std::map<int, std::vector<int>> faces_of;
  for (std::size_t f = 0; f < face_region.size(); ++f)
    faces_of[face_region[f]].push_back(static_cast<int>(f));
  std::map<int, int> parent;
  std::function<int(int)> root = [&](int r) {
    auto it = parent.find(r);
    if (it == parent.end())
      return r;
    return it->second = root(it->second);
  };
  std::set<std::pair<std::size_t, int>> queue;  // (size, region)
  for (const auto& [r, faces] : faces_of) {
    if (static_cast<int>(faces.size()) < min_faces)
      queue.insert({faces.size(), r});
  }
  while (!queue.empty()) {
    const int r = queue.begin()->second;
    queue.erase(queue.begin());
    std::map<int, int> shared;
    for (int f : faces_of[r]) {
      for (auto h : mesh.fh_range(FaceHandle(f))) {
        const auto g = h.opp().face();
        if (!g.is_valid())
          continue;
        const int other = root(face_region[g.idx()]);
        if (other != r)
          ++shared[other];
      }
    }
    int target = -1, most = 0;
    for (auto [other, n] : shared) {
      if (n > most) {
        target = other;
        most = n;
      }
    }
    if (target < 0)
      continue;  // an isolated component: nothing to join
    auto& into = faces_of[target];
    const bool was_small = static_cast<int>(into.size()) < min_faces;
    if (was_small)
      queue.erase({into.size(), target});
    into.insert(into.end(), faces_of[r].begin(), faces_of[r].end());
    faces_of.erase(r);
    parent[r] = target;
    if (static_cast<int>(into.size()) < min_faces)
      queue.insert({into.size(), target});
  }
  for (int& r : face_region)
    r = root(r);
}

void segment_hole_boundary(const Mesh& mesh, const std::vector<int>& face_region, Hole& hole,
                           const BoundarySegmentationOptions& options) {
  hole.segments.clear();
  std::vector<Run> runs;
  for (auto h : hole.boundary) {
    const int region = face_region[mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx()];
    if (runs.empty() || runs.back().region != region)
      runs.push_back({region, {}});
    runs.back().halfedges.push_back(h);
  }
  auto merge_equal_neighbours = [&] {
    for (std::size_t i = 0; runs.size() > 1 && i < runs.size();) {
      const std::size_t next = (i + 1) % runs.size();
      if (runs[i].region == runs[next].region) {
        if (next == 0) {
          runs[i].halfedges.insert(runs[i].halfedges.end(), runs[0].halfedges.begin(),
                                   runs[0].halfedges.end());
          runs.erase(runs.begin());
        } else {
          runs[i].halfedges.insert(runs[i].halfedges.end(), runs[next].halfedges.begin(),
                                   runs[next].halfedges.end());
          runs.erase(runs.begin() + next);
        }
      } else {
        ++i;
      }
    }
  };
  merge_equal_neighbours();
  // Short runs (noise, a region grazed at one vertex) join the longer neighbour.
  while (runs.size() > 1) {
    std::size_t shortest = 0;
    for (std::size_t i = 1; i < runs.size(); ++i) {
      if (runs[i].halfedges.size() < runs[shortest].halfedges.size())
        shortest = i;
    }
    if (static_cast<int>(runs[shortest].halfedges.size()) >= options.min_segment_edges)
      break;
    const std::size_t prev = (shortest + runs.size() - 1) % runs.size();
    const std::size_t next = (shortest + 1) % runs.size();
    runs[shortest].region = runs[prev].halfedges.size() >= runs[next].halfedges.size()
                                ? runs[prev].region
                                : runs[next].region;
    merge_equal_neighbours();
  }

  for (std::size_t i = 0; i < runs.size(); ++i) {
    Segment segment;
    segment.region = runs[i].region;
    segment.halfedges = runs[i].halfedges;
    for (auto h : segment.halfedges)
      segment.vertices.push_back(mesh.from_vertex_handle(h));
    segment.vertices.push_back(mesh.to_vertex_handle(segment.halfedges.back()));
    segment.start = segment.vertices.front();
    segment.end = segment.vertices.back();
    if (runs.size() > 1) {
      const int prev_region = runs[(i + runs.size() - 1) % runs.size()].region;
      const int next_region = runs[(i + 1) % runs.size()].region;
      segment.start_region_edge =
          region_edge_at(mesh, segment.start, face_region, prev_region, segment.region, options);
      segment.end_region_edge =
          region_edge_at(mesh, segment.end, face_region, segment.region, next_region, options);
    }
    hole.segments.push_back(std::move(segment));
  }
  hole.type = hole.segments.size() <= 1   ? HoleType::SingleSegment
              : hole.segments.size() == 2 ? HoleType::MultiSegmentOrdinary
                                          : HoleType::MultiSegmentCorner;
}

}  // namespace holebench::slice_loft
