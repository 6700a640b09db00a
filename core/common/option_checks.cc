#include "core/common/option_checks.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

void FailOption(const char* owner, const char* field, double value, const char* requirement) {
  throw std::invalid_argument(std::string(owner) + ": " + field + " must be " + requirement + ", got " +
                              std::to_string(value));
}

void CheckOptionPositive(const char* owner, const char* field, double value) {
  if (!std::isfinite(value) || value <= 0.0) FailOption(owner, field, value, "finite and > 0");
}

void CheckOptionNonNegative(const char* owner, const char* field, double value) {
  if (!std::isfinite(value) || value < 0.0) FailOption(owner, field, value, "finite and >= 0");
}

}  // namespace topay
