// core/atomic_file.h: a file written atomically is either the old one or the new one; a
// failed write leaves the old one and no temporary file, with an error naming the file.
#include "core/atomic_file.h"

#include "tests/harness/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace holebench {
namespace {

using harness::test_support::read_text;

// A folder of its own per test: CTest runs the tests of this file in parallel, and one test
// emptying a shared folder would pull the file from under another.
std::filesystem::path fresh_dir() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() /
                   (std::string("holebench_atomic_file_test_") + test->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(AtomicFile, ReplacesTheFileWhole) {
  const auto path = fresh_dir() / "results.json";
  write_file_atomically(path, "old\n");
  write_file_atomically(path, "new\n");
  EXPECT_EQ(read_text(path), "new\n");
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

// A write that fails half-way (the stream goes bad, as on a full disk) leaves the old file.
TEST(AtomicFile, AFailedWriteKeepsTheOldFileAndSaysWhy) {
  const auto path = fresh_dir() / "results.json";
  write_file_atomically(path, "old\n");
  try {
    write_file_atomically(path, [](std::ostream& out) {
      out << "half of the new";
      out.setstate(std::ios::badbit);
    });
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text(path), "old\n");
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
}

TEST(AtomicFile, AMissingFolderIsAClearError) {
  const auto path = fresh_dir() / "no_such_folder" / "results.json";
  try {
    write_file_atomically(path, "text");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace holebench
