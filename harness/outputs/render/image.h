// An 8-bit RGB image and its PNG output (through OpenImageIO, in a module loaded at the first
// picture: image_file_module.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace holebench::render {

struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;  ///< linear 0..1
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  ///< row-major RGB, top row first

  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 3, 0) {}
  void set(int x, int y, const Rgb& colour);
};

/// A linear value's byte: round(255 x clamp(linear, 0, 1)^(1 / 2.2)), an sRGB-like gamma so
/// that shading reads naturally (found among the bytes' thresholds: no power per pixel).
std::uint8_t to_byte(float linear);

/// Copies `tile` into `sheet` with its top-left corner at (x0, y0); what falls outside the
/// sheet is cut off.
void paste(Image& sheet, const Image& tile, int x0, int y0);

/// Fills the whole image with one colour.
void fill(Image& image, const Rgb& colour);

/// Reads an image file (PNG and the other formats OpenImageIO knows) as 8-bit RGB (grey is
/// repeated, alpha dropped). Throws std::runtime_error with OpenImageIO's message on failure,
/// or the loader's when the image-file module cannot be loaded.
Image read_image(const std::filesystem::path& path);

/// Writes `image` as PNG. Throws std::runtime_error with OpenImageIO's message on failure, or
/// the loader's when the image-file module cannot be loaded.
void write_png(const Image& image, const std::filesystem::path& path);

/// Loads what writing a PNG needs once (the image-file module and OpenImageIO's catalogue of
/// its plugins), so that the processes forked afterwards find it loaded instead of each
/// loading it again. Throws std::runtime_error when the module cannot be loaded.
void load_png_writer();

}  // namespace holebench::render
