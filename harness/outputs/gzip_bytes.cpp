#include "harness/outputs/gzip_bytes.h"

#include <zlib.h>

#include <stdexcept>
#include <utility>

namespace holebench::harness {
namespace {

constexpr int kGzipWindowBits = 15 + 16;  // zlib: a gzip header and trailer
constexpr std::size_t kChunk = 1 << 16;

/// Runs `step` (deflate or inflate on `stream`) into chunks of output until it returns
/// anything but Z_OK; returns the output and that last status.
template <typename Step>
std::pair<std::string, int> drain(z_stream& stream, const std::string& input, Step step) {
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
  stream.avail_in = static_cast<uInt>(input.size());
  std::string out;
  int status = Z_OK;
  while (status == Z_OK) {
    const std::size_t before = out.size();
    out.resize(before + kChunk);
    stream.next_out = reinterpret_cast<Bytef*>(out.data() + before);
    stream.avail_out = static_cast<uInt>(kChunk);
    status = step();
    out.resize(before + kChunk - stream.avail_out);
  }
  return {std::move(out), status};
}

}  // namespace

std::string gzip_bytes(const std::string& bytes) {
  z_stream stream{};
  if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, kGzipWindowBits, 8,
                   Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("gzip: zlib did not start");
  auto [out, status] = drain(stream, bytes, [&] { return deflate(&stream, Z_FINISH); });
  deflateEnd(&stream);
  if (status != Z_STREAM_END)
    throw std::runtime_error("gzip: zlib failed");
  return out;
}

std::string gunzip_bytes(const std::string& gzip) {
  z_stream stream{};
  if (inflateInit2(&stream, kGzipWindowBits) != Z_OK)
    throw std::runtime_error("gunzip: zlib did not start");
  // Z_BUF_ERROR with input left: the output chunk was full; go on.
  auto [out, status] = drain(stream, gzip, [&] {
    const int step = inflate(&stream, Z_NO_FLUSH);
    return step == Z_BUF_ERROR && stream.avail_in > 0 ? Z_OK : step;
  });
  inflateEnd(&stream);
  if (status != Z_STREAM_END)
    throw std::runtime_error("gunzip: not a whole gzip stream");
  return out;
}

}  // namespace holebench::harness
