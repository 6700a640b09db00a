#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace topay {

/// Reads and validates the fields of one JSON file, turning every problem into a
/// topay::ConfigError("<file>", "<field path>", "<message>"), e.g. field "boxes[12].size".
/// Field paths are built with Child ("a.b") and Index ("a[3]").
class JsonFieldReader {
 public:
  /// The limit of ParseFile when the caller gives none (trajectory files with their samples).
  static constexpr std::size_t kDefaultMaxBytes = std::size_t{256} << 20;  // 256 MiB

  explicit JsonFieldReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  /// Reads (core/io/bounded_text_file.h: at most max_bytes, not a directory, no NUL byte) and
  /// parses the file; `what` names the kind of file in errors. A missing, unreadable or
  /// oversized file, or malformed JSON, throws.
  nlohmann::json ParseFile(std::size_t max_bytes = kDefaultMaxBytes,
                           const std::string& what = "JSON file") const;
  /// Parses text as if it were the file's contents.
  nlohmann::json ParseText(const std::string& text) const;

  static std::string Child(const std::string& path, const std::string& key);
  static std::string Index(const std::string& path, std::size_t index);

  void RequireObject(const nlohmann::json& value, const std::string& path) const;
  void RequireArray(const nlohmann::json& value, const std::string& path) const;
  /// The member `key` of object `object` (at `path`); throws if missing.
  const nlohmann::json& Member(const nlohmann::json& object, const std::string& path,
                               const std::string& key) const;
  /// Throws for the first member of `object` (at `path`) whose key is not in `known`, as the
  /// YAML readers do: a misspelt optional field is an error, not silently ignored.
  void RequireKnownKeys(const nlohmann::json& object, const std::string& path,
                        std::initializer_list<const char*> known) const;
  /// The member or nullptr if absent.
  const nlohmann::json* OptionalMember(const nlohmann::json& object,
                                       const std::string& key) const;

  /// A finite number.
  double Number(const nlohmann::json& value, const std::string& path) const;
  /// A string.
  std::string String(const nlohmann::json& value, const std::string& path) const;
  /// A non-negative integer that fits in 64 bits.
  std::uint64_t Unsigned(const nlohmann::json& value, const std::string& path) const;
  /// An array of exactly `size` finite numbers (size < 0: any size).
  Eigen::VectorXd NumberArray(const nlohmann::json& value, const std::string& path,
                              int size) const;
  Eigen::Vector3d Vector3(const nlohmann::json& value, const std::string& path) const {
    return NumberArray(value, path, 3);
  }

  [[noreturn]] void Fail(const std::string& path, const std::string& message) const;

 private:
  std::string file_;
};

/// Shortest round-trip text of a number, as nlohmann::json writes it.
std::string JsonNumberText(double value);

}  // namespace topay
