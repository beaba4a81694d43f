// The growth law of the evaluation: one hole (the fandisk's edge hole, liepa_cgal's repair)
// on the same model refined far from the hole, at about 27k, 108k, 430k and 1.7M triangles
// (refinement levels 0 to 3). The hole and the faces within four rings of it are untouched;
// every other face is split 1-to-4 at each level (the fourth ring takes the transition:
// a face with one or two split edges is split into two or three), so the surface, the hole,
// its patch and the distances stay the same and only the model's size grows.
//
// Two benchmarks per level: what the case's jobs share (CaseEvaluation, built once per case
// instance by the runner) and one job's evaluation after it (evaluate() with the shared work).
// The per-job time should not grow with the model (issue 49: at most 2x from level 0 to 3).
//
// Run: holebench_benchmarks --benchmark_filter=EvaluationGrowth
#include "core/face_rings.h"
#include "core/mesh_builder.h"
#include "generators/case_catalog.h"
#include "generators/hole_punch.h"
#include "methods/registry.h"
#include "metrics/case_evaluation.h"
#include "metrics/evaluation.h"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace holebench {
namespace {

constexpr const char* kGrowthCase = "cad/fandisk/edge_convex/small";
constexpr int kUntouchedRings = 4;  ///< the hole's faces and these rings keep their triangles

/// The faces of `mesh` within `rings` vertex rings of `faces` (and `faces` themselves).
std::vector<bool> faces_near(const Mesh& mesh, const std::vector<int>& faces, int rings) {
  std::vector<VertexHandle> seeds;
  for (int f : faces) {
    for (auto v : mesh.fv_range(FaceHandle(f)))
      seeds.push_back(v);
  }
  const std::vector<char> within = faces_within_rings(mesh, seeds, rings);
  std::vector<bool> near(within.begin(), within.end());
  for (int f : faces)
    near[f] = true;
  return near;
}

/// One level of refinement of the case's complete model far from its hole, and the holed
/// input punched again from it (the same removed triangles).
Case refine_far_from_hole(const Case& c) {
  std::vector<int> removed;
  for (const auto& hole : c.holes)
    removed.insert(removed.end(), hole.removed_faces.begin(), hole.removed_faces.end());
  const std::vector<bool> untouched = faces_near(c.complete, removed, kUntouchedRings);
  TriangleSoup soup = to_soup(c.complete);
  // The midpoint of every edge of a face that is split 1-to-4.
  std::map<std::pair<int, int>, int> midpoint;
  const auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    if (untouched[f])
      continue;
    for (int k = 0; k < 3; ++k) {
      const int a = soup.triangles[f][k], b = soup.triangles[f][(k + 1) % 3];
      if (midpoint.try_emplace(key(a, b), -1).second) {
        midpoint[key(a, b)] = static_cast<int>(soup.points.size());
        soup.points.push_back((soup.points[a] + soup.points[b]) * 0.5);
      }
    }
  }
  const auto split_of = [&](int a, int b) {
    const auto it = midpoint.find(key(a, b));
    return it == midpoint.end() ? -1 : it->second;
  };
  TriangleSoup out;
  out.points = soup.points;
  const bool with_regions = !soup.regions.empty();
  std::vector<int> removed_out;
  std::vector<bool> is_removed(soup.triangles.size(), false);
  for (int f : removed)
    is_removed[f] = true;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const auto& t = soup.triangles[f];
    std::vector<std::array<int, 3>> pieces;
    const std::array<int, 3> m = {split_of(t[0], t[1]), split_of(t[1], t[2]), split_of(t[2], t[0])};
    const int splits = (m[0] >= 0) + (m[1] >= 0) + (m[2] >= 0);
    if (splits == 0) {
      pieces.push_back(t);
    } else if (splits == 3) {
      pieces = {{t[0], m[0], m[2]}, {m[0], t[1], m[1]}, {m[2], m[1], t[2]}, {m[0], m[1], m[2]}};
    } else {
      // Rotate so that edge (r0, r1) is split; with two splits, (r1, r2) is the other one.
      int s = 0;
      while (!(m[s] >= 0 && (splits == 1 || m[(s + 1) % 3] >= 0)))
        ++s;
      const std::array<int, 3> r = {t[s], t[(s + 1) % 3], t[(s + 2) % 3]};
      const int m01 = m[s], m12 = m[(s + 1) % 3];
      if (splits == 1)
        pieces = {{r[0], m01, r[2]}, {m01, r[1], r[2]}};
      else
        pieces = {{r[0], m01, r[2]}, {m01, r[1], m12}, {m01, m12, r[2]}};
    }
    for (const auto& piece : pieces) {
      if (is_removed[f])
        removed_out.push_back(static_cast<int>(out.triangles.size()));
      out.triangles.push_back(piece);
      if (with_regions)
        out.regions.push_back(soup.regions[f]);
    }
  }
  Case refined = c;
  refined.complete = build_mesh(out, BuildOptions{"refined model"});
  generators::PunchResult punched = generators::punch_faces(refined.complete, removed_out);
  refined.input = std::move(punched.holed);
  refined.holes.resize(1);
  refined.holes[0].removed_faces = std::move(punched.removed_faces);
  return refined;
}

/// The case refined `level` times, and liepa_cgal's repair of it (made once per level).
struct GrowthJob {
  Case c;
  MethodResult result;
};
const GrowthJob& growth_job(int level) {
  static std::map<int, std::unique_ptr<GrowthJob>> jobs;
  auto& slot = jobs[level];
  if (!slot) {
    slot = std::make_unique<GrowthJob>();
    slot->c = level == 0 ? generators::make_case(kGrowthCase)
                         : refine_far_from_hole(growth_job(level - 1).c);
    MethodParameters parameters;
    parameters.structure_size = slot->c.parameters.structure_size;
    NoUser user;
    slot->result = make_method("liepa_cgal")->run(slot->c.input, parameters, user);
  }
  return *slot;
}

void BM_EvaluationGrowth_SharedCaseWork(benchmark::State& state) {
  const GrowthJob& job = growth_job(static_cast<int>(state.range(0)));
  state.SetLabel(fmt::format("{} triangles", job.c.complete.n_faces()));
  const EvaluationOptions options;
  for (auto _ : state) {
    const CaseEvaluation shared(job.c, options);
    benchmark::DoNotOptimize(shared.complete_scene());
  }
}
BENCHMARK(BM_EvaluationGrowth_SharedCaseWork)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_EvaluationGrowth_PerJob(benchmark::State& state) {
  const GrowthJob& job = growth_job(static_cast<int>(state.range(0)));
  state.SetLabel(fmt::format("{} triangles", job.c.complete.n_faces()));
  const EvaluationOptions options;
  const CaseEvaluation shared(job.c, options);
  std::map<std::string, double> phase_seconds;
  for (auto _ : state) {
    const Evaluation evaluation = evaluate(job.c, job.result, options, shared);
    benchmark::DoNotOptimize(evaluation.values.size());
    for (const auto& phase : evaluation.phases)
      phase_seconds[phase.phase] += phase.seconds;
  }
  // Each phase's mean time per job, in milliseconds, where the time goes as the model grows.
  for (const auto& [name, seconds] : phase_seconds)
    state.counters[name + "_ms"] = 1000.0 * seconds / static_cast<double>(state.iterations());
}
BENCHMARK(BM_EvaluationGrowth_PerJob)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace holebench
