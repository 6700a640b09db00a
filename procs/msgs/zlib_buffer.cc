#include "procs/msgs/zlib_buffer.h"

#include <zlib.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace topay::msgs {
namespace {

constexpr std::size_t kMaxZlibChunk = std::numeric_limits<uInt>::max();

// Owns an inflate stream (inflateEnd on every path).
class Inflater {
 public:
  Inflater() { ok_ = inflateInit(&stream_) == Z_OK; }
  ~Inflater() {
    if (ok_) inflateEnd(&stream_);
  }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;
  bool ok() const { return ok_; }
  z_stream* stream() { return &stream_; }

 private:
  z_stream stream_{};
  bool ok_ = false;
};

std::string ZlibMessage(const z_stream& stream, int code) {
  return stream.msg != nullptr ? std::string(stream.msg) : "zlib error " + std::to_string(code);
}

}  // namespace

std::vector<std::uint8_t> ZlibDeflate(std::span<const std::uint8_t> raw, int level) {
  if (level < 0 || level > 9) {
    throw std::invalid_argument("ZlibDeflate: level " + std::to_string(level) +
                                " is outside 0..9");
  }
  if (raw.size() > kMaxZlibChunk) throw std::invalid_argument("ZlibDeflate: buffer above 4 GiB");
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> stream(size);
  const int code = compress2(stream.data(), &size, raw.data(), static_cast<uLong>(raw.size()),
                             level);
  if (code != Z_OK) throw std::runtime_error("ZlibDeflate: zlib error " + std::to_string(code));
  stream.resize(size);
  return stream;
}

bool ZlibInflateExactly(std::span<const std::uint8_t> stream, std::size_t raw_size,
                        std::vector<std::uint8_t>* raw, std::string* error) {
  if (stream.size() > kMaxZlibChunk || raw_size >= kMaxZlibChunk) {
    *error = "buffer above 4 GiB";
    return false;
  }
  Inflater inflater;
  if (!inflater.ok()) {
    *error = "zlib could not start inflating";
    return false;
  }
  // One spare byte tells "inflates to more than raw_size" from "exactly raw_size".
  raw->resize(raw_size + 1);
  z_stream* z = inflater.stream();
  z->next_in = const_cast<Bytef*>(stream.data());
  z->avail_in = static_cast<uInt>(stream.size());
  z->next_out = raw->data();
  z->avail_out = static_cast<uInt>(raw->size());
  const int code = inflate(z, Z_FINISH);
  const std::size_t produced = z->total_out;
  raw->resize(std::min(produced, raw_size));
  if (produced > raw_size) {
    *error = "inflates to more than the declared " + std::to_string(raw_size) + " bytes";
    return false;
  }
  if (code == Z_STREAM_END && produced < raw_size) {
    *error = "inflates to " + std::to_string(produced) + " bytes, not the declared " +
             std::to_string(raw_size);
    return false;
  }
  if (code == Z_BUF_ERROR) {
    *error = "the zlib stream ends early (truncated)";
    return false;
  }
  if (code != Z_STREAM_END) {
    *error = "not a valid zlib stream (" + ZlibMessage(*z, code) + ")";
    return false;
  }
  if (z->avail_in != 0) {
    *error = std::to_string(z->avail_in) + " bytes follow the end of the zlib stream";
    return false;
  }
  return true;
}

}  // namespace topay::msgs
