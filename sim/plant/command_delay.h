#pragma once
// A command's transport and processing latency: values pushed at plant step k come out at step
// k + delay_steps, in order. Header only.

#include <cstdint>
#include <deque>
#include <optional>
#include <utility>

namespace topay::sim {

template <class T>
class CommandDelay {
 public:
  explicit CommandDelay(std::int64_t delay_steps) : delay_steps_(delay_steps) {}

  /// Queues `value`, sent at plant step `step` (steps must not decrease).
  void Push(std::int64_t step, T value) { queue_.emplace_back(step + delay_steps_, std::move(value)); }

  /// The newest value due at `step` (older due ones are dropped), or nullopt if none is due.
  std::optional<T> Pop(std::int64_t step) {
    std::optional<T> due;
    while (!queue_.empty() && queue_.front().first <= step) {
      due = std::move(queue_.front().second);
      queue_.pop_front();
    }
    return due;
  }

  std::int64_t delay_steps() const { return delay_steps_; }
  std::size_t pending() const { return queue_.size(); }

 private:
  std::int64_t delay_steps_;
  std::deque<std::pair<std::int64_t, T>> queue_;
};

}  // namespace topay::sim
