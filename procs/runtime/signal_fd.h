#pragma once
// Signals delivered as readable events on a file descriptor (signalfd), so a poll() loop waits
// on them with everything else and no handler runs asynchronously (no globals needed).

#include <csignal>
#include <initializer_list>
#include <optional>

namespace topay::procs {

/// Blocks `signals` in the calling thread (create it before any other thread, so that every
/// thread inherits the mask) and opens a non-blocking signalfd for them. The destructor closes
/// the fd and restores the previous mask. Throws std::system_error on failure.
class SignalFd {
 public:
  explicit SignalFd(std::initializer_list<int> signals);
  ~SignalFd();
  SignalFd(const SignalFd&) = delete;
  SignalFd& operator=(const SignalFd&) = delete;

  int fd() const { return fd_; }
  /// The next pending signal number, or nullopt if none is pending.
  std::optional<int> Read();
  /// The mask that was in force before construction (for children: restore it before exec).
  const sigset_t& previous_mask() const { return previous_mask_; }

 private:
  int fd_ = -1;
  sigset_t previous_mask_{};
};

}  // namespace topay::procs
