// A file's bytes, and bytes as base64: for outputs that embed one file in another (the
// viewer's data files, the figures' SVGs).
#pragma once

#include <filesystem>
#include <string>

namespace holebench::harness {

/// The bytes of `path`. Throws std::runtime_error naming the path when it cannot be read.
std::string read_bytes(const std::filesystem::path& path);

/// Base64 of `bytes` (RFC 4648, with padding).
std::string base64(const std::string& bytes);

/// The bytes base64() wrote (RFC 4648, with padding). Throws std::runtime_error on a
/// character outside the alphabet.
std::string from_base64(const std::string& text);

}  // namespace holebench::harness
