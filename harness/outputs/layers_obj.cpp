#include "harness/outputs/layers_obj.h"

#include "core/atomic_file.h"

#include <fmt/format.h>

namespace holebench::harness {
namespace {

// Appends `p` as a vertex line; returns its 1-based OBJ index.
std::size_t add_vertex(std::string& text, std::size_t& count, const Point& p) {
  text += fmt::format("v {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
  return ++count;
}

}  // namespace

std::string layers_obj(const std::vector<MethodLayer>& layers) {
  std::string text = "# holebench: a method's steps as geometry (one group per layer)\n";
  std::size_t count = 0;
  for (const auto& layer : layers) {
    text += fmt::format("g {}\n# step: {}; kind: {}; {} element(s)\n", layer.name, layer.step,
                        to_string(layer.kind), layer.size());
    switch (layer.kind) {
      case LayerKind::Points:
        for (const auto& p : layer.points) {
          const std::size_t index = add_vertex(text, count, p);
          text += fmt::format("p {}\n", index);
        }
        break;
      case LayerKind::Polylines:
        for (const auto& line : layer.polylines) {
          if (line.size() < 2)
            continue;
          std::string indices;
          for (const auto& p : line) {
            const std::size_t index = add_vertex(text, count, p);
            indices += fmt::format(" {}", index);
          }
          text += "l" + indices + "\n";
        }
        break;
      case LayerKind::Surface: {
        const std::size_t base = count;
        for (const auto& p : layer.surface.points)
          add_vertex(text, count, p);
        for (const auto& t : layer.surface.triangles)
          text += fmt::format("f {} {} {}\n", base + t[0] + 1, base + t[1] + 1, base + t[2] + 1);
        break;
      }
    }
  }
  return text;
}

void write_layers_obj(const std::vector<MethodLayer>& layers, const std::filesystem::path& path) {
  write_file_atomically(path, layers_obj(layers));
}

}  // namespace holebench::harness
