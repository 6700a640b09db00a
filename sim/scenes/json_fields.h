#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace topay {

/// Reads and validates the fields of one JSON file, turning every problem into a
/// topay::ConfigError("<file>", "<field path>", "<message>"), e.g. field "boxes[12].size".
/// Field paths are built with Child ("a.b") and Index ("a[3]").
class JsonFieldReader {
 public:
  explicit JsonFieldReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  /// Reads and parses the file: missing/unreadable file or malformed JSON throw.
  nlohmann::json ParseFile() const;
  /// Parses text as if it were the file's contents.
  nlohmann::json ParseText(const std::string& text) const;

  static std::string Child(const std::string& path, const std::string& key);
  static std::string Index(const std::string& path, std::size_t index);

  void RequireObject(const nlohmann::json& value, const std::string& path) const;
  void RequireArray(const nlohmann::json& value, const std::string& path) const;
  /// The member `key` of object `object` (at `path`); throws if missing.
  const nlohmann::json& Member(const nlohmann::json& object, const std::string& path,
                               const std::string& key) const;
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
