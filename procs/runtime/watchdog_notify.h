#pragma once
// A local liveness channel beside the HEARTBEAT, in the form of systemd's sd_notify watchdog:
// each process sends "WATCHDOG=1" with every heartbeat to the Unix datagram socket named by
// NOTIFY_SOCKET (a path, or "@name" for the abstract namespace), and topay-launch, which sets
// NOTIFY_SOCKET for its children, reads the sender's pid from the kernel's credentials. A
// datagram on a local socket is not lost the way a UDP multicast heartbeat is on a lossy bus:
// with 10 % of the bus's datagrams dropped, four heartbeats in a row were lost and the launcher
// killed a working mapper (docs/reliability.md, finding 40).

#include <sys/socket.h>
#include <sys/types.h>
#include <sys/un.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace topay::procs {

/// The environment variable naming the socket (systemd's name: the same units may run under it).
inline constexpr const char* kNotifySocketEnv = "NOTIFY_SOCKET";
inline constexpr std::string_view kWatchdogMessage = "WATCHDOG=1";

/// The process side. Without NOTIFY_SOCKET it does nothing.
class WatchdogNotifier {
 public:
  /// Reads NOTIFY_SOCKET; `socket_name` overrides it (tests).
  explicit WatchdogNotifier(std::optional<std::string> socket_name = std::nullopt);
  ~WatchdogNotifier();
  WatchdogNotifier(const WatchdogNotifier&) = delete;
  WatchdogNotifier& operator=(const WatchdogNotifier&) = delete;

  bool enabled() const { return fd_ >= 0; }
  /// Sends "WATCHDOG=1" without blocking; false if it could not (error() says why; a full
  /// socket buffer or a launcher gone is not the process's fault, so callers only count it).
  bool Notify();
  const std::string& error() const { return error_; }

 private:
  int fd_ = -1;
  std::string name_;
  sockaddr_un address_{};         // the socket's address, made once (0 length: a bad name, error_)
  socklen_t address_length_ = 0;
  std::string error_;
};

/// The supervisor side: a bound datagram socket that passes each sender's credentials.
class WatchdogSocket {
 public:
  /// Binds `name` ("@..." abstract, else a path, which is replaced); throws std::runtime_error
  /// naming the socket and the error if it cannot.
  explicit WatchdogSocket(std::string name);
  ~WatchdogSocket();
  WatchdogSocket(const WatchdogSocket&) = delete;
  WatchdogSocket& operator=(const WatchdogSocket&) = delete;

  int fd() const { return fd_; }
  const std::string& name() const { return name_; }
  /// Reads every waiting datagram and calls `on_message(sender pid, text)` for each; datagrams
  /// without credentials are dropped. Returns how many were read.
  int ReadAll(const std::function<void(pid_t, std::string_view)>& on_message);

 private:
  int fd_ = -1;
  std::string name_;
};

}  // namespace topay::procs
