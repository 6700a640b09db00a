#pragma once
// Private network namespaces for LCM's UDP multicast: nothing sent or joined inside one leaves
// the machine, and two namespaces do not see each other's packets.

#include <functional>
#include <string>

namespace topay::procs {

/// The environment variable through which EnterPrivateNetworkNamespace hands its children the
/// network namespace it left (an open file descriptor number, inherited across exec): a process
/// of an isolated graph that must serve the machine itself (topay-viz's page) binds there.
inline constexpr const char* kHostNetnsFdVariable = "TOPAY_HOST_NETNS_FD";

/// Moves the calling process into a new, private network namespace with loopback up and a
/// multicast route (224.0.0.0/4 via lo), like
/// `unshare -rn sh -c 'ip link set lo up; ip route add 224.0.0.0/4 dev lo'`.
/// As root (or with CAP_SYS_ADMIN) only the network namespace is new; otherwise a user
/// namespace mapping the caller's uid and gid to root is created with it (unprivileged
/// `unshare -rn`). Must be called before the process starts any thread (unshare of a user
/// namespace requires a single-threaded caller). Returns false with *error on failure.
/// Before leaving, it opens the namespace it is in (inherited by children) and names the
/// descriptor in $TOPAY_HOST_NETNS_FD, unless that is already set (the outermost one counts).
bool EnterPrivateNetworkNamespace(std::string* error);

/// Runs `fn` on the calling thread inside the network namespace of $TOPAY_HOST_NETNS_FD and
/// returns to the current one: sockets `fn` creates (a listening socket, and every connection
/// it accepts) belong to that namespace. Without the variable, runs `fn` here. Returns false
/// with *error, without running fn, if the namespace cannot be entered (no CAP_SYS_ADMIN
/// there, e.g. an unprivileged graph in a user namespace).
bool RunInHostNetworkNamespace(const std::function<void()>& fn, std::string* error);

/// Sets lo up and adds the route 224.0.0.0/4 dev lo in the current network namespace (needs
/// CAP_NET_ADMIN in it). An existing route counts as success. Returns false with *error.
bool SetUpLoopbackMulticast(std::string* error);

}  // namespace topay::procs
