#pragma once
// The HTTP responses of topay-viz's server: one body type (a string), the headers every
// response carries (Server, Cache-Control: no-cache, nosniff), and short plain-text answers
// for errors and refusals.

#include <string_view>

#include <boost/beast/http/message.hpp>
#include <boost/beast/http/status.hpp>
#include <boost/beast/core/string.hpp>
#include <boost/beast/http/string_body.hpp>

namespace topay::viz {

/// Every request the server reads (bodies are limited by the parser).
using HttpRequest = boost::beast::http::request<boost::beast::http::string_body>;
/// Every response the server writes.
using HttpResponse = boost::beast::http::response<boost::beast::http::string_body>;

/// Beast's string_view (boost's in 1.74) as a std::string_view.
inline std::string_view ToStd(boost::beast::string_view text) { return {text.data(), text.size()}; }

/// A std::string_view as Beast's string_view.
inline boost::beast::string_view ToBeast(std::string_view text) {
  return {text.data(), text.size()};
}

/// Sets the headers every response carries: Server, Cache-Control: no-cache,
/// X-Content-Type-Options: nosniff.
void SetCommonHeaders(HttpResponse& response);

/// A `status` response whose body is `text` (text/plain), for HTTP `version` (10 or 11);
/// `keep_alive` false adds Connection: close.
HttpResponse PlainResponse(boost::beast::http::status status, std::string_view text,
                           unsigned version, bool keep_alive);

}  // namespace topay::viz
