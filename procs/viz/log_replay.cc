#include "procs/viz/log_replay.h"

#include <cmath>
#include <stdexcept>

#include "topay_msgs/channels.h"

namespace topay::viz {
namespace {

std::unique_ptr<lcm::LogFile> OpenLog(const std::string& path) {
  auto log = std::make_unique<lcm::LogFile>(path, "r");
  if (!log->good()) throw std::runtime_error(path + ": cannot open the LCM log");
  return log;
}

}  // namespace

LogSpan ScanLog(const std::string& path) {
  std::unique_ptr<lcm::LogFile> log = OpenLog(path);
  LogSpan span;
  while (const lcm::LogEvent* event = log->readNextEvent()) {
    if (span.events == 0) span.first_utime = event->timestamp;
    span.first_utime = std::min(span.first_utime, event->timestamp);
    span.last_utime = std::max(span.last_utime, event->timestamp);
    ++span.events;
  }
  if (span.events == 0) throw std::runtime_error(path + ": no events in the LCM log");
  return span;
}

LogReplay::LogReplay(const std::string& path, VizFeed* feed, bool paused, double speed)
    : path_(path), feed_(feed), span_(ScanLog(path)), clock_(span_.first_utime, span_.last_utime) {
  Restart();
  clock_.SetSpeed(speed, 0);
  play_on_first_tick_ = !paused;  // the clock starts with the first Tick's wall time
}

void LogReplay::Restart() {
  log_ = OpenLog(path_);
  next_.reset();
  fed_until_ = span_.first_utime - 1;
  feed_->Reset();
}

bool LogReplay::ReadNext() {
  if (next_) return true;
  const lcm::LogEvent* event = log_->readNextEvent();
  if (event == nullptr) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(event->data);
  next_ = Event{event->timestamp, event->channel, std::vector<std::uint8_t>(bytes, bytes + event->datalen)};
  return true;
}

void LogReplay::FeedUntil(std::int64_t log_utime) {
  while (ReadNext() && next_->utime <= log_utime) {
    feed_->Handle(next_->channel, next_->data.data(), next_->data.size(), next_->utime);
    ++events_fed_;
    next_.reset();
  }
  fed_until_ = std::max(fed_until_, log_utime);
}

void LogReplay::CatchUp(std::int64_t log_utime, std::int64_t wall_utime) {
  Restart();
  ++seeks_;
  feed_->SetMuted(true);
  std::optional<Event> last_scan;  // scans are many and heavy: only the last one counts
  while (ReadNext() && next_->utime <= log_utime) {
    if (next_->channel == channels::POINT_CLOUD) {
      last_scan = std::move(next_);
    } else {
      feed_->Handle(next_->channel, next_->data.data(), next_->data.size(), next_->utime);
      ++events_fed_;
    }
    next_.reset();
  }
  if (last_scan) feed_->Handle(last_scan->channel, last_scan->data.data(), last_scan->data.size(), last_scan->utime);
  feed_->Flush(log_utime);
  feed_->SetMuted(false);
  fed_until_ = log_utime;
  feed_->PublishPlayback(log_utime, State(wall_utime));
  feed_->ResendLatched(log_utime);
}

void LogReplay::Command(const PlaybackCommand& command) {
  std::lock_guard lock(commands_mutex_);
  constexpr std::size_t kMaxQueued = 256;  // a client flooding commands
  if (commands_.size() < kMaxQueued) commands_.push_back(command);
}

void LogReplay::Apply(const PlaybackCommand& c, std::int64_t wall_utime) {
  if (c.command == "play") {
    clock_.Play(wall_utime);
  } else if (c.command == "pause") {
    clock_.Pause(wall_utime);
  } else if (c.command == "speed") {
    clock_.SetSpeed(c.speed, wall_utime);
  } else if (c.command == "seek" && std::isfinite(c.t)) {
    clock_.Seek(static_cast<std::int64_t>(c.t * 1e6), wall_utime);
  }
}

void LogReplay::Tick(std::int64_t wall_utime) {
  std::deque<PlaybackCommand> commands;
  {
    std::lock_guard lock(commands_mutex_);
    commands.swap(commands_);
  }
  bool seek = false;
  if (play_on_first_tick_) {
    clock_.Play(wall_utime);
    play_on_first_tick_ = false;
  }
  feed_->ServeNewSubscribers(fed_until_);  // as things stand before the clock moves on
  for (const PlaybackCommand& c : commands) {
    Apply(c, wall_utime);
    seek = seek || c.command == "seek";
  }
  const std::int64_t now = clock_.Now(wall_utime);
  if (!commands.empty() && !seek) feed_->PublishPlayback(now, State(wall_utime));  // answer at once
  if (seek || now < fed_until_) {
    CatchUp(now, wall_utime);  // a seek (the skipped part muted), or back in time: from the start again
  } else {
    FeedUntil(now);
  }
  feed_->Tick(now);
}

PlaybackState LogReplay::State(std::int64_t wall_utime) {
  PlaybackState s;
  s.replay = true;
  s.t = clock_.Now(wall_utime) * 1e-6;
  s.start_t = span_.first_utime * 1e-6;
  s.end_t = span_.last_utime * 1e-6;
  s.playing = clock_.playing();
  s.speed = clock_.speed();
  s.seeks = seeks_;
  return s;
}

}  // namespace topay::viz
