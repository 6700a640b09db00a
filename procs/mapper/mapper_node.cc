#include "procs/mapper/mapper_node.h"

#include <spdlog/spdlog.h>

#include "procs/msgs/convert_robot_state.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::mapper {
namespace {

constexpr double kHealthPeriodS = 1.0;
// Scans stopped: no cloud for this long (s) turns the health to WARN.
constexpr double kStaleScansS = 1.0;
// A rejected cloud or a scan without a robot state keeps the health at WARN this long (s).
constexpr double kWarnHoldS = 10.0;

double MsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

MapperNode::MapperNode(procs::ProcessLoop* loop, ScanMapper* mapper, OctomapWorker* octomap,
                       const MapperOptions& options, MapJournal* journal)
    : loop_(loop),
      mapper_(mapper),
      octomap_(octomap),
      journal_(journal),
      options_(options),
      history_(options.robot_state),
      schedule_({.snapshot_period_s = options.publish.snapshot_period_s}) {
  loop_->Subscribe<point_cloud_t>(std::string(channels::POINT_CLOUD),
                                  [this](const point_cloud_t& m) { OnCloud(m); });
  loop_->Subscribe<robot_state_t>(std::string(channels::ROBOT_STATE),
                                  [this](const robot_state_t& m) { OnRobotState(m); });
  // The silence timer: an update at least every max_silence_s, scans or not.
  loop_->AddTimer(options_.publish.max_silence_s / 2.0, [this] {
    if (NowS() - last_publish_s_ >= options_.publish.max_silence_s) Publish(procs::NowUtime());
  });
  loop_->AddTimer(kHealthPeriodS, [this] { OnHealthTimer(); });
  loop_->SetHealth(heartbeat_t::OK, "waiting for POINT_CLOUD");
}

double MapperNode::NowS() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void MapperNode::OnRobotState(const robot_state_t& msg) {
  std::string error;
  const std::optional<msgs::RobotStateEstimate> estimate = state_intake_.Take(msg, &error);
  if (!estimate || !history_.Add(estimate->utime, estimate->state)) {
    ++stats_.states_rejected;
    stats_.last_error = "ROBOT_STATE: " + (error.empty() ? std::string("wrong joint count") : error);
    return;
  }
}

void MapperNode::OnCloud(const point_cloud_t& msg) {
  const auto start = std::chrono::steady_clock::now();
  ++stats_.clouds;
  if (const std::optional<msgs::CloudError> error = msgs::CheckCloud(msg, options_.filter.input, &cloud_)) {
    ++stats_.clouds_rejected;
    stats_.last_error = error->ToString();
    spdlog::warn("POINT_CLOUD utime {} skipped: {}", msg.utime, stats_.last_error);
    return;
  }
  const ScanMapperSummary summary = mapper_->Integrate(cloud_, history_.At(cloud_.utime), &pending_);
  stats_.AddScan(summary);
  last_data_utime_ = std::max(last_data_utime_, cloud_.utime);
  if (octomap_ != nullptr && scans_++ % options_.octomap.every_n_scans == 0) {
    octomap_->Submit(cloud_.X_WS.translation(), mapper_->last_points());
  }
  Publish(last_data_utime_);
  AddSample(&stats_.scan_to_update_ms, MsSince(start));
}

void MapperNode::Publish(std::int64_t utime, bool force_snapshot) {
  const auto start = std::chrono::steady_clock::now();
  const double now_s = NowS();
  if (force_snapshot) schedule_.RequestSnapshot();
  const msgs::MapPublishStep step = schedule_.Next(now_s);
  const bool full = step.is_full;
  const OccupancyMap& map = mapper_->map();
  const map_update_t msg =
      full ? msgs::EncodeFullMap(map.geometry(), map.states(), utime, step.map_seq, options_.publish.codec)
           : msgs::EncodeMapDelta(map.geometry(), pending_, utime, step.map_seq, options_.publish.codec);
  const double encode_ms = MsSince(start);
  pending_.clear();
  loop_->lcm().publish(std::string(channels::MAP_UPDATE), &msg);
  Journal(msg, now_s);
  last_publish_s_ = now_s;
  ++stats_.updates;
  const double bytes = static_cast<double>(msg.getEncodedSize());
  if (full) {
    ++stats_.snapshots;
    AddSample(&stats_.snapshot_bytes, bytes);
    AddSample(&stats_.snapshot_encode_ms, encode_ms);
  } else {
    AddSample(&stats_.delta_bytes, bytes);
    AddSample(&stats_.encode_ms, encode_ms);
  }
}

void MapperNode::Journal(const map_update_t& msg, double now_s) {
  if (journal_ == nullptr) return;
  try {
    journal_->Record(msg);
  } catch (const std::exception& e) {  // the map still goes out; a restart would lose it
    ++stats_.journal_errors;
    last_journal_error_ = e.what();
    if (now_s - last_journal_error_s_ >= kWarnHoldS) spdlog::error("{}", e.what());
    last_journal_error_s_ = now_s;
  }
}

void MapperNode::OnHealthTimer() {
  const double now_s = NowS();
  if (stats_.clouds_rejected > rejected_at_last_health_) last_rejection_s_ = now_s;
  if (stats_.scans_without_state > without_state_at_last_health_) last_without_state_s_ = now_s;
  if (stats_.clouds > clouds_at_last_health_) last_cloud_s_ = now_s;
  rejected_at_last_health_ = stats_.clouds_rejected;
  without_state_at_last_health_ = stats_.scans_without_state;
  clouds_at_last_health_ = stats_.clouds;
  // A problem keeps the health at WARN for kWarnHoldS after it was last seen, so that a
  // supervisor polling the heartbeat does not miss it.
  const bool rejecting = now_s - last_rejection_s_ < kWarnHoldS;
  const bool no_state = now_s - last_without_state_s_ < kWarnHoldS;
  const bool stale = now_s - last_cloud_s_ > kStaleScansS;
  const bool journal_failing = now_s - last_journal_error_s_ < kWarnHoldS;
  std::string status = stats_.StatusLine(mapper_->map().CountStates());
  if (rejecting) status += "; rejecting clouds: " + stats_.last_error;
  if (no_state) status += "; no ROBOT_STATE at scan time: own points not removed";
  if (stale) status += "; no POINT_CLOUD";
  if (journal_failing) status += "; map journal not written: " + last_journal_error_;
  loop_->SetHealth(rejecting || no_state || stale || journal_failing ? heartbeat_t::WARN : heartbeat_t::OK, status);
}

}  // namespace topay::mapper
