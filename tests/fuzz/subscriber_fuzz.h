#pragma once
// The input of a fuzz target that plays one process's subscriptions: a sequence of operations,
// each [selector][...]. The selector's low seven bits modulo (channels + 1) pick a channel,
// whose message follows as [u16 length][bytes] (decoded with DecodeFuzzed, lcm_fuzz.h; the
// selector's high bit fixes the fingerprint), or, for the value `channels`, a tick: [u16 ms],
// the process's clock advancing that many milliseconds (0-65 s) before its periodic step.
// At most kMaxSubscriberOps operations are read, so every input runs in bounded time.

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/io/robot_loader.h"
#include "tests/fuzz/lcm_fuzz.h"

namespace topay::fuzz {

inline constexpr int kMaxSubscriberOps = 256;
/// The clock's start: a wall-clock utime (2023-11-14), as the processes see it.
inline constexpr std::int64_t kFuzzT0Utime = 1'700'000'000'000'000;

struct SubscriberOp {
  bool tick = false;
  int channel = 0;  ///< when !tick
  bool fix_fingerprint = false;
  std::span<const std::uint8_t> bytes;
  std::int64_t advance_us = 0;  ///< when tick
};

/// The next operation, or nullopt at the end of the input.
inline std::optional<SubscriberOp> NextSubscriberOp(FuzzReader& in, int num_channels) {
  if (in.empty()) return std::nullopt;
  const std::uint8_t selector = in.Byte();
  SubscriberOp op;
  op.channel = (selector & 0x7f) % (num_channels + 1);
  op.fix_fingerprint = (selector & 0x80) != 0;
  if (op.channel == num_channels) {
    op.tick = true;
    op.advance_us = std::int64_t{in.U16()} * 1000;
  } else {
    op.bytes = in.LengthPrefixed();
  }
  return op;
}

/// The robot the graph runs (config/robot/), loaded once per fuzzing process.
inline const RobotModel& ShippedRobotModel() {
  static const RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                                 std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  return model;
}

inline std::string ShippedConfig(const std::string& relative) {
  return std::string(TOPAY_SOURCE_DIR) + "/config/" + relative;
}

}  // namespace topay::fuzz
