#pragma once
// The channels topay-viz advertises over the Foxglove WebSocket protocol and writes to MCAP: one
// topic per view of the graph, JSON encoded, each with a JSON schema (docs/viewer.md).

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace topay::viz {

/// Every channel, in docs/viewer.md's order; the Foxglove channel id is index + 1.
enum class Topic : std::size_t {
  kRobotDescription,
  kRobotState,
  kMapBlocks,
  kScan,
  kTrajectory,
  kCandidatePaths,
  kPlannerStatus,
  kGoal,
  kContacts,
  kPlotSample,
  kTrackerStatus,
  kMissionStatus,
  kGraphStatus,
  kDriveStatus,
  kSimStatus,
  kVizStats,
  kPlayback,
  kCount,
};
inline constexpr std::size_t kNumTopics = static_cast<std::size_t>(Topic::kCount);

/// One channel: its topic, schema ("topay.viz.<Name>", a JSON schema) and whether a new
/// subscriber gets its last message at once (latched).
struct VizChannel {
  Topic topic;
  std::string name;         ///< e.g. "/robot/state"
  std::string schema_name;  ///< e.g. "topay.viz.RobotState"
  std::string schema;       ///< JSON schema text (draft 2020-12 style, type object)
  bool latched = true;
};

/// The catalogue (built once per call site that keeps it; cheap enough to copy).
std::array<VizChannel, kNumTopics> VizChannels();

/// Index of a topic (for arrays indexed by topic).
constexpr std::size_t Index(Topic topic) { return static_cast<std::size_t>(topic); }

}  // namespace topay::viz
