#include "harness/outputs/gzip_bytes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>

namespace holebench::harness {
namespace {

/// Bytes that compress somewhat: a repeated header and random floats' bytes.
std::string sample_bytes(std::size_t size) {
  std::mt19937_64 random(7);
  std::string bytes = "ply\nformat binary_little_endian 1.0\n";
  while (bytes.size() < size)
    bytes += static_cast<char>(random() % 7 == 0 ? 'x' : random() & 0xFF);
  return bytes;
}

// gzip_bytes and gunzip_bytes are each other's inverse, on nothing and on 300 kB.
TEST(GzipBytes, RoundTrip) {
  for (std::size_t size : {std::size_t{0}, std::size_t{300'000}}) {
    const std::string bytes = sample_bytes(size);
    EXPECT_EQ(gunzip_bytes(gzip_bytes(bytes)), bytes);
  }
}

// The stream is gzip as the gzip tool reads it (an independent decoder), and the same bytes
// give the same stream.
TEST(GzipBytes, TheGzipToolReadsIt) {
  const std::string bytes = sample_bytes(100'000);
  const std::string stream = gzip_bytes(bytes);
  EXPECT_EQ(stream, gzip_bytes(bytes));
  const auto path = std::filesystem::temp_directory_path() / "gzip_bytes_test.gz";
  std::ofstream(path, std::ios::binary) << stream;
  const std::string command = "gzip -dc '" + path.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buffer[4096];
  while (const std::size_t n = fread(buffer, 1, sizeof buffer, pipe))
    out.append(buffer, n);
  EXPECT_EQ(pclose(pipe), 0);
  EXPECT_EQ(out, bytes);
}

// Not gzip, or cut short: an error, not garbage.
TEST(GzipBytes, BrokenStreamsThrow) {
  EXPECT_THROW(gunzip_bytes("not gzip at all"), std::runtime_error);
  const std::string stream = gzip_bytes(sample_bytes(10'000));
  EXPECT_THROW(gunzip_bytes(stream.substr(0, stream.size() / 2)), std::runtime_error);
}

}  // namespace
}  // namespace holebench::harness
