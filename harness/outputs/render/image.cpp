#include "harness/outputs/render/image.h"

#include "harness/outputs/render/image_file_module.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace holebench::render {

namespace {

// sRGB-like gamma so that shading reads naturally: the definition of a pixel's byte.
std::uint8_t gamma_byte(float linear) {
  const float v = std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f);
  return static_cast<std::uint8_t>(std::lround(v * 255.0f));
}

// For each byte k = 1..255, the smallest float in [0, 1] whose gamma_byte is k or more
// (gamma_byte is non-decreasing there, checked for every float in [0, 1]), by bisection on
// the floats' bit patterns, which are ordered as the floats for non-negative values.
std::array<float, 255> byte_thresholds() {
  std::array<float, 255> thresholds{};
  const auto float_of = [](std::uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  };
  const float one = 1.0f;
  std::uint32_t one_bits;
  std::memcpy(&one_bits, &one, sizeof one);
  for (int k = 1; k <= 255; ++k) {
    std::uint32_t low = 0, high = one_bits;  // gamma_byte(high) = 255 >= k
    while (low < high) {
      const std::uint32_t middle = low + (high - low) / 2;
      if (gamma_byte(float_of(middle)) >= k)
        high = middle;
      else
        low = middle + 1;
    }
    thresholds[k - 1] = float_of(low);
  }
  return thresholds;
}

}  // namespace

std::uint8_t to_byte(float linear) {
  if (!(linear >= 0.0f && linear <= 1.0f))
    return gamma_byte(linear);  // clamped (or not a number): as defined
  static const std::array<float, 255> thresholds = byte_thresholds();
  return static_cast<std::uint8_t>(std::upper_bound(thresholds.begin(), thresholds.end(), linear) -
                                   thresholds.begin());
}

void Image::set(int x, int y, const Rgb& colour) {
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  pixels[i] = to_byte(colour.r);
  pixels[i + 1] = to_byte(colour.g);
  pixels[i + 2] = to_byte(colour.b);
}

void paste(Image& sheet, const Image& tile, int x0, int y0) {
  for (int y = 0; y < tile.height; ++y) {
    for (int x = 0; x < tile.width; ++x) {
      if (x0 + x < 0 || y0 + y < 0 || x0 + x >= sheet.width || y0 + y >= sheet.height)
        continue;
      for (int c = 0; c < 3; ++c) {
        sheet.pixels[(static_cast<std::size_t>(y0 + y) * sheet.width + x0 + x) * 3 + c] =
            tile.pixels[(static_cast<std::size_t>(y) * tile.width + x) * 3 + c];
      }
    }
  }
}

void fill(Image& image, const Rgb& colour) {
  const std::uint8_t bytes[3] = {to_byte(colour.r), to_byte(colour.g), to_byte(colour.b)};
  for (std::size_t i = 0; i + 2 < image.pixels.size(); i += 3)
    std::memcpy(&image.pixels[i], bytes, 3);
}

Image read_image(const std::filesystem::path& path) {
  std::vector<std::uint8_t> pixels;
  int width = 0, height = 0;
  std::string error;
  if (!image_file_module().read_rgb(path.c_str(), &pixels, &width, &height, &error))
    throw std::runtime_error("cannot read " + path.string() + ": " + error);
  Image image(width, height);
  image.pixels = std::move(pixels);
  return image;
}

void write_png(const Image& image, const std::filesystem::path& path) {
  std::string error;
  if (!image_file_module().write_png(image.pixels.data(), image.width, image.height, path.c_str(),
                                     &error)) {
    throw std::runtime_error("cannot write " + path.string() + ": " + error);
  }
}

void load_png_writer() {
  image_file_module().load_png_writer();
}

}  // namespace holebench::render
