#include "fault_queue.h"

namespace topay::tools {

FaultQueue::FaultQueue(std::vector<FaultSpec> faults, int runs) : faults_(std::move(faults)) {
  for (const FaultSpec& f : faults_) remaining_[f.name] = runs;
}

const FaultSpec* FaultQueue::Next(int episodes_in_mission, int episodes_per_mission) {
  bool others_owed = false;
  for (const FaultSpec& f : faults_) others_owed = others_owed || (!f.ends_mission && remaining_[f.name] > 0);
  for (std::size_t k = 0; k < faults_.size(); ++k) {
    const FaultSpec& f = faults_[(cursor_ + k) % faults_.size()];
    if (remaining_[f.name] <= 0) continue;
    if (f.ends_mission && others_owed && episodes_in_mission < episodes_per_mission) continue;
    cursor_ = (cursor_ + k + 1) % faults_.size();
    return &f;
  }
  return nullptr;
}

bool FaultQueue::Record(const EpisodeResult& result) {
  if (result.injected) {
    failed_attempts_[result.fault] = 0;
    --remaining_[result.fault];
    return true;
  }
  if (!result.refused) return false;  // not tried (the mission ended first): owed as before
  if (++failed_attempts_[result.fault] < kAttempts) return false;
  failed_attempts_[result.fault] = 0;
  --remaining_[result.fault];
  return true;
}

void FaultQueue::Count(const EpisodeResult& earlier) {
  const auto it = remaining_.find(earlier.fault);
  if (it != remaining_.end() && it->second > 0) --it->second;
}

bool FaultQueue::Done() const {
  for (const auto& [name, left] : remaining_) {
    if (left > 0) return false;
  }
  return true;
}

int FaultQueue::Remaining(const std::string& fault) const {
  const auto it = remaining_.find(fault);
  return it == remaining_.end() ? 0 : it->second;
}

}  // namespace topay::tools
