#include "procs/viz/viz_pipeline.h"

#include <cmath>

#include "procs/msgs/convert_robot_state.h"
#include "procs/viz/json_text.h"
#include "procs/viz/status_json.h"
#include "topay/map_update_t.hpp"
#include "topay/point_cloud_t.hpp"
#include "topay/poly_trajectory_t.hpp"
#include "topay/robot_state_t.hpp"
#include "topay/sim_contact_t.hpp"
#include "topay_msgs/channels.h"
#include "topay_msgs/checked_decode.h"

namespace topay::viz {
namespace {

std::int64_t IntervalOf(double rate_hz) { return rate_hz > 0 ? std::llround(1e6 / rate_hz) : 0; }

nlohmann::json Nullable(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

}  // namespace

VizPipeline::VizPipeline(const RobotView& robot, const VizPipelineOptions& options, Sink sink)
    : robot_(robot), options_(options), sink_(std::move(sink)),
      description_(robot.Description().dump(-1, ' ', false, kReplaceInvalidUtf8)), trajectory_(robot, options.trajectory) {
  const VizRates& r = options_.rates;
  topics_[Index(Topic::kRobotState)].min_interval_us = IntervalOf(r.robot_state_hz);
  topics_[Index(Topic::kMapBlocks)].min_interval_us = IntervalOf(r.map_hz);
  topics_[Index(Topic::kScan)].min_interval_us = IntervalOf(r.scan_hz);
  topics_[Index(Topic::kPlotSample)].min_interval_us = IntervalOf(r.plot_hz);
  for (Topic t : {Topic::kPlannerStatus, Topic::kTrackerStatus, Topic::kMissionStatus}) {
    topics_[Index(t)].min_interval_us = IntervalOf(r.status_hz);
  }
  topics_[Index(Topic::kDriveStatus)].min_interval_us = IntervalOf(r.drive_hz);
  topics_[Index(Topic::kSimStatus)].min_interval_us = IntervalOf(r.sim_hz);
  topics_[Index(Topic::kRobotDescription)].last = description_;
}

void VizPipeline::Reset() {
  for (TopicState& s : topics_) {
    s.emitted_once = false;
    s.last_emit_utime = 0;
    s.waiting.reset();
    s.last.clear();
  }
  topics_[Index(Topic::kRobotDescription)].last = description_;
  map_ = MapBlocks();
  trajectory_ = TrajectoryView(robot_, options_.trajectory);
  robot_state_.reset();
  contacts_ = nlohmann::json::array();
  contact_count_ = 0;
}

bool VizPipeline::Due(const TopicState& state, std::int64_t utime) const {
  return !state.emitted_once || utime - state.last_emit_utime >= state.min_interval_us ||
         utime < state.last_emit_utime;  // a clock that went back (a new log, a seek)
}

void VizPipeline::Emit(Topic topic, std::int64_t log_utime, std::string payload) {
  TopicState& state = topics_[Index(topic)];
  state.emitted_once = true;
  state.last_emit_utime = log_utime;
  state.waiting.reset();
  ++counts_.emitted;
  sink_(topic, log_utime, payload);
  state.last = std::move(payload);
}

void VizPipeline::Offer(Topic topic, std::int64_t log_utime, std::string payload) {
  TopicState& state = topics_[Index(topic)];
  if (Due(state, log_utime)) {
    Emit(topic, log_utime, std::move(payload));
  } else {
    state.waiting.emplace(log_utime, std::move(payload));
  }
}

void VizPipeline::Flush(std::int64_t now_utime) {
  for (std::size_t i = 0; i < kNumTopics; ++i) {
    TopicState& state = topics_[i];
    if (state.waiting && Due(state, now_utime)) {
      auto [utime, payload] = std::move(*state.waiting);
      Emit(static_cast<Topic>(i), utime, std::move(payload));
    }
  }
  TopicState& map = topics_[Index(Topic::kMapBlocks)];
  if (map_.dirty() && Due(map, now_utime)) {
    if (std::optional<nlohmann::json> changes = map_.Changes(map_utime_ * 1e-6)) {
      Emit(Topic::kMapBlocks, map_utime_, changes->dump());
    }
  }
}

std::optional<std::string> VizPipeline::Latched(Topic topic) const {
  if (topic == Topic::kMapBlocks) {
    std::optional<nlohmann::json> full = map_.Full(map_utime_ * 1e-6);
    return full ? std::optional<std::string>(full->dump()) : std::nullopt;
  }
  const TopicState& state = topics_[Index(topic)];
  if (state.last.empty()) return std::nullopt;
  return state.last;
}

void VizPipeline::Malformed(std::string_view channel, const std::string& why) {
  ++counts_.malformed;
  counts_.last_error = std::string(channel) + ": " + why;
}

void VizPipeline::Handle(std::string_view channel, const void* data, std::size_t size, std::int64_t recv_utime) {
  namespace ch = channels;
  ++counts_.messages;
  if (channel == ch::ROBOT_STATE) return HandleRobotState(data, size, recv_utime);
  if (channel == ch::MAP_UPDATE) return HandleMap(data, size, recv_utime);
  if (channel == ch::POINT_CLOUD) return HandleScan(data, size, recv_utime);
  if (channel == ch::TRAJECTORY) return HandleTrajectory(data, size, recv_utime);
  if (channel == ch::SIM_CONTACT) return HandleContact(data, size, recv_utime);
  if (channel == ch::PLANNER_PATHS) {
    return HandleStatus(channel, data, size, recv_utime, Topic::kCandidatePaths, &CandidatePathsJson);
  }
  if (channel == ch::PLANNER_STATUS) {
    return HandleStatus(channel, data, size, recv_utime, Topic::kPlannerStatus, &PlannerStatusJson);
  }
  if (channel == ch::GOAL) return HandleStatus(channel, data, size, recv_utime, Topic::kGoal, &GoalJson);
  if (channel == ch::TRACKER_STATUS) {
    return HandleStatus(channel, data, size, recv_utime, Topic::kTrackerStatus, &TrackerStatusJson);
  }
  if (channel == ch::MISSION_STATUS) {
    return HandleStatus(channel, data, size, recv_utime, Topic::kMissionStatus, &MissionStatusJson);
  }
  if (channel == ch::GRAPH_STATUS) {
    return HandleStatus(channel, data, size, recv_utime, Topic::kGraphStatus, &GraphStatusJson);
  }
  if (channel == ch::DRIVE_STATUS) {
    return HandleStatus(channel, data, size, recv_utime, Topic::kDriveStatus, &DriveStatusJson);
  }
  if (channel == ch::SIM_STATUS) return HandleStatus(channel, data, size, recv_utime, Topic::kSimStatus, &SimStatusJson);
  --counts_.messages;
  ++counts_.ignored;
}

template <class Msg>
void VizPipeline::HandleStatus(std::string_view channel, const void* data, std::size_t size, std::int64_t recv_utime,
                               Topic topic, nlohmann::json (*to_json)(const Msg&)) {
  std::string error;
  const std::optional<Msg> msg = CheckedDecode<Msg>(data, size, &error);
  if (!msg) return Malformed(channel, error);
  Offer(topic, recv_utime, to_json(*msg).dump(-1, ' ', false, kReplaceInvalidUtf8));
}

void VizPipeline::HandleRobotState(const void* data, std::size_t size, std::int64_t recv_utime) {
  std::string error;
  const std::optional<robot_state_t> msg = CheckedDecode<robot_state_t>(data, size, &error);
  std::optional<msgs::RobotStateEstimate> estimate = msg ? msgs::FromMessage(*msg, &error) : std::nullopt;
  if (!estimate) return Malformed(channels::ROBOT_STATE, error);
  if (estimate->state.num_joints() != robot_.model().num_joints()) {
    return Malformed(channels::ROBOT_STATE, std::to_string(estimate->state.num_joints()) + " joints, the robot has " +
                                                std::to_string(robot_.model().num_joints()));
  }
  robot_state_ = estimate->state;
  const double t = estimate->utime * 1e-6;
  if (Due(topics_[Index(Topic::kRobotState)], recv_utime)) {
    Emit(Topic::kRobotState, recv_utime,
         robot_.State(t, estimate->state, estimate->v_mps, estimate->omega_radps, estimate->gripper).dump(-1, ' ', false, kReplaceInvalidUtf8));
  }
  if (!Due(topics_[Index(Topic::kPlotSample)], recv_utime)) return;
  const std::vector<double> q(estimate->state.q_rad.data(), estimate->state.q_rad.data() + estimate->state.q_rad.size());
  nlohmann::json plot = {{"t", t},           {"trajectory_id", trajectory_.active_id()},
                         {"v_mps", estimate->v_mps}, {"omega_radps", estimate->omega_radps},
                         {"q_rad", q}};
  const TrajectorySample* plan = trajectory_.PlannedAt(estimate->utime);
  plot["v_plan_mps"] = plan ? Nullable(plan->v_mps) : nullptr;
  plot["omega_plan_radps"] = plan ? Nullable(plan->omega_radps) : nullptr;
  plot["a_plan_mps2"] = plan ? Nullable(plan->a_mps2) : nullptr;
  plot["beta_plan_radps2"] = plan ? Nullable(plan->beta_radps2) : nullptr;
  plot["q_plan_rad"] = plan ? nlohmann::json(std::vector<double>(plan->state.q_rad.data(),
                                                                  plan->state.q_rad.data() + plan->state.q_rad.size()))
                            : nlohmann::json(nullptr);
  Emit(Topic::kPlotSample, recv_utime, plot.dump(-1, ' ', false, kReplaceInvalidUtf8));
}

void VizPipeline::HandleMap(const void* data, std::size_t size, std::int64_t recv_utime) {
  std::string error;
  const std::optional<map_update_t> msg = CheckedDecode<map_update_t>(data, size, &error);
  if (!msg) return Malformed(channels::MAP_UPDATE, error);
  const msgs::MapAcceptResult result = map_.Accept(*msg);
  if (result.outcome == msgs::MapUpdateOutcome::kRejected) return Malformed(channels::MAP_UPDATE, result.reason);
  map_utime_ = recv_utime;
  if (options_.rates.map_hz <= 0) Flush(recv_utime);  // every update at once (conversion)
}

void VizPipeline::HandleScan(const void* data, std::size_t size, std::int64_t recv_utime) {
  if (!Due(topics_[Index(Topic::kScan)], recv_utime)) return;  // decode only the scans that go
  std::string error;
  const std::optional<point_cloud_t> msg = CheckedDecode<point_cloud_t>(data, size, &error);
  std::optional<nlohmann::json> scan = msg ? ScanPayload(*msg, options_.scan, &error) : std::nullopt;
  if (!scan) return Malformed(channels::POINT_CLOUD, error);
  Emit(Topic::kScan, recv_utime, scan->dump());
}

void VizPipeline::HandleTrajectory(const void* data, std::size_t size, std::int64_t recv_utime) {
  std::string error;
  const std::optional<poly_trajectory_t> msg = CheckedDecode<poly_trajectory_t>(data, size, &error);
  if (!msg) return Malformed(channels::TRAJECTORY, error);
  std::optional<nlohmann::json> payload = trajectory_.Accept(*msg, &error);
  if (payload) return Emit(Topic::kTrajectory, recv_utime, payload->dump());
  if (!error.empty()) Malformed(channels::TRAJECTORY, error);
}

void VizPipeline::HandleContact(const void* data, std::size_t size, std::int64_t recv_utime) {
  std::string error;
  const std::optional<sim_contact_t> msg = CheckedDecode<sim_contact_t>(data, size, &error);
  if (!msg) return Malformed(channels::SIM_CONTACT, error);
  nlohmann::json contact = {{"t", msg->utime * 1e-6}, {"body", msg->body}, {"box_id", msg->box_id},
                            {"depth_m", Nullable(msg->depth_m)}, {"p_W_m", nullptr}, {"radius_m", 0.0}};
  Eigen::Vector3d p_W;
  double radius = 0.0;
  if (robot_state_ && robot_.BodyPlace(msg->body, *robot_state_, &p_W, &radius)) {
    contact["p_W_m"] = VectorJson(p_W);
    contact["radius_m"] = radius;
  }
  ++contact_count_;
  contacts_.push_back(std::move(contact));
  if (static_cast<int>(contacts_.size()) > options_.max_contacts) contacts_.erase(contacts_.begin());
  Emit(Topic::kContacts, recv_utime, nlohmann::json{{"count", contact_count_}, {"contacts", contacts_}}.dump(-1, ' ', false, kReplaceInvalidUtf8));
}

}  // namespace topay::viz
