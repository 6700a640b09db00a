#include "procs/viz/server/listener.h"

#include <chrono>
#include <utility>

#include <boost/asio/ip/address.hpp>
#include <spdlog/spdlog.h>

#include "procs/viz/server/http_session.h"

namespace topay::viz {
namespace {

namespace asio = boost::asio;
using asio::ip::tcp;

/// Wait before accepting again after an accept error (e.g. EMFILE), so it does not spin.
constexpr std::chrono::milliseconds kAcceptRetryDelay{100};

std::string Describe(const std::string& address, int port) {
  const bool ipv6 = address.find(':') != std::string::npos;
  return (ipv6 ? "[" + address + "]" : address) + ":" + std::to_string(port);
}

}  // namespace

Listener::Listener(asio::io_context& io_context, ServerContext& context)
    : acceptor_(io_context), retry_timer_(io_context), context_(context) {}

bool Listener::Open(const std::string& address, int port, std::string* error) {
  boost::system::error_code failure;
  std::string step = "parse";
  const asio::ip::address ip = asio::ip::make_address(address, failure);
  const tcp::endpoint endpoint(ip, static_cast<unsigned short>(port));
  if (!failure) {
    step = "open";
    acceptor_.open(endpoint.protocol(), failure);
  }
  if (!failure) {
    step = "configure";
    acceptor_.set_option(tcp::acceptor::reuse_address(true), failure);
  }
  if (!failure) {
    step = "bind";
    acceptor_.bind(endpoint, failure);
  }
  if (!failure) {
    step = "listen on";
    acceptor_.listen(asio::socket_base::max_listen_connections, failure);
  }
  if (!failure) port_ = acceptor_.local_endpoint(failure).port();
  if (!failure) return true;
  if (error) *error = "cannot " + step + " " + Describe(address, port) + ": " + failure.message();
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  return false;
}

void Listener::Start() { DoAccept(); }

void Listener::Stop() {
  boost::system::error_code ignored;
  retry_timer_.cancel();
  acceptor_.close(ignored);
}

void Listener::DoAccept() {
  acceptor_.async_accept([self = shared_from_this()](boost::beast::error_code error,
                                                     tcp::socket socket) {
    self->OnAccept(error, std::move(socket));
  });
}

void Listener::OnAccept(boost::beast::error_code error, tcp::socket socket) {
  if (!acceptor_.is_open() || error == asio::error::operation_aborted) return;
  if (error) {
    spdlog::warn("viz server: accept failed: {}; retrying", error.message());
    RetryLater();
    return;
  }
  Increment(context_.counters.connections_accepted);
  if (context_.http_connections.load() >= context_.options.max_http_connections) {
    Increment(context_.counters.connections_refused);
    boost::system::error_code ignored;
    socket.close(ignored);
  } else {
    boost::system::error_code ignored;
    socket.set_option(tcp::no_delay(true), ignored);
    std::make_shared<HttpSession>(std::move(socket), context_)->Start();
  }
  DoAccept();
}

void Listener::RetryLater() {
  retry_timer_.expires_after(kAcceptRetryDelay);
  retry_timer_.async_wait([self = shared_from_this()](boost::beast::error_code error) {
    if (!error) self->DoAccept();
  });
}

}  // namespace topay::viz
