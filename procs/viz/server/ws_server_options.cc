#include "procs/viz/server/ws_server_options.h"

#include <boost/asio/ip/address.hpp>

namespace topay::viz {
namespace {

std::string CheckPositive(const char* name, double value) {
  if (value > 0.0) return "";
  return std::string(name) + " must be > 0 (is " + std::to_string(value) + ")";
}

std::string CheckAtLeastOne(const char* name, std::size_t value) {
  if (value >= 1) return "";
  return std::string(name) + " must be >= 1";
}

std::string CheckAddress(const std::string& address) {
  boost::system::error_code error;
  boost::asio::ip::make_address(address, error);
  if (!error) return "";
  return "bind address '" + address + "' is not an IP address";
}

}  // namespace

std::string CheckWsServerOptions(const WsServerOptions& options) {
  if (options.port < 0 || options.port > 65535) {
    return "port " + std::to_string(options.port) + " is not in 0..65535";
  }
  if (options.subprotocol.empty()) return "subprotocol must not be empty";
  for (const std::string& problem :
       {CheckAddress(options.bind_address), CheckAtLeastOne("max_clients", options.max_clients),
        CheckAtLeastOne("max_http_connections", options.max_http_connections),
        CheckAtLeastOne("max_queue_frames", options.max_queue_frames),
        CheckAtLeastOne("max_queue_bytes", options.max_queue_bytes),
        CheckAtLeastOne("max_incoming_message_bytes", options.max_incoming_message_bytes),
        CheckPositive("handshake_timeout_s", options.handshake_timeout_s),
        CheckPositive("idle_timeout_s", options.idle_timeout_s),
        CheckPositive("close_timeout_s", options.close_timeout_s)}) {
    if (!problem.empty()) return problem;
  }
  return "";
}

}  // namespace topay::viz
