// The option checks: the defaults pass, each bad value is named.
#include "procs/viz/server/ws_server_options.h"

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

TEST(WsServerOptionsTest, DefaultsAreLoopbackAndValid) {
  const WsServerOptions options;
  EXPECT_EQ(options.bind_address, "127.0.0.1");
  EXPECT_EQ(options.subprotocol, "foxglove.websocket.v1");
  EXPECT_EQ(CheckWsServerOptions(options), "");
}

TEST(WsServerOptionsTest, NamesTheBadValue) {
  WsServerOptions options;
  options.port = 70000;
  EXPECT_NE(CheckWsServerOptions(options).find("port 70000"), std::string::npos);
  options = {};
  options.bind_address = "localhost";  // a name, not an address
  EXPECT_NE(CheckWsServerOptions(options).find("localhost"), std::string::npos);
  options = {};
  options.max_clients = 0;
  EXPECT_NE(CheckWsServerOptions(options).find("max_clients"), std::string::npos);
  options = {};
  options.max_queue_bytes = 0;
  EXPECT_NE(CheckWsServerOptions(options).find("max_queue_bytes"), std::string::npos);
  options = {};
  options.handshake_timeout_s = 0;
  EXPECT_NE(CheckWsServerOptions(options).find("handshake_timeout_s"), std::string::npos);
  options = {};
  options.subprotocol = "";
  EXPECT_NE(CheckWsServerOptions(options).find("subprotocol"), std::string::npos);
  options = {};
  options.bind_address = "::1";
  EXPECT_EQ(CheckWsServerOptions(options), "");
}

}  // namespace
}  // namespace topay::viz
