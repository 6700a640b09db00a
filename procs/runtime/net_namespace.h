#pragma once
// Private network namespaces for LCM's UDP multicast: nothing sent or joined inside one leaves
// the machine, and two namespaces do not see each other's packets.

#include <string>

namespace topay::procs {

/// Moves the calling process into a new, private network namespace with loopback up and a
/// multicast route (224.0.0.0/4 via lo), like
/// `unshare -rn sh -c 'ip link set lo up; ip route add 224.0.0.0/4 dev lo'`.
/// As root (or with CAP_SYS_ADMIN) only the network namespace is new; otherwise a user
/// namespace mapping the caller's uid and gid to root is created with it (unprivileged
/// `unshare -rn`). Must be called before the process starts any thread (unshare of a user
/// namespace requires a single-threaded caller). Returns false with *error on failure.
bool EnterPrivateNetworkNamespace(std::string* error);

/// Sets lo up and adds the route 224.0.0.0/4 dev lo in the current network namespace (needs
/// CAP_NET_ADMIN in it). An existing route counts as success. Returns false with *error.
bool SetUpLoopbackMulticast(std::string* error);

}  // namespace topay::procs
