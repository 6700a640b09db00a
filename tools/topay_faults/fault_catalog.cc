#include "fault_catalog.h"

#include <stdexcept>

namespace topay::tools {
namespace {

FaultSpec Kill(const std::string& process, const std::string& expected, bool stop, bool from_last_command = false) {
  FaultSpec f;
  f.name = "kill-" + process;
  f.family = FaultFamily::kKill;
  f.target = process;
  f.what = "kill -9 of " + process + " while the robot moves";
  f.expected = expected;
  f.stop_expected = stop;
  f.from_last_command = from_last_command;
  f.stop_within_limit = from_last_command;
  return f;
}

// The stop must begin within 100 ms of the fault itself (the devices' own watchdogs).
FaultSpec WithStopLimit(FaultSpec f) {
  f.stop_within_limit = true;
  return f;
}

FaultSpec Make(const std::string& name, FaultFamily family, const std::string& what, const std::string& expected,
               double hold_s, bool stop) {
  FaultSpec f;
  f.name = name;
  f.family = family;
  f.what = what;
  f.expected = expected;
  f.hold_s = hold_s;
  f.stop_expected = stop;
  return f;
}

std::vector<FaultSpec> KillFaults() {
  std::vector<FaultSpec> faults = {
      Kill("tracker", "command stream lost: the bridge stops the drives within 100 ms; restarted, the mission resumes",
           true, true),
      WithStopLimit(Kill("canbridge",
                         "the devices' own watchdogs stop them (arm drives: RPDO deadline 50 ms, EMCY 0x8250; "
                         "wheels: command watchdog 50 ms); restarted, the bridge resets the drives' faults and "
                         "re-enables them",
                         true)),
      Kill("motorsim", "drive heartbeats lost: the bridge stops; restarted drives are re-enabled", true),
      Kill("estimator",
           "a gap in ROBOT_STATE: the tracker decelerates once it is 0.1 s stale (unless the restart is quicker); "
           "tracking resumes",
           false),
      Kill("planner", "the trajectory in hand is still tracked; restarted, the mission's goal is planned again", false),
      Kill("mapper", "the planner keeps its last map; restarted, the map is rebuilt from scans", false),
      Kill("sim", "(the world itself) restarted; the estimator and tracker follow the new state", false),
      Kill("director", "no effect on motion; restarted", false),
      Kill("logger", "no effect on motion; restarted (a new log)", false),
  };
  FaultSpec mission = Kill("mission", "the graph's job is gone: the launcher ends the graph and reports the failure", false);
  mission.ends_mission = true;
  faults.push_back(mission);
  return faults;
}

std::vector<FaultSpec> CanFaults() {
  FaultSpec drive = Make("can-drive-fault", FaultFamily::kCan, "a drive fault (EMCY 0x5000) on one arm drive",
                         "the bridge FAULTs and stops every drive; back to RUNNING after a FAULT_RESET", 0.0, true);
  drive.operator_reset = true;
  FaultSpec base = Make("can-base-fault", FaultFamily::kCan, "a base controller fault (code 1)",
                        "the bridge FAULTs and stops; back to RUNNING after a FAULT_RESET", 0.0, true);
  base.operator_reset = true;
  return {
      Make("can-loss", FaultFamily::kCan, "10 % of the frames lost each way for 10 s",
           "the mission goes on (frames are re-sent every cycle); no stop needed", 10.0, false),
      Make("can-delay", FaultFamily::kCan, "three 0.5 s bursts of 20 ms delay on every frame, 1 s apart",
           "the mission goes on or the bridge stops briefly and recovers by itself", 3.0, false),
      drive,
      Make("can-heartbeat-loss", FaultFamily::kCan, "one arm drive's heartbeat lost for 1 s",
           "the bridge stops every drive; recovers by itself once heartbeats return", 1.0, true),
      Make("can-bus-off", FaultFamily::kCan, "bus-off: the nodes silent for 0.5 s, then a restart",
           "the bridge stops; recovers by itself after the restart", 0.5, true),
      base,
  };
}

std::vector<FaultSpec> LcmFaults() {
  return {
      Make("lcm-drop", FaultFamily::kLcm, "10 % of every LCM datagram dropped for 10 s (nftables in the namespace)",
           "the mission goes on; brief stale-state stops allowed", 10.0, false),
      Make("lcm-reorder", FaultFamily::kLcm,
           "for 5 s every state and command message re-sent 30 ms late (older after newer)",
           "older messages ignored; the mission goes on", 5.0, false),
      Make("lcm-stale-localisation", FaultFamily::kLcm, "BASE_POSE lost for 8 s (dropped by nftables)",
           "the estimator dead-reckons up to 5 s, then stops publishing: the tracker stops; resumes after", 8.0,
           true),
      Make("lcm-map-frozen", FaultFamily::kLcm,
           "MAP_UPDATE lost for 10 s (dropped by nftables): the map stops updating while the mapper runs",
           "the planner plans on its last map; the mission goes on", 10.0, false),
      Make("lcm-goal-flood", FaultFamily::kLcm, "the mission's last GOAL re-sent at 1 kHz for 5 s",
           "duplicates ignored; the planner keeps up; the mission goes on", 5.0, false),
  };
}

std::vector<FaultSpec> GoalFaults() {
  std::vector<FaultSpec> faults = {
      Make("goal-nan", FaultFamily::kGoal, "a GOAL with a NaN position", "refused with a reason; the mission goes on",
           0.0, false),
      Make("goal-unreachable", FaultFamily::kGoal, "a GOAL 100 m outside the room",
           "the planner fails it with a reason; the robot stops safely; the mission's goal is taken up again", 0.0,
           false),
      Make("goal-in-obstacle", FaultFamily::kGoal, "a GOAL inside a box of the room",
           "the planner fails it with a reason; the robot stops safely; the mission's goal is taken up again", 0.0,
           false),
      Make("goal-every-50ms", FaultFamily::kGoal, "for 5 s a new random GOAL in the room every 50 ms",
           "the planner supersedes plans safely; the mission's goal is taken up again", 5.0, false),
  };
  for (FaultSpec& f : faults) f.refusal_expected = f.name != "goal-every-50ms";
  return faults;
}

}  // namespace

std::vector<FaultSpec> FaultCatalog() {
  std::vector<FaultSpec> all = KillFaults();
  for (auto family : {CanFaults(), LcmFaults(), GoalFaults()}) all.insert(all.end(), family.begin(), family.end());
  all.push_back(Make("hostile-payloads", FaultFamily::kHostile,
                     "3 rounds over 3 s, on each of the 25 channels: random bytes, a 256 KiB payload, a truncated "
                     "copy of the channel's last message and (but on the simulator's own channels) bit-flipped ones",
                     "rejected (or clamped) by every subscriber; no process dies; the mission goes on", 3.0, false));
  return all;
}

std::vector<FaultSpec> SelectFaults(const std::vector<std::string>& names) {
  const std::vector<FaultSpec> all = FaultCatalog();
  if (names.empty()) return all;
  std::vector<FaultSpec> chosen;
  for (const std::string& name : names) {
    bool found = false;
    for (const FaultSpec& f : all) {
      if (f.name == name) chosen.push_back(f), found = true;
    }
    if (!found) {
      std::string known;
      for (const FaultSpec& f : all) known += (known.empty() ? "" : ", ") + f.name;
      throw std::invalid_argument("unknown fault '" + name + "' (known: " + known + ")");
    }
  }
  return chosen;
}

std::string FamilyName(FaultFamily family) {
  switch (family) {
    case FaultFamily::kKill: return "kill -9";
    case FaultFamily::kCan: return "CAN";
    case FaultFamily::kLcm: return "LCM";
    case FaultFamily::kGoal: return "planner goals";
    case FaultFamily::kHostile: return "hostile input";
  }
  return "?";
}

}  // namespace topay::tools
