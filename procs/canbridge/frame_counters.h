#pragma once
// Counts of received frames the bridge could not use, by kind, each kind logged once (a
// malformed or unknown frame never stops the bridge; a flood of them does not flood the log).

#include <cstdint>
#include <map>
#include <string>

namespace topay::canbridge {

class FrameCounters {
 public:
  /// A frame of a known id that failed to decode; `kind` groups them (e.g. "TPDO1 q3 (node 3)"),
  /// `error` is the decoder's message. Logs (warn) the first of each kind.
  void CountMalformed(const std::string& kind, const std::string& error);
  /// A frame of no id the bridge knows (`kind`: e.g. "id 0x123").
  void CountUnknown(const std::string& kind, const std::string& text);
  /// A frame the host itself sends (echo, replayed log): counted, not an error.
  void CountHostFrame() { ++host_frames_; }

  std::int64_t malformed() const { return malformed_; }
  std::int64_t unknown() const { return unknown_; }
  std::int64_t host_frames() const { return host_frames_; }
  /// Count per kind ("malformed: TPDO1 q3 (node 3)" -> n), for the exit report.
  const std::map<std::string, std::int64_t>& by_kind() const { return by_kind_; }
  /// The last message logged ("" when none).
  const std::string& last_message() const { return last_message_; }

 private:
  void Count(const std::string& key, const std::string& message);

  std::int64_t malformed_ = 0;
  std::int64_t unknown_ = 0;
  std::int64_t host_frames_ = 0;
  std::map<std::string, std::int64_t> by_kind_;
  std::string last_message_;
};

}  // namespace topay::canbridge
