#include "procs/viz/server/http_response.h"

#include <string>

#include <boost/beast/http/field.hpp>

namespace topay::viz {

namespace http = boost::beast::http;

void SetCommonHeaders(HttpResponse& response) {
  response.set(http::field::server, "topay-viz");
  response.set(http::field::cache_control, "no-cache");
  response.set("X-Content-Type-Options", "nosniff");
}

HttpResponse PlainResponse(http::status status, std::string_view text, unsigned version,
                           bool keep_alive) {
  HttpResponse response{status, version};
  SetCommonHeaders(response);
  response.set(http::field::content_type, "text/plain; charset=utf-8");
  response.body() = std::string(text);
  response.keep_alive(keep_alive);
  response.prepare_payload();
  return response;
}

}  // namespace topay::viz
