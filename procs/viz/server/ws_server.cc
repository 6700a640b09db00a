#include "procs/viz/server/ws_server.h"

#include <chrono>
#include <exception>
#include <utility>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "procs/viz/server/listener.h"
#include "procs/viz/server/server_context.h"
#include "procs/viz/server/ws_session.h"

namespace topay::viz {
namespace {

namespace asio = boost::asio;

/// Stop() waits this long beyond close_timeout_s for the cut sockets' sessions to end.
constexpr double kStopSlackS = 0.5;

}  // namespace

WsServer::WsServer(WsServerOptions options, WsServerCallbacks callbacks)
    : context_(std::make_unique<ServerContext>(std::move(options), std::move(callbacks))) {}

WsServer::~WsServer() { Stop(); }

const WsServerOptions& WsServer::options() const { return context_->options; }

bool WsServer::Start(std::string* error) {
  std::lock_guard lock(lifecycle_mutex_);
  if (io_thread_.joinable()) {
    if (error) *error = "the server is already started";
    return false;
  }
  if (std::string problem = CheckWsServerOptions(context_->options); !problem.empty()) {
    if (error) *error = "bad viz server options: " + problem;
    return false;
  }
  io_context_ = std::make_unique<asio::io_context>(1);
  listener_ = std::make_shared<Listener>(*io_context_, *context_);
  const WsServerOptions& options = context_->options;
  if (!listener_->Open(options.bind_address, options.port, error)) {
    listener_.reset();
    io_context_.reset();
    return false;
  }
  port_ = listener_->port();
  context_->stopping = false;
  listener_->Start();
  io_thread_ = std::thread([this] { RunIoThread(); });
  running_ = true;
  spdlog::info("viz server: listening on {}:{}", options.bind_address, port_.load());
  return true;
}

void WsServer::RunIoThread() {
  for (;;) {
    try {
      io_context_->run();
      return;
    } catch (const std::exception& error) {
      spdlog::error("viz server: I/O thread caught an exception (serving on): {}", error.what());
    } catch (...) {
      spdlog::error("viz server: I/O thread caught a non-exception (serving on)");
    }
  }
}

void WsServer::Stop() {
  std::lock_guard lock(lifecycle_mutex_);
  if (!io_thread_.joinable()) return;
  if (std::this_thread::get_id() == io_thread_.get_id()) {
    spdlog::error("viz server: Stop() called from a callback: ignored");
    return;
  }
  context_->stopping = true;
  running_ = false;
  asio::post(*io_context_, [this] {
    listener_->Stop();
    for (const auto& session : context_->registry.All()) {
      session->BeginClose(boost::beast::websocket::close_code::going_away);
    }
  });
  const double wait_s = context_->options.close_timeout_s + kStopSlackS;
  context_->registry.WaitEmpty(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(wait_s)));
  io_context_->stop();
  io_thread_.join();
  ForgetRemainingClients();
  listener_.reset();
  io_context_.reset();  // destroys the pending handlers, and with them the sessions
  port_ = 0;
}

void WsServer::ForgetRemainingClients() {
  for (auto& [id, session] : context_->registry.TakeAll()) {
    session->Detach();
    context_->counters.clients.fetch_sub(1, std::memory_order_relaxed);
    InvokeCallback(context_->callbacks.on_close, "on_close", id);
  }
}

void WsServer::Send(ClientId client, OutgoingFrame frame) {
  if (!frame.bytes) return;
  context_->registry.With(client, [&frame](WsSession& session) {
    session.Enqueue(std::move(frame));
  });
}

void WsServer::Close(ClientId client) {
  context_->registry.With(client, [](WsSession& session) { session.RequestClose(); });
}

WsServerStats WsServer::stats() const {
  WsServerStats stats = context_->counters.Snapshot();
  stats.http_connections = context_->http_connections.load();
  return stats;
}

std::optional<ClientStats> WsServer::client_stats(ClientId client) const {
  std::optional<ClientStats> stats;
  context_->registry.With(client, [&stats](WsSession& session) { stats = session.stats(); });
  return stats;
}

}  // namespace topay::viz
