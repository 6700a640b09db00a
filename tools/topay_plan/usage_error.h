#pragma once

#include <stdexcept>
#include <string>

namespace topay::plan {

/// A command-line mistake: an unknown option value, a missing or contradictory choice, a
/// number out of range or not finite. what() names the option as the CLI spells it, e.g.
/// "--range: unknown range 'huge' (small, medium or large)". topay-plan exits with code 2.
class UsageError : public std::invalid_argument {
 public:
  explicit UsageError(const std::string& message) : std::invalid_argument(message) {}
};

}  // namespace topay::plan
