// The image-file module: loaded on demand, with errors that say what to do, and never by a
// command that draws no picture.
#include "harness/outputs/render/image_file_module.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace holebench::render {
namespace {

std::string load_error(const std::string& path) {
  try {
    load_image_file_module(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ImageFileModule, AMissingModuleIsAnErrorNamingItAndTheVariable) {
  const std::string error = load_error("/nonexistent/holebench_image_file_module.so");
  EXPECT_NE(error.find("/nonexistent/holebench_image_file_module.so"), std::string::npos) << error;
  EXPECT_NE(error.find("HOLEBENCH_IMAGE_MODULE"), std::string::npos) << error;
}

TEST(ImageFileModule, ALibraryWithoutTheEntryIsNotTheModule) {
  const std::string error = load_error("libc.so.6");
  EXPECT_NE(error.find("is not holebench's image-file module"), std::string::npos) << error;
}

TEST(ImageFileModule, TheBuiltModuleLoadsAndTheVariableOverridesItsPath) {
  const ImageFileFunctions& functions = load_image_file_module(image_file_module_path());
  EXPECT_NE(functions.write_png, nullptr);
  EXPECT_NE(functions.read_rgb, nullptr);
  EXPECT_NE(functions.load_png_writer, nullptr);
  ::setenv("HOLEBENCH_IMAGE_MODULE", "/elsewhere/module.so", 1);
  EXPECT_EQ(image_file_module_path(), "/elsewhere/module.so");
  ::unsetenv("HOLEBENCH_IMAGE_MODULE");
}

// The dynamic loader lists every library it opens (LD_DEBUG=files): `holebench --help`
// opens no OpenImageIO.
TEST(ImageFileModule, ACommandWithoutPicturesLoadsNoOpenImageIO) {
  const std::string command =
      std::string("LD_DEBUG=files '") + HOLEBENCH_BINARY + "' --help 2>&1 >/dev/null";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string loaded;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe))
    loaded.append(buffer, n);
  EXPECT_EQ(::pclose(pipe), 0);
  EXPECT_NE(loaded.find("libembree3"), std::string::npos) << "LD_DEBUG listed nothing";
  EXPECT_EQ(loaded.find("libOpenImageIO"), std::string::npos);
}

}  // namespace
}  // namespace holebench::render
