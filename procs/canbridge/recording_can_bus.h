#pragma once
// --record FILE: a CanBus that passes everything to the real bus and writes every frame sent
// (when Send() succeeded, stamped with the clock) and received (with its receive timestamp) to a
// can-utils `candump -l` log (drivers/can/candump_log.h), error frames included.

#include <cstdint>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

#include "drivers/can/can_bus.h"
#include "drivers/can/candump_log.h"

namespace topay::canbridge {

/// ns since the Unix epoch (CLOCK_REALTIME, as candump's timestamps).
std::int64_t RealtimeNowNs();

class RecordingCanBus final : public can::CanBus {
 public:
  /// Records the traffic of `inner` into `path` under `interface` (e.g. "can0"), appended to what
  /// the file holds: a bridge the launcher restarts continues its run's log (truncated, the log
  /// of a mission with a bridge restart held only the traffic since the last one).
  /// `now_ns` stamps sent frames (default RealtimeNowNs). Throws std::runtime_error when the
  /// file cannot be opened.
  RecordingCanBus(std::unique_ptr<can::CanBus> inner, const std::string& path, std::string interface,
                  std::function<std::int64_t()> now_ns = RealtimeNowNs);
  ~RecordingCanBus() override;

  can::CanResult Send(const can::CanFrame& frame) override;
  can::CanResult Receive(double timeout_s, can::ReceivedCanFrame* received) override;
  const can::CanBusStatus& status() const override { return inner_->status(); }
  can::CanResult Reopen() override { return inner_->Reopen(); }
  int fd() const override { return inner_->fd(); }
  std::string url() const override { return inner_->url(); }

  std::int64_t lines_written() const { return lines_; }
  /// Writes buffered lines to the file.
  void Flush() { file_.flush(); }

 private:
  void Write(std::int64_t timestamp_ns, const can::CanFrame& frame);

  std::unique_ptr<can::CanBus> inner_;
  std::ofstream file_;
  can::CandumpLogWriter writer_;
  std::string interface_;
  std::function<std::int64_t()> now_ns_;
  std::int64_t lines_ = 0;
};

}  // namespace topay::canbridge
