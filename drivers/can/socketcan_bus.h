#pragma once
// The SocketCAN backend: a CAN_RAW socket bound to one interface (can0, vcan0, ...).

#include <linux/can.h>

#include <memory>
#include <string>
#include <vector>

#include "drivers/can/can_bus.h"
#include "drivers/can/can_url.h"

namespace topay::can {

/// A node on a SocketCAN interface:
///  - socket(PF_CAN, SOCK_RAW, CAN_RAW), non-blocking, bound to the interface's index;
///  - receive filters handed to the kernel (CAN_RAW_FILTER), own frames per the options
///    (CAN_RAW_RECV_OWN_MSGS);
///  - every error class enabled (CAN_RAW_ERR_FILTER = CAN_ERR_MASK): error frames update
///    status() (state from bus-off / warning / passive / restarted, can_error.h);
///  - kernel receive timestamps (SO_TIMESTAMPNS, read with recvmsg);
///  - Send() never blocks: a full queue (ENOBUFS, EAGAIN) is reported as kTxQueueFull.
///
/// Recovery (docs/can.md): after bus-off the controller is restarted by the kernel (the
/// interface's `restart-ms`, or `ip link set IFACE type can restart`); its CAN_ERR_RESTARTED
/// error frame brings the state back to error-active. While the state is bus-off, Send()
/// refuses with kBusOff. When the interface is down or gone (kInterfaceDown), call Reopen()
/// periodically until it succeeds.
///
/// On a kernel without AF_CAN (these development machines), Open() fails with "AF_CAN not
/// supported by this kernel ...".
class SocketCanBus final : public CanBus {
 public:
  /// Opens the bus on url.interface; nullptr with *error on failure.
  static std::unique_ptr<SocketCanBus> Open(const CanUrl& url, const CanBusOptions& options,
                                            std::string* error);
  ~SocketCanBus() override;

  CanResult Send(const CanFrame& frame) override;
  CanResult Receive(double timeout_s, ReceivedCanFrame* received) override;
  const CanBusStatus& status() const override { return status_; }
  CanResult Reopen() override;
  int fd() const override { return fd_; }
  std::string url() const override { return url_.ToString(); }

 private:
  SocketCanBus(const CanUrl& url, const CanBusOptions& options);
  // Creates, configures and binds the socket into fd_; false with *error.
  bool OpenSocket(std::string* error);
  void Close();
  CanResult Failure(CanResult::Code code, const std::string& message);

  CanUrl url_;
  CanBusOptions options_;
  int fd_ = -1;
  CanBusStatus status_;
};

/// The kernel filter list for `filters` (what CAN_RAW_FILTER receives); exposed for tests.
std::vector<struct can_filter> ToKernelFilters(const std::vector<CanFilter>& filters);

/// The CanResult code for a send() errno: ENOBUFS/EAGAIN -> kTxQueueFull, ENETDOWN/ENODEV/ENXIO
/// -> kInterfaceDown, EINVAL -> kInvalidFrame, others kIoError. Exposed for tests.
CanResult::Code SendErrorCode(int error_number);

}  // namespace topay::can
