#include "drivers/can/udp_can_bus.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <random>

#include "drivers/can/socket_io.h"
#include "drivers/can/udp_can_datagram.h"

namespace topay::can {
namespace {

using internal::ErrnoText;

std::uint32_t RandomNodeId() {
  std::random_device device;  // getrandom(): distinct per process
  std::uint32_t id = 0;
  while (id == 0) id = device();
  return id;
}

sockaddr_in GroupAddress(const CanUrl& url) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(url.port);
  inet_pton(AF_INET, url.group.c_str(), &address.sin_addr);
  return address;
}

}  // namespace

UdpCanBus::UdpCanBus(const CanUrl& url, const CanBusOptions& options, std::uint32_t node_id)
    : url_(url), options_(options), node_id_(node_id) {}

UdpCanBus::~UdpCanBus() { Close(); }

std::unique_ptr<UdpCanBus> UdpCanBus::Open(const CanUrl& url, const CanBusOptions& options, std::string* error) {
  const std::uint32_t id = options.udp_node_id != 0 ? options.udp_node_id : RandomNodeId();
  std::unique_ptr<UdpCanBus> bus(new UdpCanBus(url, options, id));
  std::string why;
  if (!bus->OpenSocket(&why)) {
    if (error != nullptr) *error = url.ToString() + ": " + why;
    return nullptr;
  }
  return bus;
}

void UdpCanBus::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool UdpCanBus::OpenSocket(std::string* error) {
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    *error = ErrnoText("socket(AF_INET, SOCK_DGRAM)", errno);
    return false;
  }
  const auto fail = [fd, error](const std::string& what) {
    *error = ErrnoText(what, errno);
    ::close(fd);
    return false;
  };
  const int on = 1;
  if (setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof(on)) != 0) return fail("setsockopt(SO_REUSEADDR)");
  if (options_.receive_buffer_bytes > 0 &&
      setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &options_.receive_buffer_bytes, sizeof(int)) != 0) {
    return fail("setsockopt(SO_RCVBUF)");
  }
  const sockaddr_in group = GroupAddress(url_);
  // Bound to the group address: only datagrams sent to the group reach this socket.
  if (bind(fd, reinterpret_cast<const sockaddr*>(&group), sizeof(group)) != 0) {
    return fail("bind to " + url_.group + ":" + std::to_string(url_.port));
  }
  ip_mreq membership{};
  membership.imr_multiaddr = group.sin_addr;
  membership.imr_interface.s_addr = htonl(INADDR_ANY);
  if (setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof(membership)) != 0) {
    return fail("joining multicast group " + url_.group + " (is there a multicast route?)");
  }
  const unsigned char ttl = 0;  // never leave the host
  const unsigned char loop = 1; // deliver to the other nodes on this host
  if (setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof(ttl)) != 0) return fail("IP_MULTICAST_TTL");
  if (setsockopt(fd, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof(loop)) != 0) return fail("IP_MULTICAST_LOOP");
  std::string why;
  if (!internal::EnableKernelTimestamps(fd, &why)) {
    errno = 0;
    *error = why;
    ::close(fd);
    return false;
  }
  fd_ = fd;
  return true;
}

CanResult UdpCanBus::Failure(CanResult::Code code, const std::string& message) {
  status_.last_error = message;
  if (code == CanResult::Code::kTxQueueFull) ++status_.tx_queue_full;
  return {code, message};
}

CanResult UdpCanBus::Send(const CanFrame& frame) {
  if (fd_ < 0) return Failure(CanResult::Code::kClosed, url() + ": not open (Reopen() failed)");
  const std::string problem = CheckCanFrame(frame);
  if (!problem.empty()) return Failure(CanResult::Code::kInvalidFrame, "invalid frame: " + problem);
  // Like a controller, a node whose bus is off does not transmit; error frames (a simulator's
  // way to drive the bus state, including its restart) always go out.
  if (status_.state == CanBusState::kBusOff && !frame.error) {
    return Failure(CanResult::Code::kBusOff, url() + ": bus-off, waiting for a restart (CAN_ERR_RESTARTED)");
  }
  const auto bytes = EncodeUdpCanDatagram({node_id_, next_sequence_, frame});
  const sockaddr_in group = GroupAddress(url_);
  const ssize_t sent = sendto(fd_, bytes.data(), bytes.size(), MSG_DONTWAIT,
                              reinterpret_cast<const sockaddr*>(&group), sizeof(group));
  if (sent == static_cast<ssize_t>(bytes.size())) {
    ++next_sequence_;
    ++status_.frames_sent;
    return CanResult::Ok();
  }
  if (sent >= 0) return Failure(CanResult::Code::kIoError, url() + ": short send");
  const int e = errno;
  const CanResult::Code code = (e == ENOBUFS || e == EAGAIN) ? CanResult::Code::kTxQueueFull
                               : (e == ENETDOWN || e == ENETUNREACH || e == ENODEV)
                                   ? CanResult::Code::kInterfaceDown
                                   : CanResult::Code::kIoError;
  return Failure(code, ErrnoText(url() + ": sendto", e));
}

void UdpCanBus::TrackSequence(std::uint32_t sender, std::uint32_t sequence) {
  const auto [entry, first] = expected_sequence_.try_emplace(sender, sequence);
  if (!first) {
    // Unsigned difference: wraps correctly. An older sequence (a huge gap) is not a loss: the
    // loopback does not reorder, so it is a sender restarted with a fixed udp_node_id, and the
    // count starts again from it.
    const std::uint32_t gap = sequence - entry->second;
    if (gap != 0 && gap < 0x80000000u) status_.lost_frames += gap;
  }
  entry->second = sequence + 1;
}

CanResult UdpCanBus::Receive(double timeout_s, ReceivedCanFrame* received) {
  if (fd_ < 0) return Failure(CanResult::Code::kClosed, url() + ": not open (Reopen() failed)");
  const internal::Deadline deadline(timeout_s);
  std::uint8_t bytes[kUdpCanDatagramBytes + 1];  // one more: a longer datagram shows as too long
  while (true) {
    const int ready = internal::WaitReadable(fd_, deadline.remaining_s());
    if (ready == 0) return {CanResult::Code::kTimeout, ""};
    if (ready < 0) return Failure(CanResult::Code::kIoError, ErrnoText(url() + ": poll", errno));
    const ssize_t got = internal::ReceiveWithTimestamp(fd_, bytes, sizeof(bytes), &received->timestamp_ns,
                                                       &received->kernel_timestamp);
    if (got < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      return Failure(CanResult::Code::kIoError, ErrnoText(url() + ": recvmsg", errno));
    }
    std::string why;
    // `got` is the datagram's real size (MSG_TRUNC); the decoder reads bytes only when it is 32.
    const std::optional<UdpCanDatagram> datagram =
        DecodeUdpCanDatagram(bytes, static_cast<std::size_t>(got), &why);
    if (!datagram) {
      ++status_.malformed;
      status_.last_error = url() + ": dropped a malformed datagram: " + why;
      continue;
    }
    const bool own = datagram->sender_id == node_id_;
    if (!own) TrackSequence(datagram->sender_id, datagram->sequence);
    if (own && !options_.receive_own_frames) continue;
    ApplyErrorFrame(datagram->frame, &status_);
    if (datagram->frame.error ? !options_.deliver_error_frames : !PassesFilters(options_.filters, datagram->frame)) {
      continue;
    }
    received->frame = datagram->frame;
    ++status_.frames_received;
    return CanResult::Ok();
  }
}

CanResult UdpCanBus::Reopen() {
  Close();
  std::string why;
  if (!OpenSocket(&why)) return Failure(CanResult::Code::kClosed, url() + ": reopen failed: " + why);
  ++status_.reopen_count;
  status_.state = CanBusState::kErrorActive;  // a fresh node, as SocketCanBus::Reopen()
  return CanResult::Ok();
}

}  // namespace topay::can
