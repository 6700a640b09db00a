#include "procs/runtime/watchdog_notify.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace topay::procs {
namespace {

// sockaddr_un for a path or an abstract name ("@name": a leading NUL instead of the '@').
bool MakeAddress(const std::string& name, sockaddr_un* address, socklen_t* length, std::string* error) {
  std::memset(address, 0, sizeof(*address));
  address->sun_family = AF_UNIX;
  if (name.empty() || name.size() >= sizeof(address->sun_path)) {
    *error = "notify socket name '" + name + "': empty or longer than " +
             std::to_string(sizeof(address->sun_path) - 1) + " characters";
    return false;
  }
  std::memcpy(address->sun_path, name.data(), name.size());
  if (name[0] == '@') address->sun_path[0] = '\0';
  *length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + name.size() + (name[0] == '@' ? 0 : 1));
  return true;
}

}  // namespace

WatchdogNotifier::WatchdogNotifier(std::optional<std::string> socket_name) {
  if (!socket_name) {
    const char* env = std::getenv(kNotifySocketEnv);
    if (env == nullptr || *env == '\0') return;
    socket_name = env;
  }
  name_ = *socket_name;
  if (!MakeAddress(name_, &address_, &address_length_, &error_)) address_length_ = 0;
  fd_ = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) error_ = std::string("notify socket: ") + std::strerror(errno);
}

WatchdogNotifier::~WatchdogNotifier() {
  if (fd_ >= 0) close(fd_);
}

bool WatchdogNotifier::Notify() {
  if (fd_ < 0 || address_length_ == 0) return false;  // a bad name: error_ says so
  if (sendto(fd_, kWatchdogMessage.data(), kWatchdogMessage.size(), MSG_DONTWAIT | MSG_NOSIGNAL,
             reinterpret_cast<const sockaddr*>(&address_), address_length_) < 0) {
    error_ = "notify socket " + name_ + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

WatchdogSocket::WatchdogSocket(std::string name) : name_(std::move(name)) {
  sockaddr_un address;
  socklen_t length = 0;
  std::string error;
  if (!MakeAddress(name_, &address, &length, &error)) throw std::runtime_error(error);
  fd_ = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) throw std::runtime_error("notify socket " + name_ + ": " + std::strerror(errno));
  const int on = 1;
  if (name_[0] != '@') unlink(name_.c_str());
  if (setsockopt(fd_, SOL_SOCKET, SO_PASSCRED, &on, sizeof(on)) < 0 ||
      bind(fd_, reinterpret_cast<const sockaddr*>(&address), length) < 0) {
    const std::string why = std::strerror(errno);
    close(fd_);
    fd_ = -1;
    throw std::runtime_error("notify socket " + name_ + ": " + why);
  }
}

WatchdogSocket::~WatchdogSocket() {
  if (fd_ < 0) return;
  close(fd_);
  if (name_[0] != '@') unlink(name_.c_str());
}

int WatchdogSocket::ReadAll(const std::function<void(pid_t, std::string_view)>& on_message) {
  int count = 0;
  for (;;) {
    char text[256];
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(ucred))];
    iovec io{text, sizeof(text)};
    msghdr message{};
    message.msg_iov = &io;
    message.msg_iovlen = 1;
    message.msg_control = control;
    message.msg_controllen = sizeof(control);
    const ssize_t n = recvmsg(fd_, &message, MSG_DONTWAIT | MSG_CMSG_CLOEXEC);
    if (n < 0) return count;  // EAGAIN: none left (or an error: tried again at the next poll)
    ++count;
    const cmsghdr* c = CMSG_FIRSTHDR(&message);
    if (c == nullptr || c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_CREDENTIALS) continue;
    ucred credentials;
    std::memcpy(&credentials, CMSG_DATA(c), sizeof(credentials));
    on_message(credentials.pid, std::string_view(text, static_cast<std::size_t>(n)));
  }
}

}  // namespace topay::procs
