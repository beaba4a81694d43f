#include "metrics/mean_search.h"

#include "metrics/cell_queue.h"
#include "metrics/cell_table.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/mean_bounds.h"
#include "metrics/triangle_cell.h"
#include "metrics/triangle_geometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

namespace holebench {
namespace {

// The errors of the estimates from the sums of area-weighted bound widths.
struct Estimate {
  double mean = 0.0, mean_error = 0.0, rms = 0.0, rms_error = 0.0;
  double mean_lower() const { return std::max(0.0, mean - mean_error); }
  double rms_lower() const { return std::max(0.0, rms - rms_error); }
};

Estimate estimate(double area, double sum_mean, double sum_mean_width, double sum_square,
                  double sum_square_width) {
  Estimate e;
  e.mean = sum_mean / area;
  e.mean_error = 0.5 * sum_mean_width / area;
  // The mean square lies in [q - w, q + w]; the RMS in the square roots of that interval.
  const double q = sum_square / area, w = 0.5 * sum_square_width / area;
  const double hi = std::sqrt(std::max(0.0, q + w)), lo = std::sqrt(std::max(0.0, q - w));
  e.rms = 0.5 * (hi + lo);
  e.rms_error = 0.5 * (hi - lo);
  return e;
}

// The error bounds a search ran under: a cell's bounds and steps computed under them are the
// ones another search takes only when it runs under the same.
struct SearchErrorBounds {
  double error_bound = 0.0;
  double relative_error_bound = 0.0;
  static SearchErrorBounds of(const MeanDistanceOptions& options) {
    return {options.error_bound, options.relative_error_bound};
  }
  bool serve(const MeanDistanceOptions& options) const {
    return options.error_bound == error_bound &&
           options.relative_error_bound == relative_error_bound;
  }
};

// What MeanCellBounder::bound() gives a cell, with where it read B0.
struct CellBounds {
  MeanBounds bounds;
  GrowingBox reach;  // the balls of B0 the bounds read: valid where B is B0 in this box
};

}  // namespace

struct MeanCellBounds::Table {
  SearchErrorBounds error_bounds;
  CellTable<CellBounds> cells;
  // The first pass over A0's vertices: each vertex's point and answer, and whether the
  // answer came from a query (not from lying on a face shared with B0).
  std::vector<Point> vertex_points;
  VertexDistances vertices;
  std::vector<char> vertex_queried;
  // Whether a search with `options` bounds a cell as these were bounded.
  bool serves(const MeanDistanceOptions& options) const { return error_bounds.serve(options); }
};

struct MeanSearchSteps::Table {
  bool recorded = false;  // by a search with these error bounds:
  SearchErrorBounds error_bounds;
  // By cell (each a function of the cell's key and of B alone): its first bounds, its
  // bounds after tighten(), and its children (each bounded) after split().
  std::unordered_map<CellKey, MeanBounds, CellKeyHash> bounded;
  std::unordered_map<CellKey, MeanBounds, CellKeyHash> tightened;
  std::unordered_map<CellKey, std::vector<MeanCell>, CellKeyHash> children;
  bool serves(const MeanDistanceOptions& options) const {
    return recorded && error_bounds.serve(options);
  }
};

MeanSearchSteps::MeanSearchSteps() : table_(std::make_unique<Table>()) {}
MeanSearchSteps::~MeanSearchSteps() = default;
std::size_t MeanSearchSteps::size() const {
  return table_->bounded.size() + table_->tightened.size() + table_->children.size();
}

namespace {

class MeanSearch {
 public:
  MeanSearch(const embree::TriangleScene& scene, const MeanDistanceOptions& options)
      : scene_(scene), options_(options), bounder_(scene, options) {}

  // Keeps every cell's first bounds and every refinement step in `steps`, and takes the
  // steps of `replay` for the cells it has (null: none).
  void use_steps(MeanSearchSteps::Table* record, const MeanSearchSteps::Table* replay) {
    if (record) {
      record->recorded = true;
      record->error_bounds = SearchErrorBounds::of(options_);
      record_ = record;
    }
    if (replay && replay->serves(options_))
      replay_ = replay;
  }

  // The first bounds of `cells` (bound()), in parallel (one query each, no shared state),
  // taken from `first` where it holds the same cell and B is its B0 within the cell's reach
  // (`faces`: the face of A of each cell, tried first as A0's). Returns how many came from
  // the replayed steps.
  std::size_t bound_each(std::vector<MeanCell>& cells, const std::vector<int>& faces,
                         const FirstBounds* first) const {
    std::vector<char> done(cells.size(), 0);
    if (first && first->bounds && first->bounds->table().serves(options_)) {
      const auto& table = first->bounds->table().cells;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (const CellBounds* recorded = find_against(table, cells[i], faces[i], &first->change)) {
          cells[i].take_bounds(recorded->bounds);
          done[i] = 1;
        }
      }
    }
    std::size_t replayed = 0;
    if (replay_) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (done[i])
          continue;
        const auto it = replay_->bounded.find(key_of(cells[i]));
        if (it != replay_->bounded.end()) {
          cells[i].take_bounds(it->second);
          done[i] = 1;
          ++replayed;
        }
      }
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 256),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if (!done[i])
                            bounder_.bound(cells[i]);
                        }
                      });
    return replayed;
  }

  // bound() of each cell, with the box of the balls of B its bounds read (the corners'
  // included).
  // `faces`: by cell, its face of A; `centroid`: by face of A, the answer of its cell
  // centroid's query, asked before (FirstPass::centroid).
  void bound_each_with_reach(std::vector<MeanCell>& cells, std::vector<GrowingBox>& reach,
                             const std::vector<int>& faces,
                             const std::vector<embree::ClosestPoint>& centroid) const {
    reach.assign(cells.size(), GrowingBox());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells.size(), 256),
                      [&](const auto& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          for (int k = 0; k < 3; ++k)
                            reach[i].add_ball(cells[i].corners[k], cells[i].corner_distance[k]);
                          bounder_.bound(cells[i], &reach[i], &centroid[faces[i]]);
                        }
                      });
  }

  DirectedMeanDistance run(const Mesh& a, const KnownDistances& known,
                           const FirstBounds* first_bounds) {
    VertexDistances computed;
    const VertexDistances& vertices = vertex_distances(a, scene_, known, computed);
    result_.queries += computed.queries;
    std::vector<MeanCell> initial;
    std::vector<int> initial_faces;  // the face of A of each first cell
    if (known.unshared_faces) {
      // A's area and its faces not on B as the caller knows them (SearchStart).
      total_area_ = known.area;
      initial.reserve(known.unshared_faces->size());
      initial_faces.reserve(known.unshared_faces->size());
      for (int f : *known.unshared_faces) {
        MeanCell cell(face_cell(a, FaceHandle(f), vertices));
        cell.area = triangle_area(cell.corners);
        if (cell.area > 0.0) {
          initial.push_back(std::move(cell));
          initial_faces.push_back(f);
        }
      }
    } else {
      initial.reserve(a.n_faces());
      initial_faces.reserve(a.n_faces());
      for (auto f : a.faces()) {
        MeanCell cell(face_cell(a, f, vertices));
        cell.area = triangle_area(cell.corners);
        if (!(cell.area > 0.0))
          continue;  // a degenerate triangle has no area to integrate
        total_area_ += cell.area;
        if (known.b_face_of_a && (*known.b_face_of_a)[f.idx()] >= 0)
          continue;  // lies on B: contributes zero, exactly
        initial.push_back(std::move(cell));
        initial_faces.push_back(f.idx());
      }
    }
    // The first cells' bounds; queued below in face order, so the result does not depend
    // on the number of threads.
    result_.steps_taken += bound_each(initial, initial_faces, first_bounds);
    if (record_) {
      for (const MeanCell& cell : initial)
        record_->bounded.emplace(key_of(cell), cell.bounds());
    }
    if (total_area_ <= 0.0)
      return result_;
    // The RMS error is about the mean-square error / (2 RMS): the scale that weighs the
    // cells' mean-square widths against their mean widths when choosing what to split.
    double sum_square = 0.0;
    for (const MeanCell& cell : initial)
      sum_square += cell.area * 0.5 * (cell.square_lo + cell.square_hi);
    rms_scale_ = std::max(options_.error_bound, std::sqrt(sum_square / total_area_));
    // Queued all at once, in face order.
    for (MeanCell& cell : initial)
      prepare(cell);
    queue_.start(std::move(initial));
    // Refine the cell with the largest share of the errors (its plane bounds first, where
    // near enough, else its split) until the estimates are within their bounds.
    const bool bound_met = refine_largest_first(
        queue_, [this](const MeanCell&) { return within_bound(); },
        [this] {
          return result_.queries >= options_.max_queries ||
                 (result_.queries >= options_.query_budget && within_coarse_bound());
        },
        [this](MeanCell& cell) {
          remove_sums(cell);
          if (!cell.planes_tried && bounder_.near_enough_to_tighten(cell)) {
            tighten_or_replay(cell);
            enqueue(std::move(cell));
          } else {
            split_or_replay(cell);
          }
        });
    if (!bound_met)
      result_.converged = false;
    // Final sums from the cells themselves (no drift from the running sums).
    sum_mean_ = sum_mean_width_ = sum_square_ = sum_square_width_ = 0.0;
    while (!queue_.empty()) {
      add_sums(queue_.top(), 1.0);
      queue_.pop();
    }
    const Estimate e =
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_);
    result_.area = total_area_;
    result_.mean = e.mean;
    result_.mean_error = e.mean_error;
    // Widened by a relative 1e-12 for the rounding of the sums and closed forms.
    const double rounding = 1e-12;
    result_.mean_lower = e.mean_lower() * (1.0 - rounding);
    result_.mean_upper = (e.mean + e.mean_error) * (1.0 + rounding);
    result_.rms = e.rms;
    result_.rms_error = e.rms_error;
    result_.rms_lower = e.rms_lower() * (1.0 - rounding);
    result_.rms_upper = (e.rms + e.rms_error) * (1.0 + rounding);
    result_.converged = result_.converged && within_bound(e);
    return result_;
  }

 private:
  embree::ClosestPoint query(const Point& p, double bound) {
    ++result_.queries;
    return scene_.closest_point(p, bound);
  }

  bool within_bound() const {
    return within_bound(
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_));
  }
  bool within_coarse_bound() const {
    const Estimate e =
        estimate(total_area_, sum_mean_, sum_mean_width_, sum_square_, sum_square_width_);
    return e.mean_error <= options_.coarse_error_bound &&
           e.rms_error <= options_.coarse_error_bound;
  }
  // Each half-width within max(relative bound x its lower end, absolute bound).
  bool within_bound(const Estimate& e) const {
    const double rel = options_.relative_error_bound;
    return e.mean_error <= std::max(rel * e.mean_lower(), options_.error_bound) &&
           e.rms_error <= std::max(rel * e.rms_lower(), options_.error_bound);
  }

  void add_sums(const MeanCell& cell, double sign) {
    sum_mean_ += sign * cell.area * 0.5 * (cell.mean_lo + cell.mean_hi);
    sum_mean_width_ += sign * cell.area * (cell.mean_hi - cell.mean_lo);
    sum_square_ += sign * cell.area * 0.5 * (cell.square_lo + cell.square_hi);
    sum_square_width_ += sign * cell.area * (cell.square_hi - cell.square_lo);
  }
  void remove_sums(const MeanCell& cell) { add_sums(cell, -1.0); }

  // Counts the cell's query of bound(), gives it its priority (its share of the errors)
  // and adds it to the running sums.
  void prepare(MeanCell& cell) {
    ++result_.queries;  // the one closest-point query of bound()
    cell.priority = cell.area * ((cell.mean_hi - cell.mean_lo) +
                                 (cell.square_hi - cell.square_lo) / (2.0 * rms_scale_));
    add_sums(cell, 1.0);
  }

  void enqueue(MeanCell cell) {
    prepare(cell);
    queue_.push(std::move(cell));
  }

  // tighten(), or its recorded outcome for the same cell: the same bounds.
  void tighten_or_replay(MeanCell& cell) {
    if (!replay_ && !record_) {
      bounder_.tighten(cell);
      return;
    }
    const CellKey key = key_of(cell);
    if (replay_) {
      const auto it = replay_->tightened.find(key);
      if (it != replay_->tightened.end()) {
        cell.take_bounds(it->second);
        cell.planes_tried = true;
        ++result_.steps_taken;
        return;
      }
    }
    bounder_.tighten(cell);
    if (record_)
      record_->tightened.emplace(key, cell.bounds());
  }

  // split(), or its recorded children for the same cell: the same children, found by the
  // same three midpoint queries (counted as made).
  void split_or_replay(const MeanCell& cell) {
    if (!replay_ && !record_) {
      split(cell, nullptr);
      return;
    }
    const CellKey key = key_of(cell);
    if (replay_) {
      const auto it = replay_->children.find(key);
      if (it != replay_->children.end()) {
        result_.queries += 3;
        ++result_.steps_taken;
        for (const MeanCell& child : it->second)
          enqueue(child);
        return;
      }
    }
    std::vector<MeanCell> children;
    split(cell, record_ ? &children : nullptr);
    if (record_)
      record_->children.emplace(key, std::move(children));
  }

  // The midpoints queried first, then each child with area bounded and queued in turn (and
  // kept in `children` when given).
  void split(const MeanCell& cell, std::vector<MeanCell>* children) {
    const auto query_midpoint = [this](const Point& p, double bound) { return query(p, bound); };
    for (const TriangleCell& piece : split_at_midpoints(cell, query_midpoint)) {
      MeanCell child(piece);
      child.area = triangle_area(child.corners);
      if (!(child.area > 0.0))
        continue;
      bounder_.bound(child);
      if (children)
        children->push_back(child);
      enqueue(std::move(child));
    }
  }

  const embree::TriangleScene& scene_;
  const MeanDistanceOptions& options_;
  const MeanCellBounder bounder_;
  MeanSearchSteps::Table* record_ = nullptr;        // keeps the bounds and steps
  const MeanSearchSteps::Table* replay_ = nullptr;  // takes the recorded ones
  DirectedMeanDistance result_;
  CellQueue<MeanCell> queue_;
  double total_area_ = 0.0;
  double rms_scale_ = 0.0;
  double sum_mean_ = 0.0, sum_mean_width_ = 0.0, sum_square_ = 0.0, sum_square_width_ = 0.0;
};

}  // namespace

DirectedMeanDistance directed_mean_distance(const Mesh& a, const embree::TriangleScene& b_scene,
                                            const MeanDistanceOptions& options,
                                            const KnownDistances& known,
                                            const FirstBounds* first_bounds,
                                            MeanSearchSteps* record) {
  MeanSearch search(b_scene, options);
  search.use_steps(record ? &record->table() : nullptr,
                   first_bounds && first_bounds->steps ? &first_bounds->steps->table() : nullptr);
  return search.run(a, known, first_bounds);
}

MeanCellBounds::MeanCellBounds(const Mesh& a0, const embree::TriangleScene& b0_scene,
                               const FirstPass& first_pass, const MeanDistanceOptions& options)
    : table_(std::make_unique<Table>()) {
  table_->error_bounds = SearchErrorBounds::of(options);
  // The cells as the search makes them: the same first pass over the vertices, the faces
  // lying on B0 left out (the search skips them).
  const std::vector<int>& b0_face_of_a0 = first_pass.b_face_of_a;
  table_->vertices = first_pass.vertices;
  const VertexDistances& vertices = table_->vertices;
  table_->vertex_queried.assign(a0.n_vertices(), 1);
  for (auto f : a0.faces()) {
    if (b0_face_of_a0[f.idx()] >= 0) {
      for (auto v : a0.fv_range(f))
        table_->vertex_queried[v.idx()] = 0;
    }
  }
  table_->vertex_points.reserve(a0.n_vertices());
  for (auto v : a0.vertices())
    table_->vertex_points.push_back(a0.point(v));
  std::vector<MeanCell> cells;
  std::vector<int> faces;
  cells.reserve(a0.n_faces());
  faces.reserve(a0.n_faces());
  for (auto f : a0.faces()) {
    if (b0_face_of_a0[f.idx()] >= 0)
      continue;
    MeanCell cell(face_cell(a0, f, vertices));
    if (triangle_area(cell.corners) > 0.0) {
      cells.push_back(std::move(cell));
      faces.push_back(f.idx());
    }
  }
  std::vector<GrowingBox> reach;
  MeanSearch(b0_scene, options).bound_each_with_reach(cells, reach, faces, first_pass.centroid);
  table_->cells.reserve(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const MeanCell& cell = cells[i];
    table_->cells.add(faces[i], key_of(cell), CellBounds{cell.bounds(), reach[i]});
  }
}

MeanCellBounds::~MeanCellBounds() = default;

std::size_t MeanCellBounds::size() const {
  return table_->cells.size();
}

EarlierVertexAnswer earlier_vertex_answers(const Mesh& a, const FirstBounds* first) {
  if (!first || !first->bounds)
    return {};
  const bool b_is_b0 = first->change.b0_face_of_b == nullptr;
  const std::vector<int>* b_face_of_b0 = first->change.b_face_of_b0;
  if (!b_is_b0 && !b_face_of_b0)
    return {};
  const MeanCellBounds::Table& table = first->bounds->table();
  const GrowingBox changed = first->change.changed;
  return [&a, &table, b_face_of_b0, b_is_b0, changed](int vertex, double& distance, int& face) {
    const std::size_t i = static_cast<std::size_t>(vertex);
    if (i >= table.vertex_points.size() || !table.vertex_queried[i] ||
        a.point(VertexHandle(vertex)) != table.vertex_points[i])
      return false;
    const double d = table.vertices.distance[i];
    int answer = table.vertices.nearest_face[i];
    if (!b_is_b0) {
      const Point& p = table.vertex_points[i];
      GrowingBox ball;
      ball.add_ball(p, d + 1e-9 * (d + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2])));
      if (answer < 0 || static_cast<std::size_t>(answer) >= b_face_of_b0->size() ||
          (*b_face_of_b0)[answer] < 0 || ball.meets(changed))
        return false;
      answer = (*b_face_of_b0)[answer];
    }
    distance = d;
    face = answer;
    return true;
  };
}

}  // namespace holebench
