// The image-file module (image_file_module.h): every call into OpenImageIO, built as a shared
// library of its own and loaded by the harness only when it reads or writes a picture.
// OpenImageIO headers define FMT_HEADER_ONLY: this file includes no fmt.
#include "harness/outputs/render/image_file_module.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>

namespace holebench::render {

namespace {

constexpr int kPngCompressionLevel = 3;
constexpr int kPngFilterUp = 0x20;  // libpng's PNG_FILTER_UP

bool write_png(const std::uint8_t* pixels, int width, int height, const char* path,
               std::string* error) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    *error = OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  // zlib level 3 with libpng's "up" filter (PNG_FILTER_UP) instead of level 6 with every
  // filter tried per row: the same pixels, written in a third of the time (3.5 against
  // 10 ms for a 732x320 snapshot) in files about a quarter larger (32 against 25 KB).
  spec.attribute("png:compressionLevel", kPngCompressionLevel);
  spec.attribute("png:filter", kPngFilterUp);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels) || !out->close()) {
    *error = out->geterror();
    return false;
  }
  return true;
}

bool read_rgb(const char* path, std::vector<std::uint8_t>* pixels, int* width, int* height,
              std::string* error) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    *error = OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
  std::vector<std::uint8_t> all(count * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, all.data())) {
    *error = in->geterror();
    return false;
  }
  in->close();
  pixels->assign(count * 3, 0);
  for (std::size_t p = 0; p < count; ++p) {
    for (int c = 0; c < 3; ++c)
      (*pixels)[p * 3 + c] = all[p * channels + (channels >= 3 ? c : 0)];
  }
  *width = spec.width;
  *height = spec.height;
  return true;
}

void load_png_writer() {
  // Creating a writer catalogues OpenImageIO's plugins (once per process).
  OIIO::ImageOutput::create("png");
}

constexpr ImageFileFunctions kFunctions{&write_png, &read_rgb, &load_png_writer};

}  // namespace

}  // namespace holebench::render

extern "C" __attribute__((visibility("default"))) const holebench::render::ImageFileFunctions*
holebench_image_file_functions() {
  return &holebench::render::kFunctions;
}
