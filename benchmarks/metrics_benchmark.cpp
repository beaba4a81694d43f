// Benchmarks of the metrics' kernels (distances, closest points, arrow visibility), the
// snapshot renderer, the stages of a job and the grouped runner, and each method on fixed cases,
// beside the CGAL references the issue compares with. Every fixture is generated (same id, same
// bytes), so runs compare.
//
// Run: holebench_benchmarks --benchmark_format=json > benchmarks.json
#include "core/geometry.h"
#include "core/mesh_builder.h"
#include "generators/case_catalog.h"
#include "harness/outputs/render/case_view.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/image.h"
#include "harness/outputs/render/snapshot.h"
#include "harness/run/heap_reuse.h"
#include "harness/run/job.h"
#include "methods/registry.h"
#include "metrics/case_evaluation.h"
#include "metrics/embree/arrow_visibility.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/evaluation.h"
#include "metrics/hausdorff_distance.h"
#include "metrics/surface_distance.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>

namespace holebench {
namespace {

constexpr double kPi = 3.14159265358979323846;

// HOLEBENCH_BENCHMARK_THREADS=N runs every benchmark on at most N threads: N = 1 is how a
// nightly job runs on two workers, and under valgrind (callgrind) it makes a function's
// instruction count its own work, not the share of it that the counted thread took.
const std::unique_ptr<const tbb::global_control> thread_limit = [] {
  const char* text = std::getenv("HOLEBENCH_BENCHMARK_THREADS");
  const long threads = text ? std::strtol(text, nullptr, 10) : 0;
  return threads > 0
             ? std::make_unique<const tbb::global_control>(
                   tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads))
             : nullptr;
}();

// A torus of n x m quads (2nm triangles), outward oriented.
Mesh torus(int n, int m, double bump) {
  TriangleSoup soup;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2.0 * kPi * i / n, v = 2.0 * kPi * j / m;
      // A smooth bump on one side: the "repaired" surface that differs from the truth.
      const double r = 0.3 + bump * std::exp(-8.0 * (u * u + (v - kPi) * (v - kPi)));
      soup.points.emplace_back((1.0 + r * std::cos(v)) * std::cos(u),
                               (1.0 + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  }
  auto index = [n, m](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return build_mesh(soup);
}

struct Pair {
  Mesh a, b;
  double diagonal = 0.0;
};

// The pairs: the fandisk repaired by liepa_cgal against its complete model; a 100k-triangle
// torus against the same torus with a bump; and against itself moved by 1e-7 of its size
// (near-zero distance).
const Pair& pair(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Pair>> pairs;
  auto& slot = pairs[name];
  if (!slot) {
    slot = std::make_unique<Pair>();
    if (name == "fandisk") {
      const Case c = generators::make_case("cad/fandisk/edge_convex/small");
      NoUser user;
      MethodParameters parameters;
      parameters.structure_size = c.parameters.structure_size;
      slot->a = make_method("liepa_cgal")->run(c.input, parameters, user).repaired;
      slot->b = c.complete;
    } else if (name == "torus100k_bump") {
      slot->a = torus(250, 200, 0.02);
      slot->b = torus(250, 200, 0.0);
    } else {
      slot->a = torus(250, 200, 0.0);
      slot->b = slot->a;
      for (auto v : slot->b.vertices())
        slot->b.point(v) += Point(1e-7, -1e-7, 1e-7);
    }
    slot->diagonal = bounding_box_diagonal(slot->b);
  }
  return *slot;
}

const char* pair_name(int index) {
  static const char* names[] = {"fandisk", "torus100k_bump", "torus100k_near_zero"};
  return names[index];
}

// Two-sided Hausdorff distance, error bound 1e-4 of the diagonal: ours (Embree scenes
// included in the time) and CGAL's bounded_error_symmetric_Hausdorff_distance.
void BM_Hausdorff_Ours(benchmark::State& state) {
  const Pair& p = pair(pair_name(state.range(0)));
  state.SetLabel(pair_name(state.range(0)));
  HausdorffOptions options;
  options.error_bound = 1e-4 * p.diagonal;
  double value = 0.0;
  for (auto _ : state) {
    const auto result = hausdorff_distance(p.a, p.b, options);
    value = result.upper();
    benchmark::DoNotOptimize(value);
  }
  state.counters["hausdorff_rel_diag"] = value / p.diagonal;
}
BENCHMARK(BM_Hausdorff_Ours)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// The same on one thread (our first pass is parallel; CGAL's runs with Sequential_tag).
void BM_Hausdorff_OursOneThread(benchmark::State& state) {
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  BM_Hausdorff_Ours(state);
}
BENCHMARK(BM_Hausdorff_OursOneThread)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// Building the two Embree scenes alone (part of BM_Hausdorff_Ours's time).
void BM_EmbreeScenes(benchmark::State& state) {
  const Pair& p = pair(pair_name(state.range(0)));
  state.SetLabel(pair_name(state.range(0)));
  for (auto _ : state) {
    const embree::TriangleScene a_scene(p.a), b_scene(p.b);
    benchmark::DoNotOptimize(a_scene.triangle_count() + b_scene.triangle_count());
  }
}
BENCHMARK(BM_EmbreeScenes)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// The same with the cheap build (SceneBuild::fast_build), as hausdorff_distance builds them.
void BM_EmbreeScenesFastBuild(benchmark::State& state) {
  const Pair& p = pair(pair_name(state.range(0)));
  state.SetLabel(pair_name(state.range(0)));
  for (auto _ : state) {
    const embree::TriangleScene a_scene(p.a, embree::SceneBuild::fast_build),
        b_scene(p.b, embree::SceneBuild::fast_build);
    benchmark::DoNotOptimize(a_scene.triangle_count() + b_scene.triangle_count());
  }
}
BENCHMARK(BM_EmbreeScenesFastBuild)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// CGAL's bounded-error Hausdorff distance with the given concurrency tag.
template <class ConcurrencyTag>
void hausdorff_cgal(benchmark::State& state) {
  const Pair& p = pair(pair_name(state.range(0)));
  state.SetLabel(pair_name(state.range(0)));
  double value = 0.0;
  for (auto _ : state) {
    value =
        CGAL::Polygon_mesh_processing::bounded_error_symmetric_Hausdorff_distance<ConcurrencyTag>(
            p.a, p.b, 1e-4 * p.diagonal);
    benchmark::DoNotOptimize(value);
  }
  state.counters["hausdorff_rel_diag"] = value / p.diagonal;
}

void BM_Hausdorff_Cgal(benchmark::State& state) {
  hausdorff_cgal<CGAL::Sequential_tag>(state);
}
BENCHMARK(BM_Hausdorff_Cgal)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);

#if defined(HOLEBENCH_CGAL_PARALLEL_HAUSDORFF)
// CGAL's parallel bounded-error Hausdorff distance (Parallel_tag: TBB over a METIS partition
// of the first mesh, in CGAL 5.5 an experimental path enabled by USE_PARALLEL_BEHD, see
// benchmarks/CMakeLists.txt), on two threads, beside ours on two threads (BM_Hausdorff_Ours).
void BM_Hausdorff_CgalParallelTwoThreads(benchmark::State& state) {
  const tbb::global_control two_threads(tbb::global_control::max_allowed_parallelism, 2);
  hausdorff_cgal<CGAL::Parallel_tag>(state);
}
BENCHMARK(BM_Hausdorff_CgalParallelTwoThreads)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
#endif

// Mean and RMS distance (error bound 1e-3 of the diagonal), both directions, alone and
// as the evaluation computes them with the Hausdorff distance (scenes built outside).
SurfaceDistanceOptions mean_benchmark_options(const Pair& p) {
  SurfaceDistanceOptions options;
  options.hausdorff.error_bound = 1e-4 * p.diagonal;
  options.mean.error_bound = 1e-3 * p.diagonal;
  return options;
}

void BM_MeanDistance_Ours(benchmark::State& state) {
  const Pair& p = pair(pair_name(state.range(0)));
  state.SetLabel(pair_name(state.range(0)));
  const embree::TriangleScene a_scene(p.a), b_scene(p.b);
  const SurfaceDistanceOptions options = mean_benchmark_options(p);
  for (auto _ : state) {
    const auto a = directed_mean_distance(p.a, b_scene, options.mean);
    const auto b = directed_mean_distance(p.b, a_scene, options.mean);
    benchmark::DoNotOptimize(a.mean + b.mean);
  }
}
BENCHMARK(BM_MeanDistance_Ours)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void BM_SurfaceDistance_Ours(benchmark::State& state) {
  const Pair& p = pair(pair_name(state.range(0)));
  state.SetLabel(pair_name(state.range(0)));
  const embree::TriangleScene a_scene(p.a), b_scene(p.b);
  const SurfaceDistanceOptions options = mean_benchmark_options(p);
  for (auto _ : state) {
    const auto d = surface_distance(p.a, a_scene, p.b, b_scene, options);
    benchmark::DoNotOptimize(d.mean());
  }
}
BENCHMARK(BM_SurfaceDistance_Ours)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// Closest-point throughput: the same query points (the vertices of the bumped torus, moved
// off the surface) against the flat torus, through our Embree scene and a CGAL AABB tree.
std::vector<Point> query_points() {
  std::vector<Point> points;
  const Mesh& a = pair("torus100k_bump").a;
  for (auto v : a.vertices())
    points.push_back(a.point(v) * 1.01 + Point(0.003, -0.002, 0.001));
  return points;
}

void BM_ClosestPoint_Embree(benchmark::State& state) {
  const Mesh& b = pair("torus100k_bump").b;
  const embree::TriangleScene scene(b);
  const auto points = query_points();
  for (auto _ : state) {
    double sum = 0.0;
    for (const Point& q : points)
      sum += scene.closest_point(q).distance;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * points.size());
}
BENCHMARK(BM_ClosestPoint_Embree)->Unit(benchmark::kMillisecond);

void BM_ClosestPoint_CgalAabb(benchmark::State& state) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  const Mesh& b = pair("torus100k_bump").b;
  Tree tree(faces(b).first, faces(b).second, b);
  tree.accelerate_distance_queries();
  std::vector<Kernel::Point_3> points;
  for (const Point& q : query_points())
    points.emplace_back(q[0], q[1], q[2]);
  for (auto _ : state) {
    double sum = 0.0;
    for (const auto& q : points)
      sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(q, tree.closest_point(q))));
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * points.size());
}
BENCHMARK(BM_ClosestPoint_CgalAabb)->Unit(benchmark::kMillisecond);

// Arrow visibility: an arrow above the fandisk's hole (scenes built outside the loop, as
// the evaluation builds them once).
void BM_ArrowVisibility(benchmark::State& state) {
  const Case c = generators::make_case("cad/fandisk/face_interior/large");
  const double diagonal = bounding_box_diagonal(c.complete);
  const embree::TriangleScene complete_scene(c.complete), holed_scene(c.input);
  embree::ArrowVisibilityOptions options;
  options.sample_spacing = 5e-3 * diagonal;
  options.surface_tolerance = 1e-7 * diagonal;
  const auto samples = embree::sample_faces(c.complete, c.holes[0].removed_faces, options);
  const auto camera = render::hole_camera(c);
  const GuidanceArrow arrow{camera.target - camera.direction * diagonal, camera.direction};
  for (auto _ : state) {
    const auto q = embree::arrow_quality(arrow, samples, complete_scene, holed_scene, options);
    benchmark::DoNotOptimize(q.visible_fraction);
  }
  state.counters["samples"] = static_cast<double>(samples.points.size());
}
BENCHMARK(BM_ArrowVisibility)->Unit(benchmark::kMillisecond);

// Snapshot rendering at the harness's default size (480 x 360, 4 rays per pixel), the scene's
// build included; rays_per_second counts the primary rays.
void BM_RenderSnapshot(benchmark::State& state) {
  const Case c = generators::make_case("cad/fandisk/face_interior/large");
  const auto camera = render::hole_camera(c);
  const render::SnapshotOptions options;
  const double rays = static_cast<double>(options.width) * options.height *
                      options.samples_per_axis * options.samples_per_axis;
  for (auto _ : state) {
    auto image = render::render_snapshot(c.input, camera, options);
    benchmark::DoNotOptimize(image);
  }
  state.counters["rays_per_second"] = benchmark::Counter(
      rays * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderSnapshot)->Unit(benchmark::kMillisecond);

// Writing that snapshot as PNG (render::write_png, the settings every picture is written
// with); bytes_per_image is the file's size.
void BM_WritePng(benchmark::State& state) {
  const Case c = generators::make_case("cad/fandisk/face_interior/large");
  const auto image = render::render_snapshot(c.input, render::hole_camera(c), {});
  const auto path = std::filesystem::temp_directory_path() /
                    ("holebench_bm_write_png_" + std::to_string(::getpid()) + ".png");
  for (auto _ : state)
    render::write_png(image, path);
  state.counters["bytes_per_image"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}
BENCHMARK(BM_WritePng)->Unit(benchmark::kMillisecond);

// Raw Embree on the snapshot's own rays and mesh, one rtcIntersect1 per ray on one thread,
// the scene built once outside the timing: the throughput BM_RenderSnapshot is measured
// against (its rays_per_second over this one's).
void BM_EmbreePrimaryRays(benchmark::State& state) {
  const Case c = generators::make_case("cad/fandisk/face_interior/large");
  const auto rays = render::primary_rays(render::hole_camera(c));
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               c.input.n_vertices()));
  for (auto v : c.input.vertices())
    for (int k = 0; k < 3; ++k)
      vertices[3 * v.idx() + k] = static_cast<float>(c.input.point(v)[k]);
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), c.input.n_faces()));
  for (auto f : c.input.faces()) {
    int k = 0;
    for (auto v : c.input.fv_range(f))
      indices[3 * f.idx() + k++] = static_cast<unsigned>(v.idx());
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  std::size_t hits = 0;
  for (auto _ : state) {
    for (const Point& d : rays.directions) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit ray{};
      ray.ray.org_x = static_cast<float>(rays.eye[0]);
      ray.ray.org_y = static_cast<float>(rays.eye[1]);
      ray.ray.org_z = static_cast<float>(rays.eye[2]);
      const Point u = d / d.norm();
      ray.ray.dir_x = static_cast<float>(u[0]);
      ray.ray.dir_y = static_cast<float>(u[1]);
      ray.ray.dir_z = static_cast<float>(u[2]);
      ray.ray.tfar = std::numeric_limits<float>::infinity();
      ray.ray.mask = 0xFFFFFFFFu;
      ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &ray);
      hits += ray.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
  }
  benchmark::DoNotOptimize(hits);
  state.counters["rays_per_second"] =
      benchmark::Counter(static_cast<double>(rays.directions.size() * state.iterations()),
                         benchmark::Counter::kIsRate);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}
BENCHMARK(BM_EmbreePrimaryRays)->Unit(benchmark::kMillisecond);

// Each method on fixed cases.
const char* method_case(int index) {
  static const char* ids[] = {"box/corner", "brep/k3/inner/convex-convex-convex/small",
                              "cad/fandisk/edge_convex/small"};
  return ids[index];
}

// The stages of a job around the method, on the same fixed cases, at 0 and 25 % noise: making
// the case (stages_s.case) and evaluating a method's result (stages_s.evaluation; liepa_cgal's
// result, metrics as the nightly computes them).
void BM_Stage_Case(benchmark::State& state) {
  const double noise = static_cast<double>(state.range(1));
  state.SetLabel(fmt::format("{} noise {}", method_case(state.range(0)), noise));
  for (auto _ : state) {
    const Case c = generators::make_case(method_case(state.range(0)), 0, noise);
    benchmark::DoNotOptimize(c.input.n_faces());
  }
}
BENCHMARK(BM_Stage_Case)->ArgsProduct({{0, 1, 2}, {0, 25}})->Unit(benchmark::kMillisecond);

// A fixed case (state.range(0)) at a noise level (state.range(1)) and liepa_cgal's result.
struct EvaluatedJob {
  Case c;
  MethodResult result;
};
EvaluatedJob evaluated_job(benchmark::State& state) {
  const double noise = static_cast<double>(state.range(1));
  state.SetLabel(fmt::format("{} noise {}", method_case(state.range(0)), noise));
  EvaluatedJob job{generators::make_case(method_case(state.range(0)), 0, noise), {}};
  MethodParameters parameters;
  parameters.structure_size = job.c.parameters.structure_size;
  NoUser user;
  job.result = make_method("liepa_cgal")->run(job.c.input, parameters, user);
  return job;
}

void BM_Stage_Evaluation(benchmark::State& state) {
  const auto [c, result] = evaluated_job(state);
  for (auto _ : state) {
    const Evaluation evaluation = evaluate(c, result);
    benchmark::DoNotOptimize(evaluation.values.size());
  }
}
BENCHMARK(BM_Stage_Evaluation)->ArgsProduct({{0, 1, 2}, {0, 25}})->Unit(benchmark::kMillisecond);

// The same evaluation in a group of jobs: what the case's jobs share (CaseEvaluation) built
// once outside the timer, as the grouped runner builds it once per case instance.
void BM_Stage_EvaluationShared(benchmark::State& state) {
  const auto [c, result] = evaluated_job(state);
  const EvaluationOptions options;
  const CaseEvaluation shared(c, options);
  for (auto _ : state) {
    const Evaluation evaluation = evaluate(c, result, options, shared);
    benchmark::DoNotOptimize(evaluation.values.size());
  }
}
BENCHMARK(BM_Stage_EvaluationShared)
    ->ArgsProduct({{0, 1, 2}, {0, 25}})
    ->Unit(benchmark::kMillisecond);

// The snapshot of a job in a group (stages_s.snapshot without the PNG file): liepa_cgal's
// result drawn with what the case's pictures share built once outside the timer, from the
// whole repaired mesh (state.range(2) = 0) or over the case's views of its input (1, the
// default: the cost of the patch).
void BM_Stage_Snapshot(benchmark::State& state) {
  const auto [c, result] = evaluated_job(state);
  render::CloseUpOptions options;
  options.draw_over_input_views = state.range(2) != 0;
  const render::CasePicture shared(c, options);
  for (auto _ : state) {
    const render::Image picture = render::job_picture(c, result, shared, options);
    benchmark::DoNotOptimize(picture.pixels.data());
  }
}
BENCHMARK(BM_Stage_Snapshot)
    ->ArgsProduct({{0, 1, 2}, {0, 25}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// What the pictures of a case's jobs share, built once per case instance (with the views of
// the input when state.range(2) = 1).
void BM_Stage_SnapshotShared(benchmark::State& state) {
  const auto [c, result] = evaluated_job(state);
  render::CloseUpOptions options;
  options.draw_over_input_views = state.range(2) != 0;
  for (auto _ : state) {
    const render::CasePicture shared(c, options);
    benchmark::DoNotOptimize(shared.hole_views().size());
  }
}
BENCHMARK(BM_Stage_SnapshotShared)
    ->ArgsProduct({{0, 1, 2}, {0, 25}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// The five nightly methods on one case instance (fandisk edge hole, 25 % noise), in this
// process and without snapshots: each job making its own case (run_job, as one process per
// job did) against the case made once for the group (prepare_case + run_job_on_case, as the
// grouped runner does). The process forks are not in these times.
std::vector<harness::Job> nightly_jobs_of_one_case() {
  std::vector<harness::Job> jobs;
  for (const char* method :
       {"liepa_cgal", "brep_guidance", "slice_loft", "slice_direct", "crest_feature"}) {
    harness::Job job;
    job.case_id = "cad/fandisk/edge_convex/small";
    job.method_id = method;
    job.noise_percent = 25.0;
    jobs.push_back(job);
  }
  return jobs;
}

void BM_Runner_OneCasePerJob(benchmark::State& state) {
  const auto jobs = nightly_jobs_of_one_case();
  for (auto _ : state) {
    for (const auto& job : jobs)
      benchmark::DoNotOptimize(harness::run_job(job, {}).status);
  }
}
BENCHMARK(BM_Runner_OneCasePerJob)->Unit(benchmark::kMillisecond);

void BM_Runner_OneCasePerGroup(benchmark::State& state) {
  const auto jobs = nightly_jobs_of_one_case();
  for (auto _ : state) {
    harness::PreparedCase prepared = harness::prepare_case(jobs.front(), {});
    harness::share_case_work(prepared, {});
    for (const auto& job : jobs)
      benchmark::DoNotOptimize(
          harness::run_job_on_case(job, prepared, &job == &jobs.front(), {}).status);
  }
}
BENCHMARK(BM_Runner_OneCasePerGroup)->Unit(benchmark::kMillisecond);

void BM_Method(benchmark::State& state, const std::string& method_id) {
  const Case c = generators::make_case(method_case(state.range(0)));
  state.SetLabel(method_case(state.range(0)));
  const auto method = make_method(method_id);
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  for (auto _ : state) {
    NoUser user;  // methods run without a user here (the harness's default)
    auto result = method->run(c.input, parameters, user);
    benchmark::DoNotOptimize(result);
  }
}

void register_methods() {
  for (const auto& method : make_all_methods()) {
    const std::string id = method->id();
    benchmark::RegisterBenchmark(("BM_Method/" + id).c_str(),
                                 [id](benchmark::State& s) { BM_Method(s, id); })
        ->DenseRange(0, 2)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace
}  // namespace holebench

int main(int argc, char** argv) {
  // The heap as a run's processes have it (harness/run/heap_reuse.h), so that the evaluation
  // benchmarks time what a run's jobs spend.
  holebench::harness::keep_freed_heap_memory();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  holebench::register_methods();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
