#pragma once
// --replay FILE: a read-only CanBus that hands out the frames of a recorded candump log as if
// they were received now, at the log's timing (the gaps between lines, scaled by `speed`).
// Send() refuses (kInvalidFrame: nothing goes anywhere); error frames of the log update
// status() as a controller's would.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "drivers/can/can_bus.h"
#include "drivers/can/candump_log.h"

namespace topay::canbridge {

class ReplayCanBus final : public can::CanBus {
 public:
  /// `records` in log order; `speed` > 0 (1: real time; larger: faster); `now_ns` a clock (ns,
  /// any epoch) that also stamps the frames handed out. The first record is due at once.
  ReplayCanBus(std::vector<can::CandumpRecord> records, std::string source, double speed,
               std::function<std::int64_t()> now_ns);
  /// Reads `path`; throws std::runtime_error naming the file and line for a bad log.
  static std::vector<can::CandumpRecord> ReadLog(const std::string& path);

  can::CanResult Send(const can::CanFrame& frame) override;
  /// The next record when its time has come (waiting up to timeout_s for it), else kTimeout.
  can::CanResult Receive(double timeout_s, can::ReceivedCanFrame* received) override;
  const can::CanBusStatus& status() const override { return status_; }
  can::CanResult Reopen() override { return can::CanResult::Ok(); }
  int fd() const override { return -1; }
  std::string url() const override { return "replay://" + source_; }

  /// Every record was handed out.
  bool finished() const { return next_ >= records_.size(); }
  std::size_t size() const { return records_.size(); }

 private:
  std::vector<can::CandumpRecord> records_;
  std::string source_;
  double speed_;
  std::function<std::int64_t()> now_ns_;
  std::size_t next_ = 0;
  std::int64_t start_ns_ = 0;
  bool started_ = false;
  can::CanBusStatus status_;
};

}  // namespace topay::canbridge
