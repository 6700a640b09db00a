#include "procs/launch/log_player.h"

#include <stdexcept>

namespace topay::launch {

LogPlayer::LogPlayer(const ReplayOptions& options, std::set<std::string> excluded)
    : options_(options), excluded_(std::move(excluded)), filter_(options.channels) {
  log_ = std::make_unique<lcm::LogFile>(options.log_path, "r");
  if (!log_->good()) throw std::runtime_error(options.log_path + ": cannot read the LCM log");
  const lcm::LogEvent* first = log_->readNextEvent();
  if (first == nullptr) throw std::runtime_error(options.log_path + ": empty or not an LCM log");
  begin_utime_ = first->timestamp + static_cast<std::int64_t>(options.start_offset_s * 1e6);
  if (options.start_offset_s > 0.0) {
    log_->seekToTimestamp(begin_utime_);
    done_ = !Advance();
  } else {
    next_ = first;
    done_ = !Playable() && !Advance();
  }
  if (!done_) first_utime_ = next_->timestamp;
}

bool LogPlayer::Playable() {
  if (next_->timestamp < begin_utime_) return false;  // before the start offset
  const std::string channel = next_->channel;
  if (!excluded_.contains(channel) && std::regex_match(channel, filter_)) return true;
  ++skipped_;
  return false;
}

bool LogPlayer::Advance() {
  while ((next_ = log_->readNextEvent()) != nullptr) {
    if (Playable()) return true;
  }
  return false;
}

void LogPlayer::Start(Clock::time_point now) {
  start_ = now;
  started_ = true;
}

LogPlayer::Clock::time_point LogPlayer::NextDue() const {
  if (!started_ || done_) return Clock::time_point::max();
  if (options_.speed <= 0.0) return start_;
  const double offset_s = static_cast<double>(next_->timestamp - first_utime_) * 1e-6 / options_.speed;
  return start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(offset_s));
}

bool LogPlayer::Pump(Clock::time_point now, lcm::LCM* lcm) {
  while (started_ && !done_ && NextDue() <= now) {
    lcm->publish(next_->channel, next_->data, static_cast<unsigned int>(next_->datalen));
    ++published_;
    done_ = !Advance();
  }
  return done_;
}

}  // namespace topay::launch
