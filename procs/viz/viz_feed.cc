#include "procs/viz/viz_feed.h"
#include "procs/viz/json_text.h"

#include <fmt/format.h>

namespace topay::viz {

VizFeed::VizFeed(const RobotView& robot, const VizPipelineOptions& options, FoxgloveHub* hub)
    : hub_(hub),
      pipeline_(robot, options, [this](Topic topic, std::int64_t log_utime, const std::string& payload) {
        if (!muted_) hub_->Publish(topic, log_utime, payload);
      }) {}

void VizFeed::Serve(const LatchedRequest& request, std::int64_t now_utime) {
  if (const std::optional<std::string> payload = pipeline_.Latched(request.topic)) {
    hub_->SendTo(request, now_utime, *payload);
  }
}

void VizFeed::ServeNewSubscribers(std::int64_t now_utime) {
  for (const LatchedRequest& request : hub_->TakePendingLatched()) Serve(request, now_utime);
}

void VizFeed::Tick(std::int64_t now_utime) {
  ServeNewSubscribers(now_utime);
  pipeline_.Flush(now_utime);
}

void VizFeed::ResendLatched(std::int64_t now_utime) {
  hub_->TakePendingLatched();  // included below
  for (const LatchedRequest& request : hub_->LatchedSubscriptions()) Serve(request, now_utime);
}

void VizFeed::PublishStats(std::int64_t now_utime, const TransportCounts& transport) {
  const VizPipelineCounts& c = pipeline_.counts();
  const double dt = (now_utime - last_stats_utime_) * 1e-6;
  const double rate = last_stats_utime_ > 0 && dt > 0 ? (transport.bytes_sent - last_stats_bytes_) / dt : 0.0;
  last_stats_utime_ = now_utime;
  last_stats_bytes_ = transport.bytes_sent;
  const nlohmann::json stats = {{"t", now_utime * 1e-6},
                                {"clients", transport.clients},
                                {"lcm_messages", c.messages},
                                {"lcm_malformed", c.malformed},
                                {"frames_sent", transport.frames_sent},
                                {"frames_dropped", transport.frames_dropped},
                                {"bytes_sent", transport.bytes_sent},
                                {"bytes_per_s", rate}};
  hub_->Publish(Topic::kVizStats, now_utime, stats.dump(-1, ' ', false, kReplaceInvalidUtf8));
}

void VizFeed::PublishPlayback(std::int64_t now_utime, const PlaybackState& s) {
  const nlohmann::json playback = {{"mode", s.replay ? "replay" : "live"},
                                   {"t", s.t},
                                   {"start_t", s.start_t},
                                   {"end_t", s.end_t},
                                   {"playing", s.playing},
                                   {"speed", s.speed},
                                   {"seeks", s.seeks}};
  hub_->Publish(Topic::kPlayback, now_utime, playback.dump(-1, ' ', false, kReplaceInvalidUtf8));
}

std::string VizFeed::StatusLine(const TransportCounts& transport) const {
  const VizPipelineCounts& c = pipeline_.counts();
  return fmt::format("{} clients; {} messages ({} malformed); {} frames sent, {} dropped", transport.clients,
                     c.messages, c.malformed, transport.frames_sent, transport.frames_dropped);
}

}  // namespace topay::viz
