#pragma once
// What the options loaders' tests share: a YAML file written under the build tree, and the
// ConfigError message a load throws.

#include <filesystem>
#include <fstream>
#include <string>

#include "core/common/error.h"

namespace topay::test {

/// Writes `text` to <build>/test_out/<folder>/<name> and returns its path.
inline std::string WriteTestFile(const std::string& folder, const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::path(TOPAY_BINARY_DIR) / "test_out" / folder;
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

/// The message of the ConfigError `load()` throws; "" when it throws none.
template <class Load>
std::string ConfigErrorOf(Load&& load) {
  try {
    load();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace topay::test
