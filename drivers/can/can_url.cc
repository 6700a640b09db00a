#include "drivers/can/can_url.h"

#include <arpa/inet.h>
#include <net/if.h>

#include <stdexcept>

#include "drivers/can/socketcan_bus.h"
#include "drivers/can/udp_can_bus.h"

namespace topay::can {
namespace {

constexpr std::string_view kSocketCanPrefix = "socketcan://";
constexpr std::string_view kUdpPrefix = "udp://";

bool Fail(std::string* error, std::string_view url, const std::string& message) {
  if (error != nullptr) *error = std::string(url) + ": " + message;
  return false;
}

bool ParseInterface(std::string_view url, std::string_view name, CanUrl* out, std::string* error) {
  if (name.empty()) return Fail(error, url, "no interface name after socketcan:// (e.g. socketcan://can0)");
  if (name.size() >= IFNAMSIZ) {
    return Fail(error, url, "interface name '" + std::string(name) + "' is longer than " +
                                std::to_string(IFNAMSIZ - 1) + " characters");
  }
  for (const char c : name) {
    if (c == '/' || c == ':' || c == '?' || c <= ' ' || c > '~') {
      return Fail(error, url, "interface name '" + std::string(name) + "' has a bad character '" +
                                  std::string(1, c) + "'");
    }
  }
  out->scheme = CanUrl::Scheme::kSocketCan;
  out->interface = std::string(name);
  return true;
}

bool ParsePort(std::string_view url, std::string_view text, CanUrl* out, std::string* error) {
  if (text.empty()) return Fail(error, url, "no port after ':' (1-65535)");
  long value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return Fail(error, url, "port '" + std::string(text) + "' is not a number");
    value = value * 10 + (c - '0');
    if (value > 65535) break;
  }
  if (value < 1 || value > 65535) {
    return Fail(error, url, "port " + std::string(text) + " is outside 1-65535");
  }
  out->port = static_cast<std::uint16_t>(value);
  return true;
}

bool ParseUdp(std::string_view url, std::string_view rest, CanUrl* out, std::string* error) {
  const std::size_t colon = rest.rfind(':');
  if (rest.empty() || colon == std::string_view::npos) {
    return Fail(error, url, "expected udp://GROUP:PORT, e.g. udp://239.255.1.1:9000");
  }
  const std::string group(rest.substr(0, colon));
  in_addr address{};
  // inet_pton reads a C string: digits and dots only, or "239.255.1.1\0junk" would pass as its
  // prefix and the junk stay in the group.
  if (group.empty() || group.find_first_not_of("0123456789.") != std::string::npos ||
      inet_pton(AF_INET, group.c_str(), &address) != 1) {
    return Fail(error, url, "group '" + group + "' is not an IPv4 address (dotted quad)");
  }
  if (!IN_MULTICAST(ntohl(address.s_addr))) {
    return Fail(error, url, "group " + group + " is not an IPv4 multicast address (224.0.0.0/4)");
  }
  out->scheme = CanUrl::Scheme::kUdp;
  out->group = group;
  return ParsePort(url, rest.substr(colon + 1), out, error);
}

}  // namespace

std::string CanUrl::ToString() const {
  if (scheme == Scheme::kSocketCan) return std::string(kSocketCanPrefix) + interface;
  return std::string(kUdpPrefix) + group + ":" + std::to_string(port);
}

std::optional<CanUrl> ParseCanUrl(std::string_view text, std::string* error) {
  CanUrl url;
  bool ok = false;
  if (text.starts_with(kSocketCanPrefix)) {
    ok = ParseInterface(text, text.substr(kSocketCanPrefix.size()), &url, error);
  } else if (text.starts_with(kUdpPrefix)) {
    ok = ParseUdp(text, text.substr(kUdpPrefix.size()), &url, error);
  } else {
    Fail(error, text, "unknown scheme: expected socketcan://IFACE or udp://GROUP:PORT");
  }
  if (!ok) return std::nullopt;
  return url;
}

std::unique_ptr<CanBus> OpenCanBus(std::string_view text, const CanBusOptions& options, std::string* error) {
  std::string why;
  const std::optional<CanUrl> url = ParseCanUrl(text, &why);
  if (url) {
    try {
      options.Check();
    } catch (const std::invalid_argument& e) {
      why = std::string(text) + ": " + e.what();
      if (error != nullptr) *error = why;
      return nullptr;
    }
  }
  std::unique_ptr<CanBus> bus;
  if (url && url->scheme == CanUrl::Scheme::kSocketCan) bus = SocketCanBus::Open(*url, options, &why);
  if (url && url->scheme == CanUrl::Scheme::kUdp) bus = UdpCanBus::Open(*url, options, &why);
  if (bus == nullptr && error != nullptr) *error = why;
  return bus;
}

}  // namespace topay::can
