#include "tools/report/run_log.h"

#include <lcm/lcm-cpp.hpp>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "procs/msgs/map_receiver.h"
#include "procs/msgs/trajectory_from_message.h"
#include "procs/msgs/type_registry.h"
#include "topay/map_update_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay_msgs/channels.h"
#include "topay_msgs/checked_decode.h"

namespace topay::report {
namespace {

// Decodes a channel's payload into the run; false if it is malformed.
using Decoder = std::function<bool(const lcm::LogEvent&, RunLog*)>;

// A decoder that appends the decoded message of type Msg to the vector `member` of the run.
template <class Msg>
Decoder AppendTo(std::vector<Msg> RunLog::*member) {
  return [member](const lcm::LogEvent& event, RunLog* run) {
    std::optional<Msg> msg = CheckedDecode<Msg>(event.data, event.datalen, nullptr);
    if (!msg) return false;
    (run->*member).push_back(std::move(*msg));
    return true;
  };
}

// A decoder of robot_state_t messages into the run's vector `member`.
Decoder RobotStatesInto(std::vector<msgs::RobotStateEstimate> RunLog::*member) {
  return [member](const lcm::LogEvent& event, RunLog* run) {
    const auto msg = CheckedDecode<robot_state_t>(event.data, event.datalen, nullptr);
    if (!msg) return false;
    std::string error;  // the converters write their reason here (not used: the message is counted)
    std::optional<msgs::RobotStateEstimate> estimate = msgs::FromMessage(*msg, &error);
    if (!estimate) return false;
    (run->*member).push_back(std::move(*estimate));
    return true;
  };
}

// A trajectory that decodes but does not rebuild (not a MINCO solution) is counted in
// trajectory_messages only: it is a valid message the tracker would refuse.
bool DecodeTrajectory(const lcm::LogEvent& event, RunLog* run) {
  const auto msg = CheckedDecode<poly_trajectory_t>(event.data, event.datalen, nullptr);
  if (!msg) return false;
  std::string error;  // the converters write their reason here (not used: the message is counted)
  std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(*msg, &error);
  if (!poly) return false;
  ++run->trajectory_messages;
  std::optional<ArcYawTrajectory> trajectory = msgs::ToArcYaw(*poly, {}, &error);
  if (trajectory) run->trajectories.push_back({std::move(*poly), std::move(*trajectory)});
  return true;
}

// The map receiver lives as long as the read; the run gets its grid at the end.
Decoder MapDecoder(msgs::MapReceiver* receiver) {
  return [receiver](const lcm::LogEvent& event, RunLog*) {
    const auto msg = CheckedDecode<map_update_t>(event.data, event.datalen, nullptr);
    if (!msg) return false;
    return receiver->Accept(*msg).outcome != msgs::MapUpdateOutcome::kRejected;
  };
}

std::unordered_map<std::string_view, Decoder> Decoders(msgs::MapReceiver* receiver) {
  namespace ch = channels;
  return {
      {ch::MISSION_STATUS, AppendTo(&RunLog::mission_statuses)},
      {ch::PLANNER_STATUS, AppendTo(&RunLog::planner_statuses)},
      {ch::TRACKER_STATUS, AppendTo(&RunLog::tracker_statuses)},
      {ch::SIM_STATUS, AppendTo(&RunLog::sim_statuses)},
      {ch::SIM_CONTACT, AppendTo(&RunLog::sim_contacts)},
      {ch::SIM_EVENT, AppendTo(&RunLog::sim_events)},
      {ch::GOAL, AppendTo(&RunLog::goals)},
      {ch::ROBOT_STATE, RobotStatesInto(&RunLog::robot_states)},
      {ch::SIM_PLANT_STATE, RobotStatesInto(&RunLog::plant_states)},
      {ch::TRAJECTORY, DecodeTrajectory},
      {ch::MAP_UPDATE, MapDecoder(receiver)},
  };
}

// Channels the report does not use: the type the fingerprint names must decode.
bool CheckOtherChannel(const lcm::LogEvent& event) {
  if (event.channel.starts_with("LCM_SELF_TEST")) return true;  // LCM's start-up probe
  const std::optional<msgs::MessageTypeInfo> type = msgs::IdentifyMessage(event.data, event.datalen);
  std::string error;
  return type && type->check(event.data, event.datalen, &error);
}

void CountEvent(const lcm::LogEvent& event, RunLog* run) {
  if (run->channels.empty()) run->first_utime = event.timestamp;
  run->first_utime = std::min(run->first_utime, event.timestamp);
  run->last_utime = std::max(run->last_utime, event.timestamp);
  ++run->channels[event.channel].messages;
}

}  // namespace

RunLog ReadRunLog(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw std::runtime_error(path + ": cannot open the LCM log (no such file)");
  }
  if (!std::filesystem::is_regular_file(path, error)) throw std::runtime_error(path + ": not a file");
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error(path + ": cannot open the LCM log");
  RunLog run;
  run.path = path;
  msgs::MapReceiver receiver;
  const std::unordered_map<std::string_view, Decoder> decoders = Decoders(&receiver);
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    CountEvent(*event, &run);
    const auto decoder = decoders.find(event->channel);
    const bool good = decoder != decoders.end() ? decoder->second(*event, &run) : CheckOtherChannel(*event);
    if (!good) ++run.channels[event->channel].decode_failures;
  }
  if (run.channels.empty() && std::filesystem::file_size(path, error) > 0) {
    throw std::runtime_error(path + ": not an LCM log (no event could be read)");
  }
  if (receiver.has_map()) {
    run.map = FinalMap{receiver.geometry(), {receiver.states().begin(), receiver.states().end()}};
  }
  return run;
}

}  // namespace topay::report
