#pragma once
// Runs a command inside a small Linux guest with a real SocketCAN vcan0
// (tools/guest/vcan-guest.sh: QEMU, Debian's kernel, the host's root shared read-only), for the
// CAN tests this machine's kernel (no AF_CAN) cannot run. Tests call GuestUnavailableReason()
// first and GTEST_SKIP() with it when a guest cannot boot here (never a silent pass).

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace topay::test {

inline std::string GuestScript() { return std::string(TOPAY_SOURCE_DIR) + "/tools/guest/vcan-guest.sh"; }

inline std::string ShellQuote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct GuestRun {
  int exit_code = -1;  ///< The command's exit code; 124 guest timed out, 125 guest failed.
  std::string output;  ///< The guest's console: the command's stdout and stderr, boot messages.
};

/// Runs `shell_command` through popen; its combined output and exit code.
inline GuestRun RunShell(const std::string& shell_command) {
  GuestRun run;
  FILE* pipe = popen((shell_command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 4096> buffer{};
  size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

/// Empty when a guest can be booted here, else why not (no QEMU, no kernel fetched).
inline std::string GuestUnavailableReason() {
  const GuestRun check = RunShell(ShellQuote(GuestScript()) + " check");
  if (check.exit_code == 0) return "";
  return "no guest kernel for the real-SocketCAN tests: " + check.output +
         " (make deps fetches it; docs/can.md)";
}

/// Boots the guest, runs `command` there (cwd: the build tree) with `out_dir` shared
/// read-write at the same path, and returns its exit code and the console output.
inline GuestRun RunInGuest(const std::vector<std::string>& command, const std::string& out_dir,
                           int timeout_s) {
  std::string line = ShellQuote(GuestScript()) + " run --out " + ShellQuote(out_dir) +
                     " --timeout " + std::to_string(timeout_s) + " --cwd " +
                     ShellQuote(TOPAY_BINARY_DIR) + " --";
  for (const std::string& word : command) line += " " + ShellQuote(word);
  return RunShell(line);
}

}  // namespace topay::test
