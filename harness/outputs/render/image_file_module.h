// The interface between the harness and its image-file module: a shared library, loaded with
// dlopen the first time a picture is read or written, that holds every call into OpenImageIO.
// OpenImageIO brings 260 shared libraries with it (GDAL, OpenCV, OpenVDB, ...); kept out of
// the holebench binary, they cost nothing to a command that draws no picture, and one load,
// not two, to a run that does (the run re-executes itself for its huge-page heap).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace holebench::render {

/// What the module offers: plain functions, each returning false and an error message on
/// failure (no exception crosses the module's boundary).
struct ImageFileFunctions {
  /// Writes `width` x `height` 8-bit RGB pixels (row-major, top row first) as PNG.
  bool (*write_png)(const std::uint8_t* pixels, int width, int height, const char* path,
                    std::string* error);
  /// Reads an image file as 8-bit RGB (grey repeated, alpha dropped).
  bool (*read_rgb)(const char* path, std::vector<std::uint8_t>* pixels, int* width, int* height,
                   std::string* error);
  /// Loads OpenImageIO's catalogue of its plugins (once per process).
  void (*load_png_writer)();
};

/// The module's one exported symbol: `extern "C" const ImageFileFunctions*
/// holebench_image_file_functions()`.
constexpr const char* kImageFileFunctionsSymbol = "holebench_image_file_functions";

/// The module's functions, from the shared library at `path`. Throws std::runtime_error
/// naming the path and the loader's message when it cannot be loaded or is not the module.
const ImageFileFunctions& load_image_file_module(const std::string& path);

/// Where the module is looked for: $HOLEBENCH_IMAGE_MODULE when set, else the path the build
/// wrote it to.
std::string image_file_module_path();

/// The module's functions, loaded once per process on the first call (thread-safe).
const ImageFileFunctions& image_file_module();

}  // namespace holebench::render
