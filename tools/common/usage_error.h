#pragma once

#include <stdexcept>
#include <string>

namespace topay::tools {

/// A command-line mistake: an unknown option value, a missing or contradictory choice, a
/// number out of range or not finite. what() names the option as the CLI spells it, e.g.
/// "--range: unknown range 'huge' (small, medium or large)". Every tool exits with
/// kExitUsageError (2) on it (tool_cli.h).
class UsageError : public std::invalid_argument {
 public:
  explicit UsageError(const std::string& message) : std::invalid_argument(message) {}
};

}  // namespace topay::tools

namespace topay::plan {
using tools::UsageError;  // the tools' libraries throw it as plan::UsageError too
}  // namespace topay::plan
