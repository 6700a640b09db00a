#pragma once
// What the server checks of a WebSocket upgrade request before Beast's own handshake: the
// subprotocol it requires, and the answers to upgrades it refuses.

#include <string_view>

#include "procs/viz/server/http_response.h"

namespace topay::viz {

/// Whether a Sec-WebSocket-Protocol header of `request` lists `subprotocol` (the header may
/// repeat; its value is a comma-separated list; tokens compare case-sensitively, RFC 6455).
bool OffersSubprotocol(const HttpRequest& request, std::string_view subprotocol);

/// The answer to an upgrade that does not offer `subprotocol`: 400, Connection: close.
HttpResponse MissingSubprotocolResponse(const HttpRequest& request, std::string_view subprotocol);

/// The answer to an upgrade beyond max_clients: 503, Connection: close.
HttpResponse TooManyClientsResponse(const HttpRequest& request);

}  // namespace topay::viz
