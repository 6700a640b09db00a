#include "procs/planner/issued_goals.h"

#include <algorithm>
#include <stdexcept>

namespace topay::planner {

IssuedGoals::IssuedGoals(std::size_t capacity) : capacity_(capacity) {
  if (capacity_ == 0) throw std::invalid_argument("IssuedGoals: capacity must be >= 1");
}

IssuedGoals::Verdict IssuedGoals::Take(std::int64_t goal_id, std::vector<std::uint8_t> content) {
  const auto seen = std::find_if(goals_.begin(), goals_.end(), [&](const auto& g) { return g.first == goal_id; });
  if (seen != goals_.end()) return seen->second == content ? Verdict::kRepeat : Verdict::kReused;
  if (goals_.size() == capacity_) goals_.pop_front();
  goals_.emplace_back(goal_id, std::move(content));
  return Verdict::kNew;
}

}  // namespace topay::planner
