#pragma once

// What every command-line tool shares: the exit codes, their --help footer, the flag checks
// that CLI11 does not make, and the parse step that maps CLI11's errors to those codes.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace topay::tools {

/// Exit codes of every tool.
enum ExitCode : int {
  kExitSuccess = 0,      ///< done (for planners: a validated trajectory)
  kExitFileError = 1,    ///< a file, configuration or output error
  kExitUsageError = 2,   ///< bad flags or flag values
  kExitPlanFailed = 3,   ///< the planner found no validated trajectory (reason printed)
};

/// The --help footer that lists the exit codes; `with_plan_failed` for tools that plan.
inline std::string ExitCodesFooter(bool with_plan_failed) {
  std::string text =
      "Exit codes: 0 success, 1 file or configuration error, 2 usage error";
  return text + (with_plan_failed ? ", 3 plan failed (the reason is printed)." : ".");
}

/// A check for unsigned integer flags (seeds, counts): CLI11 would wrap "-1" to 2^64 - 1.
inline CLI::Validator NonNegativeInteger() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
          return "must be a non-negative integer, got '" + text + "'";
        }
        return {};
      },
      "UINT");
}

/// The robot and planner config folder: $TOPAY_CONFIG_DIR if set, else `compiled_in`.
inline std::string ConfigDir(const char* compiled_in) {
  const char* from_env = std::getenv("TOPAY_CONFIG_DIR");
  return from_env != nullptr && *from_env != '\0' ? from_env : compiled_in;
}

/// Parses the command line. Returns the exit code when the tool must stop now: 0 after
/// --help, kExitUsageError (message on stderr, prefixed by `tool`) on a parse error.
inline std::optional<int> ParseCommandLine(CLI::App& app, int argc, char** argv,
                                           const std::string& tool) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": " << e.what() << "\n(run with --help for usage)\n";
    return kExitUsageError;
  }
  return std::nullopt;
}

}  // namespace topay::tools
