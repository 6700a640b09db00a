#pragma once

#include <stdexcept>
#include <string>

namespace topay {

/// A file (URDF, YAML, scene JSON, ...) that is missing, malformed or inconsistent.
/// what() reads "<file>: <field>: <message>", so the user knows what to fix and where.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& file, const std::string& field, const std::string& message);

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  std::string field_;
};

}  // namespace topay
