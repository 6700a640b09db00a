// The subprotocol check of an upgrade request (a list, repeated headers, exact tokens) and
// the refusals' answers.
#include "procs/viz/server/upgrade_checks.h"

#include <gtest/gtest.h>

#include <boost/beast/http/field.hpp>

namespace topay::viz {
namespace {

namespace http = boost::beast::http;

constexpr char kProtocol[] = "foxglove.websocket.v1";

HttpRequest WithProtocols(std::initializer_list<const char*> headers) {
  HttpRequest request{http::verb::get, "/", 11};
  for (const char* header : headers) request.insert(http::field::sec_websocket_protocol, header);
  return request;
}

TEST(UpgradeChecksTest, FindsTheSubprotocolInTheOfferedList) {
  EXPECT_TRUE(OffersSubprotocol(WithProtocols({"foxglove.websocket.v1"}), kProtocol));
  EXPECT_TRUE(OffersSubprotocol(WithProtocols({"a, foxglove.websocket.v1 ,b"}), kProtocol));
  EXPECT_TRUE(OffersSubprotocol(WithProtocols({"a", "foxglove.websocket.v1"}), kProtocol));
}

TEST(UpgradeChecksTest, RefusesMissingOrMerelySimilarSubprotocols) {
  EXPECT_FALSE(OffersSubprotocol(WithProtocols({}), kProtocol));
  EXPECT_FALSE(OffersSubprotocol(WithProtocols({""}), kProtocol));
  EXPECT_FALSE(OffersSubprotocol(WithProtocols({"foxglove.websocket.v2"}), kProtocol));
  EXPECT_FALSE(OffersSubprotocol(WithProtocols({"foxglove.websocket.v1x"}), kProtocol));
  EXPECT_FALSE(OffersSubprotocol(WithProtocols({"Foxglove.WebSocket.v1"}), kProtocol));
}

TEST(UpgradeChecksTest, RefusalsCloseTheConnection) {
  const HttpRequest request = WithProtocols({});
  const HttpResponse missing = MissingSubprotocolResponse(request, kProtocol);
  EXPECT_EQ(missing.result(), http::status::bad_request);
  EXPECT_FALSE(missing.keep_alive());
  EXPECT_NE(missing.body().find(kProtocol), std::string::npos);
  const HttpResponse full = TooManyClientsResponse(request);
  EXPECT_EQ(full.result(), http::status::service_unavailable);
  EXPECT_FALSE(full.keep_alive());
}

}  // namespace
}  // namespace topay::viz
