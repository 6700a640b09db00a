#include "core/common/error.h"

namespace topay {

ConfigError::ConfigError(const std::string& file, const std::string& field,
                         const std::string& message)
    : std::runtime_error(file + ": " + (field.empty() ? std::string() : field + ": ") + message),
      file_(file),
      field_(field) {}

}  // namespace topay
