// A pixel's byte against its definition, computed here with the power function; a PNG
// written and read back holds the same bytes.
#include "harness/outputs/render/image.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <random>
#include <string>

namespace holebench::render {
namespace {

int defined_byte(float linear) {
  return static_cast<int>(
      std::lround(std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f) * 255.0f));
}

// Random values over [0, 1], and the floats on either side of every byte's first value
// (where a threshold off by one float would show).
TEST(Image, ByteIsTheGammaOfItsValue) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 1'000'000; ++i) {
    const float v = unit(random);
    ASSERT_EQ(to_byte(v), defined_byte(v)) << v;
  }
  float v = 0.0f;
  for (int k = 1; k <= 255; ++k) {
    while (defined_byte(v) < k)
      v = std::min(1.0f, std::max(std::nextafter(v, 2.0f), v * 1.001f));
    // Somewhere in (previous v, v] the byte reached k: check around it float by float.
    float w = v;
    for (int step = 0; step < 2000 && w > 0.0f; ++step)
      w = std::nextafter(w, -1.0f);
    for (; w <= v; w = std::nextafter(w, 2.0f))
      ASSERT_EQ(to_byte(w), defined_byte(w)) << w;
  }
  for (float outside : {-1.0f, -0.0f, 0.0f, 1.0f, 1.5f, std::numeric_limits<float>::infinity()})
    EXPECT_EQ(to_byte(outside), defined_byte(outside)) << outside;
}

// fill() gives every pixel the colour's bytes.
TEST(Image, FillSetsEveryPixel) {
  Image image(7, 5);
  fill(image, {0.2f, 0.5f, 0.9f});
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    EXPECT_EQ(image.pixels[i], defined_byte(0.2f));
    EXPECT_EQ(image.pixels[i + 1], defined_byte(0.5f));
    EXPECT_EQ(image.pixels[i + 2], defined_byte(0.9f));
  }
}

// The PNG writer's settings (its compression and row filter) keep every byte: noise,
// smooth gradients and flat runs, in an image whose width is not a multiple of anything.
TEST(Image, PngWrittenAndReadBackHasTheSameBytes) {
  Image image(97, 61);
  std::mt19937 random(11);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      auto* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 3];
      if (y < 20) {
        for (int c = 0; c < 3; ++c)
          p[c] = static_cast<std::uint8_t>(random() & 0xFF);
      } else if (y < 40) {
        p[0] = static_cast<std::uint8_t>(x * 2);
        p[1] = static_cast<std::uint8_t>(y * 4);
        p[2] = static_cast<std::uint8_t>((x + y) & 0xFF);
      } else {
        p[0] = 255;
        p[1] = 128;
        p[2] = 0;
      }
    }
  }
  const auto path = std::filesystem::temp_directory_path() /
                    ("holebench_png_test_" + std::to_string(::getpid()) + ".png");
  write_png(image, path);
  const Image read = read_image(path);
  std::filesystem::remove(path);
  EXPECT_EQ(read.width, image.width);
  EXPECT_EQ(read.height, image.height);
  EXPECT_EQ(read.pixels, image.pixels);
}

}  // namespace
}  // namespace holebench::render
