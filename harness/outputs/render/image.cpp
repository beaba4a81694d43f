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
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x)
      image.set(x, y, colour);
  }
}

Image read_image(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in)
    throw std::runtime_error("cannot read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  std::vector<std::uint8_t> all(static_cast<std::size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, all.data())) {
    throw std::runtime_error("cannot read " + path.string() + ": " + in->geterror());
  }
  in->close();
  Image image(spec.width, spec.height);
  for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p) {
    for (int c = 0; c < 3; ++c)
      image.pixels[p * 3 + c] = all[p * channels + (channels >= 3 ? c : 0)];
  }
  return image;
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
