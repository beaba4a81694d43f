// OpenImageIO headers define FMT_HEADER_ONLY: this file includes no fmt.
#include "harness/outputs/render/image.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/oiioversion.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace holebench::render {

namespace {
std::uint8_t to_byte(float linear) {
  // sRGB-like gamma so that shading reads naturally.
  const float v = std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f);
  return static_cast<std::uint8_t>(std::lround(v * 255.0f));
}
}  // namespace

void Image::set(int x, int y, const Rgb& colour) {
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  pixels[i] = to_byte(colour.r);
  pixels[i + 1] = to_byte(colour.g);
  pixels[i + 2] = to_byte(colour.b);
}

void write_png(const Image& image, const std::filesystem::path& path) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out)
    throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open(path.string(), spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) || !out->close()) {
    throw std::runtime_error("cannot write " + path.string() + ": " + out->geterror());
  }
}

const char* openimageio_version() {
  return OIIO_VERSION_STRING;
}

}  // namespace holebench::render
