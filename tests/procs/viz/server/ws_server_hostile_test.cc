// Hostile input: garbage instead of HTTP, garbage / unmasked / huge / oversized / invalid
// UTF-8 frames after a valid upgrade, slowloris, 2,000 connections opened and dropped (some
// mid-handshake), hundreds of idle or refused connections. After each: the offender is cut
// and counted, and the server still serves a normal client while Send from this thread
// returns at once.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <random>
#include <thread>

#include "procs/viz/server/ws_server.h"
#include "tests/procs/viz/server/ws_test_client.h"

namespace topay::viz {
namespace {

using namespace topay::viz::testing;

constexpr std::size_t kMaxIncoming = 64 << 10;

std::string RandomBytes(std::size_t size, unsigned seed) {
  std::mt19937 random(seed);
  std::string bytes(size, '\0');
  for (char& byte : bytes) byte = static_cast<char>(random() & 0xff);
  return bytes;
}

class WsServerHostileTest : public ::testing::Test {
 protected:
  void StartServer(WsServerOptions options) {
    server_ = std::make_unique<WsServer>(options, log_.Callbacks());
    std::string error;
    ASSERT_TRUE(server_->Start(&error)) << error;
  }
  void SetUp() override {
    WsServerOptions options = TestOptions();
    options.max_incoming_message_bytes = kMaxIncoming;
    options.handshake_timeout_s = 1.0;
    StartServer(options);
  }

  // A normal client still connects, talks and gets a frame that Send queued at once.
  void ExpectServesANormalClient() {
    SCOPED_TRACE("a normal client after the hostile one");
    TestClient client(server_->port());
    const beast::error_code error = client.Connect();
    ASSERT_FALSE(error) << error.message() << " " << client.response();
    const std::string hello = "hello " + std::to_string(++normal_clients_);
    ASSERT_FALSE(client.Write(hello));
    ClientId id = 0;
    ASSERT_TRUE(WaitUntil([&] {
      for (const CallbackLog::Message& message : log_.messages()) {
        if (message.data == hello) id = message.client;
      }
      return id != 0;
    }));
    const auto start = std::chrono::steady_clock::now();
    server_->Send(id, TextFrame("reply"));
    EXPECT_LT(SecondsSince(start), 0.05);
    std::string reply;
    ASSERT_FALSE(client.Read(&reply));
    EXPECT_EQ(reply, "reply");
    ASSERT_FALSE(client.Close());
    EXPECT_TRUE(log_.WaitClosed(id));
  }

  // A raw connection that completed the WebSocket handshake.
  std::unique_ptr<RawConnection> UpgradedRaw() {
    auto raw = std::make_unique<RawConnection>(server_->port());
    EXPECT_FALSE(raw->Write(UpgradeRequest()));
    EXPECT_TRUE(raw->ReadUntil("\r\n\r\n"));
    EXPECT_EQ(raw->received().rfind("HTTP/1.1 101", 0), 0u) << raw->received();
    return raw;
  }

  // Sends `bytes` after a valid upgrade; expects the server to close the connection, the
  // client to be opened and closed, and `counter` of the stats to grow.
  void ExpectCutAfterUpgrade(const std::string& bytes, std::uint64_t WsServerStats::*counter) {
    const std::uint64_t before = server_->stats().*counter;
    const std::size_t closed_before = log_.closed().size();
    std::unique_ptr<RawConnection> raw = UpgradedRaw();
    raw->Write(bytes);  // may fail: the server can cut the connection before the end
    EXPECT_TRUE(raw->ReadUntilClosed(3.0));
    EXPECT_TRUE(WaitUntil([&] { return server_->stats().*counter == before + 1; }));
    EXPECT_TRUE(WaitUntil([&] { return log_.closed().size() == closed_before + 1; }));
  }

  CallbackLog log_;
  std::unique_ptr<WsServer> server_;
  int normal_clients_ = 0;
};

TEST_F(WsServerHostileTest, GarbageInsteadOfAnHttpRequest) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    RawConnection raw(server_->port());
    raw.Write(RandomBytes(4096, seed));
    EXPECT_TRUE(raw.ReadUntilClosed(3.0)) << seed;
  }
  RawConnection raw(server_->port());
  raw.Write(std::string("\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03", 11));  // a TLS hello
  EXPECT_TRUE(raw.ReadUntilClosed(3.0));
  EXPECT_EQ(raw.received().rfind("HTTP/1.1 400", 0), 0u) << raw.received();
  RawConnection huge_header(server_->port());
  huge_header.Write("GET / HTTP/1.1\r\nX: " + std::string(100000, 'a') + "\r\n\r\n");
  EXPECT_TRUE(huge_header.ReadUntilClosed(3.0));
  EXPECT_GE(server_->stats().http_errors, 21u);
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, GarbageFramesAfterAValidUpgrade) {
  // 0xff: FIN, the three reserved bits and a reserved opcode.
  ExpectCutAfterUpgrade("\xff" + RandomBytes(1024, 7), &WsServerStats::protocol_errors);
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, AnUnmaskedClientFrame) {
  ExpectCutAfterUpgrade(ClientFrame(0x1, "hello", false), &WsServerStats::protocol_errors);
  for (const CallbackLog::Message& message : log_.messages()) EXPECT_NE(message.data, "hello");
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, AFrameHeaderAnnouncing2To40Bytes) {
  std::string header = "\x82\xff";  // binary, FIN; masked, 64-bit length
  for (int shift = 56; shift >= 0; shift -= 8) {
    header.push_back(static_cast<char>((std::uint64_t{1} << 40 >> shift) & 0xff));
  }
  header += "\x01\x02\x03\x04" + std::string(1000, 'z');
  const std::uint64_t before = server_->stats().oversized_messages;
  std::unique_ptr<RawConnection> raw = UpgradedRaw();
  raw->Write(header);
  EXPECT_TRUE(raw->ReadUntilClosed(3.0));
  // The server's close frame: code 1009 (message too big).
  EXPECT_NE(raw->received().find(std::string("\x88\x02\x03\xf1", 4)), std::string::npos);
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().oversized_messages == before + 1; }));
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, AMessageOneByteOverTheLimit) {
  TestClient at_limit(server_->port());
  ASSERT_FALSE(at_limit.Connect());
  ASSERT_FALSE(at_limit.Write(std::string(kMaxIncoming, 'a')));
  ASSERT_TRUE(WaitUntil([&] { return log_.messages().size() == 1; }));
  EXPECT_EQ(log_.messages()[0].data.size(), kMaxIncoming);

  TestClient over(server_->port());
  ASSERT_FALSE(over.Connect());
  ASSERT_FALSE(over.Write(std::string(kMaxIncoming + 1, 'b')));
  std::string message;
  EXPECT_EQ(over.Read(&message), websocket::error::closed);
  EXPECT_EQ(over.ws().reason().code, websocket::close_code::too_big);
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().oversized_messages == 1; }));
  EXPECT_EQ(log_.messages().size(), 1u);
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, AFragmentedMessageOverTheLimit) {
  const std::string half(kMaxIncoming / 2 + 10, 'c');
  std::string first = ClientFrame(0x1, half);
  first[0] = 0x01;  // text, no FIN
  const std::string last = ClientFrame(0x0, half);  // continuation, FIN
  ExpectCutAfterUpgrade(first + last, &WsServerStats::oversized_messages);
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, InvalidUtf8Text) {
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  ASSERT_FALSE(client.Write("ok \xff\xfe\xfd"));
  std::string message;
  EXPECT_EQ(client.Read(&message), websocket::error::closed);
  EXPECT_EQ(client.ws().reason().code, websocket::close_code::bad_payload);
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().protocol_errors == 1; }));
  EXPECT_TRUE(log_.messages().empty());
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, ASlowlorisIsCutAfterTheHandshakeTimeout) {
  RawConnection raw(server_->port());
  const auto start = std::chrono::steady_clock::now();
  raw.Write("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n");
  bool closed = false;
  for (int i = 0; i < 40 && !closed; ++i) {  // a header byte every 100 ms, never ending
    closed = raw.Write("X").failed();
    if (!closed) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_TRUE(raw.ReadUntilClosed(3.0));
  EXPECT_LT(SecondsSince(start), 2.5);  // handshake_timeout_s = 1
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().http_errors >= 1; }));
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, TwoThousandConnectionsOpenedAndDropped) {
  // Meanwhile another thread keeps Sending to a client that never reads.
  TestClient idle(server_->port());
  ASSERT_FALSE(idle.Connect());
  const ClientId idle_id = log_.WaitOpened(1);
  std::atomic<bool> done{false};
  std::atomic<double> longest_send_s{0.0};
  std::thread sender([&] {
    const OutgoingFrame frame = BinaryFrame(std::string(1000, 's'));
    while (!done) {
      const auto start = std::chrono::steady_clock::now();
      server_->Send(idle_id, frame);
      longest_send_s = std::max(longest_send_s.load(), SecondsSince(start));
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  for (int i = 0; i < 2000; ++i) {
    switch (i % 5) {
      case 0: {  // connect, drop
        RawConnection raw(server_->port());
        raw.Drop(i % 2 == 0);
        break;
      }
      case 1: {  // half a request, drop
        RawConnection raw(server_->port());
        raw.Write("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgr");
        raw.Drop(i % 2 == 0);
        break;
      }
      case 2: {  // a whole upgrade request, drop before the answer
        RawConnection raw(server_->port());
        raw.Write(UpgradeRequest());
        raw.Drop(true);
        break;
      }
      case 3: {  // a completed handshake, dropped without a close frame
        TestClient client(server_->port());
        EXPECT_FALSE(client.Connect());
        client.Drop();
        break;
      }
      default: {  // upgraded, half a frame, reset
        RawConnection raw(server_->port());
        raw.Write(UpgradeRequest());
        raw.ReadUntil("\r\n\r\n");
        raw.Write(ClientFrame(0x1, "half a frame").substr(0, 8));
        raw.Drop(true);
        break;
      }
    }
  }
  // Every client opened is closed again, but the idle one.
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().clients == 1; }, 10.0));
  EXPECT_TRUE(WaitUntil([&] { return log_.closed().size() + 1 == log_.opened().size(); }, 10.0));
  EXPECT_GE(server_->stats().connections_accepted, 2001u);
  ExpectServesANormalClient();
  done = true;
  sender.join();
  EXPECT_LT(longest_send_s.load(), 0.1);
  EXPECT_TRUE(server_->client_stats(idle_id));  // the idle client survived it all
}

TEST_F(WsServerHostileTest, IdleConnectionsAndUpgradesBeyondMaxClients) {
  WsServerOptions options = TestOptions();
  options.max_clients = 8;
  options.handshake_timeout_s = 1.0;
  StartServer(options);
  std::vector<std::unique_ptr<TestClient>> clients;
  for (int i = 0; i < 8; ++i) {
    clients.push_back(std::make_unique<TestClient>(server_->port()));
    ASSERT_FALSE(clients.back()->Connect());
  }
  // 200 concurrent upgrades beyond max_clients: all refused with 503.
  std::vector<std::unique_ptr<RawConnection>> refused;
  for (int i = 0; i < 200; ++i) {
    refused.push_back(std::make_unique<RawConnection>(server_->port()));
    refused.back()->Write(UpgradeRequest());
  }
  for (auto& raw : refused) {
    EXPECT_TRUE(raw->ReadUntilClosed(3.0));
    EXPECT_EQ(raw->received().rfind("HTTP/1.1 503", 0), 0u) << raw->received();
  }
  EXPECT_EQ(server_->stats().connections_refused, 200u);
  EXPECT_EQ(server_->stats().clients, 8u);
  refused.clear();
  ASSERT_TRUE(WaitUntil([&] { return server_->stats().http_connections == 0; }));
  // 200 concurrent idle TCP connections: the server serves meanwhile, then cuts them.
  std::vector<std::unique_ptr<RawConnection>> idle;
  for (int i = 0; i < 200; ++i) idle.push_back(std::make_unique<RawConnection>(server_->port()));
  clients.pop_back();  // one slot for the normal client
  ASSERT_TRUE(WaitUntil([&] { return server_->stats().clients == 7; }));
  ExpectServesANormalClient();
  EXPECT_EQ(server_->stats().http_connections, 200u);
  for (auto& raw : idle) EXPECT_TRUE(raw->ReadUntilClosed(3.0));
  EXPECT_EQ(server_->stats().clients, 7u);
  EXPECT_TRUE(WaitUntil([&] { return server_->stats().http_connections == 0; }));
  ExpectServesANormalClient();
}

TEST_F(WsServerHostileTest, HttpConnectionsBeyondTheirLimitAreClosedAtOnce) {
  WsServerOptions options = TestOptions();
  options.max_http_connections = 20;
  options.handshake_timeout_s = 1.0;
  StartServer(options);
  std::vector<std::unique_ptr<RawConnection>> held;
  for (int i = 0; i < 20; ++i) held.push_back(std::make_unique<RawConnection>(server_->port()));
  ASSERT_TRUE(WaitUntil([&] { return server_->stats().connections_accepted == 20; }));
  for (int i = 0; i < 10; ++i) {
    RawConnection extra(server_->port());
    EXPECT_TRUE(extra.ReadUntilClosed(0.5)) << i;
  }
  EXPECT_EQ(server_->stats().connections_refused, 10u);
  for (auto& raw : held) EXPECT_TRUE(raw->ReadUntilClosed(3.0));  // the handshake timeout
  ExpectServesANormalClient();
}

}  // namespace
}  // namespace topay::viz
