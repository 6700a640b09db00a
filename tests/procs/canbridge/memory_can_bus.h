#pragma once
// An in-memory CAN bus for tests: every node of a MemoryWire receives the frames the others send
// (in order, not its own), with timestamps from the wire's (simulated) clock. Error frames put
// into the wire drive every node's bus state as a controller's would (bus-off refuses Send).

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "drivers/can/can_bus.h"

namespace topay::canbridge::test {

class MemoryCanBus;

struct MemoryWire {
  std::function<std::int64_t()> now_ns = [] { return std::int64_t{0}; };
  std::vector<MemoryCanBus*> nodes;
};

class MemoryCanBus final : public can::CanBus {
 public:
  MemoryCanBus(std::shared_ptr<MemoryWire> wire, std::string name) : wire_(std::move(wire)), name_(std::move(name)) {
    wire_->nodes.push_back(this);
  }
  ~MemoryCanBus() override {
    auto& nodes = wire_->nodes;
    for (auto it = nodes.begin(); it != nodes.end(); ++it) {
      if (*it == this) {
        nodes.erase(it);
        break;
      }
    }
  }

  can::CanResult Send(const can::CanFrame& frame) override {
    if (down) return {can::CanResult::Code::kInterfaceDown, "interface down (test)"};
    if (!can::CheckCanFrame(frame).empty()) return {can::CanResult::Code::kInvalidFrame, can::CheckCanFrame(frame)};
    if (status_.state == can::CanBusState::kBusOff && !frame.error) return {can::CanResult::Code::kBusOff, "bus-off"};
    const std::int64_t now = wire_->now_ns();
    for (MemoryCanBus* node : wire_->nodes) {
      if (node != this) node->queue_.push_back({frame, now, false});
    }
    ++status_.frames_sent;
    sent.emplace_back(now, frame);
    return can::CanResult::Ok();
  }

  can::CanResult Receive(double, can::ReceivedCanFrame* received) override {
    if (down) return {can::CanResult::Code::kInterfaceDown, "interface down (test)"};
    while (!queue_.empty()) {
      *received = queue_.front();
      queue_.pop_front();
      if (received->frame.error) {
        can::ApplyErrorFrame(received->frame, &status_);
        continue;
      }
      ++status_.frames_received;
      return can::CanResult::Ok();
    }
    return {can::CanResult::Code::kTimeout, ""};
  }

  const can::CanBusStatus& status() const override { return status_; }
  can::CanResult Reopen() override {
    if (down) return {can::CanResult::Code::kClosed, "still down (test)"};
    status_.state = can::CanBusState::kErrorActive;
    ++status_.reopen_count;
    return can::CanResult::Ok();
  }
  int fd() const override { return -1; }
  std::string url() const override { return "mem://" + name_; }

  /// Puts `frame` into this node's receive queue as if it came from the wire.
  void Inject(const can::CanFrame& frame) { queue_.push_back({frame, wire_->now_ns(), false}); }

  bool down = false;                                          ///< Send/Receive: interface down.
  std::vector<std::pair<std::int64_t, can::CanFrame>> sent;  ///< Everything this node sent.

 private:
  std::shared_ptr<MemoryWire> wire_;
  std::string name_;
  std::deque<can::ReceivedCanFrame> queue_;
  can::CanBusStatus status_;
};

}  // namespace topay::canbridge::test
