#pragma once
// The open WebSocket clients by id, shared between the I/O thread (which adds and removes
// them) and the threads that Send to them. Thread-safe. Other threads reach a session only
// through With, under the lock, so WsServer::Stop can take them all away before the I/O
// context they live on goes.

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

#include "procs/viz/server/outgoing_frame.h"

namespace topay::viz {

/// `Session`: the per-client object (WsSession; anything in tests).
template <typename Session>
class ClientRegistry {
 public:
  /// Registers `session` as `id` (replaces a previous one of that id).
  void Add(ClientId id, std::shared_ptr<Session> session) {
    std::lock_guard lock(mutex_);
    sessions_[id] = std::move(session);
  }

  /// Forgets `id` (if known) and wakes WaitEmpty.
  void Remove(ClientId id) {
    std::lock_guard lock(mutex_);
    sessions_.erase(id);
    if (sessions_.empty()) emptied_.notify_all();
  }

  /// Calls `use(session)` with the session of `id` while holding the registry's lock (so the
  /// session cannot be taken away meanwhile: `use` must be quick and must not call back into
  /// the registry). false when `id` is unknown (never opened, or gone).
  template <typename Use>
  bool With(ClientId id, Use&& use) const {
    std::lock_guard lock(mutex_);
    const auto found = sessions_.find(id);
    if (found == sessions_.end()) return false;
    use(*found->second);
    return true;
  }

  /// Every session registered now.
  std::vector<std::shared_ptr<Session>> All() const {
    std::lock_guard lock(mutex_);
    std::vector<std::shared_ptr<Session>> all;
    all.reserve(sessions_.size());
    for (const auto& [id, session] : sessions_) all.push_back(session);
    return all;
  }

  /// Removes and returns every session.
  std::vector<std::pair<ClientId, std::shared_ptr<Session>>> TakeAll() {
    std::lock_guard lock(mutex_);
    std::vector<std::pair<ClientId, std::shared_ptr<Session>>> all(sessions_.begin(),
                                                                   sessions_.end());
    sessions_.clear();
    return all;
  }

  /// Sessions registered now.
  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return sessions_.size();
  }

  /// Waits until no session is registered or `timeout` passed; true when empty.
  bool WaitEmpty(std::chrono::steady_clock::duration timeout) const {
    std::unique_lock lock(mutex_);
    return emptied_.wait_for(lock, timeout, [this] { return sessions_.empty(); });
  }

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable emptied_;
  std::unordered_map<ClientId, std::shared_ptr<Session>> sessions_;
};

}  // namespace topay::viz
