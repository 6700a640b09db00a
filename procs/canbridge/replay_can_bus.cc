#include "procs/canbridge/replay_can_bus.h"

#include <fstream>
#include <stdexcept>
#include <thread>

#include "drivers/can/can_error.h"

namespace topay::canbridge {

ReplayCanBus::ReplayCanBus(std::vector<can::CandumpRecord> records, std::string source, double speed,
                           std::function<std::int64_t()> now_ns)
    : records_(std::move(records)), source_(std::move(source)), speed_(speed), now_ns_(std::move(now_ns)) {
  if (!(speed_ > 0.0)) throw std::invalid_argument("replay speed must be > 0");
}

std::vector<can::CandumpRecord> ReplayCanBus::ReadLog(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read the CAN log '" + path + "'");
  std::vector<can::CandumpRecord> records;
  std::string error;
  if (!can::ReadCandumpLog(file, &records, &error)) throw std::runtime_error(path + ": " + error);
  return records;
}

can::CanResult ReplayCanBus::Send(const can::CanFrame&) {
  return {can::CanResult::Code::kInvalidFrame, "the replay bus is read-only"};
}

can::CanResult ReplayCanBus::Receive(double timeout_s, can::ReceivedCanFrame* received) {
  if (!started_) {
    started_ = true;
    start_ns_ = now_ns_();
  }
  while (next_ < records_.size()) {
    const can::CandumpRecord& record = records_[next_];
    const double offset_ns = static_cast<double>(record.timestamp_us - records_.front().timestamp_us) * 1e3 / speed_;
    const std::int64_t due_ns = start_ns_ + static_cast<std::int64_t>(offset_ns);
    const std::int64_t now = now_ns_();
    if (now < due_ns) {
      const double wait_s = static_cast<double>(due_ns - now) * 1e-9;
      if (timeout_s == 0.0 || (timeout_s > 0.0 && wait_s > timeout_s)) {
        if (timeout_s > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(timeout_s));
        return {can::CanResult::Code::kTimeout, ""};
      }
      std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
      continue;
    }
    ++next_;
    if (record.frame.error) {
      can::ApplyErrorFrame(record.frame, &status_);
      continue;
    }
    received->frame = record.frame;
    received->timestamp_ns = now;
    received->kernel_timestamp = false;
    ++status_.frames_received;
    return can::CanResult::Ok();
  }
  return {can::CanResult::Code::kTimeout, ""};
}

}  // namespace topay::canbridge
