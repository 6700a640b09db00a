#include "drivers/can/socketcan_bus.h"

#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "drivers/can/socket_io.h"

namespace topay::can {

using internal::ErrnoText;

std::vector<struct can_filter> ToKernelFilters(const std::vector<CanFilter>& filters) {
  std::vector<struct can_filter> out;
  out.reserve(filters.size());
  for (const CanFilter& filter : filters) out.push_back({filter.can_id, filter.can_mask});
  return out;
}

CanResult::Code SendErrorCode(int error_number) {
  switch (error_number) {
    case ENOBUFS:
    case EAGAIN:
      return CanResult::Code::kTxQueueFull;
    case ENETDOWN:
    case ENODEV:
    case ENXIO:
      return CanResult::Code::kInterfaceDown;
    case EINVAL:
      return CanResult::Code::kInvalidFrame;
    default:
      return CanResult::Code::kIoError;
  }
}

SocketCanBus::SocketCanBus(const CanUrl& url, const CanBusOptions& options) : url_(url), options_(options) {}

SocketCanBus::~SocketCanBus() { Close(); }

std::unique_ptr<SocketCanBus> SocketCanBus::Open(const CanUrl& url, const CanBusOptions& options,
                                                 std::string* error) {
  std::unique_ptr<SocketCanBus> bus(new SocketCanBus(url, options));
  std::string why;
  if (!bus->OpenSocket(&why)) {
    if (error != nullptr) *error = url.ToString() + ": " + why;
    return nullptr;
  }
  return bus;
}

void SocketCanBus::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool SocketCanBus::OpenSocket(std::string* error) {
  const int fd = socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    const int e = errno;
    *error = (e == EAFNOSUPPORT)
                 ? "AF_CAN not supported by this kernel (socket(PF_CAN, SOCK_RAW, CAN_RAW): " +
                       std::string(std::strerror(e)) +
                       "); use a kernel with CAN support (modules can, can_raw) or a udp:// bus"
                 : ErrnoText("socket(PF_CAN, SOCK_RAW, CAN_RAW)", e);
    return false;
  }
  // Everything below needs the fd closed on failure.
  const auto fail = [fd, error](const std::string& what) {
    *error = ErrnoText(what, errno);
    ::close(fd);
    return false;
  };
  const unsigned index = if_nametoindex(url_.interface.c_str());
  if (index == 0) return fail("no CAN interface '" + url_.interface + "' (if_nametoindex)");
  if (!options_.filters.empty()) {
    const std::vector<struct can_filter> filters = ToKernelFilters(options_.filters);
    if (setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, filters.data(),
                   static_cast<socklen_t>(filters.size() * sizeof(struct can_filter))) != 0) {
      return fail("setsockopt(CAN_RAW_FILTER)");
    }
  }
  const can_err_mask_t error_mask = CAN_ERR_MASK;  // every error class
  if (setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &error_mask, sizeof(error_mask)) != 0) {
    return fail("setsockopt(CAN_RAW_ERR_FILTER)");
  }
  const int own = options_.receive_own_frames ? 1 : 0;
  if (setsockopt(fd, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &own, sizeof(own)) != 0) {
    return fail("setsockopt(CAN_RAW_RECV_OWN_MSGS)");
  }
  if (options_.receive_buffer_bytes > 0 &&
      setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &options_.receive_buffer_bytes, sizeof(int)) != 0) {
    return fail("setsockopt(SO_RCVBUF)");
  }
  std::string why;
  if (!internal::EnableKernelTimestamps(fd, &why)) return fail(why);
  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = static_cast<int>(index);
  if (bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    return fail("bind to " + url_.interface);
  }
  fd_ = fd;
  return true;
}

CanResult SocketCanBus::Failure(CanResult::Code code, const std::string& message) {
  status_.last_error = message;
  if (code == CanResult::Code::kTxQueueFull) ++status_.tx_queue_full;
  return {code, message};
}

CanResult SocketCanBus::Send(const CanFrame& frame) {
  if (fd_ < 0) return Failure(CanResult::Code::kClosed, url() + ": not open (Reopen() failed)");
  const std::string problem = CheckCanFrame(frame);
  if (!problem.empty()) return Failure(CanResult::Code::kInvalidFrame, "invalid frame: " + problem);
  if (frame.error) {
    return Failure(CanResult::Code::kInvalidFrame, "error frames come from the controller, they cannot be sent");
  }
  if (status_.state == CanBusState::kBusOff) {
    return Failure(CanResult::Code::kBusOff, url() + ": bus-off, waiting for the controller's restart");
  }
  const struct can_frame out = ToLinuxFrame(frame);
  const ssize_t sent = ::send(fd_, &out, sizeof(out), MSG_DONTWAIT);
  if (sent == static_cast<ssize_t>(sizeof(out))) {
    ++status_.frames_sent;
    return CanResult::Ok();
  }
  if (sent >= 0) return Failure(CanResult::Code::kIoError, "short send of a CAN frame");
  const int e = errno;
  return Failure(SendErrorCode(e), ErrnoText(url() + ": send", e));
}

CanResult SocketCanBus::Receive(double timeout_s, ReceivedCanFrame* received) {
  if (fd_ < 0) return Failure(CanResult::Code::kClosed, url() + ": not open (Reopen() failed)");
  const internal::Deadline deadline(timeout_s);
  while (true) {
    const int ready = internal::WaitReadable(fd_, deadline.remaining_s());
    if (ready == 0) return {CanResult::Code::kTimeout, ""};
    if (ready < 0) return Failure(CanResult::Code::kIoError, ErrnoText(url() + ": poll", errno));
    struct can_frame in{};
    const ssize_t got = internal::ReceiveWithTimestamp(fd_, &in, sizeof(in), &received->timestamp_ns,
                                                       &received->kernel_timestamp);
    if (got < 0) {
      const int e = errno;
      if (e == EAGAIN || e == EINTR) continue;
      return Failure(SendErrorCode(e) == CanResult::Code::kInterfaceDown ? CanResult::Code::kInterfaceDown
                                                                          : CanResult::Code::kIoError,
                     ErrnoText(url() + ": recvmsg", e));
    }
    std::string why;
    const std::optional<CanFrame> frame =
        got == static_cast<ssize_t>(sizeof(in)) ? FromLinuxFrame(in, &why) : std::nullopt;
    if (!frame) {
      ++status_.malformed;
      status_.last_error = "dropped a malformed frame (" + std::to_string(got) + " bytes) " + why;
      continue;
    }
    ApplyErrorFrame(*frame, &status_);
    if (frame->error && !options_.deliver_error_frames) continue;
    received->frame = *frame;
    ++status_.frames_received;
    return CanResult::Ok();
  }
}

CanResult SocketCanBus::Reopen() {
  Close();
  std::string why;
  if (!OpenSocket(&why)) return Failure(CanResult::Code::kClosed, url() + ": reopen failed: " + why);
  ++status_.reopen_count;
  // A new socket knows nothing of the controller's state: start error-active again (a
  // controller still bus-off reports itself with its next error frame).
  status_.state = CanBusState::kErrorActive;
  return CanResult::Ok();
}

}  // namespace topay::can
