#pragma once
// The goal ids the planner has taken, each with its content: a goal id is issued once. A GOAL
// under an id taken before is a repeat (the same content) or a corrupted or foreign copy (other
// content), and neither may replace the goal in hand nor fail the goal of that id.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

namespace topay::planner {

class IssuedGoals {
 public:
  enum class Verdict {
    kNew,     ///< never seen: taken, and remembered
    kRepeat,  ///< taken before with the same content
    kReused,  ///< taken before with other content
  };

  /// Remembers the newest `capacity` ids (>= 1). A goal flood of new ids pushes the oldest out;
  /// the goals a mission may still be waiting for are its newest.
  explicit IssuedGoals(std::size_t capacity = 64);

  /// `content`: the goal's bytes that must match for a repeat (the planner leaves its utime out).
  Verdict Take(std::int64_t goal_id, std::vector<std::uint8_t> content);

  std::size_t size() const { return goals_.size(); }

 private:
  std::size_t capacity_;
  std::deque<std::pair<std::int64_t, std::vector<std::uint8_t>>> goals_;  // oldest first
};

}  // namespace topay::planner
