#include "generators/vertex_noise.h"

#include "core/geometry.h"
#include "generators/random.h"

namespace holebench::generators {

double noise_reference_length(const Mesh& complete) {
  return 0.01 * bounding_box_diagonal(complete);
}

void add_vertex_noise(Mesh& mesh, const NoiseOptions& options) {
  if (options.percent == 0.0)
    return;
  const double amplitude = options.percent / 100.0 * options.reference_length;
  Random random(options.seed);
  for (auto v : mesh.vertices())
    mesh.point(v) += random.unit_vector() * amplitude;
}

}  // namespace holebench::generators
