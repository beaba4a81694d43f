#include "core/method_layers.h"

#include <algorithm>

namespace holebench {

const char* to_string(LayerKind kind) {
  switch (kind) {
    case LayerKind::Points:
      return "points";
    case LayerKind::Polylines:
      return "polylines";
    case LayerKind::Surface:
      return "surface";
  }
  return "unknown";
}

std::size_t MethodLayer::size() const {
  switch (kind) {
    case LayerKind::Points:
      return points.size();
    case LayerKind::Polylines:
      return polylines.size();
    case LayerKind::Surface:
      return surface.triangles.size();
  }
  return 0;
}

MethodLayer& layer_named(std::vector<MethodLayer>& layers, const std::string& name,
                         const std::string& step, LayerKind kind) {
  const auto it = std::find_if(layers.begin(), layers.end(),
                               [&](const MethodLayer& l) { return l.name == name; });
  if (it != layers.end())
    return *it;
  MethodLayer layer;
  layer.name = name;
  layer.step = step;
  layer.kind = kind;
  layers.push_back(std::move(layer));
  return layers.back();
}

void append_layers(std::vector<MethodLayer>& into, std::vector<MethodLayer> from) {
  for (auto& layer : from) {
    MethodLayer& to = layer_named(into, layer.name, layer.step, layer.kind);
    to.points.insert(to.points.end(), layer.points.begin(), layer.points.end());
    for (auto& line : layer.polylines)
      to.polylines.push_back(std::move(line));
    const int base = static_cast<int>(to.surface.points.size());
    to.surface.points.insert(to.surface.points.end(), layer.surface.points.begin(),
                             layer.surface.points.end());
    for (const auto& t : layer.surface.triangles)
      to.surface.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
}

void append_new_faces(MethodLayer& layer, const Mesh& mesh) {
  for (const FaceHandle f : mesh.faces()) {
    if (!is_new(mesh, f))
      continue;
    std::array<int, 3> triangle{};
    int corner = 0;
    for (const auto v : mesh.fv_range(f)) {
      if (corner == 3)
        break;
      triangle[corner++] = static_cast<int>(layer.surface.points.size());
      layer.surface.points.push_back(mesh.point(v));
    }
    if (corner == 3)
      layer.surface.triangles.push_back(triangle);
  }
}

}  // namespace holebench
