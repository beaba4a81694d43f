#include "harness/outputs/render/image_file_module.h"

#include <dlfcn.h>

#include <cstdlib>
#include <stdexcept>

namespace holebench::render {

const ImageFileFunctions& load_image_file_module(const std::string& path) {
  // RTLD_NOW: a missing symbol shows here, not at the first picture of some job.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    throw std::runtime_error("cannot load the image-file module " + path + " (" +
                             (why ? why : "unknown reason") +
                             "); build it (scripts/build.sh) or name it in HOLEBENCH_IMAGE_MODULE");
  }
  using Entry = const ImageFileFunctions* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kImageFileFunctionsSymbol));
  if (!entry) {
    ::dlclose(handle);
    throw std::runtime_error(path + " is not holebench's image-file module (no " +
                             kImageFileFunctionsSymbol + ")");
  }
  return *entry();  // the handle stays open for the process's life
}

std::string image_file_module_path() {
  if (const char* named = std::getenv("HOLEBENCH_IMAGE_MODULE"); named && *named)
    return named;
  return HOLEBENCH_IMAGE_MODULE_PATH;
}

const ImageFileFunctions& image_file_module() {
  static const ImageFileFunctions& functions = load_image_file_module(image_file_module_path());
  return functions;
}

}  // namespace holebench::render
