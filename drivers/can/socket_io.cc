#include "drivers/can/socket_io.h"

#include <poll.h>
#include <sys/socket.h>
#include <time.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>

namespace topay::can::internal {

std::int64_t NowRealtimeNs() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<std::int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}

namespace {
std::int64_t NowMonotonicNs() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<std::int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}
}  // namespace

Deadline::Deadline(double timeout_s) : timeout_s_(timeout_s), start_ns_(NowMonotonicNs()) {}

double Deadline::remaining_s() const {
  if (timeout_s_ < 0) return -1;
  const double left_s = timeout_s_ - (NowMonotonicNs() - start_ns_) * 1e-9;
  return left_s > 0 ? left_s : 0;
}

bool EnableKernelTimestamps(int fd, std::string* error) {
  const int on = 1;
  if (setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on)) != 0) {
    *error = ErrnoText("setsockopt(SO_TIMESTAMPNS)", errno);
    return false;
  }
  return true;
}

int WaitReadable(int fd, double timeout_s) {
  using Clock = std::chrono::steady_clock;
  const bool forever = timeout_s < 0;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::nanoseconds(forever ? 0 : static_cast<std::int64_t>(timeout_s * 1e9));
  while (true) {
    int timeout_ms = -1;
    if (!forever) {
      const double left_s = std::chrono::duration<double>(deadline - Clock::now()).count();
      timeout_ms = left_s <= 0 ? 0 : static_cast<int>(std::ceil(left_s * 1e3));
    }
    pollfd entry{fd, POLLIN, 0};
    const int ready = poll(&entry, 1, timeout_ms);
    if (ready >= 0) return ready > 0 ? 1 : 0;
    if (errno != EINTR) return -1;
  }
}

ssize_t ReceiveWithTimestamp(int fd, void* buffer, std::size_t size, std::int64_t* timestamp_ns,
                             bool* kernel_timestamp) {
  iovec vector{buffer, size};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec)) * 2];
  msghdr message{};
  message.msg_iov = &vector;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof(control);
  const ssize_t got = recvmsg(fd, &message, MSG_DONTWAIT | MSG_TRUNC);
  if (got < 0) return got;
  *kernel_timestamp = false;
  for (cmsghdr* c = CMSG_FIRSTHDR(&message); c != nullptr; c = CMSG_NXTHDR(&message, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_TIMESTAMPNS) {
      timespec stamp{};
      std::memcpy(&stamp, CMSG_DATA(c), sizeof(stamp));
      *timestamp_ns = static_cast<std::int64_t>(stamp.tv_sec) * 1'000'000'000 + stamp.tv_nsec;
      *kernel_timestamp = true;
    }
  }
  if (!*kernel_timestamp) *timestamp_ns = NowRealtimeNs();
  return got;
}

std::string ErrnoText(const std::string& what, int error_number) {
  return what + ": " + std::strerror(error_number);
}

}  // namespace topay::can::internal
