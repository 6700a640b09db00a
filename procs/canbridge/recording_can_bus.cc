#include "procs/canbridge/recording_can_bus.h"

#include <chrono>
#include <stdexcept>

namespace topay::canbridge {

std::int64_t RealtimeNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

RecordingCanBus::RecordingCanBus(std::unique_ptr<can::CanBus> inner, const std::string& path, std::string interface,
                                 std::function<std::int64_t()> now_ns)
    : inner_(std::move(inner)),
      file_(path, std::ios::out | std::ios::app),
      writer_(file_),
      interface_(std::move(interface)),
      now_ns_(std::move(now_ns)) {
  if (!file_) throw std::runtime_error("cannot write the CAN log '" + path + "'");
}

RecordingCanBus::~RecordingCanBus() { file_.flush(); }

void RecordingCanBus::Write(std::int64_t timestamp_ns, const can::CanFrame& frame) {
  try {
    writer_.Write(timestamp_ns, interface_, frame);
    ++lines_;
    if (lines_ % 256 == 0) file_.flush();
  } catch (const std::invalid_argument&) {
    // a frame the log format cannot hold (never from a bus): not recorded
  }
}

can::CanResult RecordingCanBus::Send(const can::CanFrame& frame) {
  can::CanResult result = inner_->Send(frame);
  if (result.ok()) Write(now_ns_(), frame);
  return result;
}

can::CanResult RecordingCanBus::Receive(double timeout_s, can::ReceivedCanFrame* received) {
  can::CanResult result = inner_->Receive(timeout_s, received);
  if (result.ok()) Write(received->timestamp_ns, received->frame);
  return result;
}

}  // namespace topay::canbridge
