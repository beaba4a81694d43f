// A method's layers as OBJ (layers_obj.h): one group per layer, its elements as p, l and f
// lines whose indices name the right vertices.
#include "harness/outputs/layers_obj.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace holebench::harness {
namespace {

TEST(LayersObj, OneGroupPerLayerWithItsElements) {
  MethodLayer points{"corner", "III", LayerKind::Points, {Point(1, 2, 3)}, {}, {}};
  MethodLayer lines{
      "edges", "III", LayerKind::Polylines, {}, {{Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0)}},
      {}};
  MethodLayer surface{"patch", "V", LayerKind::Surface, {}, {}, {}};
  surface.surface.points = {Point(0, 0, 1), Point(1, 0, 1), Point(0, 1, 1)};
  surface.surface.triangles = {{0, 1, 2}};
  const std::string text = layers_obj({points, lines, surface});

  std::vector<Point> vertices;
  std::vector<std::string> groups, elements;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      double x, y, z;
      words >> x >> y >> z;
      vertices.emplace_back(x, y, z);
    } else if (tag == "g") {
      std::string name;
      words >> name;
      groups.push_back(name);
    } else if (tag == "p" || tag == "l" || tag == "f") {
      elements.push_back(line);
    }
  }
  EXPECT_EQ(groups, (std::vector<std::string>{"corner", "edges", "patch"}));
  ASSERT_EQ(vertices.size(), 7u);
  EXPECT_EQ(vertices[0], Point(1, 2, 3));
  EXPECT_EQ(vertices[3], Point(1, 1, 0));
  EXPECT_EQ(elements, (std::vector<std::string>{"p 1", "l 2 3 4", "f 5 6 7"}));
}

}  // namespace
}  // namespace holebench::harness
