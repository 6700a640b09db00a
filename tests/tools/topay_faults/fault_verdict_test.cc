// Violations: each rule of the fault-injection suite is reported when broken, and only then.

#include <gtest/gtest.h>

#include "tools/topay_faults/fault_verdict.h"

namespace topay::tools {
namespace {

FaultSpec CommandLoss() {
  FaultSpec f;
  f.name = "kill-tracker";
  f.stop_expected = true;
  f.from_last_command = true;
  f.stop_within_limit = true;
  return f;
}

EpisodeResult Good() {
  EpisodeResult e;
  e.fault = "kill-tracker";
  e.seed = 5;
  e.injected = true;
  e.safe_ms = 60.0;
  e.recovered = true;
  e.recover_s = 4.0;
  return e;
}

std::vector<std::string> Of(const EpisodeResult& e) { return Violations({CommandLoss()}, {e}); }

TEST(FaultVerdict, AGoodEpisodeBreaksNoRule) { EXPECT_TRUE(Of(Good()).empty()); }

TEST(FaultVerdict, EachBrokenRuleIsNamed) {
  EpisodeResult contact = Good();
  contact.contacts = 2;
  ASSERT_EQ(Of(contact).size(), 1u);
  EXPECT_NE(Of(contact)[0].find("2 ground-truth contact(s)"), std::string::npos);

  EpisodeResult late = Good();
  late.safe_ms = 140.0;
  ASSERT_EQ(Of(late).size(), 1u);
  EXPECT_NE(Of(late)[0].find("140 ms after the last command (limit 100 ms)"), std::string::npos);

  // A dead bridge: the devices' own stop, timed from the kill.
  FaultSpec bridge;
  bridge.name = "kill-canbridge";
  bridge.stop_expected = true;
  bridge.stop_within_limit = true;
  EpisodeResult slow = Good();
  slow.fault = "kill-canbridge";
  slow.safe_ms = 110.0;
  const std::vector<std::string> slow_violations = Violations({bridge}, {slow});
  ASSERT_EQ(slow_violations.size(), 1u);
  EXPECT_NE(slow_violations[0].find("110 ms after the fault (limit 100 ms)"), std::string::npos);
  slow.safe_ms = 67.0;
  EXPECT_TRUE(Violations({bridge}, {slow}).empty());

  EpisodeResult no_stop = Good();
  no_stop.safe_ms = -1.0;
  ASSERT_EQ(Of(no_stop).size(), 1u);
  EXPECT_NE(Of(no_stop)[0].find("not commanded to stop"), std::string::npos);

  EpisodeResult crash = Good();
  crash.other_restarts = 1;
  EXPECT_EQ(Of(crash).size(), 1u);

  EpisodeResult refused = Good();
  refused.injected = false;
  refused.notes = "topay-tracker is not running";
  ASSERT_EQ(Of(refused).size(), 1u);
  EXPECT_NE(Of(refused)[0].find("could not be injected: topay-tracker is not running"), std::string::npos);
}

TEST(FaultVerdict, NoRecoveryIsAcceptedOnlyWithAClearFailure) {
  EpisodeResult stuck = Good();
  stuck.recovered = false;
  stuck.reaction = "not recovered 45 s after the fault was cleared";
  EXPECT_EQ(Of(stuck).size(), 1u);
  EpisodeResult failed = stuck;
  failed.reaction = "mission FAILED: goto drop-off: no plan";
  EXPECT_TRUE(Of(failed).empty());
}

}  // namespace
}  // namespace topay::tools
