#include "core/mesh.h"

#include <algorithm>

namespace holebench {

void mark_all_original(Mesh& mesh) {
  for (auto v : mesh.vertices())
    mesh.data(v).provenance = Provenance::Original;
  for (auto f : mesh.faces())
    mesh.data(f).provenance = Provenance::Original;
}

std::size_t count_new_faces(const Mesh& mesh) {
  return static_cast<std::size_t>(std::count_if(mesh.faces_begin(), mesh.faces_end(),
                                                [&](FaceHandle f) { return is_new(mesh, f); }));
}

int region_count(const Mesh& mesh) {
  int largest = kNoRegion;
  for (auto f : mesh.faces())
    largest = std::max(largest, region(mesh, f));
  return largest + 1;
}

}  // namespace holebench
