#pragma once
// Shared by the viewer's tests: the shipped robot, LCM messages as bytes, and the payloads a
// pipeline forwards, recorded.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "procs/viz/robot_view.h"
#include "procs/viz/viz_channels.h"

namespace topay::viz::test {

inline RobotView ShippedRobot() {
  return RobotView(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                   std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
}

template <class Msg>
std::vector<std::uint8_t> Encode(const Msg& msg) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

/// What a pipeline forwarded, in order.
struct Forwarded {
  Topic topic;
  std::int64_t log_utime;
  nlohmann::json payload;
};

class Recorder {
 public:
  void operator()(Topic topic, std::int64_t log_utime, const std::string& payload) {
    all.push_back({topic, log_utime, nlohmann::json::parse(payload)});
  }
  std::vector<Forwarded> Of(Topic topic) const {
    std::vector<Forwarded> out;
    for (const Forwarded& f : all) {
      if (f.topic == topic) out.push_back(f);
    }
    return out;
  }
  std::vector<Forwarded> all;
};

}  // namespace topay::viz::test
