// Bytes compressed as gzip (RFC 1952) and back, through zlib: the viewer's mesh files
// (viewer/viewer_mesh.h), which browsers decompress with DecompressionStream('gzip').
#pragma once

#include <string>

namespace holebench::harness {

/// `bytes` as a gzip stream (zlib's default level: the same bytes give the same stream).
/// Throws std::runtime_error when zlib fails.
std::string gzip_bytes(const std::string& bytes);

/// The bytes a gzip stream holds. Throws std::runtime_error when `gzip` is not one.
std::string gunzip_bytes(const std::string& gzip);

}  // namespace holebench::harness
