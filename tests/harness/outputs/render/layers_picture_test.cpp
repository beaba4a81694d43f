// A method's layers drawn (layers_picture.h): one test per layer kind that the layer is
// drawn (its panel differs from the input's where the layer lies), and that the same inputs
// give the same picture.
#include "harness/outputs/render/layers_picture.h"

#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "harness/outputs/render/bitmap_text.h"

#include <gtest/gtest.h>

namespace holebench::render {
namespace {

constexpr int kView = 160;
constexpr int kCaption = 22;

LayersPictureOptions small_panels() {
  LayersPictureOptions options;
  options.view_size = kView;
  options.samples_per_axis = 1;
  options.caption_height = kCaption;
  options.columns = 4;
  return options;
}

// Pixels of the view (caption strip excluded) of panel `index` that differ between two
// pictures of the same layout.
std::size_t differing_view_pixels(const Image& a, const Image& b, int index) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  const int x0 = index * (kView + 4);
  std::size_t count = 0;
  for (int y = kCaption; y < kCaption + kView; ++y) {
    for (int x = x0; x < x0 + kView; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 3;
      if (a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] ||
          a.pixels[i + 2] != b.pixels[i + 2])
        ++count;
    }
  }
  return count;
}

// A result with the case's input as its repair and one layer: the layer's panel against the
// same panel with the layer emptied.
std::size_t pixels_the_layer_changes(const Case& c, const MethodLayer& layer) {
  MethodResult drawn;
  drawn.repaired = c.input;
  drawn.layers = {layer};
  MethodResult empty = drawn;
  empty.layers[0].points.clear();
  empty.layers[0].polylines.clear();
  empty.layers[0].surface = {};
  empty.layers[0].name = layer.name;  // the same caption length, its count aside
  const Image with = layers_picture(c, drawn, small_panels());
  const Image without = layers_picture(c, empty, small_panels());
  // Two panels each: the layer's, then the repair's.
  EXPECT_EQ(with.width, 2 * kView + 4);
  return differing_view_pixels(with, without, 0);
}

// The box corner case, and points on the removed corner's boundary (in the view: the
// close-up frames the hole's boundary).
struct Fixture {
  Case c = generators::make_case("box/corner");
  std::vector<Point> boundary_points() const {
    std::vector<Point> points;
    for (auto h : c.input.halfedges()) {
      if (c.input.is_boundary(h))
        points.push_back(c.input.point(c.input.from_vertex_handle(h)));
    }
    return points;
  }
};

TEST(LayersPicture, PointsLayerIsDrawn) {
  Fixture f;
  MethodLayer layer;
  layer.name = "feature_points";
  layer.kind = LayerKind::Points;
  layer.points = f.boundary_points();
  EXPECT_GT(pixels_the_layer_changes(f.c, layer), 50u);
}

TEST(LayersPicture, PolylinesLayerIsDrawn) {
  Fixture f;
  MethodLayer layer;
  layer.name = "segments";
  layer.kind = LayerKind::Polylines;
  layer.polylines = {f.boundary_points()};
  EXPECT_GT(pixels_the_layer_changes(f.c, layer), 50u);
}

TEST(LayersPicture, SurfaceLayerIsDrawn) {
  Fixture f;
  MethodLayer layer;
  layer.name = "lofted_surface";
  layer.kind = LayerKind::Surface;
  // The removed faces of the complete model, as a surface over the hole.
  const auto points = f.boundary_points();
  Point centre(0, 0, 0);
  for (const auto& p : points)
    centre += p;
  centre /= static_cast<double>(points.size());
  layer.surface.points = points;
  layer.surface.points.push_back(centre);
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i)
    layer.surface.triangles.push_back({i, (i + 1) % n, n});
  EXPECT_GT(pixels_the_layer_changes(f.c, layer), 50u);
}

// One panel per layer and the repair's; the same bytes for the same inputs; captions name
// the layers in capitals with their sizes.
TEST(LayersPicture, OnePanelPerLayerAndTheSameBytes) {
  Fixture f;
  MethodResult result;
  result.repaired = f.c.input;
  for (const char* name : {"a", "b", "c", "d", "e"}) {
    MethodLayer layer;
    layer.name = name;
    layer.kind = LayerKind::Points;
    layer.points = f.boundary_points();
    result.layers.push_back(layer);
  }
  const Image a = layers_picture(f.c, result, small_panels());
  const Image b = layers_picture(f.c, result, small_panels());
  EXPECT_EQ(a.width, 4 * kView + 3 * 4);  // 6 panels in rows of 4
  EXPECT_EQ(a.height, 2 * (kView + kCaption) + 4);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_EQ(layer_caption(result.layers[0]),
            "A (" + std::to_string(f.boundary_points().size()) + ")");
}

// Captions need letters: every capital has a glyph (it draws pixels), unlike an unknown
// character.
TEST(BitmapText, CapitalsAndUnderscoreAreDrawn) {
  for (char ch = 'A'; ch <= 'Z'; ++ch) {
    Image image(12, 16);
    fill(image, {1, 1, 1});
    draw_text(image, 0, 0, std::string(1, ch));
    std::size_t dark = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      dark += image.pixels[i] == 0 ? 1 : 0;
    EXPECT_GT(dark, 0u) << ch;
  }
  Image image(12, 16);
  fill(image, {1, 1, 1});
  draw_text(image, 0, 0, "#");
  for (auto p : image.pixels)
    EXPECT_EQ(p, 255);
}

}  // namespace
}  // namespace holebench::render
