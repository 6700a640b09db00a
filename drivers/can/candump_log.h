#pragma once
// can-utils' `candump -l` log format (also what `canplayer -I` reads): one frame per line,
//   (1700000000.123456) can0 123#DEADBEEF
// a timestamp in seconds since the Unix epoch with exactly 6 decimals (candump pads the
// seconds to 10 digits), the interface name, and the frame in cansend syntax (can_frame.h:
// 3-digit standard ids, 8-digit extended ids, R for remote frames, 8-digit error frames with
// the CAN_ERR_FLAG bit). Newer candumps may append a direction flag (T or R) with -x; it is
// accepted and ignored when read, never written.

#include <cstdint>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/can/can_frame.h"

namespace topay::can {

/// One line of a candump log.
struct CandumpRecord {
  std::int64_t timestamp_us = 0;  ///< Microseconds since the Unix epoch (>= 0).
  std::string interface;          ///< e.g. "can0" (1-15 characters, no whitespace).
  CanFrame frame;
};

/// The line for `record`, without the newline: "(1700000000.123456) can0 123#DEADBEEF".
/// Throws std::invalid_argument for a negative timestamp, a bad interface name or an invalid
/// frame (a recorder must not write lines it could not read back).
std::string FormatCandumpLine(const CandumpRecord& record);

/// Parses one line (without the newline); nullopt with *error (when not null) saying what is
/// wrong, e.g. "timestamp '(17.5)' must be (SECONDS.MICROSECONDS) with 6 decimals".
std::optional<CandumpRecord> ParseCandumpLine(std::string_view line, std::string* error);

/// Writes records as a candump log, one line each.
class CandumpLogWriter {
 public:
  /// Writes to `out`, which must outlive the writer.
  explicit CandumpLogWriter(std::ostream& out) : out_(out) {}
  /// Writes one line (FormatCandumpLine(), which may throw) and flushes nothing.
  void Write(const CandumpRecord& record);
  /// Convenience: a frame received at `timestamp_ns` (ns since the epoch; truncated to us).
  void Write(std::int64_t timestamp_ns, const std::string& interface, const CanFrame& frame);

 private:
  std::ostream& out_;
};

/// Reads a candump log from `in` into *records (appended). Empty lines are skipped. Stops at
/// the first bad line and returns false with *error = "line N: what is wrong".
bool ReadCandumpLog(std::istream& in, std::vector<CandumpRecord>* records, std::string* error);

}  // namespace topay::can
