#pragma once
// Which fault the campaign injects next: round robin over the faults still owed episodes, so
// each mission hosts a mix; a fault that ends the mission only as a mission's last episode.
// A fault that could not be injected three times in a row is given up (its failed attempt is
// kept as a result, so the table shows it).

#include <map>
#include <string>
#include <vector>

#include "fault_catalog.h"
#include "fault_episode.h"

namespace topay::tools {

class FaultQueue {
 public:
  FaultQueue(std::vector<FaultSpec> faults, int runs);

  /// The next fault for a mission that has hosted `episodes_in_mission` episodes (nullptr: none
  /// owed). A mission-ending fault is returned only once the mission has hosted
  /// `episodes_per_mission` episodes or when nothing else is owed.
  const FaultSpec* Next(int episodes_in_mission, int episodes_per_mission);
  /// Books an episode's result: true if it is kept (injected, or given up after 3 refused
  /// injections); an episode that never came to its injection is owed again.
  bool Record(const EpisodeResult& result);
  /// Books an episode kept by an earlier run of the campaign (`--resume`): one run fewer owed
  /// for its fault (nothing for a fault not chosen now).
  void Count(const EpisodeResult& earlier);
  bool Done() const;
  int Remaining(const std::string& fault) const;

  static constexpr int kAttempts = 3;

 private:
  std::vector<FaultSpec> faults_;
  std::map<std::string, int> remaining_;
  std::map<std::string, int> failed_attempts_;
  std::size_t cursor_ = 0;
};

}  // namespace topay::tools
