// The page's files over the server's port: index.html on "/", a JS file with its content
// type, 404, traversal attempts sent raw ("/../", "%2e%2e", ...), HEAD, POST -> 405,
// keep-alive and Connection: close, HTTP/1.0, and a WebSocket on the same port.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "procs/viz/server/ws_server.h"
#include "tests/procs/viz/server/ws_test_client.h"

namespace topay::viz {
namespace {

using namespace topay::viz::testing;
namespace fs = std::filesystem;

constexpr char kIndex[] = "<!doctype html><title>topay</title>";
constexpr char kScript[] = "export const x = 1;\n";

class WsServerHttpTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "viz_http_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    base_ = pattern;
    fs::create_directories(base_ / "web" / "assets");
    std::ofstream(base_ / "web" / "index.html") << kIndex;
    std::ofstream(base_ / "web" / "assets" / "main.js") << kScript;
    std::ofstream(base_ / "secret.txt") << "SECRET";
    WsServerOptions options = TestOptions();
    options.web_root = (base_ / "web").string();
    server_ = std::make_unique<WsServer>(options, log_.Callbacks());
    std::string error;
    ASSERT_TRUE(server_->Start(&error)) << error;
  }
  void TearDown() override {
    server_.reset();
    fs::remove_all(base_);
  }

  HttpResult Get(std::string target, http::verb method = http::verb::get) {
    return HttpRequestOnce(server_->port(), method, std::move(target));
  }

  fs::path base_;
  CallbackLog log_;
  std::unique_ptr<WsServer> server_;
};

TEST_F(WsServerHttpTest, ServesIndexOnTheRoot) {
  const HttpResult result = Get("/");
  ASSERT_FALSE(result.error) << result.error.message();
  EXPECT_EQ(result.response.result(), http::status::ok);
  EXPECT_EQ(result.response.body(), kIndex);
  EXPECT_EQ(result.response[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_EQ(result.response[http::field::cache_control], "no-cache");
  EXPECT_EQ(Get("/index.html").response.body(), kIndex);
}

TEST_F(WsServerHttpTest, ServesScriptsWithTheirContentType) {
  const HttpResult result = Get("/assets/main.js?v=3");
  ASSERT_FALSE(result.error);
  EXPECT_EQ(result.response.result(), http::status::ok);
  EXPECT_EQ(result.response.body(), kScript);
  EXPECT_EQ(result.response[http::field::content_type], "text/javascript; charset=utf-8");
}

TEST_F(WsServerHttpTest, MissingFilesAre404) {
  const HttpResult result = Get("/assets/missing.js");
  ASSERT_FALSE(result.error);
  EXPECT_EQ(result.response.result(), http::status::not_found);
  EXPECT_GE(server_->stats().http_errors, 1u);
}

TEST_F(WsServerHttpTest, TraversalNeverLeavesTheWebRoot) {
  for (const char* target :
       {"/../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E%2Fsecret.txt",
        "/assets/../../secret.txt", "/assets/%2e%2e/%2e%2e/secret.txt", "/..%5csecret.txt",
        "/../etc/passwd",
        "/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/%252e%252e/secret.txt"}) {
    const HttpResult result = Get(target);
    ASSERT_FALSE(result.error) << target;
    const unsigned status = result.response.result_int();
    EXPECT_TRUE(status == 400 || status == 404) << target << ": " << status;
    EXPECT_EQ(result.response.body().find("SECRET"), std::string::npos) << target;
    EXPECT_EQ(result.response.body().find("root:"), std::string::npos) << target;
  }
}

TEST_F(WsServerHttpTest, HeadSendsHeadersWithoutTheBody) {
  const HttpResult result = Get("/assets/main.js", http::verb::head);
  ASSERT_FALSE(result.error) << result.error.message();
  EXPECT_EQ(result.response.result(), http::status::ok);
  EXPECT_EQ(result.response[http::field::content_length], std::to_string(sizeof(kScript) - 1));
  EXPECT_EQ(result.response[http::field::content_type], "text/javascript; charset=utf-8");
  EXPECT_EQ(result.response.body(), "");
}

TEST_F(WsServerHttpTest, OtherMethodsAre405) {
  for (http::verb method : {http::verb::post, http::verb::put, http::verb::delete_}) {
    const HttpResult result = Get("/", method);
    ASSERT_FALSE(result.error);
    EXPECT_EQ(result.response.result(), http::status::method_not_allowed);
    EXPECT_EQ(result.response[http::field::allow], "GET, HEAD");
  }
}

TEST_F(WsServerHttpTest, KeepAliveServesSeveralRequestsThenCloseCloses) {
  RawConnection raw(server_->port());
  for (int i = 0; i < 3; ++i) {
    raw.Write("GET /assets/main.js HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  }
  raw.Write("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
  EXPECT_TRUE(raw.ReadUntilClosed(3.0));  // the server closes after the fourth answer
  std::size_t answers = 0;
  for (std::size_t at = raw.received().find("HTTP/1.1 200 OK"); at != std::string::npos;
       at = raw.received().find("HTTP/1.1 200 OK", at + 1)) {
    ++answers;
  }
  EXPECT_EQ(answers, 4u);
  EXPECT_NE(raw.received().find(kIndex), std::string::npos);
}

TEST_F(WsServerHttpTest, Http10ClosesAfterTheAnswer) {
  RawConnection raw(server_->port());
  raw.Write("GET / HTTP/1.0\r\n\r\n");
  EXPECT_TRUE(raw.ReadUntilClosed(3.0));
  EXPECT_EQ(raw.received().rfind("HTTP/1.0 200 OK", 0), 0u) << raw.received();
  EXPECT_NE(raw.received().find(kIndex), std::string::npos);
}

TEST_F(WsServerHttpTest, MalformedRequestsAre400) {
  RawConnection raw(server_->port());
  raw.Write("GET /\x01 HTTP/1.1\r\n\r\n");
  EXPECT_TRUE(raw.ReadUntilClosed(3.0));
  EXPECT_EQ(raw.received().rfind("HTTP/1.1 400", 0), 0u) << raw.received();
}

TEST_F(WsServerHttpTest, WebSocketOnTheSamePort) {
  EXPECT_EQ(Get("/").response.result(), http::status::ok);
  TestClient client(server_->port());
  ASSERT_FALSE(client.Connect());
  const ClientId id = log_.WaitOpened(1);
  server_->Send(id, TextFrame("{}"));
  std::string message;
  ASSERT_FALSE(client.Read(&message));
  EXPECT_EQ(message, "{}");
  EXPECT_GE(server_->stats().http_requests, 2u);
}

}  // namespace
}  // namespace topay::viz
