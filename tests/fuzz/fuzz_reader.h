#pragma once
// Reads typed values off a fuzzer's input, front to back; once the bytes run out every read
// returns zeros (or an empty span), so a target never reads past the input. A small
// stand-in for clang's FuzzedDataProvider that also builds with g++ (the replay driver).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>

namespace topay::fuzz {

class FuzzReader {
 public:
  FuzzReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::size_t remaining() const { return size_ - pos_; }
  bool empty() const { return remaining() == 0; }

  std::uint8_t Byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Byte() | (Byte() << 8)); }
  std::uint32_t U32() { return static_cast<std::uint32_t>(U16()) | (static_cast<std::uint32_t>(U16()) << 16); }
  bool Bool() { return (Byte() & 1) != 0; }

  /// Any double bit pattern (NaN, infinities, subnormals included).
  double RawDouble() {
    std::uint64_t bits = static_cast<std::uint64_t>(U32()) | (static_cast<std::uint64_t>(U32()) << 32);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  /// Up to `max_bytes` bytes (fewer when the input ends first).
  std::span<const std::uint8_t> Bytes(std::size_t max_bytes) {
    const std::size_t n = max_bytes < remaining() ? max_bytes : remaining();
    std::span<const std::uint8_t> out(data_ + pos_, n);
    pos_ += n;
    return out;
  }
  /// A record of the form [u16 length][length bytes]: up to 65,535 bytes.
  std::span<const std::uint8_t> LengthPrefixed() { return Bytes(U16()); }
  /// The rest of the input.
  std::span<const std::uint8_t> Rest() { return Bytes(remaining()); }
  std::string RestAsString() {
    const auto bytes = Rest();
    return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
  std::string LengthPrefixedString() {
    const auto bytes = LengthPrefixed();
    return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace topay::fuzz
