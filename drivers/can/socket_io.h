#pragma once
// Small socket helpers shared by the CAN backends (not part of the public interface): waiting
// for a readable socket with a timeout, and reading one datagram/frame with its kernel
// receive timestamp (SO_TIMESTAMPNS).

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace topay::can::internal {

/// ns since the Unix epoch (CLOCK_REALTIME), read now.
std::int64_t NowRealtimeNs();

/// Enables SO_TIMESTAMPNS on `fd`; false with *error (errno text) on failure.
bool EnableKernelTimestamps(int fd, std::string* error);

/// A receive deadline: `timeout_s` from construction (0: now, negative: never).
class Deadline {
 public:
  explicit Deadline(double timeout_s);
  /// Seconds left (>= 0), or -1 when there is no deadline.
  double remaining_s() const;

 private:
  double timeout_s_;
  std::int64_t start_ns_;
};

/// poll()s `fd` for input up to `timeout_s` (0: no wait, negative: forever). Returns 1 when
/// readable, 0 on timeout, -1 on error (errno set). Retries on EINTR with the remaining time.
int WaitReadable(int fd, double timeout_s);

/// One recvmsg() without blocking (MSG_DONTWAIT) into `buffer`. Returns the datagram's size
/// (which may exceed `size`: MSG_TRUNC), or -1 with errno. *timestamp_ns is the kernel's
/// SCM_TIMESTAMPNS when present (*kernel_timestamp true), else NowRealtimeNs().
ssize_t ReceiveWithTimestamp(int fd, void* buffer, std::size_t size, std::int64_t* timestamp_ns,
                             bool* kernel_timestamp);

/// "what: strerror(errno)".
std::string ErrnoText(const std::string& what, int error_number);

}  // namespace topay::can::internal
