#include "python/mesh_arrays.h"

#include "core/errors.h"
#include "core/mesh_io.h"

#include <cstdint>
#include <limits>
#include <string>

namespace py = pybind11;

namespace holebench::python {
namespace {

using Coordinates = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

bool is_path(py::handle value) {
  return py::isinstance<py::str>(value) ||
         py::hasattr(value, "__fspath__");  // pathlib.Path and the like
}

std::vector<Point> points_from(py::handle value, const std::string& what) {
  const auto array = Coordinates::ensure(value);
  if (!array || array.ndim() != 2 || array.shape(1) != 3)
    throw InvalidInputError(what + ": vertices must be an (n, 3) array of numbers");
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(array.shape(0)));
  const auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i)
    points.emplace_back(view(i, 0), view(i, 1), view(i, 2));
  return points;
}

std::vector<std::array<int, 3>> triangles_from(py::handle value, std::size_t vertex_count,
                                               const std::string& what) {
  const auto array = Indices::ensure(value);
  if (!array || array.ndim() != 2 || array.shape(1) != 3)
    throw InvalidInputError(what + ": faces must be an (m, 3) array of vertex indices");
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(static_cast<std::size_t>(array.shape(0)));
  const auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    std::array<int, 3> triangle{};
    for (int corner = 0; corner < 3; ++corner) {
      const std::int64_t index = view(i, corner);
      if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count)
        throw InvalidInputError(what + ": face " + std::to_string(i) + " names vertex " +
                                std::to_string(index) + " of " + std::to_string(vertex_count));
      triangle[static_cast<std::size_t>(corner)] = static_cast<int>(index);
    }
    triangles.push_back(triangle);
  }
  return triangles;
}

std::vector<int> regions_from(py::handle value, std::size_t face_count, const std::string& what) {
  if (value.is_none())
    return {};
  const auto array = Indices::ensure(value);
  if (!array || array.ndim() != 1 || static_cast<std::size_t>(array.shape(0)) != face_count)
    throw InvalidInputError(what + ": regions must be an (m,) array, one per face");
  std::vector<int> regions;
  regions.reserve(face_count);
  const auto view = array.unchecked<1>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    if (view(i) < std::numeric_limits<int>::min() || view(i) > std::numeric_limits<int>::max())
      throw InvalidInputError(what + ": region id out of range at face " + std::to_string(i));
    regions.push_back(static_cast<int>(view(i)));
  }
  return regions;
}

TriangleSoup soup_from_parts(py::handle vertices, py::handle faces, py::handle regions,
                             const std::string& what) {
  TriangleSoup soup;
  soup.points = points_from(vertices, what);
  soup.triangles = triangles_from(faces, soup.points.size(), what);
  soup.regions = regions_from(regions, soup.triangles.size(), what);
  return soup;
}

}  // namespace

py::dict soup_to_dict(const TriangleSoup& soup) {
  py::array_t<double> vertices({static_cast<py::ssize_t>(soup.points.size()), py::ssize_t{3}});
  auto v = vertices.mutable_unchecked<2>();
  for (std::size_t i = 0; i < soup.points.size(); ++i)
    for (int c = 0; c < 3; ++c)
      v(static_cast<py::ssize_t>(i), c) = soup.points[i][c];
  py::array_t<std::int32_t> faces(
      {static_cast<py::ssize_t>(soup.triangles.size()), py::ssize_t{3}});
  auto f = faces.mutable_unchecked<2>();
  for (std::size_t i = 0; i < soup.triangles.size(); ++i)
    for (int c = 0; c < 3; ++c)
      f(static_cast<py::ssize_t>(i), c) = soup.triangles[i][static_cast<std::size_t>(c)];
  py::dict mesh;
  mesh["vertices"] = vertices;
  mesh["faces"] = faces;
  if (!soup.regions.empty()) {
    py::array_t<std::int32_t> regions(static_cast<py::ssize_t>(soup.regions.size()));
    auto r = regions.mutable_unchecked<1>();
    for (std::size_t i = 0; i < soup.regions.size(); ++i)
      r(static_cast<py::ssize_t>(i)) = soup.regions[i];
    mesh["regions"] = regions;
  }
  return mesh;
}

TriangleSoup soup_from_python(py::handle mesh, const std::string& what) {
  if (is_path(mesh))
    return read_soup(py::str(py::module_::import("os").attr("fspath")(mesh)).cast<std::string>());
  if (py::isinstance<py::dict>(mesh)) {
    const auto dict = py::reinterpret_borrow<py::dict>(mesh);
    if (!dict.contains("vertices") || !dict.contains("faces"))
      throw InvalidInputError(what + ": a mesh dict needs 'vertices' and 'faces'");
    const py::object regions =
        dict.contains("regions") ? py::object(dict["regions"]) : py::object(py::none());
    return soup_from_parts(dict["vertices"], dict["faces"], regions, what);
  }
  if (py::isinstance<py::tuple>(mesh) || py::isinstance<py::list>(mesh)) {
    const auto parts = py::reinterpret_borrow<py::sequence>(mesh);
    if (parts.size() != 2 && parts.size() != 3)
      throw InvalidInputError(what +
                              ": a mesh tuple is (vertices, faces) or (vertices, faces, "
                              "regions)");
    const py::object regions = parts.size() == 3 ? py::object(parts[2]) : py::object(py::none());
    return soup_from_parts(parts[0], parts[1], regions, what);
  }
  throw InvalidInputError(what +
                          ": a mesh is a dict with 'vertices' and 'faces', a (vertices, faces) "
                          "tuple or a mesh file path");
}

Mesh mesh_from_python(py::handle mesh, const std::string& what) {
  if (is_path(mesh))
    return read_mesh(py::str(py::module_::import("os").attr("fspath")(mesh)).cast<std::string>());
  BuildOptions options;
  options.source = what;
  return build_mesh(soup_from_python(mesh, what), options);
}

}  // namespace holebench::python
