// Messages both ways: on_open / on_text / on_binary / on_close with the client's id, Send
// delivering text and binary frames in order to the right client, Close from the server,
// permessage-deflate, callbacks that Send (re-entrantly) or throw.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <thread>

#include "procs/viz/server/ws_server.h"
#include "tests/procs/viz/server/ws_test_client.h"

namespace topay::viz {
namespace {

using namespace topay::viz::testing;

class WsServerMessagesTest : public ::testing::Test {
 protected:
  void StartServer(WsServerOptions options = TestOptions(),
                   std::optional<WsServerCallbacks> callbacks = std::nullopt) {
    server_ = std::make_unique<WsServer>(options, callbacks ? *callbacks : log_.Callbacks());
    std::string error;
    ASSERT_TRUE(server_->Start(&error)) << error;
  }

  CallbackLog log_;
  std::unique_ptr<WsServer> server_;
};

TEST_F(WsServerMessagesTest, CallbacksSeeOpenMessagesAndClose) {
  StartServer();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  const ClientId id = log_.WaitOpened(1);
  ASSERT_NE(id, 0u);
  ASSERT_FALSE(client.Write("{\"op\":\"subscribe\"}"));
  ASSERT_FALSE(client.Write(std::string("\x00\x01\xff", 3), true));
  ASSERT_TRUE(WaitUntil([&] { return log_.messages().size() == 2; }));
  const auto messages = log_.messages();
  EXPECT_EQ(messages[0].client, id);
  EXPECT_EQ(messages[0].data, "{\"op\":\"subscribe\"}");
  EXPECT_FALSE(messages[0].binary);
  EXPECT_EQ(messages[1].data, std::string("\x00\x01\xff", 3));
  EXPECT_TRUE(messages[1].binary);
  ASSERT_FALSE(client.Close());
  EXPECT_TRUE(log_.WaitClosed(id));
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().clients == 0; }));
  EXPECT_EQ(log_.closed().size(), 1u);
}

TEST_F(WsServerMessagesTest, SendDeliversTextAndBinaryInOrderToItsClientOnly) {
  StartServer();
  TestClient a(server_->port());
  TestClient b(server_->port());
  ASSERT_FALSE(a.Connect());
  const ClientId a_id = log_.WaitOpened(1);
  ASSERT_FALSE(b.Connect());
  const ClientId b_id = log_.WaitOpened(2);
  constexpr int kFrames = 200;
  for (int i = 0; i < kFrames; ++i) {
    server_->Send(a_id, i % 2 ? BinaryFrame("bin " + std::to_string(i))
                              : TextFrame("text " + std::to_string(i)));
  }
  server_->Send(b_id, TextFrame("for b"));
  for (int i = 0; i < kFrames; ++i) {
    std::string message;
    bool binary = false;
    ASSERT_FALSE(a.Read(&message, &binary)) << i;
    EXPECT_EQ(message, (i % 2 ? "bin " : "text ") + std::to_string(i));
    EXPECT_EQ(binary, i % 2 == 1);
  }
  std::string message;
  ASSERT_FALSE(b.Read(&message));
  EXPECT_EQ(message, "for b");
  ASSERT_TRUE(WaitUntil([&] { return server_->stats().frames_sent == kFrames + 1; }));
  EXPECT_EQ(server_->stats().frames_dropped, 0u);
  const std::optional<ClientStats> a_stats = server_->client_stats(a_id);
  ASSERT_TRUE(a_stats);
  EXPECT_EQ(a_stats->frames_sent, static_cast<std::uint64_t>(kFrames));
  EXPECT_EQ(a_stats->queued_frames, 0u);
}

TEST_F(WsServerMessagesTest, UnknownClientsAndNullPayloadsAreIgnored) {
  StartServer();
  server_->Send(12345, TextFrame("nobody"));
  server_->Send(0, TextFrame("nobody"));
  server_->Close(12345);
  EXPECT_FALSE(server_->client_stats(12345));
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  const ClientId id = log_.WaitOpened(1);
  server_->Send(id, OutgoingFrame{nullptr, true});
  server_->Send(id, TextFrame("real"));
  std::string message;
  ASSERT_FALSE(client.Read(&message));
  EXPECT_EQ(message, "real");
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().frames_sent == 1; }));
}

TEST_F(WsServerMessagesTest, CloseFromTheServerEndsTheClient) {
  StartServer();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  const ClientId id = log_.WaitOpened(1);
  server_->Close(id);
  std::string message;
  EXPECT_EQ(client.Read(&message), websocket::error::closed);
  EXPECT_EQ(client.ws().reason().code, websocket::close_code::normal);
  EXPECT_TRUE(log_.WaitClosed(id));
  EXPECT_FALSE(server_->client_stats(id));
  server_->Send(id, TextFrame("too late"));  // ignored
  EXPECT_EQ(server_->stats().clients, 0u);
}

TEST_F(WsServerMessagesTest, CompressesForClientsThatOfferDeflate) {
  StartServer();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect(kSubprotocol, true));
  EXPECT_NE(std::string(client.response()[http::field::sec_websocket_extensions])
                .find("permessage-deflate"),
            std::string::npos);
  const ClientId id = log_.WaitOpened(1);
  std::string big;
  for (int i = 0; big.size() < 200000; ++i) big += "{\"x\":" + std::to_string(i % 100) + "},";
  server_->Send(id, TextFrame(big));
  server_->Send(id, BinaryFrame("tail"));
  std::string message;
  ASSERT_FALSE(client.Read(&message));
  EXPECT_EQ(message, big);
  ASSERT_FALSE(client.Read(&message));
  EXPECT_EQ(message, "tail");
  ASSERT_FALSE(client.Write("compressed from the client too"));
  ASSERT_TRUE(WaitUntil([&] { return log_.messages().size() == 1; }));
  EXPECT_EQ(log_.messages()[0].data, "compressed from the client too");
}

TEST_F(WsServerMessagesTest, DeflateCanBeTurnedOff) {
  WsServerOptions options = TestOptions();
  options.permessage_deflate = false;
  StartServer(options);
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect(kSubprotocol, true));
  EXPECT_EQ(client.response()[http::field::sec_websocket_extensions], "");
}

TEST_F(WsServerMessagesTest, CallbacksMaySendAndThrowingOnesAreSurvived) {
  WsServer* server = nullptr;
  WsServerCallbacks callbacks = log_.Callbacks();
  callbacks.on_text = [&server](ClientId id, std::string_view text) {
    if (text == "throw") throw std::runtime_error("a callback's bug");
    server->Send(id, TextFrame("echo " + std::string(text)));
  };
  callbacks.on_open = [&server](ClientId id) { server->Send(id, TextFrame("welcome")); };
  StartServer(TestOptions(), callbacks);
  server = server_.get();
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  std::string message;
  ASSERT_FALSE(client.Read(&message));
  EXPECT_EQ(message, "welcome");
  ASSERT_FALSE(client.Write("throw"));
  ASSERT_FALSE(client.Write("hi"));
  ASSERT_FALSE(client.Read(&message));
  EXPECT_EQ(message, "echo hi");
}

}  // namespace
}  // namespace topay::viz
