// The WebSocket handshake: the subprotocol required and selected, any path, refusals (no or
// another subprotocol: 400; beyond max_clients: 503), Start's errors (port in use, bad
// options, twice), Stop closing clients (1001) and a restart.
#include <gtest/gtest.h>

#include <memory>
#include <thread>

#include "procs/viz/server/ws_server.h"
#include "tests/procs/viz/server/ws_test_client.h"

namespace topay::viz {
namespace {

using namespace topay::viz::testing;

class WsServerHandshakeTest : public ::testing::Test {
 protected:
  void StartServer(WsServerOptions options = TestOptions()) {
    server_ = std::make_unique<WsServer>(options, log_.Callbacks());
    std::string error;
    ASSERT_TRUE(server_->Start(&error)) << error;
    ASSERT_GT(server_->port(), 0);
  }

  CallbackLog log_;
  std::unique_ptr<WsServer> server_;
};

TEST_F(WsServerHandshakeTest, SelectsTheRequiredSubprotocol) {
  StartServer();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect()) << "handshake failed";
  EXPECT_EQ(client.response()[http::field::sec_websocket_protocol], kSubprotocol);
  EXPECT_NE(log_.WaitOpened(1), 0u);
  EXPECT_EQ(server_->stats().clients, 1u);
  EXPECT_EQ(server_->stats().clients_opened, 1u);
}

TEST_F(WsServerHandshakeTest, AcceptsItAmongOthersAndOnAnyPath) {
  StartServer();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect("other.v1, foxglove.websocket.v1", false, "/any/path?x=1"));
  EXPECT_EQ(client.response()[http::field::sec_websocket_protocol], kSubprotocol);
  EXPECT_NE(log_.WaitOpened(1), 0u);
}

TEST_F(WsServerHandshakeTest, RefusesUpgradesWithoutIt) {
  StartServer();
  for (const char* offered : {"", "foxglove.websocket.v2", "foxglove.websocket.v1.1"}) {
    TestClient client(server_->port());
    EXPECT_EQ(client.Connect(offered), websocket::error::upgrade_declined) << offered;
    EXPECT_EQ(client.response().result(), http::status::bad_request) << offered;
  }
  EXPECT_EQ(server_->stats().connections_refused, 3u);
  EXPECT_EQ(server_->stats().clients_opened, 0u);
  EXPECT_TRUE(log_.opened().empty());
}

TEST_F(WsServerHandshakeTest, RefusesClientsBeyondMaxClientsWith503) {
  WsServerOptions options = TestOptions();
  options.max_clients = 2;
  StartServer(options);
  TestClient first(server_->port());
  TestClient second(server_->port());
  ASSERT_FALSE(first.Connect());
  ASSERT_FALSE(second.Connect());
  TestClient third(server_->port());
  EXPECT_EQ(third.Connect(), websocket::error::upgrade_declined);
  EXPECT_EQ(third.response().result(), http::status::service_unavailable);
  EXPECT_EQ(server_->stats().connections_refused, 1u);
  // A slot freed is a slot again.
  const ClientId first_id = log_.WaitOpened(1);
  ASSERT_FALSE(first.Close());
  ASSERT_TRUE(log_.WaitClosed(first_id));
  ASSERT_TRUE(WaitUntil([&] { return server_->stats().clients == 1; }));
  TestClient fourth(server_->port());
  EXPECT_FALSE(fourth.Connect());
}

TEST_F(WsServerHandshakeTest, StartFailsOnAPortInUseNamingTheAddress) {
  StartServer();
  WsServerOptions options = TestOptions();
  options.port = server_->port();
  WsServer second(options, {});
  std::string error;
  EXPECT_FALSE(second.Start(&error));
  EXPECT_NE(error.find("127.0.0.1:" + std::to_string(server_->port())), std::string::npos)
      << error;
  EXPECT_FALSE(second.running());
  second.Stop();  // harmless
}

TEST_F(WsServerHandshakeTest, StartFailsOnBadOptionsAndWhenStarted) {
  WsServerOptions options = TestOptions();
  options.bind_address = "not-an-address";
  WsServer bad(options, {});
  std::string error;
  EXPECT_FALSE(bad.Start(&error));
  EXPECT_NE(error.find("not-an-address"), std::string::npos) << error;
  StartServer();
  EXPECT_FALSE(server_->Start(&error));
  EXPECT_NE(error.find("already"), std::string::npos) << error;
}

TEST_F(WsServerHandshakeTest, StopClosesClientsWithGoingAwayAndIsIdempotent) {
  StartServer();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  const ClientId id = log_.WaitOpened(1);
  ASSERT_NE(id, 0u);
  beast::error_code read_error;
  std::thread reader([&] {  // a reading client answers the close frame
    std::string message;
    read_error = client.Read(&message);
  });
  const auto start = std::chrono::steady_clock::now();
  server_->Stop();
  EXPECT_LT(SecondsSince(start), 0.5);
  reader.join();
  EXPECT_EQ(log_.closed(), std::vector<ClientId>{id});
  EXPECT_EQ(read_error, websocket::error::closed);
  EXPECT_EQ(client.ws().reason().code, websocket::close_code::going_away);
  server_->Stop();
  EXPECT_FALSE(server_->running());
  EXPECT_EQ(server_->stats().clients, 0u);
  server_->Send(id, TextFrame("after stop"));  // ignored
}

TEST_F(WsServerHandshakeTest, RestartsAfterStop) {
  StartServer();
  server_->Stop();
  std::string error;
  ASSERT_TRUE(server_->Start(&error)) << error;
  TestClient client(server_->port());
  EXPECT_FALSE(client.Connect());
  EXPECT_NE(log_.WaitOpened(1), 0u);
}

TEST_F(WsServerHandshakeTest, StopCallsOnCloseForClientsThatDoNotAnswer) {
  WsServerOptions options = TestOptions();
  options.close_timeout_s = 0.2;
  StartServer(options);
  TestClient client(server_->port());  // never reads: never answers the close frame
  ASSERT_FALSE(client.Connect());
  const ClientId id = log_.WaitOpened(1);
  const auto start = std::chrono::steady_clock::now();
  server_->Stop();
  EXPECT_LT(SecondsSince(start), 2.0);
  EXPECT_EQ(log_.closed(), std::vector<ClientId>{id});
}

}  // namespace
}  // namespace topay::viz
