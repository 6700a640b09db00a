#include "procs/runtime/net_namespace.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <net/if.h>
#include <net/route.h>
#include <netinet/in.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace topay::procs {
namespace {

std::string Errno(const std::string& what) { return what + ": " + std::strerror(errno); }

bool WriteFile(const std::string& path, const std::string& text, std::string* error) {
  std::ofstream file(path);
  file << text;
  file.flush();
  if (!file) {
    *error = "cannot write " + path;
    return false;
  }
  return true;
}

// unshare(CLONE_NEWUSER | CLONE_NEWNET) with the caller mapped to root in the new namespace.
bool EnterUserAndNetworkNamespace(std::string* error) {
  const uid_t uid = geteuid();
  const gid_t gid = getegid();
  if (unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0) {
    *error = Errno("unshare(CLONE_NEWUSER | CLONE_NEWNET)");
    return false;
  }
  return WriteFile("/proc/self/setgroups", "deny", error) &&
         WriteFile("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1", error) &&
         WriteFile("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1", error);
}

sockaddr_in Ipv4(const char* address) {
  sockaddr_in in{};
  in.sin_family = AF_INET;
  inet_pton(AF_INET, address, &in.sin_addr);
  return in;
}

// Opens the current network namespace, inheritable, and names it in $TOPAY_HOST_NETNS_FD.
void RememberHostNamespace() {
  if (std::getenv(kHostNetnsFdVariable) != nullptr) return;
  const int fd = open("/proc/self/ns/net", O_RDONLY);  // no O_CLOEXEC: children inherit it
  if (fd >= 0) setenv(kHostNetnsFdVariable, std::to_string(fd).c_str(), 1);
}

}  // namespace

bool RunInHostNetworkNamespace(const std::function<void()>& fn, std::string* error) {
  const char* variable = std::getenv(kHostNetnsFdVariable);
  if (variable == nullptr || *variable == '\0') {
    fn();
    return true;
  }
  const int host = std::atoi(variable);
  const int here = open("/proc/thread-self/ns/net", O_RDONLY | O_CLOEXEC);
  if (here < 0) {
    *error = Errno("open /proc/thread-self/ns/net");
    return false;
  }
  if (setns(host, CLONE_NEWNET) != 0) {
    *error = Errno(std::string("setns to the host network namespace ($") + kHostNetnsFdVariable + "=" + variable + ")");
    close(here);
    return false;
  }
  fn();
  const bool back = setns(here, CLONE_NEWNET) == 0;
  if (!back) *error = Errno("setns back to the graph's network namespace");
  close(here);
  return back;
}

bool EnterPrivateNetworkNamespace(std::string* error) {
  RememberHostNamespace();
  if (unshare(CLONE_NEWNET) != 0) {
    const std::string plain = Errno("unshare(CLONE_NEWNET)");
    if (!EnterUserAndNetworkNamespace(error)) {
      *error = plain + "; " + *error;
      return false;
    }
  }
  return SetUpLoopbackMulticast(error);
}

bool SetUpLoopbackMulticast(std::string* error) {
  const int sock = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (sock < 0) {
    *error = Errno("socket");
    return false;
  }
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, "lo", IFNAMSIZ - 1);
  bool ok = ioctl(sock, SIOCGIFFLAGS, &ifr) == 0;
  if (ok) {
    ifr.ifr_flags |= IFF_UP | IFF_RUNNING;
    ok = ioctl(sock, SIOCSIFFLAGS, &ifr) == 0;
  }
  if (!ok) {
    *error = Errno("setting lo up");
    close(sock);
    return false;
  }
  rtentry route{};
  const sockaddr_in dst = Ipv4("224.0.0.0");
  const sockaddr_in mask = Ipv4("240.0.0.0");
  std::memcpy(&route.rt_dst, &dst, sizeof(dst));
  std::memcpy(&route.rt_genmask, &mask, sizeof(mask));
  char device[] = "lo";
  route.rt_dev = device;
  route.rt_flags = RTF_UP;
  if (ioctl(sock, SIOCADDRT, &route) != 0 && errno != EEXIST) {
    *error = Errno("adding the route 224.0.0.0/4 dev lo");
    close(sock);
    return false;
  }
  close(sock);
  return true;
}

}  // namespace topay::procs
