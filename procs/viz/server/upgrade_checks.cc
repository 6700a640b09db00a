#include "procs/viz/server/upgrade_checks.h"

#include <string>

#include <boost/beast/http/field.hpp>

namespace topay::viz {
namespace {

namespace http = boost::beast::http;

std::string_view Trim(std::string_view text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  const std::size_t end = text.find_last_not_of(" \t");
  return text.substr(begin, end - begin + 1);
}

bool ListContains(std::string_view list, std::string_view token) {
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    if (Trim(list.substr(0, comma)) == token) return true;
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  return false;
}

}  // namespace

bool OffersSubprotocol(const HttpRequest& request, std::string_view subprotocol) {
  const auto [begin, end] = request.equal_range(http::field::sec_websocket_protocol);
  for (auto field = begin; field != end; ++field) {
    if (ListContains(ToStd(field->value()), subprotocol)) return true;
  }
  return false;
}

HttpResponse MissingSubprotocolResponse(const HttpRequest& request, std::string_view subprotocol) {
  return PlainResponse(http::status::bad_request,
                       "WebSocket subprotocol '" + std::string(subprotocol) + "' required.\n",
                       request.version(), false);
}

HttpResponse TooManyClientsResponse(const HttpRequest& request) {
  HttpResponse response = PlainResponse(http::status::service_unavailable,
                                        "Too many WebSocket clients.\n", request.version(), false);
  response.set(http::field::retry_after, "5");
  return response;
}

}  // namespace topay::viz
